// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria_base.h>

#include <psmpm/mesh/confinement.h>

#include <cmath>

namespace psmpm
{
  namespace Mesh
  {
    namespace
    {
      /// Unit outward normal up to sign: only |n_d| matters here.
      Tensor<1, 1>
      face_normal(const TriaIterator<CellAccessor<1>> &, const unsigned int)
      {
        Tensor<1, 1> n;
        n[0] = 1;
        return n;
      }

      Tensor<1, 2>
      face_normal(const TriaIterator<CellAccessor<2>> &cell,
                  const unsigned int                   f)
      {
        const Tensor<1, 2> edge =
          cell->face(f)->vertex(1) - cell->face(f)->vertex(0);
        Tensor<1, 2> n;
        n[0] = edge[1];
        n[1] = -edge[0];
        return n / n.norm();
      }
    } // namespace

    template <int dim>
    bool
    is_closed(const Triangulation<dim>                            &tria,
              const std::array<std::set<types::boundary_id>, dim> &fixed)
    {
      // Each rank looks at the boundary faces of its own cells (on a
      // distributed mesh it holds no others beyond its ghost layer, whose
      // outer faces are no boundary), and all ranks agree.
      const auto *par =
        dynamic_cast<const parallel::TriangulationBase<dim> *>(&tria);
      bool closed = true;
      for (const auto &cell : tria.active_cell_iterators())
        if (par == nullptr || cell->is_locally_owned())
          for (const unsigned int f : cell->face_indices())
            if (cell->at_boundary(f))
              {
                const auto           id = cell->face(f)->boundary_id();
                const Tensor<1, dim> n  = face_normal(cell, f);
                for (unsigned int d = 0; d < dim; ++d)
                  closed = closed &&
                           !(fixed[d].count(id) == 0 && std::abs(n[d]) > 1e-10);
              }
      if (par != nullptr)
        closed =
          Utilities::MPI::min(closed ? 1U : 0U, par->get_communicator()) == 1;
      return closed;
    }

    template bool
    is_closed<1>(const Triangulation<1> &,
                 const std::array<std::set<types::boundary_id>, 1> &);
    template bool
    is_closed<2>(const Triangulation<2> &,
                 const std::array<std::set<types::boundary_id>, 2> &);
  } // namespace Mesh
} // namespace psmpm
