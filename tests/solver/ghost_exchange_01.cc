// ---------------------------------------------------------------------
// psmpm: Solver::GhostExchange on 2 ranks (.mpirun=2) against Trilinos'
// route (add into a writable ghosted vector, compress, import into a
// ghosted vector) on the P1 DoFs of a partitioned mesh: every rank puts
// value f(global index, rank) into each locally relevant entry;
// sum_to_owned() must give, on the owner, the sum over the ranks that
// see the entry, and owned_to_relevant() must return the owner's values
// on every rank. Also a second, different call to check that no state
// of the first call remains (the ghost entries are zeroed in between).
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/lac/trilinos_vector.h>

#include <psmpm/mesh/mesh_generator.h>
#include <psmpm/solver/ghost_exchange.h>

#include "../tests.h"

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  return run_test([comm]() {
    const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
    std::ofstream      out(rank == 0 ? "output" : "/dev/null");

    parallel::shared::Triangulation<2> tria(
      comm,
      Triangulation<2>::none,
      false,
      parallel::shared::Triangulation<2>::partition_metis);
    psmpm::Mesh::MeshGenerator<2>::make_blocks(
      tria,
      Point<2>(0, 0),
      Point<2>(2, 1),
      8,
      4,
      psmpm::Mesh::MeshGenerator<2>::Type::criss_cross);
    DoFHandler<2> dof_handler(tria);
    dof_handler.distribute_dofs(FE_SimplexP<2>(1));
    const IndexSet owned = dof_handler.locally_owned_dofs();
    IndexSet       relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    const unsigned int n_ghosts =
      Utilities::MPI::sum(relevant.n_elements() - owned.n_elements(), comm);
    out << "ranks " << Utilities::MPI::n_mpi_processes(comm) << ", dofs "
        << dof_handler.n_dofs() << ", ghost entries " << n_ghosts << std::endl;
    PSMPM_CHECK(out, n_ghosts > 0);

    psmpm::Solver::GhostExchange exchange;
    exchange.reinit(owned, relevant, comm);

    for (const double shift : {0., 100.})
      {
        const auto f = [shift](const types::global_dof_index i,
                               const unsigned int            r) {
          return shift + 1. + i + 1000. * r;
        };
        std::vector<double>                  local(relevant.n_elements());
        std::vector<types::global_dof_index> global(local.size());
        for (unsigned int l = 0; l < local.size(); ++l)
          {
            global[l] = relevant.nth_index_in_set(l);
            local[l]  = f(global[l], rank);
          }

        // Trilinos' route, the reference.
        TrilinosWrappers::MPI::Vector writable;
        writable.reinit(owned, relevant, comm, true);
        writable = 0;
        writable.add(global, local);
        writable.compress(VectorOperation::add);
        TrilinosWrappers::MPI::Vector owned_vector(owned, comm);
        owned_vector = writable;

        TrilinosWrappers::MPI::Vector summed(owned, comm);
        exchange.sum_to_owned(local, summed.begin());
        double difference = 0;
        for (unsigned int j = 0; j < owned.n_elements(); ++j)
          difference =
            std::max(difference,
                     std::abs(summed.begin()[j] - owned_vector.begin()[j]));
        difference = Utilities::MPI::max(difference, comm);
        PSMPM_CHECK(out, difference == 0);

        // The owner's values on every rank.
        TrilinosWrappers::MPI::Vector ghosted(owned, relevant, comm);
        ghosted = owned_vector;
        std::vector<double> back;
        exchange.owned_to_relevant(summed.begin(), back);
        double ghost_difference = 0;
        for (unsigned int l = 0; l < back.size(); ++l)
          ghost_difference =
            std::max(ghost_difference, std::abs(back[l] - ghosted[global[l]]));
        ghost_difference = Utilities::MPI::max(ghost_difference, comm);
        PSMPM_CHECK(out, back.size() == relevant.n_elements());
        PSMPM_CHECK(out, ghost_difference == 0);

        // A shared entry really is a sum over two ranks.
        unsigned int n_shared = 0;
        for (unsigned int l = 0; l < back.size(); ++l)
          n_shared += back[l] > f(global[l], 0) + f(global[l], 1) - 1;
        n_shared = Utilities::MPI::sum(n_shared, comm);
        PSMPM_CHECK(out, n_shared > 0);
      }
  });
}
