// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_mesh_distributed_mesh_h
#define psmpm_mesh_distributed_mesh_h

#include <deal.II/grid/tria.h>
#include <deal.II/grid/tria_description.h>

#include <vector>

namespace psmpm
{
  namespace Mesh
  {
    using namespace dealii;

    /**
     * Rank @p rank's part of @p whole, whose cells @p owner gives to the
     * ranks (by active cell index): its cells and @p layers (1 or 2) layers
     * of cells around them (a cell of layer k shares a vertex with one of
     * layer k - 1), the faces of ghost cells without a neighbour in the
     * part marked rim_boundary_id. The subdomain ids of @p whole are
     * overwritten with @p owner. What MeshGenerator::create_distributed()
     * sends from rank 0 with Mesh/Partitioner = metis.
     */
    template <int dim>
    TriangulationDescription::Description<dim, dim>
    describe_part(Triangulation<dim>              &whole,
                  const std::vector<unsigned int> &owner,
                  const unsigned int               rank,
                  const unsigned int               layers,
                  const MPI_Comm                   comm);
  } // namespace Mesh
} // namespace psmpm

#endif
