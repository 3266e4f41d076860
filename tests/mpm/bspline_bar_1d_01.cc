// ---------------------------------------------------------------------
// psmpm: BSMPM (Basis/Type = bspline) against MPM on the small-deformation
// vibrating bar of Wobbes et al. 2019, section 4.5 (prm/chapter_bar_1d.prm:
// Table 4.1, 12 particles per element, dt = 1e-7 to T = 1.9e-6, MUSL) on
// 5, 10, 20, 40 elements. Asserted:
// * MPM (linear, lumped): displacement RMS error rate 2; velocity rate
//   about 2 with dt = 1e-9 (at the chapter's dt = 1e-7 the velocity error
//   of every method sits on the floor of the explicit step, ~6.5e-10:
//   the stress lags one step behind);
// * BSMPM with consistent mass: displacement rate 3, stress rate 2, both
//   below MPM's on every mesh;
// * BSMPM with lumped mass (the chapter's mapping) still converges in
//   displacement (rate above 1.2; the open-knot end functions limit it);
// * cubic BSMPM (Basis/Degree = 3) with consistent mass: displacement
//   rate 4 and stress rate 3 (measured 4.2, 4.0, 4.0 and 3.1, 3.0, 2.9:
//   asserted at least 0.25 below), both below quadratic BSMPM's on every
//   mesh;
// * linear B-splines (Basis/Degree = 1) with lumped mass are MPM: the
//   same errors to round-off;
// * a free bar conserves mass and momentum to 1e-12 with both spaces and
//   both verified mass matrices, and with cubic B-splines and consistent
//   mass.
// ---------------------------------------------------------------------
#include <deal.II/base/parameter_handler.h>

#include <psmpm/app/application.h>
#include <psmpm/simulator/simulator.h>

#include "../mpm_tests.h"

#include <algorithm>

namespace
{
  void
  read_scene(ParameterHandler  &prm,
             const std::string &basis,
             const std::string &mass,
             const unsigned int elements,
             const unsigned int degree = 2)
  {
    psmpm::App::declare_parameters(prm);
    prm.parse_input(std::string(PSMPM_SOURCE_DIR) + "/prm/chapter_bar_1d.prm");
    psmpm::App::apply_override(prm, "Basis/Type=" + basis);
    psmpm::App::apply_override(prm, "Mass matrix/Type=" + mass);
    psmpm::App::apply_override(prm,
                               "Mesh/Blocks x=" + std::to_string(elements));
    psmpm::App::apply_override(prm, "Basis/Degree=" + std::to_string(degree));
  }

  psmpm::Postprocess::Errors
  errors(const std::string &basis,
         const std::string &mass,
         const unsigned int elements,
         const double       dt,
         const unsigned int degree = 2)
  {
    ParameterHandler prm;
    read_scene(prm, basis, mass, elements, degree);
    psmpm::Simulator::Simulator<1> solver(MPI_COMM_WORLD);
    solver.quiet = true;
    solver.parse_parameters(prm);
    solver.setup();
    const unsigned int steps = std::lround(1.9e-6 / dt);
    for (unsigned int step = 0; step < steps; ++step)
      solver.do_time_step(dt);
    return solver.compute_errors();
  }

  /// Largest relative change of mass and momentum over 19 steps of a bar
  /// whose ends are free (the fixed ends of the scene take momentum).
  std::pair<double, double>
  conservation(const std::string &basis,
               const std::string &mass,
               const unsigned int degree = 2)
  {
    ParameterHandler prm;
    read_scene(prm, basis, mass, 10, degree);
    psmpm::App::apply_override(prm, "Boundary conditions/Fixed x=");
    psmpm::Simulator::Simulator<1> solver(MPI_COMM_WORLD);
    solver.quiet = true;
    solver.parse_parameters(prm);
    solver.setup();
    const auto e0 = solver.compute_energies();
    double     dm = 0, dp = 0;
    for (unsigned int step = 0; step < 19; ++step)
      {
        solver.do_time_step(1e-7);
        const auto e = solver.compute_energies();
        dm           = std::max(dm, std::abs(e.mass - e0.mass) / e0.mass);
        dp           = std::max(dp,
                      std::abs(e.momentum[0] - e0.momentum[0]) /
                        std::abs(e0.momentum[0]));
      }
    return {dm, dp};
  }

} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");
  const unsigned int               elements[] = {5, 10, 20, 40};

  double mpm_u[4], mpm_s[4], mpm_v[4], bs_u[4], bs_s[4], lumped_u[4],
    cubic_u[4], cubic_s[4];
  for (unsigned int i = 0; i < 4; ++i)
    {
      const auto mpm = errors("linear", "lumped", elements[i], 1e-7);
      mpm_u[i]       = mpm.displacement;
      mpm_s[i]       = mpm.stress;
      mpm_v[i]       = errors("linear", "lumped", elements[i], 1e-9).velocity;
      const auto bs  = errors("bspline", "consistent", elements[i], 1e-7);
      bs_u[i]        = bs.displacement;
      bs_s[i]        = bs.stress;
      lumped_u[i] = errors("bspline", "lumped", elements[i], 1e-7).displacement;
      const auto cubic = errors("bspline", "consistent", elements[i], 1e-7, 3);
      cubic_u[i]       = cubic.displacement;
      cubic_s[i]       = cubic.stress;
    }
  for (const double r : rates(out, "MPM displacement", mpm_u))
    PSMPM_CHECK(out, std::abs(r - 2) < 0.2);
  for (const double r : rates(out, "MPM velocity (dt = 1e-9)", mpm_v))
    PSMPM_CHECK(out, r > 1.5 && r < 2.5);
  for (const double r : rates(out, "BSMPM consistent displacement", bs_u))
    PSMPM_CHECK(out, std::abs(r - 3) < 0.25);
  for (const double r : rates(out, "BSMPM consistent stress", bs_s))
    PSMPM_CHECK(out, std::abs(r - 2) < 0.2);
  for (const double r : rates(out, "BSMPM lumped displacement", lumped_u))
    PSMPM_CHECK(out, r > 1.2);
  bool better = true;
  for (unsigned int i = 0; i < 4; ++i)
    better = better && bs_u[i] < mpm_u[i] && bs_s[i] < mpm_s[i];
  PSMPM_CHECK(out, better);
  for (const double r : rates(out, "cubic BSMPM displacement", cubic_u))
    PSMPM_CHECK(out, r > 3.75);
  for (const double r : rates(out, "cubic BSMPM stress", cubic_s))
    PSMPM_CHECK(out, r > 2.6);
  bool cubic_better = true;
  for (unsigned int i = 0; i < 4; ++i)
    cubic_better = cubic_better && cubic_u[i] < bs_u[i] && cubic_s[i] < bs_s[i];
  PSMPM_CHECK(out, cubic_better);

  // Linear B-splines are the hat functions: MPM, evaluated differently.
  const auto   mpm    = errors("linear", "lumped", 10, 1e-7);
  const auto   linear = errors("bspline", "lumped", 10, 1e-7, 1);
  const double same =
    std::max({std::abs(linear.displacement / mpm.displacement - 1),
              std::abs(linear.velocity / mpm.velocity - 1),
              std::abs(linear.stress / mpm.stress - 1)});
  out << "linear B-splines, lumped mass: MPM's errors "
      << (same < 1e-12 ? "to 1e-12" : "NOT reproduced") << std::endl;
  PSMPM_CHECK(out, same < 1e-12);

  for (const std::string basis : {"linear", "bspline"})
    for (const std::string mass : {"lumped", "consistent"})
      {
        const auto [dm, dp] = conservation(basis, mass);
        out << basis << ", " << mass << " mass, free bar: mass and momentum "
            << (dm < 1e-12 && dp < 1e-12 ? "conserved to 1e-12" :
                                           "NOT conserved")
            << std::endl;
        PSMPM_CHECK(out, dm < 1e-12 && dp < 1e-12);
      }
  const auto [dm, dp] = conservation("bspline", "consistent", 3);
  out << "cubic bspline, consistent mass, free bar: mass and momentum "
      << (dm < 1e-12 && dp < 1e-12 ? "conserved to 1e-12" : "NOT conserved")
      << std::endl;
  PSMPM_CHECK(out, dm < 1e-12 && dp < 1e-12);
}
