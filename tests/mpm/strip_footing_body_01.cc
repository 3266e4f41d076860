// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// The strip footing as a driven body, prm/strip_footing_body.prm: the
// rigid rough footing (B = 1 m, half model) is Body 2, moved down at
// 0.1 m/s (ramped over 0.1 s) in no-slip multi-velocity contact with the
// weightless Tresca soil (c_u = 10 kPa, E = 500 c_u, nu = 0.3), linear
// basis, lumped mass, MUSL, h = B/8, to a settlement of 0.12 B (beyond
// 0.6 h = 0.075 B, where the footing as a mesh boundary loses the load).
// q = -2 contact_force_1_2_y / B. Checked:
// - the plateau: the mean load over the last 0.02 B of settlement, q_end,
//   above (2 + pi) c_u by less than 25 % (measured +18.0 %: the contact
//   through the cells the footing covers acts on a width about one cell
//   wider; +40.6 %, +18.0 %, +10.6 %, +2.7 % on h = B/4, B/8, B/16, B/32;
//   doc/geomechanics.md, "Strip footing"), so that a fall of the load, or
//   a change of the contact or of the driven motion, fails;
//   and q_end at least 0.95 of the largest window mean q_u (measured
//   0.987): the load does not fall as the footing sinks;
// - the floor carries the footing's load within 3 % (s > 0.02 B, measured
//   0.1 %), the footing's work (driven_work) equals dissipated plus strain
//   plus kinetic energy within 3 % (measured 1.2 %), the kinetic energy
//   stays below 1 % of the work (measured 0.4 %);
// - the footing's particles moved rigidly with the integral of the
//   velocity: the mean height of Body 2 fell by the settlement within
//   1e-6 m (measured 1e-8 m, the midpoint rule in the step of the ramp's
//   kink), its mean x stayed.
#include "../mpm_tests.h"

#include <filesystem>

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");
  const double      B = 1, c_u = 1e4, v0 = 0.1, ramp = 0.1;
  const double      prandtl = 2 + numbers::PI;
  auto              solver = make_scene_solver("strip_footing_body.prm",
                                  {"Time/End time=1.25", "Output/Interval=0"});
  const std::string dir    = "run";
  std::filesystem::create_directories(dir);
  const auto status = solver->run(dir);
  out << "status: " << psmpm::Simulator::status_name(status) << std::endl;
  PSMPM_CHECK(out, status == psmpm::Simulator::Status::completed);

  const StatisticsTable statistics(dir);
  const auto            t          = statistics.column("time");
  const auto            footing    = statistics.column("contact_force_1_2_y");
  const auto            floor      = statistics.column("reaction_bottom_y");
  const auto            kinetic    = statistics.column("kinetic_energy");
  const auto            work       = statistics.column("driven_work");
  const auto            strain     = statistics.column("strain_energy");
  const auto            dissipated = statistics.column("dissipated_energy");
  const auto            y          = statistics.column("body2_y");
  const auto            x          = statistics.column("body2_x");
  PSMPM_CHECK(out, t.size() > 100 && footing.size() == t.size());

  // Settlement over B and load over c_u per row.
  std::vector<double> s(t.size()), q(t.size());
  for (std::size_t i = 0; i < t.size(); ++i)
    {
      s[i] =
        (t[i] < ramp ? v0 * t[i] * t[i] / (2 * ramp) : v0 * (t[i] - ramp / 2)) /
        B;
      q[i] = -2 * footing[i] / B / c_u;
    }
  const auto window_mean = [&](const double lo, const double hi) {
    double sum = 0;
    int    n   = 0;
    for (std::size_t i = 0; i < s.size(); ++i)
      if (s[i] >= lo && s[i] < hi)
        sum += q[i], ++n;
    return n > 0 ? sum / n : 0.;
  };
  double q_u = 0;
  for (double lo = 0; lo + 0.01 <= s.back() + 1e-12; lo += 0.0025)
    q_u = std::max(q_u, window_mean(lo, lo + 0.01));
  const double q_end = window_mean(s.back() - 0.02, s.back() + 1);

  double footing_sum = 0, floor_sum = 0, kinetic_max = 0;
  for (std::size_t i = 0; i < s.size(); ++i)
    {
      if (s[i] > 0.02)
        footing_sum += footing[i], floor_sum += floor[i];
      kinetic_max = std::max(kinetic_max, kinetic[i]);
    }
  const double balance = -floor_sum / footing_sum - 1;
  const double closure =
    (work.back() - dissipated.back() - strain.back() - kinetic.back()) /
    work.back();
  const double sinking = y.front() - y.back() - s.back() * B;
  std::cout << "q_end / c_u = " << q_end << " (Prandtl " << prandtl
            << ", error " << q_end / prandtl - 1
            << "), q_end / q_u = " << q_end / q_u
            << ", floor/footing - 1 = " << balance
            << ", max kinetic / work = " << kinetic_max / work.back()
            << ", energy closure = " << closure
            << ", sinking - settlement = " << sinking << std::endl;
  PSMPM_CHECK(out, q_end > prandtl && q_end < 1.25 * prandtl);
  PSMPM_CHECK(out, q_end >= 0.95 * q_u);
  PSMPM_CHECK(out, std::abs(balance) < 0.03);
  PSMPM_CHECK(out, kinetic_max < 0.01 * work.back());
  PSMPM_CHECK(out, std::abs(closure) < 0.03);
  PSMPM_CHECK(out, std::abs(sinking) < 1e-6);
  PSMPM_CHECK(out, std::abs(x.back() - x.front()) < 1e-12);
}
