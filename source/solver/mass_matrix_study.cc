// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/utilities.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <psmpm/base/checked_file.h>
#include <psmpm/base/format.h>
#include <psmpm/basis/bspline_1d.h>
#include <psmpm/solver/cg_iterations.h>
#include <psmpm/solver/mass_matrix_study.h>

#include <algorithm>
#include <filesystem>
#include <limits>
#include <sstream>

namespace psmpm
{
  namespace Solver
  {
    namespace
    {
      /// Gravity of the chapter's load (9.81 in -x and -y: both components
      /// are the same system, so one is solved).
      constexpr double gravity = 9.81;

      /// Rows and columns [first, size - first) of @p M in both directions
      /// (first = 1: without the two boundary functions).
      FullMatrix<double>
      interior(const FullMatrix<double> &M, const unsigned int first)
      {
        FullMatrix<double> R(M.m() - 2 * first, M.n() - 2 * first);
        for (unsigned int i = 0; i < R.m(); ++i)
          for (unsigned int j = 0; j < R.n(); ++j)
            R(i, j) = M(i + first, j + first);
        return R;
      }

      /// Univariate L2 projection from @p from to @p to with the lumped
      /// mass matrix of @p to: (M^L_to)^-1 P_{to,from}.
      FullMatrix<double>
      lumped_projection(const Basis::BSpline1D &to,
                        const Basis::BSpline1D &from,
                        const unsigned int      first)
      {
        const FullMatrix<double> M = interior(to.mass_matrix(to), first);
        FullMatrix<double>       P = interior(to.mass_matrix(from), first);
        for (unsigned int i = 0; i < P.m(); ++i)
          {
            double row_sum = 0;
            for (unsigned int j = 0; j < M.n(); ++j)
              row_sum += M(i, j);
            for (unsigned int j = 0; j < P.n(); ++j)
              P(i, j) /= row_sum;
          }
        return P;
      }

      std::vector<unsigned int>
      parse_list(const std::string &entry, const std::string &value)
      {
        std::vector<unsigned int> list;
        for (const auto &s : Utilities::split_string_list(value, ','))
          {
            int v = 0;
            try
              {
                v = Utilities::string_to_int(s);
              }
            catch (...)
              {
                v = 0;
              }
            AssertThrow(v > 0,
                        ExcMessage("Mass matrix study/" + entry + " = '" +
                                   value +
                                   "': expected a list of positive "
                                   "integers."));
            list.push_back(v);
          }
        AssertThrow(!list.empty(),
                    ExcMessage("Mass matrix study/" + entry + " is empty."));
        return list;
      }

      std::string
      count(const unsigned int n)
      {
        return n == numbers::invalid_unsigned_int ? "-" : std::to_string(n);
      }
    } // namespace

    std::unique_ptr<OwnedSparseMatrix>
    kronecker_product(const FullMatrix<double> &A, const FullMatrix<double> &B)
    {
      auto                   K = std::make_unique<OwnedSparseMatrix>();
      DynamicSparsityPattern dsp(A.m() * B.m(), A.n() * B.n());
      for (unsigned int i = 0; i < A.m(); ++i)
        for (unsigned int j = 0; j < A.n(); ++j)
          if (A(i, j) != 0)
            for (unsigned int k = 0; k < B.m(); ++k)
              for (unsigned int l = 0; l < B.n(); ++l)
                if (B(k, l) != 0)
                  dsp.add(i * B.m() + k, j * B.n() + l);
      K->sparsity.copy_from(dsp);
      K->matrix.reinit(K->sparsity);
      for (unsigned int i = 0; i < A.m(); ++i)
        for (unsigned int j = 0; j < A.n(); ++j)
          if (A(i, j) != 0)
            for (unsigned int k = 0; k < B.m(); ++k)
              for (unsigned int l = 0; l < B.n(); ++l)
                if (B(k, l) != 0)
                  K->matrix.set(i * B.m() + k,
                                j * B.n() + l,
                                A(i, j) * B(k, l));
      return K;
    }

    namespace
    {
      /// cond(M1 (x) M1): its eigenvalues are the products of those of M1.
      double
      kronecker_condition_number(const FullMatrix<double> &M1)
      {
        LAPACKFullMatrix<double> L(M1.m());
        L = M1;
        L.compute_eigenvalues();
        double lmin = std::numeric_limits<double>::max(), lmax = 0;
        for (unsigned int i = 0; i < M1.m(); ++i)
          {
            lmin = std::min(lmin, L.eigenvalue(i).real());
            lmax = std::max(lmax, L.eigenvalue(i).real());
          }
        return std::pow(lmax / lmin, 2);
      }

      /// The p-multigrid's levels: mass matrices, prolongations and
      /// restrictions (nullptr on the coarsest level), owned here.
      struct Levels
      {
        std::vector<std::unique_ptr<OwnedSparseMatrix>> owned;
        std::vector<const SparseMatrix<double> *>       matrices, prolongations,
          restrictions;
      };

      /// The levels of @p level_degrees on n elements per direction, the
      /// first @p first functions of each end removed; restriction by the
      /// prolongation's @p transpose or the lumped projection.
      Levels
      build_levels(const std::vector<unsigned int> &level_degrees,
                   const unsigned int               n,
                   const unsigned int               first,
                   const bool                       transpose)
      {
        Levels levels;
        for (unsigned int l = 0; l < level_degrees.size(); ++l)
          {
            const Basis::BSpline1D   s(level_degrees[l], n);
            const FullMatrix<double> Ml = interior(s.mass_matrix(s), first);
            levels.owned.push_back(kronecker_product(Ml, Ml));
            levels.matrices.push_back(&levels.owned.back()->matrix);
            if (l == 0)
              {
                levels.prolongations.push_back(nullptr);
                levels.restrictions.push_back(nullptr);
                continue;
              }
            const Basis::BSpline1D   coarse(level_degrees[l - 1], n);
            const FullMatrix<double> P = lumped_projection(s, coarse, first);
            levels.owned.push_back(kronecker_product(P, P));
            levels.prolongations.push_back(&levels.owned.back()->matrix);
            if (transpose)
              {
                FullMatrix<double> R(P.n(), P.m());
                R.copy_transposed(P);
                levels.owned.push_back(kronecker_product(R, R));
              }
            else
              {
                const FullMatrix<double> R =
                  lumped_projection(coarse, s, first);
                levels.owned.push_back(kronecker_product(R, R));
              }
            levels.restrictions.push_back(&levels.owned.back()->matrix);
          }
        return levels;
      }

      /// Mass matrix study/Right-hand side for the matrix @p M of
      /// @p space (x) @p space without the first @p first functions at
      /// each end (@p m per direction).
      Vector<double>
      load_vector(const std::string          &type,
                  const SparseMatrix<double> &M,
                  const Basis::BSpline1D     &space,
                  const unsigned int          m,
                  const unsigned int          first)
      {
        Vector<double> b(M.m());
        if (type == "constant")
          b = gravity;
        else if (type == "row sums")
          {
            // With the boundary functions removed this differs from the
            // load vector near the boundary: the solution is the smooth
            // coefficient vector 9.81, while the load vector's (the L2
            // projection of 9.81 onto functions that vanish on the
            // boundary) oscillates next to the boundary, where CG and
            // p-multigrid converge slowly (doc/solver_study.md).
            Vector<double> f(M.m());
            f = gravity;
            M.vmult(b, f);
          }
        else
          {
            Vector<double> l1(m);
            const auto     integrals = space.integrals();
            for (unsigned int i = 0; i < l1.size(); ++i)
              l1(i) = integrals(i + first);
            for (unsigned int i = 0; i < l1.size(); ++i)
              for (unsigned int j = 0; j < l1.size(); ++j)
                b(i * l1.size() + j) = gravity * l1(i) * l1(j);
          }
        return b;
      }
    } // namespace

    void
    MassMatrixStudy::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Mass matrix study");
      {
        prm.declare_entry("Degrees",
                          "1, 2, 3, 4, 5",
                          Patterns::List(Patterns::Integer(1, 10)),
                          "B-spline degrees p.");
        prm.declare_entry("Inverse h",
                          "8, 16, 32, 64, 128",
                          Patterns::List(Patterns::Integer(1, 1024)),
                          "Elements per direction of the unit square.");
        prm.declare_entry("Tolerance",
                          "1e-8",
                          Patterns::Double(0, 1),
                          "Relative residual ||r_k|| / ||r_0|| of CG and "
                          "p-multigrid (zero start).");
        prm.declare_entry(
          "Right-hand side",
          "row sums",
          Patterns::Selection("row sums|load vector|constant"),
          "row sums: b = M f with f_j = 9.81 for every DoF of the matrix "
          "(b_i = 9.81 sum_j M_ij, the solution is the constant 9.81; the "
          "chapter's 'constant force vector', which reproduces its Tables "
          "4.3 and 4.4); load vector: b_i = 9.81 int phi_i (a constant body "
          "force, the L2 projection of 9.81); constant: b_i = 9.81.");
        prm.declare_entry("Boundary conditions",
                          "dirichlet, free",
                          Patterns::List(Patterns::Selection("dirichlet|free")),
                          "dirichlet: without the functions that do not "
                          "vanish on the boundary (homogeneous Dirichlet "
                          "conditions, matrix 'bspline dirichlet'); free: all "
                          "functions ('bspline free').");
        prm.declare_entry("Maximum iterations",
                          "20000",
                          Patterns::Integer(1),
                          "CG iteration limit ('-' in the table when "
                          "reached).");
        prm.enter_subsection("Multigrid");
        {
          prm.declare_entry("Hierarchy",
                            "stepwise",
                            Patterns::Selection("stepwise|direct"),
                            "stepwise: degrees p, p-1, ..., 1; direct: p, 1.");
          prm.declare_entry("Smoother",
                            "forward gauss-seidel",
                            Patterns::Selection(
                              "gauss-seidel|forward gauss-seidel|jacobi"),
                            "gauss-seidel: forward sweeps before and "
                            "backward sweeps after the coarse correction; "
                            "forward gauss-seidel: forward both times; "
                            "jacobi: damped Jacobi (Jacobi damping).");
          prm.declare_entry("Smoothing steps",
                            "8",
                            Patterns::Integer(0),
                            "Pre- and post-smoothing steps nu_1 = nu_2.");
          prm.declare_entry("Jacobi damping",
                            "0.6666666666666666",
                            Patterns::Double(0, 2),
                            "Damping of the Jacobi smoother.");
          prm.declare_entry("Coarse tolerance",
                            "1e-4",
                            Patterns::Double(0, 1),
                            "Relative residual of the CG solve at p = 1.");
          prm.declare_entry("Restriction",
                            "projection",
                            Patterns::Selection("projection|transpose"),
                            "projection: lumped L2 projection onto the "
                            "coarser space; transpose: the prolongation's "
                            "transpose.");
          prm.declare_entry("Maximum cycles",
                            "1000",
                            Patterns::Integer(1),
                            "V-cycle limit ('-' in the table when "
                            "reached).");
        }
        prm.leave_subsection();
      }
      prm.leave_subsection();
    }

    void
    MassMatrixStudy::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Mass matrix study");
      // The entries as given, for the message below.
      const std::string entries =
        "Inverse h = " + prm.get("Inverse h") +
        " with Degrees = " + prm.get("Degrees") +
        " and Boundary conditions = " + prm.get("Boundary conditions");
      degrees         = parse_list("Degrees", prm.get("Degrees"));
      inverse_h       = parse_list("Inverse h", prm.get("Inverse h"));
      tolerance       = prm.get_double("Tolerance");
      right_hand_side = prm.get("Right-hand side");
      dirichlet.clear();
      for (const auto &b :
           Utilities::split_string_list(prm.get("Boundary conditions")))
        dirichlet.push_back(b == "dirichlet");
      AssertThrow(!dirichlet.empty(),
                  ExcMessage("Mass matrix study/Boundary conditions is "
                             "empty."));
      max_iterations = prm.get_integer("Maximum iterations");
      prm.enter_subsection("Multigrid");
      hierarchy                  = prm.get("Hierarchy");
      multigrid.smoother         = prm.get("Smoother");
      multigrid.pre_smoothing    = prm.get_integer("Smoothing steps");
      multigrid.post_smoothing   = multigrid.pre_smoothing;
      multigrid.jacobi_damping   = prm.get_double("Jacobi damping");
      multigrid.coarse_tolerance = prm.get_double("Coarse tolerance");
      restriction                = prm.get("Restriction");
      multigrid.max_cycles       = prm.get_integer("Maximum cycles");
      prm.leave_subsection();
      prm.leave_subsection();
      // The patterns admit the ends of their ranges; these cannot be met
      // (a residual of zero) or do nothing (no damping).
      const std::pair<const char *, double> open_ranges[] = {
        {"Tolerance", tolerance},
        {"Multigrid/Coarse tolerance", multigrid.coarse_tolerance}};
      for (const auto &[name, value] : open_ranges)
        AssertThrow(value > 0 && value < 1,
                    ExcMessage("Mass matrix study/" + std::string(name) +
                               " = " + prm_value(value) +
                               ": a relative residual must lie strictly "
                               "between 0 and 1 (e.g. 1e-8)."));
      AssertThrow(multigrid.jacobi_damping > 0 && multigrid.jacobi_damping < 2,
                  ExcMessage("Mass matrix study/Multigrid/Jacobi damping = " +
                             prm_value(multigrid.jacobi_damping) +
                             ": must lie strictly between 0 and 2 (0 does "
                             "not smooth, 2 and above diverge)."));
      // Without the boundary functions, one element of degree 1 keeps no
      // function: there is no matrix to study.
      const bool with_dirichlet =
        std::find(dirichlet.begin(), dirichlet.end(), true) != dirichlet.end();
      for (const unsigned int n : inverse_h)
        for (const unsigned int p : degrees)
          AssertThrow(!with_dirichlet || n + p > 2,
                      ExcMessage("Mass matrix study/" + entries +
                                 ": one element (Inverse h = 1) of degree 1 "
                                 "has no interior function; use Inverse h "
                                 "of at least 2, degrees above 1 or "
                                 "Boundary conditions = free."));
    }

    MassMatrixStudy::Row
    MassMatrixStudy::compute(const unsigned int p,
                             const unsigned int n,
                             const bool         dirichlet) const
    {
      const unsigned int first = dirichlet ? 1 : 0;
      Row                row;
      row.matrix    = dirichlet ? "bspline dirichlet" : "bspline free";
      row.degree    = p;
      row.inverse_h = n;

      const Basis::BSpline1D   space(p, n);
      const FullMatrix<double> M1 = interior(space.mass_matrix(space), first);
      row.n_dofs                  = M1.m() * M1.m();
      row.condition_number        = kronecker_condition_number(M1);

      // The matrices of degrees 1..p (only those of the hierarchy are
      // used).
      std::vector<unsigned int> level_degrees;
      if (hierarchy == "direct" && p > 1)
        level_degrees = {1, p};
      else
        for (unsigned int q = 1; q <= p; ++q)
          level_degrees.push_back(q);
      const Levels levels =
        build_levels(level_degrees, n, first, restriction == "transpose");
      const SparseMatrix<double> &M = *levels.matrices.back();
      const Vector<double>        b =
        load_vector(right_hand_side, M, space, M1.m(), first);

      row.cg_iterations =
        cg_iterations(M, b, "none", tolerance, max_iterations);
      row.jacobi_cg_iterations =
        cg_iterations(M, b, "jacobi", tolerance, max_iterations);
      row.amg_cg_iterations =
        cg_iterations(M, b, "amg", tolerance, max_iterations);

      const PMultigrid mg(multigrid,
                          levels.matrices,
                          levels.prolongations,
                          levels.restrictions);
      Vector<double>   x(M.m());
      row.pmg_vcycles = mg.solve(b, x, tolerance);
      return row;
    }

    std::vector<MassMatrixStudy::Row>
    MassMatrixStudy::compute() const
    {
      std::vector<Row> rows;
      for (const bool d : dirichlet)
        for (const unsigned int p : degrees)
          for (const unsigned int n : inverse_h)
            rows.push_back(compute(p, n, d));
      return rows;
    }

    void
    MassMatrixStudy::write_table(const std::string      &filename,
                                 const std::vector<Row> &rows)
    {
      write_atomically(filename, [&](std::ostream &out) {
        out << "matrix\tdegree\tinverse_h\tn_dofs\tcondition_number\t"
               "cg_iterations\tjacobi_cg_iterations\tamg_cg_iterations\t"
               "pmg_vcycles\n";
        for (const auto &r : rows)
          {
            std::ostringstream cond;
            cond.precision(4);
            cond << std::scientific << r.condition_number;
            out << r.matrix << '\t' << r.degree << '\t' << r.inverse_h << '\t'
                << r.n_dofs << '\t'
                << (r.condition_number > 0 ? cond.str() : "-") << '\t'
                << count(r.cg_iterations) << '\t'
                << count(r.jacobi_cg_iterations) << '\t'
                << count(r.amg_cg_iterations) << '\t' << count(r.pmg_vcycles)
                << '\n';
          }
      });
    }

    void
    MassMatrixStudy::run(const std::string &output_directory,
                         Summary           &summary,
                         MPI_Comm           comm) const
    {
      const auto   rows              = compute();
      double       largest_condition = 0;
      unsigned int most_cg = 0, most_cycles = 0, not_converged = 0;
      for (const auto &r : rows)
        {
          largest_condition = std::max(largest_condition, r.condition_number);
          for (const unsigned int c : {r.cg_iterations,
                                       r.jacobi_cg_iterations,
                                       r.amg_cg_iterations,
                                       r.pmg_vcycles})
            not_converged += (c == numbers::invalid_unsigned_int);
          // A count that did not converge is invalid_unsigned_int: not
          // the largest count.
          if (r.cg_iterations != numbers::invalid_unsigned_int)
            most_cg = std::max(most_cg, r.cg_iterations);
          if (r.pmg_vcycles != numbers::invalid_unsigned_int)
            most_cycles = std::max(most_cycles, r.pmg_vcycles);
        }
      summary.set_integer("n_rows", rows.size());
      summary.set("largest_condition_number", largest_condition);
      summary.set_integer("most_cg_iterations", most_cg);
      summary.set_integer("most_pmg_vcycles", most_cycles);
      // Solves that reached their limit ('-' in the table): a study with
      // too few iterations must not look like one without.
      summary.set_integer("n_not_converged", not_converged);
      if (Utilities::MPI::this_mpi_process(comm) != 0)
        return;
      std::filesystem::create_directories(output_directory);
      write_table(output_directory + "/solver_study.tsv", rows);
    }
  } // namespace Solver
} // namespace psmpm
