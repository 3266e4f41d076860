// ---------------------------------------------------------------------
// psmpm: helpers for tests that run the application in-process.
// ---------------------------------------------------------------------
#ifndef psmpm_tests_app_tests_h
#define psmpm_tests_app_tests_h

#include <psmpm/app/application.h>

#include "tests.h"

#include <filesystem>
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

/// The start of a small scene for check_bad_input(): output to bad_output,
/// 1 m x 1 m in 10 x 10 blocks of 2 x 2 particles, no walls, no
/// reference, to 0.01 s; the case appends its bodies and entries.
inline std::string
small_bad_input_scene()
{
  return "set Output directory = bad_output\n"
         "subsection Geometry\n set Length = 1\n set Height = 1\nend\n"
         "subsection Mesh\n set Blocks x = 10\n set Blocks y = 10\nend\n"
         "subsection Particles\n set Per block x = 2\n set Per block y = "
         "2\nend\n"
         "subsection Boundary conditions\n set Fixed x =\n set Fixed y "
         "=\nend\n"
         "subsection Reference solution\n set Type = none\nend\n"
         "subsection Time\n set End time = 0.01\nend\n";
}

/// Run the scene @p prm (written to case.prm, whose Output directory is
/// bad_output) and check that it is refused as bad input: exit code 2, a
/// message naming case.prm and each of @p must_mention, nothing written.
inline void
check_bad_input(std::ostream                   &out,
                const std::string              &name,
                const std::string              &prm,
                const std::vector<std::string> &must_mention)
{
  std::filesystem::remove_all("bad_output");
  std::ofstream("case.prm") << prm;
  std::string screen, message;
  const int   code     = run_app({"case.prm"}, screen, message);
  bool        mentions = message.find("case.prm") != std::string::npos;
  for (const auto &m : must_mention)
    mentions = mentions && message.find(m) != std::string::npos;
  out << name << ": exit code " << code << std::endl;
  PSMPM_CHECK(out, code == psmpm::App::bad_input);
  PSMPM_CHECK(out, mentions);
  PSMPM_CHECK(out, !std::filesystem::exists("bad_output"));
  if (!mentions || code != psmpm::App::bad_input)
    out << "  message: " << message;
}

/// A case of check_bad_inputs(): its name, the scene text and what the
/// message must name.
struct BadInputCase
{
  std::string              name;
  std::string              prm;
  std::vector<std::string> must_mention;
};

/// check_bad_input() for each of @p cases, in order.
inline void
check_bad_inputs(std::ostream &out, const std::vector<BadInputCase> &cases)
{
  for (const auto &c : cases)
    check_bad_input(out, c.name, c.prm, c.must_mention);
}

#endif
