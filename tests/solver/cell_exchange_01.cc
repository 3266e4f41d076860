// ---------------------------------------------------------------------
// psmpm: Solver::CellExchange on 2 ranks (.mpirun=2). Each rank writes a
// value on its own cells (the cell's centre x + 10 y + 1, non-zero) and
// -1 elsewhere; after the exchange every cell sharing a vertex with an
// owned cell holds its owner's value, every other cell still -1, and
// the owned cells are unchanged. The integer version moves 0/1 flags the
// same way. On a serial triangulation the exchange leaves the values.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/shared_tria.h>

#include <psmpm/mesh/mesh_generator.h>
#include <psmpm/solver/cell_exchange.h>

#include "../tests.h"

namespace
{
  template <class Tria>
  void
  make_mesh(Tria &tria)
  {
    psmpm::Mesh::MeshGenerator<2>::make_blocks(
      tria,
      Point<2>(0, 0),
      Point<2>(2, 1),
      8,
      4,
      psmpm::Mesh::MeshGenerator<2>::Type::criss_cross);
  }

  double
  value_of(const Point<2> &x)
  {
    return x[0] + 10 * x[1] + 1;
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  return run_test([comm]() {
    const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
    std::ofstream      out(rank == 0 ? "output" : "/dev/null");

    Triangulation<2> serial;
    make_mesh(serial);
    psmpm::Solver::CellExchange none;
    none.reinit(serial);
    std::vector<double> kept(serial.n_active_cells(), 3.);
    none.owners_to_neighbours(kept.data());
    PSMPM_CHECK(out,
                std::count(kept.begin(), kept.end(), 3.) == int(kept.size()));

    parallel::shared::Triangulation<2> tria(
      comm,
      Triangulation<2>::none,
      false,
      parallel::shared::Triangulation<2>::partition_metis);
    make_mesh(tria);
    psmpm::Solver::CellExchange exchange;
    exchange.reinit(tria);

    std::vector<bool> at_owned(tria.n_vertices(), false);
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          at_owned[cell->vertex_index(v)] = true;
    const unsigned int  n = tria.n_active_cells();
    std::vector<double> values(n, -1.);
    std::vector<int>    flags(n, 0);
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          values[cell->active_cell_index()] = value_of(cell->center());
          flags[cell->active_cell_index()]  = 1;
        }
    exchange.owners_to_neighbours(values.data());
    exchange.owners_to_neighbours(flags);

    unsigned int wrong = 0, wrong_flags = 0, neighbours = 0, far = 0;
    for (const auto &cell : tria.active_cell_iterators())
      {
        bool touches = false;
        for (const unsigned int v : cell->vertex_indices())
          touches = touches || at_owned[cell->vertex_index(v)];
        const unsigned int c = cell->active_cell_index();
        if (touches)
          {
            neighbours += !cell->is_locally_owned();
            wrong += values[c] != value_of(cell->center());
            wrong_flags += flags[c] != 1;
          }
        else
          {
            ++far;
            wrong += values[c] != -1.;
            wrong_flags += flags[c] != 0;
          }
      }
    out << "ranks " << Utilities::MPI::n_mpi_processes(comm) << ", cells " << n
        << std::endl;
    PSMPM_CHECK(out, Utilities::MPI::sum(wrong, comm) == 0);
    PSMPM_CHECK(out, Utilities::MPI::sum(wrong_flags, comm) == 0);
    PSMPM_CHECK(out, Utilities::MPI::min(neighbours, comm) > 0);
    PSMPM_CHECK(out, Utilities::MPI::min(far, comm) > 0);
  });
}
