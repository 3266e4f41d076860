// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_base_format_h
#define psmpm_base_format_h

#include <sstream>
#include <string>

namespace psmpm
{
  /// A number as a user would have written it in a parameter file.
  inline std::string
  prm_value(const double x)
  {
    std::ostringstream s;
    s.precision(10);
    s << x;
    return s.str();
  }
} // namespace psmpm

#endif
