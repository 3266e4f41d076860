// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Multi-velocity contact with the apic transfer, Powell-Sabin's default
// with contact (Mass matrix/Type and Transfer/Scheme automatic: lumped and
// apic, which the run's log names; doc/contact.md "With the defaults"):
// (a) the rolling disk (prm/contact_rolling_disk.prm, two cells per
//     radius, 0.1 s): the disk turns, spin R more than half its speed
//     (with musl it slid without turning: spin R 0.02 of the speed), and
//     its centre accelerates at more than 0.8 of (2/3) g sin 30 = 3.27
//     m/s^2 (a quadratic fit of body1_x over t >= 0.02);
// (b) two elastic disks in an oblique impact with mu = 0.3
//     (prm/contact_two_disks.prm, radius 0.15, centres 0.2 apart across
//     their paths, to t = 1.2): the momentum stays zero to round-off, the
//     angular momentum (apic's, with the affine part) within 1e-3 of its
//     start (apic without contact: 9e-4), and friction acts (friction
//     work < 0);
// (c) the rolling disk stopped at 0.05 s and resumed repeats the run to
//     0.1 s bit for bit (every statistics column but the wall time).
#include "../checkpoint_tests.h"
#include "../contact_tests.h"
#include "../vtu_tests.h"

#include <cmath>
#include <filesystem>

namespace
{
  /// Body 1's speed along x and spin rate (its particles' angular
  /// momentum about their mass centre over their moment of inertia) in the
  /// last particle output of @p directory.
  std::pair<double, double>
  disk_motion(const std::string &directory)
  {
    std::string last;
    for (const auto &f : std::filesystem::directory_iterator(directory))
      {
        const std::string name = f.path().filename().string();
        if (name.rfind("particles-", 0) == 0 &&
            name.find(".000.vtu") != std::string::npos && name > last)
          last = name;
      }
    const std::string        vtu = read_file(directory + "/" + last);
    const std::vector<float> x   = read_floats(vtu, "<Points>"),
                             v   = read_floats(vtu, "Name=\"velocity\""),
                             m   = read_floats(vtu, "Name=\"mass\""),
                             id  = read_floats(vtu, "Name=\"body_id\"");
    double M = 0, c[2] = {0, 0}, u[2] = {0, 0};
    for (std::size_t p = 0; p < m.size(); ++p)
      if (id[p] == 1)
        {
          M += m[p];
          for (unsigned int d = 0; d < 2; ++d)
            {
              c[d] += m[p] * x[3 * p + d];
              u[d] += m[p] * v[3 * p + d];
            }
        }
    for (unsigned int d = 0; d < 2; ++d)
      c[d] /= M, u[d] /= M;
    double L = 0, I = 0;
    for (std::size_t p = 0; p < m.size(); ++p)
      if (id[p] == 1)
        {
          const double rx = x[3 * p] - c[0], ry = x[3 * p + 1] - c[1];
          L += m[p] * (rx * (v[3 * p + 1] - u[1]) - ry * (v[3 * p] - u[0]));
          I += m[p] * (rx * rx + ry * ry);
        }
    return {u[0], L / I};
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");
  std::string       screen;
  const auto        run = [&](const std::string       &scene,
                       const std::string       &directory,
                       std::vector<std::string> settings) {
    settings.insert(settings.begin(), "Basis/Type=powell-sabin");
    return run_prm_scene(out, scene, directory, settings, screen);
  };
  for (const auto &d : {"rolling", "disks", "split"})
    std::filesystem::remove_all(d);

  // (a)
  PSMPM_CHECK(out,
              run("contact_rolling_disk.prm",
                  "rolling",
                  {"Time/End time=0.1", "Output/Interval=0"}) == 0);
  PSMPM_CHECK(out, screen.find("Transfer/Scheme = apic") != std::string::npos);
  {
    const StatisticsTable s("rolling");
    const double          a =
      fitted_acceleration(s.column("time"), s.column("body1_x"), 0.02);
    const double closed      = 2. / 3 * 9.81 * 0.5;
    const auto [speed, spin] = disk_motion("rolling");
    const double spin_R      = -spin * 0.1;
    std::cout << "rolling: a " << a << " (closed form " << closed << "), speed "
              << speed << ", spin R " << spin_R << std::endl;
    PSMPM_CHECK(out, a > 0.8 * closed && a < 1.02 * closed);
    PSMPM_CHECK(out, spin_R > 0.5 * speed && spin_R < 1.02 * speed);
  }

  // (b)
  PSMPM_CHECK(out,
              run("contact_two_disks.prm",
                  "disks",
                  {"Contact/Friction coefficient=0.3",
                   "Bodies/Body 1/Center=0.25, 0.4",
                   "Bodies/Body 2/Center=0.75, 0.6",
                   "Bodies/Body 1/Radius=0.15",
                   "Bodies/Body 2/Radius=0.15",
                   "Bodies/Body 1/Initial velocity=0.2; 0",
                   "Bodies/Body 2/Initial velocity=-0.2; 0",
                   "Time/End time=1.2"}) == 0);
  {
    const StatisticsTable s("disks");
    const auto px = s.column("momentum_x"), py = s.column("momentum_y"),
               L = s.column("angular_momentum");
    // One disk's |p|: 1000 pi 0.15^2 0.2.
    const double scale = 1000 * M_PI * 0.0225 * 0.2;
    double       p_max = 0, dL = 0;
    for (std::size_t i = 0; i < L.size(); ++i)
      {
        p_max = std::max(p_max, std::hypot(px[i], py[i]));
        dL    = std::max(dL, std::abs(L[i] - L[0]));
      }
    const double work = s.column("friction_work_1_2").back();
    std::cout << "disks: |p|max/scale " << p_max / scale
              << ", max |L - L0| / |L0| " << dL / std::abs(L[0])
              << ", friction work " << work << std::endl;
    PSMPM_CHECK(out, p_max < 1e-12 * scale);
    PSMPM_CHECK(out, dL < 1e-3 * std::abs(L[0]));
    PSMPM_CHECK(out, work < 0);
  }

  // (c)
  PSMPM_CHECK(out,
              run("contact_rolling_disk.prm",
                  "split",
                  {"Time/End time=0.05", "Output/Interval=0"}) == 0);
  PSMPM_CHECK(out,
              run("contact_rolling_disk.prm",
                  "split",
                  {"Time/End time=0.1", "Output/Interval=0", "--resume"}) == 0);
  const auto whole = statistics_rows("rolling/statistics.txt"),
             split = statistics_rows("split/statistics.txt");
  out << "rows " << whole.size() << std::endl;
  PSMPM_CHECK(out, whole.size() > 100 && whole == split);
}
