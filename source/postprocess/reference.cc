// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/postprocess/reference.h>

namespace psmpm
{
  namespace Postprocess
  {
    template <int dim>
    void
    Reference<dim>::declare_parameters(ParameterHandler &prm)
    {
      // The 2D registry holds every reference; 1D ones are a subset,
      // checked in create().
      prm.enter_subsection("Reference solution");
      prm.declare_entry("Type",
                        "none",
                        Patterns::Selection(
                          "none|" +
                          ReferenceRegistry<2>::instance().selection()),
                        "Reference for error norms. none; " +
                          ReferenceRegistry<2>::instance().documentation());
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

    template <int dim>
    std::unique_ptr<Reference<dim>>
    Reference<dim>::create(
      ParameterHandler                                &prm,
      const Material::Material<dim>                   &material,
      const double                                     length,
      const double                                     height,
      const Tensor<1, dim>                            &gravity,
      const std::vector<double>                       &region,
      const std::array<std::vector<std::string>, dim> &fixed)
    {
      prm.enter_subsection("Reference solution");
      const std::string     type = prm.get("Type");
      ReferenceContext<dim> context{material,
                                    length,
                                    height,
                                    gravity,
                                    prm.get_double("Velocity amplitude"),
                                    static_cast<unsigned int>(
                                      prm.get_integer("ULFEM elements")),
                                    region,
                                    fixed};
      prm.leave_subsection();
      if (type == "none")
        return nullptr;
      if (context.region.empty())
        context.region = dim == 1 ? std::vector<double>{0, length} :
                                    std::vector<double>{0, 0, length, height};
      auto reference = ReferenceRegistry<dim>::instance().create(
        type,
        "Reference solution/Type (in " + std::to_string(dim) + "D)",
        context);
      AssertThrow(!reference->one_dimensional() || material.poisson_ratio == 0,
                  ExcMessage("Reference solution/Type = " + type +
                             " is a 1D solution and needs Material/Poisson's "
                             "ratio = 0."));
      return reference;
    }

    template class Reference<1>;
    template class Reference<2>;
  } // namespace Postprocess
} // namespace psmpm
