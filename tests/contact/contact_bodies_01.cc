// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Multi-velocity contact in runs of other shapes and more bodies
// (linear basis, frictionless):
// (a) prm/contact_ring_impact.prm to t = 0.3 with Courant number 0.1: the
//     ring falls on the block, its centre's vertical velocity (the
//     change of body1_y) reverses from below -1 m/s to above 0.5 m/s and
//     the centre ends more than 5 cm above its lowest point: it
//     rebounds; the horizontal momentum stays zero to round-off (the
//     floor holds y only, gravity is vertical, the scene is symmetric);
// (b) three disks on a line (prm/contact_two_disks.prm with three
//     bodies): the outer two approach the middle one at rest at
//     0.1 m/s. Pairs 1-2 and 2-3 touch (normal work < 0) with mirror
//     impulses (within 2 %), pair 1-3 never (every column zero), the
//     outer disks come back (velocity reversed), the middle one stays
//     at x = 0.5 within 1 mm, and the momentum stays zero to round-off.
#include "../contact_tests.h"

#include <cmath>

namespace
{
  double
  largest_magnitude(const std::vector<double> &v)
  {
    double m = 0;
    for (const double x : v)
      m = std::max(m, std::abs(x));
    return m;
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");

  // (a)
  {
    const auto s = run_scene(out,
                             "contact_ring_impact.prm",
                             "ring",
                             {"Time/End time=0.3",
                              "Time/Courant number=0.1",
                              "Output/Interval=0"});
    const auto t = s.column("time"), y = s.column("body1_y");
    double     v_min = 0, v_max = 0, y_min = y.front();
    for (std::size_t i = 1; i < t.size(); ++i)
      {
        const double v = (y[i] - y[i - 1]) / (t[i] - t[i - 1]);
        v_min          = std::min(v_min, v);
        y_min          = std::min(y_min, y[i]);
        if (v_min < -1)
          v_max = std::max(v_max, v);
      }
    const auto   E     = s.column("total_energy");
    const double p     = largest_magnitude(s.column("momentum_x"));
    const double scale = largest_magnitude(s.column("momentum_y"));
    double       e_max = 0;
    for (const double e : E)
      e_max = std::max(e_max, e / E.front());
    std::cout << "ring: v " << v_min << " -> " << v_max << ", y lowest "
              << y_min << ", end " << y.back() << ", |p_x| " << p
              << ", E_max/E0 " << e_max << ", E_end/E0 " << E.back() / E.front()
              << std::endl;
    PSMPM_CHECK(out, v_min < -1 && v_max > 0.5);
    PSMPM_CHECK(out, y.back() > y_min + 0.05);
    PSMPM_CHECK(out, p < 1e-12 * scale);
  }

  // (b)
  {
    const auto   s  = run_scene(out,
                             "contact_two_disks.prm",
                             "three",
                             {"Bodies/Number of bodies=3",
                                 "Bodies/Body 1/Center=0.2, 0.5",
                                 "Bodies/Body 1/Radius=0.12",
                                 "Bodies/Body 1/Initial velocity=0.1; 0",
                                 "Bodies/Body 2/Center=0.5, 0.5",
                                 "Bodies/Body 2/Radius=0.12",
                                 "Bodies/Body 2/Initial velocity=0; 0",
                                 "Bodies/Body 3/Shape=disk",
                                 "Bodies/Body 3/Center=0.8, 0.5",
                                 "Bodies/Body 3/Radius=0.12",
                                 "Bodies/Body 3/Initial velocity=-0.1; 0",
                                 "Time/End time=1.5"});
    const auto   dt = s.column("dt");
    const double one_disk =
      s.column("mass").front() / 3 * 0.1; // an outer disk's |p|
    const double p = std::max(largest_magnitude(s.column("momentum_x")),
                              largest_magnitude(s.column("momentum_y")));
    double       impulse[2] = {0, 0};
    const char  *pairs[2]   = {"1_2", "2_3"};
    for (unsigned int q = 0; q < 2; ++q)
      {
        const auto f =
          s.column(std::string("contact_force_") + pairs[q] + "_x");
        for (std::size_t i = 0; i < f.size(); ++i)
          impulse[q] += f[i] * dt[i];
      }
    double pair_1_3 = 0;
    for (const std::string c : {"contact_force_1_3_x",
                                "contact_force_1_3_y",
                                "normal_force_1_3",
                                "friction_force_1_3",
                                "friction_work_1_3",
                                "normal_work_1_3",
                                "slip_work_1_3"})
      pair_1_3 = std::max(pair_1_3, largest_magnitude(s.column(c)));
    const auto x1 = s.column("body1_x"), x2 = s.column("body2_x"),
               x3       = s.column("body3_x");
    const std::size_t n = x1.size() - 1;
    std::cout << "three disks: impulses " << impulse[0] << ", " << impulse[1]
              << ", normal work " << s.column("normal_work_1_2").back() << ", "
              << s.column("normal_work_2_3").back() << ", |p|/one disk's "
              << p / one_disk << ", x " << x1.back() << ", " << x2.back()
              << ", " << x3.back() << ", E_end/E0 "
              << s.column("total_energy").back() /
                   s.column("total_energy").front()
              << std::endl;
    PSMPM_CHECK(out,
                s.column("normal_work_1_2").back() < 0 &&
                  s.column("normal_work_2_3").back() < 0);
    PSMPM_CHECK(out,
                impulse[0] < 0 && impulse[1] < 0 &&
                  std::abs(impulse[0] / impulse[1] - 1) < 0.02);
    PSMPM_CHECK(out, pair_1_3 == 0);
    PSMPM_CHECK(out, x1[n] < x1[n - 1] && x3[n] > x3[n - 1]);
    PSMPM_CHECK(out, std::abs(x2.back() - 0.5) < 1e-3);
    PSMPM_CHECK(out, p < 1e-12 * one_disk);
  }
}
