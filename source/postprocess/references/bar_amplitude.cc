// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>

#include <psmpm/base/format.h>
#include <psmpm/postprocess/references/bar_amplitude.h>

#include <cmath>

namespace psmpm
{
  namespace Postprocess
  {
    template <int dim>
    void
    check_bar_amplitude(const ReferenceContext<dim> &c)
    {
      const double v0      = std::abs(c.amplitude);
      const double E       = c.material.youngs_modulus;
      const double rho     = c.material.density;
      const double omega   = numbers::PI / c.length * std::sqrt(E / rho);
      double       measure = 1;
      for (unsigned int d = 0; d < dim; ++d)
        measure *= c.region[dim + d] - c.region[d];
      const double scales[3] = {v0, v0 / omega, v0 * std::sqrt(E * rho)};
      bool         fits      = std::isfinite(measure);
      for (const double s : scales)
        fits = fits && std::isfinite(s) && std::isfinite(s * s * measure);
      AssertThrow(
        fits,
        ExcMessage(
          "Reference solution/Velocity amplitude = " + prm_value(c.amplitude) +
          ": the error norms square the reference's "
          "velocity (amplitude " +
          prm_value(scales[0]) + "), displacement (" + prm_value(scales[1]) +
          ") and stress (" + prm_value(scales[2]) +
          ") over the material (measure " + prm_value(measure) +
          "), which exceeds the range of double "
          "numbers."));
    }

    template void
    check_bar_amplitude(const ReferenceContext<1> &);
    template void
    check_bar_amplitude(const ReferenceContext<2> &);
  } // namespace Postprocess
} // namespace psmpm
