// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/numbers.h>

#include <psmpm/postprocess/reference_solution.h>

#include <cmath>

namespace psmpm
{
  namespace Postprocess
  {
    void
    ReferenceSolution::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Reference solution");
      prm.declare_entry(
        "Type",
        "none",
        Patterns::Selection(
          "none|vibrating bar|soil column|vibrating bar ulfem|soil column ulfem"),
        "Reference for error norms. vibrating bar: thesis eq. 4.2 on "
        "[0, Geometry/Length], ends fixed; soil column: small-deformation "
        "column of Geometry/Height under Body force/Gravity, bottom fixed "
        "(corrected eq. 4.6); ... ulfem: the same set-ups computed by a 1D "
        "updated Lagrangian FEM run alongside (large deformations).");
      prm.declare_entry("Velocity amplitude",
                        "0.1",
                        Patterns::Double(),
                        "v0 of the vibrating bar; must match the initial "
                        "velocity v0 sin(pi x/L).");
      prm.declare_entry("ULFEM elements",
                        "2000",
                        Patterns::Integer(2),
                        "Elements of the 1D updated Lagrangian reference.");
      prm.leave_subsection();
    }

    void
    ReferenceSolution::parse_parameters(ParameterHandler              &prm,
                                        const Material::LinearElastic &material,
                                        const double                   L,
                                        const double                   H,
                                        const Tensor<1, 2>            &gravity)
    {
      prm.enter_subsection("Reference solution");
      const std::string t = prm.get("Type");
      type                = t == "none"                ? Type::none :
                            t == "vibrating bar"       ? Type::vibrating_bar :
                            t == "soil column"         ? Type::soil_column :
                            t == "vibrating bar ulfem" ? Type::vibrating_bar_ulfem :
                                                         Type::soil_column_ulfem;
      amplitude           = prm.get_double("Velocity amplitude");
      ulfem_elements      = prm.get_integer("ULFEM elements");
      prm.leave_subsection();
      length         = L;
      height         = H;
      youngs_modulus = material.youngs_modulus;
      density        = material.density;
      g              = -gravity[1];
      AssertThrow(type == Type::none || material.poisson_ratio == 0,
                  ExcMessage("Reference solution/Type = " + t +
                             " is a 1D solution and needs Material/Poisson's "
                             "ratio = 0."));

      ulfem.reset();
      if (type == Type::vibrating_bar_ulfem || type == Type::soil_column_ulfem)
        {
          UpdatedLagrangian1D::Parameters p;
          const bool bar   = type == Type::vibrating_bar_ulfem;
          p.length         = bar ? length : height;
          p.density        = density;
          p.youngs_modulus = youngs_modulus;
          p.gravity        = bar ? 0. : -g;
          p.fix_end        = bar;
          p.n_elements     = ulfem_elements;
          const double v0 = amplitude, Lb = length;
          if (bar)
            p.initial_velocity = [v0, Lb](const double X) {
              return v0 * std::sin(numbers::PI * X / Lb);
            };
          ulfem = std::make_unique<UpdatedLagrangian1D>(p);
        }
    }

    void
    ReferenceSolution::advance_to(const double t)
    {
      if (ulfem)
        ulfem->advance_to(t);
    }

    namespace
    {
      /// Initial deviation from the static column, f(s) = -u_static(s) on
      /// [0, H], extended odd about 0, even about H, period 4H; returns
      /// the value and the derivative.
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
        // f(q) = a (H q - q^2/2), f'(q) = a (H - q); even about q = H.
        const double q  = r <= H ? r : 2 * H - r;
        const double fv = a * (H * q - 0.5 * q * q);
        const double fd = (r <= H ? 1. : -1.) * a * (H - q);
        return {sign * fv, fd};
      }
    } // namespace

    double
    ReferenceSolution::soil_column_series(const double       y,
                                          const double       t,
                                          const unsigned int n_terms) const
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

    ReferenceSolution::State
    ReferenceSolution::evaluate(const Point<2> &X, const double t) const
    {
      State s;
      switch (type)
        {
          case Type::vibrating_bar:
            {
              const double k = numbers::PI / length;
              const double w = k * std::sqrt(youngs_modulus / density);
              s.displacement[0] =
                amplitude / w * std::sin(w * t) * std::sin(k * X[0]);
              s.velocity[0]  = amplitude * std::cos(w * t) * std::sin(k * X[0]);
              s.stress[0][0] = youngs_modulus * amplitude / w *
                               std::sin(w * t) * k * std::cos(k * X[0]);
              break;
            }
          case Type::soil_column:
            {
              // u = u_static + (W(y - ct) + W(y + ct)) / 2: the closed form
              // of the series (tests/postprocess compare the two).
              const double a  = density * g / youngs_modulus;
              const double c  = std::sqrt(youngs_modulus / density);
              const double y  = X[1];
              const auto   wm = column_extension(y - c * t, height, a);
              const auto   wp = column_extension(y + c * t, height, a);
              s.displacement[1] =
                a * (0.5 * y * y - height * y) + 0.5 * (wm.first + wp.first);
              s.velocity[1]  = 0.5 * c * (wp.second - wm.second);
              s.stress[1][1] = youngs_modulus * (a * (y - height) +
                                                 0.5 * (wm.second + wp.second));
              break;
            }
          case Type::vibrating_bar_ulfem:
          case Type::soil_column_ulfem:
            {
              const unsigned int d = type == Type::vibrating_bar_ulfem ? 0 : 1;
              const auto         r = ulfem->evaluate(X[d]);
              s.displacement[d]    = r.displacement;
              s.velocity[d]        = r.velocity;
              s.stress[d][d]       = r.stress;
              break;
            }
          case Type::none:
            break;
        }
      return s;
    }
  } // namespace Postprocess
} // namespace psmpm
