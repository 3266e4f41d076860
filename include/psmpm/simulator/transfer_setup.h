// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_simulator_transfer_setup_h
#define psmpm_simulator_transfer_setup_h

#include <deal.II/base/parameter_handler.h>

#include <psmpm/basis/space.h>
#include <psmpm/simulator/reconstruction.h>
#include <psmpm/simulator/state.h>
#include <psmpm/simulator/transfer_scheme.h>
#include <psmpm/solver/grid_system.h>

#include <memory>
#include <string>

namespace psmpm
{
  namespace Simulator
  {
    using namespace dealii;

    /**
     * The transfer of a run (subsection Transfer): the scheme, the
     * reconstruction, and the choice of mass matrix and scheme that
     * `automatic` makes, first from the space's measured defaults
     * (parse_parameters()) and then, once the mesh is known, for a closed
     * mesh the material fills (use_closed_choice()).
     */
    template <int dim>
    struct TransferSetup
    {
      /**
       * Create the reconstruction and the scheme of Transfer/Scheme and
       * resolve `automatic` in @p grid (Mass matrix/Type, Sampling
       * stabilization) and in the scheme with the defaults of @p space:
       * an explicit scheme first (the mass default depends on whether its
       * grid moves), an automatic scheme after the mass matrix. Prepares
       * the closed-mesh choice where it applies. Throws ExcMessage naming
       * the entry.
       */
      void
      parse_parameters(ParameterHandler                             &prm,
                       const Basis::Space<dim>                      &space,
                       typename Solver::GridSystem<dim>::Parameters &grid);

      /// Whether the scheme, or the one for a closed mesh, moves its grid.
      bool
      may_move_grid() const;

      /// Take the mass matrix and scheme for a closed mesh that the
      /// material fills (only if closed_rule).
      void
      use_closed_choice(const Basis::Space<dim>                      &space,
                        typename Solver::GridSystem<dim>::Parameters &grid);

      /// Throw ExcMessage unless the space (and the reconstruction) were
      /// verified with mass matrix @p mass_matrix and this scheme; moves
      /// the reconstruction into @p state. Ends the closed-mesh choice.
      void
      check_and_install(State<dim>        &state,
                        const std::string &mass_matrix,
                        const std::string &basis_name,
                        const unsigned int basis_degree);

      /// Transfer/Scheme (`automatic` resolved).
      std::string name;
      /// Transfer/Reconstruction ("particles": none).
      std::string                          reconstruction_name = "particles";
      /// Transfer/Volumetric strain = cell average.
      bool                                 cell_average_volume = false;
      std::unique_ptr<TransferScheme<dim>> scheme;
      /// Created by parse_parameters(), moved into the state by
      /// check_and_install().
      std::unique_ptr<Reconstruction<dim>> reconstruction;
      /// Whether `automatic` takes partially lumped mass with
      /// closed_scheme (nullptr: the scheme chosen already) named
      /// closed_name if the mesh turns out closed and filled
      /// (parse_parameters() says if the rule applies: automatic mass, a
      /// fixed grid; the set-up of the grid decides).
      bool                                 closed_rule = false;
      std::string                          closed_name;
      std::unique_ptr<TransferScheme<dim>> closed_scheme;

    private:
      /// Transfer/Reconstruction and an explicit Transfer/Scheme.
      void
      create_explicit(ParameterHandler &prm);
      /// The closed-mesh scheme (if another one) for an automatic mass.
      void
      prepare_closed_choice(ParameterHandler        &prm,
                            const Basis::Space<dim> &space,
                            const bool               automatic);
    };
  } // namespace Simulator
} // namespace psmpm

#endif
