// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/numbers.h>

#include <psmpm/postprocess/reference.h>
#include <psmpm/postprocess/references/bar_amplitude.h>

#include <cmath>

namespace psmpm
{
  namespace Postprocess
  {
    namespace
    {
      /// Thesis eq. 4.2: small-deformation bar on [0, Geometry/Length],
      /// ends fixed, v(x, 0) = v0 sin(pi x / L), along x.
      template <int dim>
      class VibratingBar : public Reference<dim>
      {
      public:
        explicit VibratingBar(const ReferenceContext<dim> &c)
          : amplitude(c.amplitude)
          , length(c.length)
          , youngs_modulus(c.material.youngs_modulus)
          , density(c.material.density)
        {
          check_bar_amplitude(c);
        }

        typename Reference<dim>::State
        evaluate(const Point<dim> &X, const double t) const override
        {
          typename Reference<dim>::State s;
          const double                   k = numbers::PI / length;
          const double w = k * std::sqrt(youngs_modulus / density);
          s.displacement[0] =
            amplitude / w * std::sin(w * t) * std::sin(k * X[0]);
          s.velocity[0]  = amplitude * std::cos(w * t) * std::sin(k * X[0]);
          s.stress[0][0] = youngs_modulus * amplitude / w * std::sin(w * t) *
                           k * std::cos(k * X[0]);
          return s;
        }

        unsigned int
        axis() const override
        {
          return 0;
        }

      private:
        const double amplitude, length, youngs_modulus, density;
      };
    } // namespace

    RegisterForDims<ReferenceRegistry, VibratingBar> register_vibrating_bar(
      "vibrating bar",
      "thesis eq. 4.2 on [0, Geometry/Length], ends fixed");
  } // namespace Postprocess
} // namespace psmpm
