// Values at the edge of double arithmetic: each is projected or run with a
// finite result, or refused with exit code 2 and a message that names the
// entry and its value, nothing written.
//  * l2 projection: a constant of +-1e308 or 1e-308 is projected (divided
//    by a power of two, so that CG's squared norms neither overflow nor
//    vanish) with a finite error below 1e-10 of the constant; a function
//    that is inf or nan at a quadrature point is refused;
//  * Reference solution/Velocity amplitude = 1e308 (squared in the error
//    norms) is refused;
//  * a Young's modulus of 1e308 is refused: with Poisson's ratio 0.45 its
//    p-wave modulus overflows, with 0 its automatic time step asks for too
//    many steps, and the message names the material entry, not only
//    Limits;
//  * Mass matrix study/Inverse h = 1 with degree 1 and Dirichlet
//    conditions is refused naming the entry (with free conditions it runs);
//  * --set "Output directory=" after --set "Output directory=out" is
//    refused and creates neither directory;
//  * a completed run whose summary.json would hold a non-finite number
//    (the root mean square of error norms of 1e152) ends with exit code 3
//    and that key as the reason;
//  * a statistics row with inf or nan is found by
//    StatisticsTable::non_finite_in_last_entries() (the simulator stops
//    such a run with exit code 3 instead of exit 0).
#include <psmpm/postprocess/statistics_table.h>

#include "../app_tests.h"

#include <cmath>
#include <filesystem>
#include <limits>

namespace
{
  const std::string projection =
    "set Problem = l2 projection\n"
    "set Output directory = bad_output\n"
    "subsection Mesh\n set Type = diagonal\n set Blocks x = 2\n"
    " set Blocks y = 2\nend\n"
    "subsection Basis\n set Type = powell-sabin\nend\n";

  std::string
  projection_of(const std::string &function)
  {
    return projection + "subsection Projection\n set Function = " + function +
           "\nend\n";
  }

  const std::string bar =
    "set Output directory = bad_output\n"
    "subsection Geometry\n set Dimension = 1\n set Length = 25\nend\n"
    "subsection Mesh\n set Blocks x = 16\nend\n"
    "subsection Basis\n set Type = linear\nend\n"
    "subsection Particles\n set Per block x = 4\nend\n"
    "subsection Initial conditions\n set Velocity = v0*sin(pi*x/L)\n"
    " set Function constants = v0=0.1, L=25\nend\n"
    "subsection Body force\n set Gravity = 0\nend\n"
    "subsection Boundary conditions\n set Fixed x = left, right\nend\n";

  std::string
  bar_with(const std::string &material,
           const std::string &time,
           const std::string &amplitude)
  {
    return bar + "subsection Material\n set Density = 1\n" + material +
           "end\nsubsection Time\n" + time +
           "end\nsubsection Reference solution\n set Type = vibrating bar\n"
           " set Velocity amplitude = " +
           amplitude + "\nend\n";
  }

  /// errors.L2 of summary.json in @p dir (nan if absent).
  double
  l2_error(const std::string &dir)
  {
    const std::string text = read_file(dir + "/summary.json");
    const auto        at   = text.find("\"L2\": ");
    return at == std::string::npos ?
             std::nan("") :
             std::strtod(text.c_str() + at + 6, nullptr);
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");
  namespace fs = std::filesystem;

  for (const std::string c : {"1e308", "-1e308", "1e-308"})
    {
      fs::remove_all("l2_output");
      std::ofstream("case.prm")
        << projection_of(c) << "set Output directory = l2_output\n";
      std::string  screen, message;
      const int    code  = run_app({"case.prm"}, screen, message);
      const double error = l2_error("l2_output");
      out << "projection of " << c << ": exit code " << code << std::endl;
      PSMPM_CHECK(out, code == psmpm::App::success);
      PSMPM_CHECK(out, std::isfinite(error));
      PSMPM_CHECK(out,
                  error <= 1e-10 * std::abs(std::strtod(c.c_str(), nullptr)));
    }
  check_bad_input(out,
                  "projection of 1e308*(1+x)",
                  projection_of("1e308*(1+x)"),
                  {"Projection/Function = '1e308*(1+x)' is inf at"});
  check_bad_input(out,
                  "projection of sqrt(x-2)",
                  projection_of("sqrt(x-2)"),
                  {"Projection/Function = 'sqrt(x-2)' is nan at"});

  const std::string fixed_step =
    " set End time = 1e-4\n set Time step = 1e-5\n";
  check_bad_input(out,
                  "velocity amplitude 1e308",
                  bar_with(" set Young's modulus = 100\n", fixed_step, "1e308"),
                  {"Reference solution/Velocity amplitude = 1e+308"});
  check_bad_input(out,
                  "velocity amplitude -1e200",
                  bar_with(" set Young's modulus = 100\n",
                           fixed_step,
                           "-1e200"),
                  {"Reference solution/Velocity amplitude = -1e+200"});
  check_bad_input(out,
                  "Young's modulus 1e308, Poisson's ratio 0.45",
                  bar + "subsection Material\n set Young's modulus = 1e308\n"
                        " set Poisson's ratio = 0.45\nend\n"
                        "subsection Reference solution\n set Type = none\n"
                        "end\n",
                  {"Material/Young's modulus = 1e+308 with Poisson's ratio = "
                   "0.45",
                   "p-wave modulus (inf)"});
  check_bad_input(out,
                  "Young's modulus 1e308, automatic time step",
                  bar_with(" set Young's modulus = 1e308\n",
                           " set End time = 1e-9\n set Time step = 0\n",
                           "0.1"),
                  {"Material/Young's modulus = 1e+308",
                   "Limits/Maximum steps"});

  const std::string study =
    "set Problem = mass matrix study\nset Output directory = bad_output\n"
    "subsection Mass matrix study\n set Degrees = 1\n set Inverse h = 1, 2\n";
  check_bad_input(out,
                  "mass matrix study, Inverse h = 1, 2",
                  study + " set Boundary conditions = dirichlet, free\nend\n",
                  {"Mass matrix study/Inverse h = 1, 2"});
  {
    fs::remove_all("study_output");
    std::ofstream("case.prm")
      << study << " set Boundary conditions = free\nend\n"
      << "set Output directory = study_output\n";
    std::string screen, message;
    const int   code = run_app({"case.prm"}, screen, message);
    out << "mass matrix study, Inverse h = 1, 2, free: exit code " << code
        << std::endl;
    PSMPM_CHECK(out, code == psmpm::App::success);
  }

  {
    fs::remove_all("out");
    std::ofstream("case.prm")
      << bar_with(" set Young's modulus = 100\n", fixed_step, "0.1");
    std::string screen, message;
    const int   code = run_app({"case.prm",
                                "--set",
                                "Output directory=out",
                                "--set",
                                "Output directory="},
                             screen,
                             message);
    out << "Output directory set twice, then empty: exit code " << code
        << std::endl;
    PSMPM_CHECK(out, code == psmpm::App::bad_input);
    PSMPM_CHECK(out,
                message.find("Output directory is empty") != std::string::npos);
    PSMPM_CHECK(out, !fs::exists("out") && !fs::exists("bad_output"));
  }

  {
    // Each error norm is finite, their sum of squares over 2000 steps (the
    // root mean square in summary.json) is not: no result, exit code 3.
    fs::remove_all("rms");
    std::ofstream("case.prm")
      << bar_with(" set Young's modulus = 100\n",
                  " set End time = 0.02\n set Time step = 1e-5\n",
                  "2.5e152\nend\nsubsection Output\n set Error interval = 1");
    std::string screen, message;
    const int   code =
      run_app({"case.prm", "--set", "Output directory=rms"}, screen, message);
    const std::string summary = read_file("rms/summary.json");
    out << "root mean square error beyond double range: exit code " << code
        << std::endl;
    PSMPM_CHECK(out, code == psmpm::App::unstable);
    PSMPM_CHECK(out,
                summary.find("\"status\": \"unstable\"") != std::string::npos);
    PSMPM_CHECK(out,
                summary.find("non-finite value in summary.json: "
                             "errors.velocity_L2_rms_over_time") !=
                  std::string::npos);
  }

  psmpm::Postprocess::StatisticsTable table;
  table.add_value("step", 0u);
  table.add_value("energy", 1.);
  table.add_value("error", std::string("-"));
  out << "finite row: '" << table.non_finite_in_last_entries() << "'"
      << std::endl;
  table.add_value("step", 1u);
  table.add_value("energy", std::numeric_limits<double>::infinity());
  table.add_value("error", std::nan(""));
  out << "row with inf and nan: '" << table.non_finite_in_last_entries() << "'"
      << std::endl;
  table.add_value("step", 2u);
  table.add_value("energy", 2.);
  table.add_value("error", -std::numeric_limits<double>::infinity());
  out << "row with -inf: '" << table.non_finite_in_last_entries() << "'"
      << std::endl;
}
