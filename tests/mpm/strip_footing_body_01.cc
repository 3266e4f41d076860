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
#include "../footing_tests.h"

#include <filesystem>

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");
  const double      B = 1, c_u = 1e4, v0 = 0.1, ramp = 0.1;
  const double      prandtl = 2 + numbers::PI;
  auto              solver  = make_scene_solver("strip_footing_body.prm",
                                  {"Time/End time=1.25", "Output/Interval=0"});
  const std::string dir     = "run";
  std::filesystem::create_directories(dir);
  const auto status = solver->run(dir);
  out << "status: " << psmpm::Simulator::status_name(status) << std::endl;
  PSMPM_CHECK(out, status == psmpm::Simulator::Status::completed);

  const StatisticsTable statistics(dir);
  const FootingRun
    run(statistics, "contact_force_1_2_y", "driven_work", B, c_u, v0, ramp);
  const auto  y = statistics.column("body2_y");
  const auto  x = statistics.column("body2_x");
  const auto &t = run.t, &footing = run.footing;
  PSMPM_CHECK(out, t.size() > 100 && footing.size() == t.size());
  double       at      = 0;
  const double q_u     = run.largest_window_mean(at);
  const double q_end   = run.window_mean(run.s.back() - 0.02, run.s.back() + 1);
  const double balance = run.balance, closure = run.closure;
  const double kinetic_max = run.kinetic_max;
  const auto  &work        = run.work;
  const auto  &s           = run.s;
  const double sinking     = y.front() - y.back() - s.back() * B;
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
