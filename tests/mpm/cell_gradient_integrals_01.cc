// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// CellGradientIntegrals (Transfer/Volumetric strain = cell average) on
// the Powell-Sabin space of prm/vertical_cut.prm's 3.5 m x 1.25 m mesh
// (14 x 5 blocks), criss-cross and diagonal:
//  * the cells' areas add up to the mesh's;
//  * sum_k G_{c,k} = 0 on every cell (the functions sum to one);
//  * sum_k X_k (x) G_{c,k} = |c| I with the control points X_k (affine
//    fields, which the space reproduces, integrate exactly: an affine
//    velocity's volume change over a cell is exact);
//  * for every function of an interior vertex, sum over the cells of
//    G_{c,k} vanishes (a uniform pressure pushes no interior
//    coefficient), where the particles' quadrature sum_p V_p grad N_k(x_p)
//    of the same integral does not (printed: the test can fail).
#include <psmpm/simulator/cell_gradient_integrals.h>

#include "../mpm_tests.h"

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out = root_output();
  for (const std::string mesh : {"criss-cross", "diagonal"})
    {
      const auto  solver = make_scene_solver("vertical_cut.prm",
                                            {"Basis/Type=powell-sabin",
                                              "Mesh/Type=" + mesh,
                                              "Mesh/Blocks x=14",
                                              "Mesh/Blocks y=5",
                                              "Output/Interval=0"});
      const auto &state  = solver->get_state();
      psmpm::Simulator::CellGradientIntegrals<2> integrals;
      integrals.reinit(*state.triangulation, *state.space);
      const unsigned int n     = state.grid->dofs_per_cell;
      const auto        &dofs  = state.grid->cell_dofs();
      const auto        &index = state.grid->relevant_dofs();
      const auto points        = state.space->control_points(state.dof_handler);
      const unsigned int        n_cells = state.triangulation->n_active_cells();
      double                    area = 0, sum_error = 0, affine_error = 0;
      std::vector<Tensor<1, 2>> push(index.n_elements()),
        quadrature(index.n_elements());
      for (unsigned int c = 0; c < n_cells; ++c)
        {
          const Tensor<1, 2> *G = integrals.integrals(c);
          area += integrals.measure(c);
          Tensor<1, 2> sum;
          Tensor<2, 2> affine;
          for (unsigned int k = 0; k < n; ++k)
            {
              const unsigned int l = dofs[c * n + k];
              sum += G[k];
              affine += outer_product(points[index.nth_index_in_set(l)], G[k]);
              push[l] += G[k];
            }
          sum_error    = std::max(sum_error, sum.norm() / integrals.measure(c));
          affine_error = std::max(affine_error,
                                  (affine - integrals.measure(c) *
                                              unit_symmetric_tensor<2>())
                                      .norm() /
                                    integrals.measure(c));
        }
      // The particles' quadrature of the same integrals.
      const auto &particles = state.particles;
      for (std::size_t p = 0; p < particles.size(); ++p)
        {
          const unsigned int  c    = particles.cell[p];
          const Tensor<1, 2> *grad = state.gradients(p, c);
          for (unsigned int k = 0; k < n; ++k)
            quadrature[dofs[c * n + k]] += particles.volume[p] * grad[k];
        }
      // Functions of interior vertices: the control points of a boundary
      // vertex lie within a third of a block (0.25 m) of the boundary.
      double interior = 0, interior_quadrature = 0, scale = 0;
      for (unsigned int l = 0; l < push.size(); ++l)
        {
          const Point<2> &X = points[index.nth_index_in_set(l)];
          scale             = std::max(scale, push[l].norm());
          if (X[0] > 0.2 && X[0] < 3.3 && X[1] > 0.2 && X[1] < 1.05)
            {
              interior = std::max(interior, push[l].norm());
              interior_quadrature =
                std::max(interior_quadrature, quadrature[l].norm());
            }
        }
      out << mesh << ": area " << area << std::endl;
      PSMPM_CHECK(out, std::abs(area - 3.5 * 1.25) < 1e-12);
      PSMPM_CHECK(out, sum_error < 1e-12);
      PSMPM_CHECK(out, affine_error < 1e-12);
      PSMPM_CHECK(out, interior < 1e-12 * scale);
      PSMPM_CHECK(out, interior_quadrature > 1e-3 * scale);
      std::cout << mesh << ": largest |sum_k G| / |c| " << sum_error
                << ", affine error " << affine_error << ", interior push "
                << interior / scale << ", particles' quadrature "
                << interior_quadrature / scale << std::endl;
    }
}
