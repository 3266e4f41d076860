// The geostatic initial stress of bodies of several shapes, on one rank and
// two (the free surface is reduced over the ranks, so the values must not
// depend on how the particles are distributed): for a slope (a polygon
// whose top rises from 0.5 to 2 m) sigma_yy = -rho g (s(x) - y) with s(x)
// the polygon's top above the particle, to within half a particle spacing
// of depth; for two rectangles side by side with other heights and
// densities, and for a light rectangle resting on a heavy one (whose
// particles then carry its weight as well), exactly; sigma_xx and
// sigma_zz are K0 sigma_yy and sigma_xy is 0. In 1D (uniaxial strain,
// gravity along x) sigma_xx = -rho g (L - x) and the lateral stress is K0
// times that. A resumed run of the column does not apply the initial
// stress again: its statistics agree with those of the uninterrupted run.
#include "../checkpoint_tests.h"
#include "../mpm_tests.h"

namespace
{
  const double g = 9.81;

  /// Largest |sigma_yy - expected(x, y, body)| / scale over all ranks'
  /// particles, and the largest deviation from K0 sigma_yy of sigma_xx,
  /// sigma_zz and of sigma_xy from 0 (relative to |sigma_yy|).
  template <typename Expected>
  std::pair<double, double>
  errors(const psmpm::Simulator::Simulator<2> &solver,
         const double                          k0,
         const Expected                       &expected)
  {
    const auto &particles = solver.get_particles();
    double      e = 0, k = 0;
    for (std::size_t p = 0; p < particles.size(); ++p)
      {
        const auto  &s   = particles.stress[p];
        const auto  &x   = particles.position[p];
        const double szz = particles.state_of(p)[0]; // stress_zz
        e                = std::max(e,
                     std::abs(s[1][1] -
                              expected(x[0], x[1], particles.body_id[p])));
        k                = std::max({k,
                                     std::abs(s[0][0] - k0 * s[1][1]) / std::abs(s[1][1]),
                                     std::abs(szz - k0 * s[1][1]) / std::abs(s[1][1]),
                                     std::abs(s[0][1]) / std::abs(s[1][1])});
      }
    return {Utilities::MPI::max(e, MPI_COMM_WORLD),
            Utilities::MPI::max(k, MPI_COMM_WORLD)};
  }

  std::vector<std::string>
  scene(const std::vector<std::string> &bodies)
  {
    std::vector<std::string> o = {"Geometry/Length=2",
                                  "Geometry/Height=2.5",
                                  "Mesh/Blocks x=8",
                                  "Mesh/Blocks y=10",
                                  "Particles/Per block x=4",
                                  "Particles/Per block y=4",
                                  "Particles/Region=",
                                  "Initial conditions/K0=0.5"};
    o.insert(o.end(), bodies.begin(), bodies.end());
    return o;
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out = root_output();
  const double      rho = 2000, dy = 0.25 / 4;

  {
    // Slope: top from (2, 0.5) up to (0.5, 2), flat to x = 0.
    auto solver = make_scene_solver(
      "geostatic_column.prm",
      scene({"Bodies/Number of bodies=1",
             "Bodies/Body 1/Shape=polygon",
             "Bodies/Body 1/Vertices=0, 0, 2, 0, 2, 0.5, 0.5, 2, 0, 2"}));
    const auto top = [](const double x) {
      return x <= 0.5 ? 2. : 2 - (x - 0.5);
    };
    const auto [e, k] =
      errors(*solver, 0.5, [&](const double x, const double y, unsigned) {
        return -rho * g * (top(x) - y);
      });
    out << "slope: sigma_yy error / (rho g dy/2) = " << std::setprecision(2)
        << e / (rho * g * dy / 2) << std::endl;
    PSMPM_CHECK(out, e <= rho * g * dy / 2 * (1 + 1e-9));
    PSMPM_CHECK(out, k < 1e-12);
  }
  {
    // Side by side: 1 m of rho = 2000 beside 1.5 m of rho = 1500.
    auto solver = make_scene_solver("geostatic_column.prm",
                                    scene({"Bodies/Number of bodies=2",
                                           "Bodies/Body 1/Corners=0, 0, 1, 1",
                                           "Bodies/Body 2/Corners=1, 0, 2, 1.5",
                                           "Bodies/Body 2/Density=1500"}));
    const auto [e, k] =
      errors(*solver, 0.5, [&](const double, const double y, const unsigned b) {
        return b == 1 ? -rho * g * (1 - y) : -1500 * g * (1.5 - y);
      });
    out << "side by side" << std::endl;
    PSMPM_CHECK(out, e < 1e-9 * rho * g);
    PSMPM_CHECK(out, k < 1e-12);
  }
  {
    // Stacked: 0.5 m of rho = 1000 on 1 m of rho = 2000.
    auto solver = make_scene_solver("geostatic_column.prm",
                                    scene({"Bodies/Number of bodies=2",
                                           "Bodies/Body 1/Corners=0, 0, 2, 1",
                                           "Bodies/Body 2/Corners=0, 1, 2, 1.5",
                                           "Bodies/Body 2/Density=1000"}));
    const auto [e, k] =
      errors(*solver, 0.5, [&](const double, const double y, const unsigned b) {
        return b == 1 ? -rho * g * (1 - y) - 1000 * g * 0.5 :
                        -1000 * g * (1.5 - y);
      });
    out << "stacked" << std::endl;
    PSMPM_CHECK(out, e < 1e-9 * rho * g);
    PSMPM_CHECK(out, k < 1e-12);
  }
  {
    // 1D: a 25 m bar standing on x = 0, gravity along -x, K0 automatic
    // (nu / (1 - nu) = 0.25 for nu = 0.2).
    auto        solver    = make_scene_solver<1>("vibrating_bar_1d.prm",
                                       {"Initial conditions/Velocity=0",
                                                  "Initial conditions/Stress=geostatic",
                                                  "Body force/Gravity=-9.81",
                                                  "Material/Poisson's ratio=0.2",
                                                  "Reference solution/Type=none"});
    const auto &particles = solver->get_particles();
    double      e = 0, k = 0;
    for (std::size_t p = 0; p < particles.size(); ++p)
      {
        const double s = particles.stress[p][0][0];
        e = std::max(e, std::abs(s + 1 * g * (25 - particles.position[p][0])));
        k = std::max(k, std::abs(particles.state_of(p)[0] - 0.25 * s));
      }
    out << "1D" << std::endl;
    PSMPM_CHECK(out, Utilities::MPI::max(e, MPI_COMM_WORLD) < 1e-12);
    PSMPM_CHECK(out, Utilities::MPI::max(k, MPI_COMM_WORLD) < 1e-12);
  }
  {
    // Resume: 0.01 s, then resumed to 0.02 s, against 0.02 s at once.
    const std::string prm =
      std::string(PSMPM_SOURCE_DIR) + "/prm/geostatic_column.prm";
    std::string screen, message;
    const auto  run =
      [&](const std::string &dir, const std::string &end, const bool resume) {
        std::vector<std::string> args = {prm,
                                         "--set",
                                         "Output directory=" + dir,
                                         "--set",
                                         "Time/End time=" + end,
                                         "--set",
                                         "Time/Time step=2e-4"};
        if (resume)
          args.push_back("--resume");
        return run_app(args, screen, message);
      };
    const int  a     = run("whole", "0.02", false);
    const int  b     = run("parts", "0.01", false);
    const int  c     = run("parts", "0.02", true);
    const auto whole = statistics_rows("whole/statistics.txt");
    const auto parts = statistics_rows("parts/statistics.txt");
    out << "resume: exit codes " << a << ' ' << b << ' ' << c << ", "
        << whole.size() << " rows" << std::endl;
    PSMPM_CHECK(out, whole.size() == 101 && whole == parts);
  }
}
