// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_base_version_h
#define psmpm_base_version_h

#include <string>

namespace psmpm
{
  /// The version of psmpm: the CMake project version, followed by the
  /// output of `git describe` at configure time when the sources were a
  /// git checkout, e.g. "0.2.0 (git 0a1d36e-dirty)".
  std::string
  version();
} // namespace psmpm

#endif
