// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// PSMPM_VERSION and PSMPM_GIT_DESCRIBE come from a header that CMake
// generates for this file only, so that a new commit recompiles nothing
// else.
// ---------------------------------------------------------------------
#include <psmpm/base/version.h>

#include "psmpm_version_info.h"

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
