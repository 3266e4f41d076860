// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/numbers.h>

#include <psmpm/postprocess/reference.h>
#include <psmpm/postprocess/references/soil_column.h>

#include <cmath>

namespace psmpm
{
  namespace Postprocess
  {
    namespace
    {
      /// W(s) and W'(s) of the odd 4H-periodic extension of the initial
      /// displacement (d'Alembert form of the column).
      std::pair<double, double>
      column_extension(const double s, const double H, const double a)
      {
        const double P = 4 * H;
        double       r = std::fmod(s, P);
        if (r < 0)
          r += P;
        double sign = 1;
        if (r > 2 * H)
          {
            r    = P - r; // W(s) = -W(4H - s), W'(s) = W'(4H - s)
            sign = -1;
          }
        const double q  = r <= H ? r : 2 * H - r;
        const double fv = a * (H * q - 0.5 * q * q);
        const double fd = (r <= H ? 1. : -1.) * a * (H - q);
        return {sign * fv, fd};
      }

      /**
       * Small-deformation column of Geometry/Height under Body
       * force/Gravity, bottom fixed, top free (corrected thesis eq. 4.6,
       * evaluated in the equivalent closed d'Alembert form), along y.
       */
      class SoilColumn : public Reference<2>
      {
      public:
        explicit SoilColumn(const ReferenceContext<2> &c)
          : height(c.height)
          , youngs_modulus(c.material.youngs_modulus)
          , density(c.material.density)
          , g(-c.gravity[1])
        {
        }

        State
        evaluate(const Point<2> &X, const double t) const override
        {
          State        s;
          const double a  = density * g / youngs_modulus;
          const double c  = std::sqrt(youngs_modulus / density);
          const double y  = X[1];
          const auto   wm = column_extension(y - c * t, height, a);
          const auto   wp = column_extension(y + c * t, height, a);
          s.displacement[1] =
            a * (0.5 * y * y - height * y) + 0.5 * (wm.first + wp.first);
          s.velocity[1] = 0.5 * c * (wp.second - wm.second);
          s.stress[1][1] =
            youngs_modulus * (a * (y - height) + 0.5 * (wm.second + wp.second));
          return s;
        }

        unsigned int
        axis() const override
        {
          return 1;
        }

      private:
        const double height, youngs_modulus, density, g;
      };

      Registration<ReferenceRegistry<2>>
        registration({"soil column",
                      "small-deformation column of Geometry/Height under Body "
                      "force/Gravity, bottom fixed (corrected thesis eq. 4.6)",
                      [](const ReferenceContext<2> &c) {
                        return std::make_unique<SoilColumn>(c);
                      },
                      nullptr});
    } // namespace

    double
    soil_column_series(const double       density,
                       const double       youngs_modulus,
                       const double       g,
                       const double       height,
                       const double       y,
                       const double       t,
                       const unsigned int n_terms)
    {
      const double a = density * g / youngs_modulus;
      const double c = std::sqrt(youngs_modulus / density);
      double       u = a * (0.5 * y * y - height * y);
      for (unsigned int n = 1; n <= n_terms; ++n)
        {
          const double m = 2. * n - 1;
          const double k = m * numbers::PI / (2 * height);
          const double un =
            16 * density * g * height * height /
            (m * m * m * std::pow(numbers::PI, 3) * youngs_modulus);
          u += un * std::cos(c * k * t) * std::sin(k * y);
        }
      return u;
    }
  } // namespace Postprocess
} // namespace psmpm
