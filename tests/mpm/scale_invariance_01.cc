// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// A scene is the same scene in any unit of length: the free vibrating bar
// of prm/free_vibrating_bar.prm (Powell-Sabin default, apic, three
// periods) with every length scaled by s and Young's modulus by s^2 (the
// wave speed scales with the lengths, so the time scale is kept) must
// take the same steps and keep the same fraction of its energy for s =
// 1e-9, 1e-6, 1e3 and 1e6 as for s = 1, to 5e-4. Its initial affine
// matrices come from differences of the velocity expression whose step
// must follow the mesh: a fixed step of 1e-4 is wider than the bar at s
// = 1e-6 and changed the kept energy by 1.3e-3.
#include <psmpm/base/format.h>

#include "../mpm_tests.h"

#include <filesystem>

namespace
{
  using namespace psmpm;

  const auto number = prm_value;

  /// Steps and E_end / E_0 (total + affine energy) of the bar at scale s.
  std::pair<std::size_t, double>
  run(const double s)
  {
    const std::string dir    = "run-" + number(s);
    auto              solver = make_scene_solver(
      "free_vibrating_bar.prm",
      {"Geometry/Length=" + number(31 * s),
                    "Geometry/Height=" + number(4 * s),
                    "Material/Young's modulus=" + number(100 * s * s),
                    "Particles/Region=" + number(3 * s) + ", " + number(s) + ", " +
                      number(28 * s) + ", " + number(3 * s),
                    "Initial conditions/Velocity=v0*cos(pi*(x-" + number(3 * s) + ")/L); 0",
                    "Initial conditions/Function constants=v0=" + number(0.1 * s) +
                      ", L=" + number(25 * s),
                    "Output/Interval=0"});
    std::filesystem::create_directories(dir);
    if (solver->run(dir) != Simulator::Status::completed)
      return {0, 0.};
    const StatisticsTable statistics(dir);
    const auto            total  = statistics.column("total_energy");
    const auto            affine = statistics.column("affine_kinetic_energy");
    return {total.size(),
            (total.back() + affine.back()) / (total[0] + affine[0])};
  }
} // namespace

int
main(int argc, char **argv)
{
  MPISession    mpi(argc, argv);
  std::ofstream out("output");
  const auto [steps, kept] = run(1.);
  out << "s = 1: " << steps - 1 << " steps" << std::endl;
  PSMPM_CHECK(out, steps > 1 && kept > 0.9 && kept < 1.01);
  for (const double s : {1e-9, 1e-6, 1e3, 1e6})
    {
      const auto [n, e] = run(s);
      out << "s = " << s << ": " << n - 1 << " steps" << std::endl;
      PSMPM_CHECK(out, n == steps);
      PSMPM_CHECK(out, std::abs(e / kept - 1) < 5e-4);
    }
}
