// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Transfer/XPIC order (apic with the control-point affine matrix,
// Powell-Sabin, lumped mass; doc/transfers.md, "Free bodies without
// numerical damping"):
// (a) prm/free_vibrating_bar.prm, the free-free bar in its first axial
//     mode, three periods with the automatic time step: XPIC order 3 keeps
//     the total energy within 1 %, where APIC (order 1) loses more than
//     1 % and at least twice as much;
// (b) prm/rotating_block.prm, the free block for a quarter turn: XPIC
//     order 3 keeps the angular momentum (with the affine part) to 1e-3
//     and the mean rotation angle to 1 %;
// (c) an affine velocity field on a filled mesh is a fixed point of the
//     XPIC correction: after one step every particle's velocity is
//     A x_p + b at its old position and its affine matrix is A, with
//     lumped, partially lumped and consistent mass;
// (d) an XPIC order above 1 without the control-point affine matrix (P1's
//     automatic rotational one) is refused at setup, naming the entry.
#include <psmpm/postprocess/rotation_statistics.h>

#include "../mpm_tests.h"

#include <map>

namespace
{
  using namespace psmpm;

  void
  run_to(Simulator::Simulator<2> &solver, const double end)
  {
    while (solver.get_time() < end * (1 - 1e-12) &&
           solver.get_failure() == Simulator::Failure::none)
      solver.do_time_step(
        std::min(solver.get_time_step(), end - solver.get_time()));
  }

  double
  bar_energy_ratio(const unsigned int order)
  {
    auto solver =
      make_scene_solver("free_vibrating_bar.prm",
                        {"Mass matrix/Type=lumped",
                         "Transfer/Scheme=apic",
                         "Transfer/XPIC order=" + std::to_string(order)});
    const double e0 = solver->compute_energies().total();
    run_to(*solver, 15);
    if (solver->get_failure() != Simulator::Failure::none)
      return 0;
    return solver->compute_energies().total() / e0;
  }

  void
  bar(std::ofstream &out)
  {
    const double apic = bar_energy_ratio(1);
    const double xpic = bar_energy_ratio(3);
    out << "free bar, 3 periods: energy end/start apic " << std::fixed
        << std::setprecision(3) << apic << ", XPIC order 3 " << xpic
        << std::defaultfloat << std::endl;
    PSMPM_CHECK(out, std::abs(xpic - 1) < 0.01);
    PSMPM_CHECK(out, 1 - apic > 0.01);
    PSMPM_CHECK(out, std::abs(xpic - 1) < 0.5 * std::abs(apic - 1));
  }

  void
  rotation(std::ofstream &out)
  {
    auto solver = make_scene_solver("rotating_block.prm",
                                    {"Basis/Type=powell-sabin",
                                     "Mass matrix/Type=lumped",
                                     "Transfer/Scheme=apic",
                                     "Transfer/XPIC order=3"});
    Postprocess::RotationStatistics<2> statistics;
    const double h0  = statistics.compute(solver->get_state()).angular_momentum;
    const double end = numbers::PI / 2;
    run_to(*solver, end);
    const auto   now   = statistics.compute(solver->get_state());
    const double ratio = now.angular_momentum / h0;
    const double angle = now.rotation_angle / end;
    out << "rotating block, XPIC order 3: failure "
        << static_cast<int>(solver->get_failure())
        << ", L(T)/L(0) = " << std::fixed << std::setprecision(4) << ratio
        << ", angle/(pi/2) = " << std::setprecision(3) << angle
        << std::defaultfloat << std::endl;
    PSMPM_CHECK(out, std::abs(ratio - 1) < 1e-3);
    PSMPM_CHECK(out, std::abs(angle - 1) < 0.01);
  }

  void
  affine(std::ofstream &out, const std::string &mass)
  {
    // A = [[0.3, -0.7], [0.5, 0.1]], b = (0.2, -0.4); 36 particles per
    // block so that the consistent Powell-Sabin rows are regular.
    auto solver = make_scene_solver(
      "rotating_block.prm",
      {"Basis/Type=powell-sabin",
       "Mass matrix/Type=" + mass,
       "Transfer/Scheme=apic",
       "Transfer/XPIC order=3",
       "Particles/Per block x=6",
       "Particles/Per block y=6",
       "Mesh/Blocks x=4",
       "Mesh/Blocks y=4",
       "Particles/Region=",
       "Initial conditions/Velocity=0.3*x - 0.7*y + 0.2; 0.5*x + 0.1*y - 0.4"});
    const Tensor<2, 2> A({{0.3, -0.7}, {0.5, 0.1}});
    const Tensor<1, 2> b({0.2, -0.4});
    const auto [v_error, c_error] = affine_step_errors(*solver, A, b, A, 1e-3);
    out << mass << ", affine field, XPIC order 3:" << std::endl;
    PSMPM_CHECK(out, v_error < 1e-10);
    PSMPM_CHECK(out, c_error < 1e-8);
  }

  void
  refused(std::ofstream &out)
  {
    std::string message;
    try
      {
        make_scene_solver("rotating_block.prm",
                          {"Transfer/Scheme=apic", "Transfer/XPIC order=2"});
      }
    catch (const std::exception &e)
      {
        message = e.what();
      }
    out << "linear, XPIC order 2: refused" << std::endl;
    PSMPM_CHECK(out,
                message.find("Transfer/XPIC order = 2") != std::string::npos);
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");
  bar(out);
  rotation(out);
  for (const char *mass : {"lumped", "partially lumped", "consistent"})
    affine(out, mass);
  refused(out);
}
