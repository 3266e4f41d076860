// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_simulator_discretisation_h
#define psmpm_simulator_discretisation_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <psmpm/basis/space.h>
#include <psmpm/simulator/state.h>
#include <psmpm/solver/grid_system.h>

#include <memory>
#include <string>

namespace psmpm
{
  namespace Simulator
  {
    using namespace dealii;

    /**
     * What the grid of a run is: the basis (subsection Basis), the mass
     * matrix (subsection Mass matrix, Solver::GridSystem::Parameters,
     * whose `automatic` type the transfer choice resolves, TransferSetup)
     * and, once the space is set up, the number of basis functions.
     */
    template <int dim>
    struct Discretisation
    {
      /// Basis/Type (the spaces of both dimensions) and Basis/Degree; the
      /// Mass matrix entries are declared by GridSystem::Parameters.
      static void
      declare_parameters(ParameterHandler &prm);

      /// Mass matrix and Basis; throws ExcMessage if Basis/Type has no
      /// @p dim D variant.
      void
      parse_parameters(ParameterHandler &prm);

      /// A space of Basis/Type with Basis/Degree.
      std::unique_ptr<Basis::Space<dim>>
      create_space() const;

      /// Create state.space on state.triangulation, distribute its DoFs
      /// and count n_functions; throws ExcMessage if the space needs
      /// another kind of cell than the mesh has (state.locator knows).
      void
      setup_space(State<dim> &state);

      typename Solver::GridSystem<dim>::Parameters grid_parameters;
      std::string                                  basis_name;
      unsigned int                                 basis_degree = 2;
      /// Basis functions: the layout's DoFs minus those the space ties
      /// to others (bspline: 2n + 1 Bezier DoFs carry n + 2 B-splines).
      types::global_dof_index n_functions = 0;
    };
  } // namespace Simulator
} // namespace psmpm

#endif
