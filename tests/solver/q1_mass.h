// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_tests_solver_q1_mass_h
#define psmpm_tests_solver_q1_mass_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/numerics/matrix_tools.h>

#include <vector>

/// The Q1 mass matrix of a 6 x 5 grid on the rectangle (p0, p1) and the
/// vertices of its DoFs: a small SPD matrix whose rows reproduce 1, x
/// and y, for the solver tests.
struct Q1Mass
{
  Q1Mass(const dealii::Point<2> &p0, const dealii::Point<2> &p1)
  {
    using namespace dealii;
    GridGenerator::subdivided_hyper_rectangle(tria, {6, 5}, p0, p1);
    dof_handler.distribute_dofs(fe);
    const unsigned int     nv = dof_handler.n_dofs();
    DynamicSparsityPattern dsp(nv);
    DoFTools::make_sparsity_pattern(dof_handler, dsp);
    pattern.copy_from(dsp);
    matrix.reinit(pattern);
    MatrixCreator::create_mass_matrix(dof_handler, QGauss<2>(2), matrix);
    support.resize(nv);
    DoFTools::map_dofs_to_support_points(MappingQ1<2>(), dof_handler, support);
  }

  dealii::Triangulation<2>      tria;
  dealii::FE_Q<2>               fe{1};
  dealii::DoFHandler<2>         dof_handler{tria};
  dealii::SparsityPattern       pattern;
  dealii::SparseMatrix<double>  matrix;
  std::vector<dealii::Point<2>> support;
};

#endif
