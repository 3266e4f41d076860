// OutputWriter<dim>: the grid output samples each cell on Subdivisions
// sub-cells per edge, so a quadratic field is reproduced at every output
// point (not only at the corners); 2D writes s^2 triangles of 3 points
// per cell, 1D one line of s + 1 points per cell; the particle output
// carries the stress as a full symmetric tensor and the material state by
// name; the .pvd series lists one record per written step. The pieces
// are read back (zlib + base64 as deal.II writes them) and checked.
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <psmpm/postprocess/output_writer.h>

#include "../tests.h"
#include "../vtu_tests.h"

#include <filesystem>

using namespace psmpm;

/**
 * Test-local quadratic space: P2 Lagrange on affine simplices, evaluated
 * by mapping to the reference cell. It stands in for Powell-Sabin (also
 * quadratic) without depending on the library's bases; only what the
 * output needs is implemented.
 */
template <int dim>
class TestP2Space : public Basis::Space<dim>
{
public:
  TestP2Space()
    : fe(2)
  {
  }

  std::string
  name() const override
  {
    return "test P2";
  }

  unsigned int
  degree() const override
  {
    return 2;
  }

  const FiniteElement<dim> &
  dof_layout() const override
  {
    return fe;
  }

  void
  reinit(const DoFHandler<dim> &dof_handler) override
  {
    origin.clear();
    inverse_jacobian.clear();
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        Tensor<2, dim> J;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int d = 0; d < dim; ++d)
            J[d][i] = cell->vertex(i + 1)[d] - cell->vertex(0)[d];
        origin.push_back(cell->vertex(0));
        inverse_jacobian.push_back(invert(J));
      }
  }

  void
  evaluate(const unsigned int cell,
           const Point<dim>  &p,
           double            *values,
           Tensor<1, dim>    *gradients) const override
  {
    const Point<dim> xi(inverse_jacobian[cell] * (p - origin[cell]));
    for (unsigned int k = 0; k < fe.n_dofs_per_cell(); ++k)
      {
        values[k] = fe.shape_value(k, xi);
        if (gradients)
          gradients[k] = fe.shape_grad(k, xi) * inverse_jacobian[cell];
      }
  }

  void
  evaluate(const unsigned int  n,
           const unsigned int *cells,
           const Point<dim>   *points,
           double             *values,
           Tensor<1, dim>     *gradients) const override
  {
    const unsigned int m = fe.n_dofs_per_cell();
    for (unsigned int q = 0; q < n; ++q)
      evaluate(cells[q],
               points[q],
               values + q * m,
               gradients ? gradients + q * m : nullptr);
  }

  void
  make_dirichlet_constraints(const DoFHandler<dim> &,
                             const std::set<types::boundary_id> &,
                             const Function<dim> &,
                             AffineConstraints<double> &) const override
  {
    AssertThrow(false, ExcNotImplemented());
  }

  std::vector<Point<dim>>
  control_points(const DoFHandler<dim> &) const override
  {
    AssertThrow(false, ExcNotImplemented());
    return {};
  }

  FullMatrix<double>
  extrapolation_weights(const unsigned int, const unsigned int) const override
  {
    AssertThrow(false, ExcNotImplemented());
    return FullMatrix<double>();
  }

  Quadrature<dim>
  cell_quadrature(const DoFHandler<dim> &, const unsigned int) const override
  {
    AssertThrow(false, ExcNotImplemented());
    return Quadrature<dim>();
  }

  double
  stability_factor(const bool) const override
  {
    return 1;
  }

  FE_SimplexP<dim>            fe;
  std::vector<Point<dim>>     origin;
  std::vector<Tensor<2, dim>> inverse_jacobian;
};



std::string
read_file(const std::string &name)
{
  std::ifstream in(name);
  AssertThrow(in, ExcMessage("cannot open " + name));
  return std::string(std::istreambuf_iterator<char>(in),
                     std::istreambuf_iterator<char>());
}

unsigned int
count(const std::string &text, const std::string &what)
{
  unsigned int n = 0;
  for (auto i = text.find(what); i != std::string::npos;
       i      = text.find(what, i + 1))
    ++n;
  return n;
}

/// An exactly representable quadratic field.
template <int dim>
double
quadratic(const Point<dim> &p)
{
  return dim == 1 ? 1 + p[0] - 2 * p[0] * p[0] :
                    1 + p[0] - 2 * p[0] * p[0] + 3 * p[0] * p[dim - 1];
}

template <int dim>
void
check_grid(std::ostream &out, const unsigned int s)
{
  const std::string dir =
    "output_" + std::to_string(dim) + "d_s" + std::to_string(s);
  std::filesystem::create_directories(dir);

  Triangulation<dim> tria;
  if constexpr (dim == 1)
    GridGenerator::subdivided_hyper_cube(tria, 3, 0, 1);
  else
    GridGenerator::subdivided_hyper_rectangle_with_simplices(tria,
                                                             {2, 2},
                                                             Point<dim>(),
                                                             Point<dim>(1, 1));
  TestP2Space<dim> space;
  DoFHandler<dim>  dof_handler(tria);
  dof_handler.distribute_dofs(space.dof_layout());
  space.reinit(dof_handler);

  // Coefficients of the P2 interpolant = values at the support points.
  const unsigned int                   n = space.dofs_per_cell();
  std::vector<unsigned int>            cell_dofs(tria.n_active_cells() * n);
  std::vector<double>                  u(dof_handler.n_dofs());
  std::vector<Tensor<1, dim>>          w(dof_handler.n_dofs());
  std::vector<types::global_dof_index> dofs(n);
  for (const auto &cell : dof_handler.active_cell_iterators())
    {
      cell->get_dof_indices(dofs);
      for (unsigned int k = 0; k < n; ++k)
        {
          cell_dofs[cell->active_cell_index() * n + k] = dofs[k];
          Point<dim>        x                          = cell->vertex(0);
          const Point<dim> &xi = space.fe.get_unit_support_points()[k];
          for (unsigned int i = 0; i < dim; ++i)
            x += xi[i] * (cell->vertex(i + 1) - cell->vertex(0));
          u[dofs[k]] = quadratic(x);
          w[dofs[k]] = 2 * x;
        }
    }

  Postprocess::OutputWriter<dim> writer(dir, MPI_COMM_WORLD, s);
  for (unsigned int step = 0; step < 3; ++step)
    writer.write_grid(step,
                      0.5 * step,
                      dof_handler,
                      space,
                      cell_dofs,
                      {{"w", &w}},
                      {{"u", &u}});

  const std::string  vtu             = read_file(dir + "/grid-00002.000.vtu");
  const unsigned int n_cells         = tria.n_active_cells();
  const unsigned int points_per_cell = (dim == 1 ? s + 1 : 3 * s * s);
  const unsigned int cells_per_cell  = (dim == 1 ? s : s * s);
  out << dim << "D, " << n_cells << " cells, subdivisions " << s << std::endl;
  PSMPM_CHECK(out,
              piece_attribute(vtu, "NumberOfPoints") ==
                n_cells * points_per_cell);
  PSMPM_CHECK(out,
              piece_attribute(vtu, "NumberOfCells") ==
                n_cells * cells_per_cell);

  // The quadratic field and the linear vector field are exact at every
  // output point (to Float32), including the interior sub-cell corners.
  const std::vector<float> points = read_floats(vtu, "<Points>");
  const std::vector<float> values = read_floats(vtu, "Name=\"u\"");
  const std::vector<float> wv     = read_floats(vtu, "Name=\"w\"");
  const std::vector<float> ranks  = read_floats(vtu, "Name=\"rank\"");
  PSMPM_CHECK(out, values.size() == n_cells * points_per_cell);
  PSMPM_CHECK(out, wv.size() == 3 * values.size());
  double error = 0, area = 0;
  for (unsigned int q = 0; q < values.size(); ++q)
    {
      Point<dim> x;
      for (unsigned int d = 0; d < dim; ++d)
        x[d] = points[3 * q + d];
      error = std::max(error, std::abs(values[q] - quadratic(x)));
      for (unsigned int d = 0; d < dim; ++d)
        error = std::max(error, std::abs(wv[3 * q + d] - 2 * x[d]));
      error = std::max(error, std::abs(double(ranks[q])));
    }
  // Sub-cells must tile the cells: their measures add up to the domain's.
  for (unsigned int t = 0; t < values.size() / (dim == 1 ? s + 1 : 3); ++t)
    if (dim == 1)
      area += points[3 * (t * (s + 1) + s)] - points[3 * t * (s + 1)];
    else
      {
        const float *a = &points[9 * t];
        area +=
          0.5 * ((a[3] - a[0]) * (a[7] - a[1]) - (a[4] - a[1]) * (a[6] - a[0]));
      }
  PSMPM_CHECK(out, error < 1e-5);
  PSMPM_CHECK(out, std::abs(area - 1) < 1e-6);

  const std::string pvd = read_file(dir + "/grid.pvd");
  PSMPM_CHECK(out, count(pvd, "<DataSet ") == 3);
  PSMPM_CHECK(out, count(pvd, "file=\"grid-00002.pvtu\"") == 1);
  const std::string pvtu = read_file(dir + "/grid-00002.pvtu");
  PSMPM_CHECK(out, count(pvtu, "grid-00002.000.vtu") == 1);
  PSMPM_CHECK(out, count(pvtu, "Name=\"rank\"") == 1);
  PSMPM_CHECK(out, count(pvtu, "traction") == 0);
}

template <int dim>
void
check_particles(std::ostream &out)
{
  const std::string dir = "output_particles_" + std::to_string(dim) + "d";
  std::filesystem::create_directories(dir);

  Particles::ParticleSet<dim> particles;
  // "strain_xx", "strain_xy" (and "strain_yy" in 2D) form a symmetric
  // tensor in the output; the other two stay scalars.
  std::vector<std::string> state_names = {"plastic_strain",
                                          "strain_xx",
                                          "stress_zz"};
  if (dim == 2)
    for (const std::string n : {"strain_xy", "strain_yy"})
      state_names.push_back(n);
  particles.set_state_names(state_names);
  for (unsigned int i = 0; i < 3; ++i)
    {
      Point<dim> x;
      x[0] = 0.25 * (i + 1);
      particles.add(10 + i, i, x, 0.5, 2.0);
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = a; b < dim; ++b)
          particles.stress[i][a][b] = 1 + i + 10 * a + 100 * b;
      for (unsigned int k = 0; k < state_names.size(); ++k)
        particles.state_of(i)[k] = k == 2 ? -1. * i : 100 * k + i;
    }

  Postprocess::OutputWriter<dim> writer(dir, MPI_COMM_WORLD, 1);
  writer.write_particles(0, 0., particles);
  writer.write_particles(7, 0.1, particles);

  const std::string vtu = read_file(dir + "/particles-00007.000.vtu");
  out << dim << "D particles" << std::endl;
  PSMPM_CHECK(out, piece_attribute(vtu, "NumberOfPoints") == 3);
  const std::vector<float> stress = read_floats(vtu, "Name=\"stress\"");
  const std::vector<float> id     = read_floats(vtu, "Name=\"id\"");
  const std::vector<float> state  = read_floats(vtu, "Name=\"stress_zz\"");
  const std::vector<float> strain = read_floats(vtu, "Name=\"strain\"");
  PSMPM_CHECK(out, stress.size() == 27);
  PSMPM_CHECK(out, strain.size() == 27);
  PSMPM_CHECK(out, vtu.find("Name=\"strain_xx\"") == std::string::npos);
  PSMPM_CHECK(out, read_floats(vtu, "Name=\"plastic_strain\"").size() == 3);
  {
    // strain_xx (state 1) at (0,0); in 2D strain_xy (state 3) at (0,1)
    // and (1,0), strain_yy (state 4) at (1,1).
    bool tensor_ok = true;
    for (unsigned int i = 0; i < 3; ++i)
      {
        tensor_ok = tensor_ok && strain[9 * i] == 100 + i;
        if (dim == 2)
          tensor_ok = tensor_ok && strain[9 * i + 1] == 300 + i &&
                      strain[9 * i + 3] == 300 + i &&
                      strain[9 * i + 4] == 400 + i;
      }
    PSMPM_CHECK(out, tensor_ok);
  }
  bool ok = (id.size() == 3 && state.size() == 3);
  for (unsigned int i = 0; i < 3 && ok; ++i)
    {
      ok = ok && id[i] == 10 + i && state[i] == -1. * i;
      // VTK's 3x3 layout, row-major: symmetric and zero outside dim x dim.
      for (unsigned int a = 0; a < 3; ++a)
        for (unsigned int b = 0; b < 3; ++b)
          {
            const double expected =
              (a < dim && b < dim) ?
                1 + i + 10 * std::min(a, b) + 100 * std::max(a, b) :
                0;
            ok = ok && stress[9 * i + 3 * a + b] == expected;
          }
    }
  PSMPM_CHECK(out, ok);

  const std::string pvtu = read_file(dir + "/particles-00007.pvtu");
  for (const std::string name : {"id",
                                 "cell",
                                 "rank",
                                 "mass",
                                 "volume",
                                 "density",
                                 "displacement",
                                 "velocity",
                                 "plastic_strain",
                                 "stress_zz"})
    out << "  field " << name << ": " << count(pvtu, "Name=\"" + name + "\"")
        << std::endl;
  PSMPM_CHECK(out,
              count(pvtu, "Name=\"stress\" NumberOfComponents=\"9\"") == 1);
  PSMPM_CHECK(out, count(read_file(dir + "/particles.pvd"), "<DataSet ") == 2);
}

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");
  return run_test([&] {
    ParameterHandler prm;
    Postprocess::OutputWriter<2>::declare_parameters(prm);
    prm.enter_subsection("Output");
    out << "Subdivisions default " << prm.get_integer("Subdivisions")
        << std::endl;
    prm.leave_subsection();

    check_grid<2>(out, 1);
    check_grid<2>(out, 3);
    check_grid<1>(out, 1);
    check_grid<1>(out, 4);
    check_particles<2>(out);
    check_particles<1>(out);
  });
}
