// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_mesh_confinement_h
#define psmpm_mesh_confinement_h

#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>

#include <array>
#include <set>

namespace psmpm
{
  namespace Mesh
  {
    using namespace dealii;

    /**
     * Whether the velocity component normal to every boundary face is
     * fixed: boundary id b with face normal n is closed if n_d = 0 (to
     * round-off) for every direction d in which b is not fixed. Material
     * that fills such a mesh cannot leave it, so no cell can empty
     * unless the material tears apart inside or thin cells empty as it
     * moves: the automatic mass matrix is then partially lumped, the
     * consistent matrix where no cell empties (doc/transfers.md
     * "Defaults").
     * @p fixed[d]: the boundary ids with velocity component d fixed.
     */
    template <int dim>
    bool
    is_closed(const Triangulation<dim>                            &tria,
              const std::array<std::set<types::boundary_id>, dim> &fixed);
  } // namespace Mesh
} // namespace psmpm

#endif
