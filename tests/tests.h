// ---------------------------------------------------------------------
// psmpm: a minimal stand-in for deal.II's tests.h, which Debian does not
// ship. Tests write their results to the file "output" in the working
// directory; the deal.II test macros compare it with <name>.output.
// ---------------------------------------------------------------------
#ifndef psmpm_tests_tests_h
#define psmpm_tests_tests_h

#include <deal.II/base/logstream.h>
#include <deal.II/base/utilities.h>

#include <psmpm/base/mpi_session.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>

using namespace dealii;

/// Round-off below @p tol is printed as 0 so that outputs are portable.
inline double
filter(const double x, const double tol = 1e-12)
{
  return std::abs(x) < tol ? 0.0 : x;
}

/// Whether this process is rank 0 of MPI_COMM_WORLD: in tests run on
/// several ranks (.mpirun=N.output) it alone writes "output".
inline bool
is_root_rank()
{
  return Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
}

/// The test's "output" file on rank 0, /dev/null on the other ranks.
inline std::ofstream
root_output()
{
  return std::ofstream(is_root_rank() ? "output" : "/dev/null");
}

/// Print a pass/fail line for a check; the .output expects "OK".
#define PSMPM_CHECK(out, condition) \
  (out) << ((condition) ? "OK   " : "FAIL ") << #condition << std::endl

/// Run the body of a test and report exceptions as test output.
template <typename F>
int
run_test(F &&f)
{
  try
    {
      f();
    }
  catch (const std::exception &e)
    {
      std::cerr << "Exception: " << e.what() << std::endl;
      return 1;
    }
  return 0;
}

#endif
