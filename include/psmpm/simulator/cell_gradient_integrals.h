// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_simulator_cell_gradient_integrals_h
#define psmpm_simulator_cell_gradient_integrals_h

#include <deal.II/base/tensor.h>
#include <deal.II/grid/tria.h>

#include <psmpm/basis/space.h>

#include <vector>

namespace psmpm
{
  namespace Simulator
  {
    using namespace dealii;

    /**
     * The integrals G_{c,k} = int_c grad N_k of the basis functions of
     * every cell and the cells' areas, from the divergence theorem,
     * G_{c,k} = oint_{boundary of c} N_k n, with Gauss points on each face
     * (QIterated of QGauss<1>(3), 4 copies).
     *
     * Why the faces: a face shared by two cells adds N_k n at the same
     * points to both with opposite normals, so sum_c G_{c,k} vanishes for
     * every function that is zero on the mesh boundary whatever the
     * quadrature, and a uniform pressure p, whose force is -p sum_c
     * G_{c,k}, pushes no interior coefficient. The particles' quadrature
     * sum_p V_p grad N_k(x_p) of the same integral does not cancel: with a
     * few particles per cell a uniform pressure then drives a velocity
     * that the particles read as a volume change the geometry does not
     * have (VolumetricAveraging). The face points integrate linear fields
     * (which every space reproduces) exactly, so the mean divergence
     * sum_k v_k . G_{c,k} / |c| of an affine velocity is exact; Powell-Sabin
     * pieces that break inside a face cost a relative error of about
     * 1e-4 on the quadratic part alone.
     *
     * For the rank's locally owned cells (others stay zero), at the mesh's
     * vertex positions: a grid that moves (otm) needs them again.
     */
    template <int dim>
    class CellGradientIntegrals
    {
    public:
      /// Compute them for @p space on @p triangulation (active cell index
      /// c, the space's dofs_per_cell() functions).
      void
      reinit(const Triangulation<dim> &triangulation,
             const Basis::Space<dim>  &space);

      bool
      empty() const
      {
        return measures.empty();
      }

      /// G_{c,k} for k = 0 .. dofs_per_cell - 1.
      const Tensor<1, dim> *
      integrals(const unsigned int cell) const
      {
        return values.data() + std::size_t(cell) * n;
      }

      /// |c|, from the same face points (exact: x . n is linear).
      double
      measure(const unsigned int cell) const
      {
        return measures[cell];
      }

    private:
      unsigned int                n = 0;
      std::vector<Tensor<1, dim>> values;
      std::vector<double>         measures;
    };
  } // namespace Simulator
} // namespace psmpm

#endif
