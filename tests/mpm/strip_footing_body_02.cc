// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// The strip footing as a driven body (prm/strip_footing_body.prm, as
// strip_footing_body_01: Tresca soil, linear basis, lumped mass, MUSL,
// h = B/8, to s = 0.12 B) with Contact/Driven body nodes = geometry: the
// footing holds the soil by friction only at the nodes on or inside its
// moved outline and pushes it along the normal at the other nodes where
// its particles have mass (doc/contact.md, "Driven bodies"). Checked:
// - q_end, the mean load over the last 0.02 B of settlement, above
//   (2 + pi) c_u by less than 12 % (measured +7.2 %; the default
//   particle mass rule gives +18.0 %, so a run that falls back to it
//   fails, and so does a load that falls below Prandtl's); q_end at
//   least 0.9 of the largest window mean q_u (measured 0.945: the load
//   steps by a few % as the bottom passes rows of nodes but does not
//   fall);
// - the floor carries the footing's load within 3 % (s > 0.02 B,
//   measured 0.3 %), the footing's work equals dissipated plus strain
//   plus kinetic energy within 5 % (measured: the soil's energy exceeds
//   the work by 3.0 %, against 1.2 % with particle mass on this mesh and
//   5-8.5 % with particle mass for B = 0.5 m, doc/geomechanics.md), the
//   kinetic energy stays below 1 % of the work (measured 0.4 %);
// - the footing's particles still move rigidly with the integral of the
//   velocity (mean height within 1e-6 m, mean x unchanged).
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
                                  {"Time/End time=1.25",
                                                 "Output/Interval=0",
                                                 "Contact/Driven body nodes=geometry"});
  const std::string dir     = "run";
  std::filesystem::create_directories(dir);
  const auto status = solver->run(dir);
  out << "status: " << psmpm::Simulator::status_name(status) << std::endl;
  PSMPM_CHECK(out, status == psmpm::Simulator::Status::completed);

  const StatisticsTable statistics(dir);
  const FootingRun
    run(statistics, "contact_force_1_2_y", "driven_work", B, c_u, v0, ramp);
  const auto y = statistics.column("body2_y");
  const auto x = statistics.column("body2_x");
  PSMPM_CHECK(out, run.t.size() > 100 && run.footing.size() == run.t.size());
  double       at      = 0;
  const double q_u     = run.largest_window_mean(at);
  const double q_end   = run.window_mean(run.s.back() - 0.02, run.s.back() + 1);
  const double sinking = y.front() - y.back() - run.s.back() * B;
  std::cout << "q_end / c_u = " << q_end << " (Prandtl " << prandtl
            << ", error " << q_end / prandtl - 1
            << "), q_end / q_u = " << q_end / q_u
            << ", floor/footing - 1 = " << run.balance
            << ", max kinetic / work = " << run.kinetic_max / run.work.back()
            << ", energy closure = " << run.closure
            << ", sinking - settlement = " << sinking << std::endl;
  PSMPM_CHECK(out, q_end > prandtl && q_end < 1.12 * prandtl);
  PSMPM_CHECK(out, q_end >= 0.9 * q_u);
  PSMPM_CHECK(out, std::abs(run.balance) < 0.03);
  PSMPM_CHECK(out, run.kinetic_max < 0.01 * run.work.back());
  PSMPM_CHECK(out, std::abs(run.closure) < 0.05);
  PSMPM_CHECK(out, std::abs(sinking) < 1e-6);
  PSMPM_CHECK(out, std::abs(x.back() - x.front()) < 1e-12);
}
