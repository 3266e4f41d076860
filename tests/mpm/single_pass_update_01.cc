// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// MUSL and USL locate the moved particles, evaluate the basis there and
// sum their mass and forces for the next step chunk by chunk inside the
// update pass (TransferScheme::move_and_update_material() with a
// ParticleRelocation), while the chunk is in the cache. After a run of
// the spinning block of prm/rotating_block.prm on two ranks, every rank's
// state must be what the separate passes give: every particle lies in its
// cell (brute-force search), on the rank that owns the cell; the basis
// arrays equal a fresh evaluation and the cell arrays a fresh
// particles_to_cells(0, 1), bit for bit; the next step will take them
// (State::forces_in_cells). The block spins at 20 rad/s for six steps of
// 1e-3 s; particles change ranks in the last one, so the sums that the
// checks see must have left them to the rank that received them. Both
// bases, the replicated and the distributed mesh.
#include <psmpm/simulator/particle_loops.h>

#include "../mpm_tests.h"

#include <cstring>
#include <filesystem>

using namespace psmpm;

namespace
{
  template <typename T>
  bool
  same_bits(const std::vector<T> &a, const std::vector<T> &b)
  {
    return a.size() == b.size() &&
           std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
  }

  /// Whether this rank's basis arrays are those of a fresh evaluation.
  bool
  basis_is_fresh(const Simulator::State<2> &state)
  {
    const auto               &particles = state.particles;
    const unsigned int        n         = state.functions_per_cell;
    std::vector<double>       values(particles.size() * n);
    std::vector<Tensor<1, 2>> gradients(
      state.gradients_per_cell ? 0 : particles.size() * n);
    state.space->evaluate(particles.size(),
                          particles.cell.data(),
                          particles.position.data(),
                          values.data(),
                          gradients.empty() ? nullptr : gradients.data());
    return same_bits(values, state.shape_values) &&
           (state.gradients_per_cell ||
            same_bits(gradients, state.shape_gradients));
  }

  /// Whether this rank's cell arrays are those of a fresh pass.
  bool
  cells_are_fresh(const Simulator::State<2> &state)
  {
    const auto kept = state.grid->cell_arrays();
    Simulator::ParticleLoops::particles_to_cells(state, 0., 1.);
    const auto &fresh = state.grid->cell_arrays();
    return same_bits(kept.lumped, fresh.lumped) &&
           same_bits(kept.mass, fresh.mass) && same_bits(kept.rhs, fresh.rhs);
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession  mpi(argc, argv);
  std::ofstream      out  = root_output();
  const unsigned int rank = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  for (const std::string distribution : {"replicated", "distributed"})
    for (const std::string scheme : {"musl", "usl"})
      for (const std::string basis : {"linear", "powell-sabin"})
        {
          const std::string directory =
            "output-" + distribution + "-" + scheme + "-" + basis;
          auto solver =
            make_scene_solver<2>("rotating_block.prm",
                                 {"Mesh/Distribution=" + distribution,
                                  "Transfer/Scheme=" + scheme,
                                  "Basis/Type=" + basis,
                                  "Initial conditions/Velocity="
                                  "-20 * (y - 0.5); 20 * (x - 0.5)",
                                  "Time/Time step=1e-3",
                                  "Time/End time=6e-3",
                                  "Output/Interval=0"});
          const auto &state = solver->get_state();
          if (rank == 0)
            std::filesystem::create_directories(directory);
          const auto status = solver->run(directory);

          const auto &particles = state.particles;
          bool        owned     = true;
          for (std::size_t p = 0; p < particles.size(); ++p)
            owned = owned && state.cell_owner[particles.cell[p]] == rank;
          const auto located    = check_particles_in_cells(*solver);
          const auto everywhere = [](const bool b) {
            return Utilities::MPI::min(b ? 1u : 0u, MPI_COMM_WORLD) == 1;
          };
          const bool         in_cells    = everywhere(located.second);
          const bool         on_owner    = everywhere(owned);
          const bool         pending     = everywhere(state.forces_in_cells);
          const bool         fresh_basis = everywhere(basis_is_fresh(state));
          const bool         fresh_cells = everywhere(cells_are_fresh(state));
          const unsigned int moved =
            Utilities::MPI::sum(static_cast<unsigned int>(
                                  solver->get_relocation().particles_sent()),
                                MPI_COMM_WORLD);
          out << distribution << ", " << scheme << ", " << basis
              << ": particles that changed ranks in the last step "
              << (moved > 0 ? "some" : "none") << std::endl;
          PSMPM_CHECK(out, status == Simulator::Status::completed);
          PSMPM_CHECK(out, in_cells && on_owner);
          PSMPM_CHECK(out, pending);
          PSMPM_CHECK(out, fresh_basis);
          PSMPM_CHECK(out, fresh_cells);
          if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
            PSMPM_CHECK(out, moved > 0);
        }
}
