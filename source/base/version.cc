// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// PSMPM_VERSION and PSMPM_GIT_DESCRIBE are set by CMake for this file
// only, so that a new commit recompiles nothing else.
// ---------------------------------------------------------------------
#include <psmpm/base/version.h>

#ifndef PSMPM_VERSION
#  define PSMPM_VERSION "unknown"
#endif
#ifndef PSMPM_GIT_DESCRIBE
#  define PSMPM_GIT_DESCRIBE ""
#endif

namespace psmpm
{
  std::string
  version()
  {
    const std::string git = PSMPM_GIT_DESCRIBE;
    return std::string(PSMPM_VERSION) +
           (git.empty() ? "" : " (git " + git + ")");
  }
} // namespace psmpm
