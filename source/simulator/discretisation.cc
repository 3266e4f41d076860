// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/lac/affine_constraints.h>

#include <psmpm/simulator/discretisation.h>

namespace psmpm
{
  namespace Simulator
  {
    template <int dim>
    void
    Discretisation<dim>::declare_parameters(ParameterHandler &prm)
    {
      // Basis/Type lists the spaces of both dimensions (bspline is 1D
      // only, powell-sabin 2D only); creation rejects the wrong one.
      const auto &registry_1d   = Basis::SpaceRegistry<1>::instance();
      const auto &registry_2d   = Basis::SpaceRegistry<2>::instance();
      std::string selection     = registry_2d.selection();
      std::string documentation = registry_2d.documentation();
      for (const auto &name : registry_1d.variant_names())
        if (!registry_2d.has(name))
          {
            selection += "|" + name;
            documentation +=
              "; " + name + " (1D only): " + registry_1d.description(name);
          }
      prm.enter_subsection("Basis");
      prm.declare_entry("Type",
                        "linear",
                        Patterns::Selection(selection),
                        documentation);
      prm.declare_entry("Degree",
                        "2",
                        Patterns::Integer(1),
                        "Polynomial degree of Basis/Type = bspline (1 to 5; "
                        "lumped mass for 1 and 2 only); linear and "
                        "powell-sabin have a fixed degree and ignore it.");
      prm.leave_subsection();
    }

    template <int dim>
    void
    Discretisation<dim>::parse_parameters(ParameterHandler &prm)
    {
      grid_parameters.parse_parameters(prm);
      prm.enter_subsection("Basis");
      basis_name   = prm.get("Type");
      basis_degree = prm.get_integer("Degree");
      prm.leave_subsection();
      AssertThrow(Basis::SpaceRegistry<dim>::instance().has(basis_name),
                  ExcMessage(
                    "Basis/Type = " + basis_name + ": not available in " +
                    std::to_string(dim) + "D (known: " +
                    Basis::SpaceRegistry<dim>::instance().names() + ")."));
    }

    template <int dim>
    std::unique_ptr<Basis::Space<dim>>
    Discretisation<dim>::create_space() const
    {
      auto space = Basis::create_space<dim>(basis_name);
      space->set_degree(basis_degree);
      return space;
    }

    template <int dim>
    void
    Discretisation<dim>::setup_space(State<dim> &state)
    {
      state.space = create_space();
      // The space's functions live on one kind of cell (triangles for
      // linear and powell-sabin, rectangles for the 2D bspline).
      if constexpr (dim == 2)
        {
          const bool space_on_quads =
            state.space->dof_layout().reference_cell() ==
            ReferenceCells::Quadrilateral;
          AssertThrow(space_on_quads == state.locator.cartesian(),
                      ExcMessage(
                        "Basis/Type = " + basis_name +
                        (space_on_quads ?
                           " needs a mesh of rectangles (Mesh/Type = "
                           "cartesian); this mesh is of triangles." :
                           " needs a mesh of triangles (Mesh/Type = "
                           "criss-cross, diagonal or gmsh); Mesh/Type = "
                           "cartesian is for Basis/Type = bspline.")));
        }
      state.dof_handler.reinit(*state.triangulation);
      state.dof_handler.distribute_dofs(state.space->dof_layout());
      state.space->reinit(state.dof_handler);
      AffineConstraints<double> ties;
      state.space->make_space_constraints(state.dof_handler, ties);
      n_functions = state.dof_handler.n_dofs() - ties.n_constraints();
    }

    template struct Discretisation<1>;
    template struct Discretisation<2>;
  } // namespace Simulator
} // namespace psmpm
