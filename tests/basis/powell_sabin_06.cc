// ---------------------------------------------------------------------
// psmpm: the Powell-Sabin space on a parallel::shared::Triangulation (the
// whole mesh on every rank): every rank builds the space (its cell data
// for its own cells and their neighbours only, tests/mesh/held_cells_01),
// it is a partition of unity on every rank's cells, and the Dirichlet
// constraints stored for the locally relevant DoFs add up to the serial
// count. Run with 2 ranks (.mpirun=2).
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>

#include <psmpm/basis/powell_sabin.h>
#include <psmpm/mesh/mesh_generator.h>

#include "../tests.h"

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  return run_test([comm]() {
    std::ofstream out = root_output();

    parallel::shared::Triangulation<2> tria(comm);
    psmpm::Mesh::MeshGenerator<2>::make_blocks(
      tria,
      Point<2>(0, 0),
      Point<2>(1, 1),
      4,
      4,
      psmpm::Mesh::MeshGenerator<2>::Type::criss_cross);
    psmpm::Basis::PowellSabin ps;
    DoFHandler<2>             dof_handler(tria);
    dof_handler.distribute_dofs(ps.dof_layout());
    ps.reinit(dof_handler);

    out << "ranks " << Utilities::MPI::n_mpi_processes(comm) << ", cells "
        << tria.n_active_cells() << ", dofs " << dof_handler.n_dofs()
        << std::endl;

    // Partition of unity at every cell centre, each on the rank that
    // owns the cell.
    double pu = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          double values[9];
          ps.evaluate(cell->active_cell_index(),
                      cell->center(),
                      values,
                      nullptr);
          double sum = 0;
          for (const double v : values)
            sum += v;
          pu = std::max(pu, std::abs(sum - 1));
        }
    pu = Utilities::MPI::max(pu, comm);
    PSMPM_CHECK(out, pu < 1e-12);

    // Constraints for the locally relevant DoFs; count the owned ones.
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    AffineConstraints<double> constraints(relevant);
    ps.make_dirichlet_constraints(dof_handler,
                                  {0, 1, 2, 3},
                                  Functions::ZeroFunction<2>(),
                                  constraints);
    constraints.close();
    unsigned int n_owned = 0;
    for (const auto dof : dof_handler.locally_owned_dofs())
      n_owned += constraints.is_constrained(dof);
    const unsigned int n_total = Utilities::MPI::sum(n_owned, comm);
    // 4 corners with 3, 12 straight-boundary vertices with 2.
    out << "constrained coefficients: " << n_total << std::endl;
    PSMPM_CHECK(out, n_total == 4 * 3 + 12 * 2);
  });
}
