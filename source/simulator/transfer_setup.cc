// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/base/format.h>
#include <psmpm/simulator/transfer_setup.h>

#include <algorithm>

namespace psmpm
{
  namespace Simulator
  {
    namespace
    {
      /// Whether @p value is on a space's list of verified mass matrices
      /// or transfers (an empty list: every one is).
      bool
      verified(const std::vector<std::string> &list, const std::string &value)
      {
        return list.empty() ||
               std::find(list.begin(), list.end(), value) != list.end();
      }

      /// "a, b, c".
      std::string
      join(const std::vector<std::string> &list)
      {
        std::string names;
        for (const auto &v : list)
          names += (names.empty() ? "" : ", ") + v;
        return names;
      }
    } // namespace

    template <int dim>
    void
    TransferSetup<dim>::create_explicit(ParameterHandler &prm)
    {
      name                = prm.get("Scheme");
      reconstruction_name = prm.get("Reconstruction");
      cell_average_volume = prm.get("Volumetric strain") == "cell average";
      reconstruction.reset();
      if (reconstruction_name != "particles")
        reconstruction =
          ReconstructionRegistry<dim>::instance().create(reconstruction_name,
                                                         "Transfer/"
                                                         "Reconstruction",
                                                         prm);
      scheme.reset();
      if (name != "automatic")
        scheme =
          TransferSchemeRegistry<dim>::instance().create(name,
                                                         "Transfer/Scheme",
                                                         prm);
    }

    template <int dim>
    void
    TransferSetup<dim>::parse_parameters(
      ParameterHandler                             &prm,
      const Basis::Space<dim>                      &space,
      typename Solver::GridSystem<dim>::Parameters &grid)
    {
      prm.enter_subsection("Transfer");
      create_explicit(prm);
      const bool mass_automatic     = grid.type == "automatic";
      const bool transfer_automatic = name == "automatic";
      const bool grid_moves         = scheme && scheme->moves_grid();
      if (mass_automatic)
        grid.type = space.default_mass_matrix(grid_moves);
      // The sampling stabilisation's cell matrices belong to the initial
      // cells: not for a grid that moves with the material.
      if (grid.sampling_stabilization < 0)
        grid.sampling_stabilization = mass_automatic && !grid_moves ? 0.5 : 0.;
      AssertThrow(!(grid_moves && grid.sampling_stabilization > 0),
                  ExcMessage("Mass matrix/Sampling stabilization = " +
                             prm_value(grid.sampling_stabilization) +
                             " with Transfer/Scheme = " + name +
                             ": its cell matrices are those of the initial "
                             "cells, and this transfer moves the grid; use "
                             "0."));
      if (transfer_automatic)
        {
          name = space.default_transfer(grid.type);
          scheme =
            TransferSchemeRegistry<dim>::instance().create(name,
                                                           "Transfer/Scheme",
                                                           prm);
        }
      // (Not for a space that was not verified with its closed-mesh
      // choice: it keeps its own default.)
      closed_rule =
        mass_automatic && !grid_moves &&
        verified(space.verified_mass_matrices(), space.closed_mass_matrix());
      prepare_closed_choice(prm, space, transfer_automatic);
      prm.leave_subsection();
    }

    template <int dim>
    void
    TransferSetup<dim>::prepare_closed_choice(ParameterHandler        &prm,
                                              const Basis::Space<dim> &space,
                                              const bool automatic)
    {
      // The choice for a closed, filled mesh is made once the mesh is
      // known; its scheme is created here, where its parameters are.
      closed_name.clear();
      closed_scheme.reset();
      if (!closed_rule)
        return;
      closed_name =
        automatic ? space.default_transfer(space.closed_mass_matrix()) : name;
      if (closed_name != name)
        closed_scheme =
          TransferSchemeRegistry<dim>::instance().create(closed_name,
                                                         "Transfer/Scheme",
                                                         prm);
    }

    template <int dim>
    bool
    TransferSetup<dim>::may_move_grid() const
    {
      return scheme->moves_grid() ||
             (closed_scheme && closed_scheme->moves_grid());
    }

    template <int dim>
    void
    TransferSetup<dim>::use_closed_choice(
      const Basis::Space<dim>                      &space,
      typename Solver::GridSystem<dim>::Parameters &grid)
    {
      grid.type = space.closed_mass_matrix();
      if (closed_scheme)
        scheme = std::move(closed_scheme);
      name = closed_name;
    }

    template <int dim>
    void
    TransferSetup<dim>::check_and_install(State<dim>        &state,
                                          const std::string &mass_matrix,
                                          const std::string &basis_name,
                                          const unsigned int basis_degree)
    {
      // A space with a restricted list names what it was verified with
      // (and the degree: bspline's list depends on it).
      const auto refuse = [&](const std::vector<std::string> &accepted,
                              const std::string              &entry,
                              const std::string              &value) {
        AssertThrow(verified(accepted, value),
                    ExcMessage(
                      entry + " = " + value +
                      ": not verified with Basis/Type = " + basis_name +
                      ", Basis/Degree = " + std::to_string(basis_degree) +
                      " (verified: " + join(accepted) + ")."));
      };
      refuse(state.space->verified_mass_matrices(),
             "Mass matrix/Type",
             mass_matrix);
      refuse(state.space->verified_transfers(), "Transfer/Scheme", name);
      // otm moves its grid: the cells' integrals would change each step.
      scheme->average_volumetric_strain(cell_average_volume, name != "otm");
      // A reconstruction names what it was verified with as well.
      state.reconstruction.reset();
      if (reconstruction_name != "particles")
        {
          state.reconstruction   = std::move(reconstruction);
          const auto refuse_with = [&](const std::vector<std::string> &list,
                                       const std::string              &entry,
                                       const std::string              &value) {
            AssertThrow(verified(list, value),
                        ExcMessage(entry + " = " + value +
                                   ": not verified with Transfer/"
                                   "Reconstruction = " +
                                   reconstruction_name +
                                   " (verified: " + join(list) + ")."));
          };
          refuse_with(state.reconstruction->verified_mass_matrices(),
                      "Mass matrix/Type",
                      mass_matrix);
          refuse_with(state.reconstruction->verified_transfers(),
                      "Transfer/Scheme",
                      name);
        }
      closed_rule = false;
    }

    template struct TransferSetup<1>;
    template struct TransferSetup<2>;
  } // namespace Simulator
} // namespace psmpm
