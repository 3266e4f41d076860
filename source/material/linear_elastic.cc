// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/base/format.h>
#include <psmpm/material/linear_elastic.h>

namespace psmpm
{
  namespace Material
  {
    void
    LinearElastic::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Material");
      prm.declare_entry("Density",
                        "1",
                        Patterns::Double(),
                        "Initial density [kg/m^3], > 0.");
      prm.declare_entry("Young's modulus",
                        "100",
                        Patterns::Double(),
                        "Young's modulus E [Pa], > 0.");
      prm.declare_entry("Poisson's ratio",
                        "0",
                        Patterns::Double(),
                        "Poisson's ratio, -1 < nu < 0.5.");
      prm.leave_subsection();
    }

    void
    LinearElastic::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Material");
      density        = prm.get_double("Density");
      youngs_modulus = prm.get_double("Young's modulus");
      poisson_ratio  = prm.get_double("Poisson's ratio");
      prm.leave_subsection();
      AssertThrow(density > 0,
                  ExcMessage("Material/Density = " + prm_value(density) +
                             ": must be positive."));
      AssertThrow(youngs_modulus > 0,
                  ExcMessage(
                    "Material/Young's modulus = " + prm_value(youngs_modulus) +
                    ": must be positive."));
      AssertThrow(poisson_ratio > -1 && poisson_ratio < 0.5,
                  ExcMessage(
                    "Material/Poisson's ratio = " + prm_value(poisson_ratio) +
                    ": must satisfy -1 < nu < 0.5 (0.5 is "
                    "incompressible, which this explicit "
                    "formulation cannot represent)."));
    }
  } // namespace Material
} // namespace psmpm
