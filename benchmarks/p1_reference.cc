// ---------------------------------------------------------------------
// psmpm: an independent P1 reference for the L2 projection study, using
// only deal.II's own machinery (FE_SimplexP<2>(1), VectorTools::project,
// VectorTools::interpolate, VectorTools::integrate_difference with
// Gauss-simplex rules), none of psmpm's basis or quadrature code. Used to
// settle which P1 values of thesis Table 3.2 are right (doc/powell_sabin.md).
//
//   p1_reference [blocks ...]
//
// Prints: blocks, n_dofs, L2 error of the projection, L2 error of the
// nodal interpolant, both times blocks^2.
// ---------------------------------------------------------------------
#include <deal.II/base/function_lib.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <psmpm/mesh/mesh_generator.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace dealii;

namespace
{
  class SinSin : public Function<2>
  {
  public:
    double
    value(const Point<2> &p, const unsigned int = 0) const override
    {
      return std::sin(numbers::PI * p[0]) * std::sin(numbers::PI * p[1]);
    }
  };
} // namespace

int
main(int argc, char **argv)
{
  std::vector<unsigned int> blocks = {4, 8, 16, 32, 64};
  if (argc > 1)
    {
      blocks.clear();
      for (int i = 1; i < argc; ++i)
        blocks.push_back(std::stoul(argv[i]));
    }
  const SinSin           u;
  const FE_SimplexP<2>   fe(1);
  const MappingFE<2>     mapping(FE_SimplexP<2>(1));
  const QGaussSimplex<2> assembly_rule(4), error_rule(4);
  std::printf("blocks\tn_dofs\tL2_projection\tL2_interpolation\t"
              "projection*n^2\tinterpolation*n^2\n");
  for (const unsigned int n : blocks)
    {
      Triangulation<2> tria;
      psmpm::Mesh::MeshGenerator<2>::make_blocks(
        tria,
        Point<2>(0, 0),
        Point<2>(1, 1),
        n,
        n,
        psmpm::Mesh::MeshGenerator<2>::Type::diagonal);
      DoFHandler<2> dof_handler(tria);
      dof_handler.distribute_dofs(fe);
      AffineConstraints<double> constraints;
      constraints.close();

      Vector<double> projection(dof_handler.n_dofs()),
        interpolation(dof_handler.n_dofs());
      VectorTools::project(mapping,
                           dof_handler,
                           constraints,
                           assembly_rule,
                           u,
                           projection);
      VectorTools::interpolate(mapping, dof_handler, u, interpolation);

      // QGaussSimplex<2>(n) exists for n <= 4 in deal.II 9.4.1 (larger n
      // give an empty rule, silently): use the largest one.
      AssertThrow(error_rule.size() > 0, ExcInternalError());
      Vector<float> cell_errors(tria.n_active_cells());
      const auto    l2_error = [&](const Vector<double> &coefficients) {
        VectorTools::integrate_difference(mapping,
                                          dof_handler,
                                          coefficients,
                                          u,
                                          cell_errors,
                                          error_rule,
                                          VectorTools::L2_norm);
        return VectorTools::compute_global_error(tria,
                                                 cell_errors,
                                                 VectorTools::L2_norm);
      };
      const double e_projection    = l2_error(projection);
      const double e_interpolation = l2_error(interpolation);
      std::printf("%u\t%u\t%.6e\t%.6e\t%.4f\t%.4f\n",
                  n,
                  dof_handler.n_dofs(),
                  e_projection,
                  e_interpolation,
                  e_projection * n * n,
                  e_interpolation * n * n);
    }
  return 0;
}
