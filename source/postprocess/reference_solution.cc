// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/numbers.h>

#include <psmpm/postprocess/reference_solution.h>

namespace psmpm
{
  namespace Postprocess
  {
    void
    ReferenceSolution::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Reference solution");
      prm.declare_entry("Type",
                        "none",
                        Patterns::Selection("none|vibrating bar"),
                        "Exact solution for error norms: vibrating bar = "
                        "thesis eq. 4.2 on [0, Geometry/Length].");
      prm.declare_entry("Velocity amplitude",
                        "0.1",
                        Patterns::Double(),
                        "v0 of the vibrating bar; must match the initial "
                        "velocity v0 sin(pi x/L).");
      prm.leave_subsection();
    }

    void
    ReferenceSolution::parse_parameters(ParameterHandler              &prm,
                                        const Material::LinearElastic &material,
                                        const double                   L)
    {
      prm.enter_subsection("Reference solution");
      type      = prm.get("Type") == "none" ? Type::none : Type::vibrating_bar;
      amplitude = prm.get_double("Velocity amplitude");
      prm.leave_subsection();
      length         = L;
      youngs_modulus = material.youngs_modulus;
      density        = material.density;
      AssertThrow(type == Type::none || material.poisson_ratio == 0,
                  ExcMessage("Reference solution/Type = vibrating bar needs "
                             "Material/Poisson's ratio = 0 (1D solution)."));
    }

    ReferenceSolution::State
    ReferenceSolution::evaluate(const Point<2> &X, const double t) const
    {
      State s;
      if (type == Type::vibrating_bar)
        {
          const double k = numbers::PI / length;
          const double w = k * std::sqrt(youngs_modulus / density);
          s.displacement[0] =
            amplitude / w * std::sin(w * t) * std::sin(k * X[0]);
          s.velocity[0]  = amplitude * std::cos(w * t) * std::sin(k * X[0]);
          s.stress[0][0] = youngs_modulus * amplitude / w * std::sin(w * t) *
                           k * std::cos(k * X[0]);
        }
      return s;
    }
  } // namespace Postprocess
} // namespace psmpm
