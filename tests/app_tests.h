// ---------------------------------------------------------------------
// psmpm: helpers for tests that run the application in-process.
// ---------------------------------------------------------------------
#ifndef psmpm_tests_app_tests_h
#define psmpm_tests_app_tests_h

#include <psmpm/app/application.h>

#include "tests.h"

#include <sstream>
#include <string>
#include <vector>

/// The whole content of @p file ("" if it cannot be read).
inline std::string
read_file(const std::string &file)
{
  std::ifstream     in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Run psmpm with @p args on MPI_COMM_WORLD; its screen output and error
/// messages are captured instead of printed. Returns the exit code.
inline int
run_app(const std::vector<std::string> &args,
        std::string                    &screen,
        std::string                    &errors)
{
  std::ostringstream out, err;
  auto              *old_out = std::cout.rdbuf(out.rdbuf());
  auto              *old_err = std::cerr.rdbuf(err.rdbuf());
  const int          code    = psmpm::App::run(args, MPI_COMM_WORLD);
  std::cout.rdbuf(old_out);
  std::cerr.rdbuf(old_err);
  screen = out.str();
  errors = err.str();
  return code;
}

#endif
