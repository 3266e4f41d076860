// ---------------------------------------------------------------------
// psmpm: Mesh::HeldCells on 2 ranks (.mpirun=2). On a serial
// triangulation every cell is held at its own index. On a partitioned
// parallel::shared mesh a rank holds exactly its own cells and the cells
// sharing a vertex with one, numbered 0, 1, ... in active cell order, and
// fewer than all; without the neighbours, exactly its own cells. The
// Powell-Sabin space, which keeps its 3 kB of cell data for the held cells
// only, evaluates bit-identically to the space on the serial mesh on every held
// cell, and reports an evaluation on a cell it does not hold instead of reading
// out of bounds.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>

#include <psmpm/basis/powell_sabin.h>
#include <psmpm/mesh/held_cells.h>
#include <psmpm/mesh/mesh_generator.h>

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
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  return run_test([comm]() {
    const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
    std::ofstream      out(rank == 0 ? "output" : "/dev/null");
    using psmpm::Mesh::HeldCells;

    Triangulation<2> serial;
    make_mesh(serial);
    HeldCells all;
    all.reinit(serial);
    bool identity = all.size() == serial.n_active_cells();
    for (unsigned int c = 0; c < serial.n_active_cells(); ++c)
      identity = identity && all.slot(c) == c;
    PSMPM_CHECK(out, all.holds_all());
    PSMPM_CHECK(out, identity);

    parallel::shared::Triangulation<2> tria(
      comm,
      Triangulation<2>::none,
      false,
      parallel::shared::Triangulation<2>::partition_metis);
    make_mesh(tria);
    HeldCells held;
    held.reinit(tria);
    out << "ranks " << Utilities::MPI::n_mpi_processes(comm) << ", cells "
        << tria.n_active_cells() << std::endl;

    std::vector<bool> at_owned(tria.n_vertices(), false);
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          at_owned[cell->vertex_index(v)] = true;
    // Held <=> owned or touching an owned cell's vertex; slots in order.
    unsigned int wrong = 0, next = 0, n_owned = 0;
    for (const auto &cell : tria.active_cell_iterators())
      {
        bool touches = false;
        for (const unsigned int v : cell->vertex_indices())
          touches = touches || at_owned[cell->vertex_index(v)];
        n_owned += cell->is_locally_owned();
        const unsigned int s = held.slot(cell->active_cell_index());
        if (touches)
          wrong += s != next++;
        else
          wrong += s != HeldCells::invalid;
      }
    const unsigned int n_wrong = Utilities::MPI::sum(wrong, comm);
    const bool         fewer =
      Utilities::MPI::max(held.size(), comm) < tria.n_active_cells();
    const bool more_than_owned =
      Utilities::MPI::min(held.size() > n_owned ? 1U : 0U, comm) == 1;
    // Without the neighbours: the rank's own cells, in order.
    HeldCells own;
    own.reinit(tria, false);
    unsigned int wrong_own = 0, next_own = 0;
    for (const auto &cell : tria.active_cell_iterators())
      wrong_own += own.slot(cell->active_cell_index()) !=
                   (cell->is_locally_owned() ? next_own++ : HeldCells::invalid);
    PSMPM_CHECK(out, Utilities::MPI::sum(wrong_own, comm) == 0);
    PSMPM_CHECK(out, own.size() == n_owned);
    PSMPM_CHECK(out, !held.holds_all());
    PSMPM_CHECK(out, held.size() == next);
    PSMPM_CHECK(out, n_wrong == 0);
    PSMPM_CHECK(out, fewer);
    PSMPM_CHECK(out, more_than_owned);

    // The Powell-Sabin space on both meshes (the same cells in the same
    // order: one generator).
    psmpm::Basis::PowellSabin ps_serial, ps_shared;
    DoFHandler<2>             dh_serial(serial), dh_shared(tria);
    dh_serial.distribute_dofs(ps_serial.dof_layout());
    dh_shared.distribute_dofs(ps_shared.dof_layout());
    ps_serial.reinit(dh_serial);
    ps_shared.reinit(dh_shared);
    std::vector<double>       a(9), b(9);
    std::vector<Tensor<1, 2>> ga(9), gb(9);
    unsigned int              differing = 0, refused = 0, not_held = 0;
    for (const auto &cell : tria.active_cell_iterators())
      {
        const unsigned int c = cell->active_cell_index();
        // A point off the cell's centre, inside it.
        const Point<2> x =
          (2. * cell->vertex(0) + 3. * cell->vertex(1) + 5. * cell->vertex(2)) /
          10.;
        if (held.slot(c) != HeldCells::invalid)
          {
            ps_serial.evaluate(1, &c, &x, a.data(), ga.data());
            ps_shared.evaluate(1, &c, &x, b.data(), gb.data());
            for (unsigned int i = 0; i < 9; ++i)
              differing += a[i] != b[i] || ga[i] != gb[i];
          }
        else
          {
            ++not_held;
            try
              {
                ps_shared.evaluate(c, x, b.data(), nullptr);
              }
            catch (const ExceptionBase &e)
              {
                refused +=
                  std::string(e.what()).find("which this rank does not hold") !=
                  std::string::npos;
              }
          }
      }
    PSMPM_CHECK(out, Utilities::MPI::sum(differing, comm) == 0);
    PSMPM_CHECK(out, Utilities::MPI::min(not_held, comm) > 0);
    PSMPM_CHECK(out,
                Utilities::MPI::sum(refused, comm) ==
                  Utilities::MPI::sum(not_held, comm));
  });
}
