// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <psmpm/solver/p_multigrid.h>

#include <cmath>

namespace psmpm
{
  namespace Solver
  {
    PMultigrid::PMultigrid(
      const Parameters                                &parameters,
      const std::vector<const SparseMatrix<double> *> &matrices,
      const std::vector<const SparseMatrix<double> *> &prolongations,
      const std::vector<const SparseMatrix<double> *> &restrictions)
      : parameters(parameters)
      , matrices(matrices)
      , prolongations(prolongations)
      , restrictions(restrictions)
    {
      AssertThrow(!matrices.empty() &&
                    prolongations.size() == matrices.size() &&
                    restrictions.size() == matrices.size(),
                  ExcMessage("PMultigrid: one matrix, prolongation and "
                             "restriction per level."));
      AssertThrow(parameters.smoother == "gauss-seidel" ||
                    parameters.smoother == "forward gauss-seidel" ||
                    parameters.smoother == "jacobi",
                  ExcMessage("PMultigrid: unknown smoother '" +
                             parameters.smoother + "'."));
      residuals.resize(matrices.size());
      coarse_rhs.resize(matrices.size());
      coarse_solution.resize(matrices.size());
      for (unsigned int l = 0; l < matrices.size(); ++l)
        {
          residuals[l].reinit(matrices[l]->m());
          if (l > 0)
            {
              coarse_rhs[l].reinit(matrices[l - 1]->m());
              coarse_solution[l].reinit(matrices[l - 1]->m());
            }
        }
    }

    void
    PMultigrid::smooth(const unsigned int    level,
                       const Vector<double> &b,
                       Vector<double>       &x,
                       const bool            pre) const
    {
      const SparseMatrix<double> &A = *matrices[level];
      const unsigned int          steps =
        pre ? parameters.pre_smoothing : parameters.post_smoothing;
      if (parameters.smoother == "jacobi")
        {
          Vector<double> &r = residuals[level];
          for (unsigned int s = 0; s < steps; ++s)
            {
              A.residual(r, x, b);
              for (unsigned int i = 0; i < x.size(); ++i)
                x(i) += parameters.jacobi_damping * r(i) / A.diag_element(i);
            }
          return;
        }
      // SOR_step with omega = 1 is one in-place forward Gauss-Seidel sweep,
      // TSOR_step the backward one; forward before and backward after the
      // correction keeps the cycle symmetric.
      const bool backward = !pre && parameters.smoother == "gauss-seidel";
      for (unsigned int s = 0; s < steps; ++s)
        if (backward)
          A.TSOR_step(x, b, 1.);
        else
          A.SOR_step(x, b, 1.);
    }

    void
    PMultigrid::coarse_correction(const Vector<double> &b,
                                  Vector<double>       &x) const
    {
      // The correction starts from zero: the tolerance is relative to the
      // restricted residual, as in the chapter.
      Vector<double> e(b.size());
      if (coarse_solver)
        {
          coarse_solver(e, b);
          x += e;
          return;
        }
      SolverControl            control(10 * b.size() + 100,
                            parameters.coarse_tolerance * b.l2_norm(),
                            false,
                            false);
      SolverCG<Vector<double>> cg(control);
      try
        {
          if (b.l2_norm() > 0)
            cg.solve(*matrices[0], e, b, PreconditionIdentity());
        }
      catch (const SolverControl::NoConvergence &)
        {
          // A diverging smoother hands down a non-finite residual; solve()
          // sees it in the fine residual and reports no convergence.
        }
      x += e;
    }

    void
    PMultigrid::vcycle(const unsigned int    level,
                       const Vector<double> &b,
                       Vector<double>       &x) const
    {
      if (level == 0 && matrices.size() > 1)
        {
          coarse_correction(b, x);
          return;
        }
      smooth(level, b, x, true);
      Vector<double> &r = residuals[level];
      matrices[level]->residual(r, x, b);
      if (level == 0)
        {
          // A hierarchy of one level: the CG correction on the level itself.
          Vector<double> e(x.size());
          coarse_correction(r, e);
          x += e;
        }
      else
        {
          Vector<double> &rc = coarse_rhs[level], &ec = coarse_solution[level];
          if (restrictions[level] != nullptr)
            restrictions[level]->vmult(rc, r);
          else
            prolongations[level]->Tvmult(rc, r);
          ec = 0;
          vcycle(level - 1, rc, ec);
          prolongations[level]->vmult_add(x, ec);
        }
      smooth(level, b, x, false);
    }

    unsigned int
    PMultigrid::solve(const Vector<double> &b,
                      Vector<double>       &x,
                      const double          tolerance) const
    {
      const unsigned int finest = matrices.size() - 1;
      Vector<double>     r(x.size());
      const double       r0 = matrices[finest]->residual(r, x, b);
      if (r0 == 0)
        return 0;
      for (unsigned int cycle = 1; cycle <= parameters.max_cycles; ++cycle)
        {
          vcycle(finest, b, x);
          const double residual = matrices[finest]->residual(r, x, b);
          if (!std::isfinite(residual))
            return numbers::invalid_unsigned_int;
          if (residual < tolerance * r0)
            return cycle;
        }
      return numbers::invalid_unsigned_int;
    }
  } // namespace Solver
} // namespace psmpm
