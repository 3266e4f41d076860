// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// summary.json's timings nest as their definitions say: the CPU seconds
// of the steps (cpu_time_steps_s) are a part of the time loop's
// (cpu_time_loop_s), which is a part of the process's (cpu_time_s); the
// wall seconds of the timed step phases (time_loop_s) are a part of the
// run's (wall_time_s); and the throughput is the particle-steps over
// time_loop_s. The default scene with a fixed step, 200 steps, so that
// the steps take measurable CPU time.
#include "../app_tests.h"

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <cmath>
#include <filesystem>

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");
  std::filesystem::remove_all("run");
  std::string screen, errors;
  const int   code = run_app({"--set",
                              "Output directory=run",
                              "--set",
                              "Time/Time step=1e-5",
                              "--set",
                              "Time/End time=2e-3",
                              "--set",
                              "Output/Interval=0"},
                           screen,
                           errors);
  out << "exit code " << code << std::endl;
  PSMPM_CHECK(out, code == 0);

  boost::property_tree::ptree summary;
  boost::property_tree::read_json("run/summary.json", summary);
  const auto number = [&](const std::string &key) {
    return summary.get<double>(key);
  };
  const double steps_cpu = number("cpu_time_steps_s");
  const double loop_cpu  = number("cpu_time_loop_s");
  const double cpu       = number("cpu_time_s");
  const double loop_wall = number("time_loop_s");
  const double wall      = number("wall_time_s");
  const double steps     = number("steps");
  out << "steps " << steps << std::endl;
  PSMPM_CHECK(out, steps == 200);
  PSMPM_CHECK(out, steps_cpu > 0);
  PSMPM_CHECK(out, steps_cpu <= loop_cpu);
  PSMPM_CHECK(out, loop_cpu <= cpu);
  PSMPM_CHECK(out, loop_wall > 0);
  PSMPM_CHECK(out, loop_wall <= wall);
  const double rate = number("particle_steps_per_second");
  PSMPM_CHECK(out,
              std::abs(rate * loop_wall - number("n_particles") * steps) <=
                1e-9 * rate * loop_wall);
  out << "timings nest" << std::endl;
}
