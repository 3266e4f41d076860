// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_solver_solver_failure_h
#define psmpm_solver_solver_failure_h

#include <stdexcept>

namespace psmpm
{
  namespace Solver
  {
    /// A mass solve that could not be carried out at all (a singular
    /// coarse matrix of the p-multigrid preconditioner), as opposed to CG
    /// running out of iterations (SolverControl::NoConvergence). The
    /// transfer schemes report both as the solver's failure: status
    /// unstable with what() as the reason, exit code 7.
    class SolverFailure : public std::runtime_error
    {
    public:
      using std::runtime_error::runtime_error;
    };
  } // namespace Solver
} // namespace psmpm

#endif
