// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/data_out_base.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <psmpm/base/checked_file.h>
#include <psmpm/base/format.h>
#include <psmpm/basis/powell_sabin_refinement.h>
#include <psmpm/basis/space.h>
#include <psmpm/mesh/triangle_geometry.h>
#include <psmpm/solver/l2_projection.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>

namespace psmpm
{
  namespace Solver
  {
    namespace
    {
      Point<2>
      combine(const std::array<Point<2>, 3> &t, const std::array<double, 3> &l)
      {
        return Point<2>(l[0] * t[0][0] + l[1] * t[1][0] + l[2] * t[2][0],
                        l[0] * t[0][1] + l[1] * t[1][1] + l[2] * t[2][1]);
      }

      /// The n^2 triangles of the uniform subdivision of @p t.
      std::vector<std::array<Point<2>, 3>>
      subdivide(const std::array<Point<2>, 3> &t, const unsigned int n)
      {
        const auto at = [&](const unsigned int i, const unsigned int j) {
          return combine(
            t,
            {{double(n - i - j) / n, double(i) / n, double(j) / n}});
        };
        std::vector<std::array<Point<2>, 3>> result;
        for (unsigned int j = 0; j < n; ++j)
          for (unsigned int i = 0; i + j < n; ++i)
            {
              result.push_back({{at(i, j), at(i + 1, j), at(i, j + 1)}});
              if (i + j + 1 < n)
                result.push_back(
                  {{at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}});
            }
        return result;
      }

      DataOutBase::Patch<2, 2>
      triangle_patch(const std::array<Point<2>, 3> &t,
                     const unsigned int             n_fields)
      {
        DataOutBase::Patch<2, 2> patch;
        patch.reference_cell = ReferenceCells::Triangle;
        patch.n_subdivisions = 1;
        for (unsigned int k = 0; k < 3; ++k)
          patch.vertices[k] = t[k];
        patch.data.reinit(n_fields, 3);
        patch.points_are_available = false;
        return patch;
      }

      void
      write_patches(const std::string                     &filename,
                    std::vector<DataOutBase::Patch<2, 2>> &patches,
                    const std::vector<std::string>        &names)
      {
        for (unsigned int i = 0; i < patches.size(); ++i)
          patches[i].patch_index = i;
        std::ofstream out(filename);
        check_written(out, filename);
        DataOutBase::write_vtu(
          patches,
          names,
          std::vector<std::tuple<
            unsigned int,
            unsigned int,
            std::string,
            DataComponentInterpretation::DataComponentInterpretation>>(),
          DataOutBase::VtkFlags(),
          out);
        check_written(out, filename);
      }

      /// The scene's mesh, space and quadrature cells (the Powell-Sabin
      /// sub-triangles, for every space).
      struct Discretization
      {
        Discretization(const Mesh::MeshGenerator<2> &mesh,
                       const std::string            &basis_name)
        {
          mesh.create(tria);
          space = Basis::create_space<2>(basis_name);
          dof_handler.reinit(tria);
          dof_handler.distribute_dofs(space->dof_layout());
          space->reinit(dof_handler);
          refinement.reinit(tria);
        }

        Triangulation<2>                 tria;
        std::unique_ptr<Basis::Space<2>> space;
        DoFHandler<2>                    dof_handler;
        Basis::PowellSabinRefinement     refinement;
      };

      /// Consistent mass matrix and right-hand side (f / @p scale, phi_i)
      /// by the 7-point rule on each sub-triangle.
      void
      assemble(const Discretization    &disc,
               const FunctionParser<2> &u,
               const double             scale,
               SparseMatrix<double>    &mass,
               Vector<double>          &rhs)
      {
        const unsigned int       dofs_per_cell = disc.space->dofs_per_cell();
        const Mesh::TriangleRule rule;
        std::vector<double>      values(dofs_per_cell);
        std::vector<types::global_dof_index> dofs(dofs_per_cell);
        FullMatrix<double>                   cell_matrix(dofs_per_cell);
        Vector<double>                       cell_rhs(dofs_per_cell);
        for (const auto &cell : disc.dof_handler.active_cell_iterators())
          {
            const unsigned int c = cell->active_cell_index();
            cell_matrix          = 0;
            cell_rhs             = 0;
            for (unsigned int s = 0; s < 6; ++s)
              {
                const auto   t    = disc.refinement.cell(c).sub_triangle(s);
                const double area = Mesh::signed_area(t);
                for (unsigned int q = 0; q < 7; ++q)
                  {
                    const Point<2> p  = combine(t, rule.points[q]);
                    const double   jw = area * rule.weights[q];
                    disc.space->evaluate(c, p, values.data(), nullptr);
                    const double f = u.value(p) / scale;
                    for (unsigned int i = 0; i < dofs_per_cell; ++i)
                      {
                        cell_rhs(i) += jw * values[i] * f;
                        for (unsigned int j = 0; j < dofs_per_cell; ++j)
                          cell_matrix(i, j) += jw * values[i] * values[j];
                      }
                  }
              }
            cell->get_dof_indices(dofs);
            mass.add(dofs, cell_matrix);
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              rhs(dofs[i]) += cell_rhs(i);
          }
      }

      /// The projection's coefficients: by the lumped (row-sum) mass, or
      /// by CG with SSOR to 1e-14 of the right-hand side. Returns why CG
      /// failed, or "".
      std::string
      project(const SparseMatrix<double> &mass,
              const Vector<double>       &rhs,
              const bool                  lumped,
              Vector<double>             &solution)
      {
        const unsigned int n_dofs = rhs.size();
        if (lumped)
          {
            // Both bases are non-negative partitions of unity: row sums are
            // the positive integrals of the basis functions.
            for (unsigned int i = 0; i < n_dofs; ++i)
              {
                double row_sum = 0;
                for (auto it = mass.begin(i); it != mass.end(i); ++it)
                  row_sum += it->value();
                solution(i) = rhs(i) / row_sum;
              }
            return "";
          }
        SolverControl                          control(10 * n_dofs + 100,
                              1e-14 * std::max(rhs.l2_norm(), 1e-300));
        SolverCG<Vector<double>>               cg(control);
        PreconditionSSOR<SparseMatrix<double>> ssor;
        ssor.initialize(mass, 1.2);
        try
          {
            cg.solve(mass, solution, rhs, ssor);
          }
        catch (const SolverControl::NoConvergence &e)
          {
            return "l2 projection: CG with SSOR did not reach the residual " +
                   prm_value(control.tolerance()) + " in " +
                   std::to_string(e.last_step) + " iterations (last residual " +
                   prm_value(e.last_residual) + ")";
          }
        return "";
      }

      /// The squared L2 error of the projection of f / @p scale on the
      /// sub-triangles split into four; @p h: the largest cell diameter.
      double
      squared_error(const Discretization    &disc,
                    const FunctionParser<2> &u,
                    const double             scale,
                    const Vector<double>    &solution,
                    double                  &h)
      {
        const unsigned int       dofs_per_cell = disc.space->dofs_per_cell();
        const Mesh::TriangleRule rule;
        std::vector<double>      values(dofs_per_cell);
        std::vector<types::global_dof_index> dofs(dofs_per_cell);
        double                               error2 = 0;
        h                                           = 0;
        for (const auto &cell : disc.dof_handler.active_cell_iterators())
          {
            const unsigned int c = cell->active_cell_index();
            h                    = std::max(h, cell->diameter());
            cell->get_dof_indices(dofs);
            for (unsigned int s = 0; s < 6; ++s)
              for (const auto &t :
                   subdivide(disc.refinement.cell(c).sub_triangle(s), 2))
                {
                  const double area = Mesh::signed_area(t);
                  for (unsigned int q = 0; q < 7; ++q)
                    {
                      const Point<2> p = combine(t, rule.points[q]);
                      disc.space->evaluate(c, p, values.data(), nullptr);
                      double uh = 0;
                      for (unsigned int i = 0; i < dofs_per_cell; ++i)
                        uh += solution(dofs[i]) * values[i];
                      error2 += area * rule.weights[q] *
                                std::pow(uh - u.value(p) / scale, 2);
                    }
                }
          }
        return error2;
      }

      /**
       * The power of two by which Projection/Function's values are
       * divided: 1 if the largest magnitude at the quadrature points of
       * assemble() and squared_error() lies in [2^-256, 2^256] (or is
       * zero), else the power of two at or below it. Throws ExcMessage
       * naming the entry at the first point where @p u is not finite.
       */
      double
      function_scale(const Discretization    &disc,
                     const FunctionParser<2> &u,
                     const std::string       &expression)
      {
        const Mesh::TriangleRule rule;
        double                   largest = 0;
        const auto               check   = [&](const Point<2> &p) {
          const double f = u.value(p);
          AssertThrow(std::isfinite(f),
                      ExcMessage("Projection/Function = '" + expression +
                                 "' is " +
                                 (std::isnan(f) ? "nan" : prm_value(f)) +
                                 " at (x, y) = (" + prm_value(p[0]) + ", " +
                                 prm_value(p[1]) +
                                 "): the projection needs finite values at "
                                                 "its quadrature points."));
          largest = std::max(largest, std::abs(f));
        };
        for (const auto &cell : disc.dof_handler.active_cell_iterators())
          for (unsigned int s = 0; s < 6; ++s)
            {
              const auto t =
                disc.refinement.cell(cell->active_cell_index()).sub_triangle(s);
              for (unsigned int q = 0; q < 7; ++q)
                check(combine(t, rule.points[q]));
              for (const auto &quarter : subdivide(t, 2))
                for (unsigned int q = 0; q < 7; ++q)
                  check(combine(quarter, rule.points[q]));
            }
        const double low = std::ldexp(1., -256), high = std::ldexp(1., 256);
        if (largest == 0 || (largest >= low && largest <= high))
          return 1;
        return std::ldexp(1., std::ilogb(largest));
      }

      /// projection.vtu (projection, exact function, error and, unless
      /// @p basis_dof is invalid, that basis function, on each
      /// sub-triangle split into @p subdivisions^2), mesh.vtu and
      /// ps_refinement.vtu.
      void
      write_files(const Discretization         &disc,
                  const FunctionParser<2>      &u,
                  const Vector<double>         &solution,
                  const types::global_dof_index basis_dof,
                  const unsigned int            subdivisions,
                  const std::string            &output_directory)
      {
        const unsigned int  dofs_per_cell = disc.space->dofs_per_cell();
        std::vector<double> values(dofs_per_cell);
        std::vector<types::global_dof_index> dofs(dofs_per_cell);
        // Output: piecewise quadratic C1 fields on a refined patch mesh.
        std::vector<std::string> names = {"projection", "exact", "error"};
        if (basis_dof != numbers::invalid_dof_index)
          names.push_back("basis_function");
        std::vector<DataOutBase::Patch<2, 2>> patches, mesh_patches,
          refinement_patches;
        for (const auto &cell : disc.dof_handler.active_cell_iterators())
          {
            const unsigned int c = cell->active_cell_index();
            cell->get_dof_indices(dofs);
            const auto &ref = disc.refinement.cell(c);
            mesh_patches.push_back(triangle_patch(ref.vertices, 1));
            for (unsigned int k = 0; k < 3; ++k)
              mesh_patches.back().data(0, k) = c;
            for (unsigned int s = 0; s < 6; ++s)
              {
                refinement_patches.push_back(
                  triangle_patch(ref.sub_triangle(s), 1));
                for (unsigned int k = 0; k < 3; ++k)
                  refinement_patches.back().data(0, k) = 6 * c + s;
                for (const auto &t :
                     subdivide(ref.sub_triangle(s), subdivisions))
                  {
                    auto patch = triangle_patch(t, names.size());
                    for (unsigned int k = 0; k < 3; ++k)
                      {
                        disc.space->evaluate(c, t[k], values.data(), nullptr);
                        double uh = 0, phi = 0;
                        for (unsigned int i = 0; i < dofs_per_cell; ++i)
                          {
                            uh += solution(dofs[i]) * values[i];
                            if (dofs[i] == basis_dof)
                              phi += values[i];
                          }
                        const double exact = u.value(t[k]);
                        patch.data(0, k)   = uh;
                        patch.data(1, k)   = exact;
                        patch.data(2, k)   = uh - exact;
                        if (names.size() > 3)
                          patch.data(3, k) = phi;
                      }
                    patches.push_back(patch);
                  }
              }
          }
        write_patches(output_directory + "/projection.vtu", patches, names);
        write_patches(output_directory + "/mesh.vtu", mesh_patches, {"cell"});
        write_patches(output_directory + "/ps_refinement.vtu",
                      refinement_patches,
                      {"sub_triangle"});
      }
    } // namespace

    /// The discretization, the projection's coefficients and its error.
    struct L2Projection::Projected
    {
      Projected(const Mesh::MeshGenerator<2> &mesh,
                const std::string            &basis_name)
        : disc(mesh, basis_name)
      {
      }

      const Discretization disc;
      Vector<double>       solution;
      double               error = 0, h = 0;
      /// Why CG failed, or "".
      std::string failure;
    };

    void
    L2Projection::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Projection");
      {
        prm.declare_entry("Function",
                          "sin(pi*x)*sin(pi*y)",
                          Patterns::Anything(),
                          "Function of x and y to project (FunctionParser "
                          "syntax; the constant pi is defined).");
        prm.declare_entry("Lumped",
                          "false",
                          Patterns::Bool(),
                          "Use the lumped (row-sum) mass matrix instead of "
                          "the consistent one.");
      }
      prm.leave_subsection();
      prm.enter_subsection("Output");
      {
        prm.declare_entry("Basis function",
                          "",
                          Patterns::Anything(),
                          "Also output one basis function, given as "
                          "'vertex, q' (vertex index, function number at "
                          "the vertex: 0 for linear, 0-2 for powell-sabin); "
                          "empty for none.");
      }
      prm.leave_subsection();
    }

    void
    L2Projection::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Projection");
      function_expression = prm.get("Function");
      lumped              = prm.get_bool("Lumped");
      prm.leave_subsection();
      prm.enter_subsection("Output");
      const std::string basis = prm.get("Basis function");
      prm.leave_subsection();

      try
        {
          FunctionParser<2> f(1);
          f.initialize("x,y", function_expression, {{"pi", numbers::PI}});
          f.value(Point<2>(0.5, 0.5));
        }
      catch (const std::exception &e)
        {
          AssertThrow(false,
                      ExcMessage(
                        "Projection/Function = '" + function_expression +
                        "' is not a valid function of x and y: " + e.what()));
        }

      output_basis_vertex = numbers::invalid_unsigned_int;
      const std::regex blank("\\s*");
      if (!std::regex_match(basis, blank))
        {
          std::smatch      m;
          const std::regex pair("\\s*(\\d+)\\s*,\\s*(\\d+)\\s*");
          AssertThrow(std::regex_match(basis, m, pair),
                      ExcMessage("Output/Basis function = '" + basis +
                                 "': expected 'vertex, q' (two "
                                 "non-negative integers) or nothing."));
          output_basis_vertex   = std::stoul(m[1].str());
          output_basis_function = std::stoul(m[2].str());
        }
    }

    void
    L2Projection::check_basis_function(const Triangulation<2> &tria,
                                       const Basis::Space<2>  &space,
                                       const std::string      &basis_name) const
    {
      if (output_basis_vertex == numbers::invalid_unsigned_int)
        return;
      const unsigned int per_vertex = space.dof_layout().n_dofs_per_vertex();
      AssertThrow(output_basis_vertex < tria.n_vertices() &&
                    tria.get_used_vertices()[output_basis_vertex] &&
                    output_basis_function < per_vertex,
                  ExcMessage("Output/Basis function = '" +
                             std::to_string(output_basis_vertex) + ", " +
                             std::to_string(output_basis_function) +
                             "': the mesh has vertices 0.." +
                             std::to_string(tria.n_vertices() - 1) +
                             " and the " + basis_name + " basis has " +
                             std::to_string(per_vertex) +
                             " function(s) per vertex."));
    }

    void
    L2Projection::prepare(const Mesh::MeshGenerator<2> &mesh,
                          const std::string            &basis_name)
    {
      auto        result = std::make_shared<Projected>(mesh, basis_name);
      const auto &disc   = result->disc;
      check_basis_function(disc.tria, *disc.space, basis_name);
      FunctionParser<2> u(1);
      u.initialize("x,y", function_expression, {{"pi", numbers::PI}});
      const double scale = function_scale(disc, u, function_expression);

      const unsigned int     n_dofs = disc.dof_handler.n_dofs();
      DynamicSparsityPattern dsp(n_dofs);
      DoFTools::make_sparsity_pattern(disc.dof_handler, dsp);
      SparsityPattern sparsity;
      sparsity.copy_from(dsp);
      SparseMatrix<double> mass(sparsity);
      Vector<double>       rhs(n_dofs);
      result->solution.reinit(n_dofs);
      assemble(disc, u, scale, mass, rhs);
      result->failure = project(mass, rhs, lumped, result->solution);
      if (result->failure.empty())
        {
          result->error =
            scale *
            std::sqrt(
              squared_error(disc, u, scale, result->solution, result->h));
          result->solution *= scale;
          AssertThrow(std::isfinite(result->error) &&
                        std::isfinite(result->solution.linfty_norm()),
                      ExcMessage("Projection/Function = '" +
                                 function_expression +
                                 "': its projection or the L2 error exceeds "
                                 "the range of double numbers (largest "
                                 "value scaled to " +
                                 prm_value(scale) + ")."));
        }
      failure_reason = result->failure;
      projected      = result;
    }

    std::string
    L2Projection::failure() const
    {
      return failure_reason;
    }

    void
    L2Projection::run(const Mesh::MeshGenerator<2> &mesh,
                      const std::string            &basis_name,
                      const std::string            &output_directory,
                      Summary                      &summary,
                      MPI_Comm                      comm)
    {
      if (!projected)
        prepare(mesh, basis_name);
      // A prepared projection serves one run: the next one (of another
      // mesh, basis or function) prepares its own.
      const std::shared_ptr<const Projected> prepared = std::move(projected);
      projected.reset();
      const Projected &p = *prepared;
      summary.set_integer("n_dofs", p.disc.dof_handler.n_dofs());
      summary.set_integer("n_cells", p.disc.tria.n_active_cells());
      if (!p.failure.empty())
        return;
      summary.set("errors.L2", p.error);
      summary.set("h", p.h);

      // The requested basis function, as a global DoF index.
      types::global_dof_index basis_dof = numbers::invalid_dof_index;
      if (output_basis_vertex != numbers::invalid_unsigned_int)
        for (const auto &cell : p.disc.dof_handler.active_cell_iterators())
          for (unsigned int k = 0; k < 3; ++k)
            if (cell->vertex_index(k) == output_basis_vertex)
              basis_dof = cell->vertex_dof_index(k, output_basis_function);

      if (!write_output || Utilities::MPI::this_mpi_process(comm) != 0)
        return;
      FunctionParser<2> u(1);
      u.initialize("x,y", function_expression, {{"pi", numbers::PI}});
      std::filesystem::create_directories(output_directory);
      write_files(p.disc,
                  u,
                  p.solution,
                  basis_dof,
                  output_subdivisions,
                  output_directory);
    }
  } // namespace Solver
} // namespace psmpm
