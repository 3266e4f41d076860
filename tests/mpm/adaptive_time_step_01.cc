// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// The automatic time step (Time/Time step = 0) is recomputed before every
// step from the current state, dt = C f h_min / max_p (c_p + |v_p|):
// (a) a block at rest: dt = C f h_min / c_p with the p-wave speed;
// (b) the same block moving at the p-wave speed: half of (a);
// (c) a neo-Hookean block squeezed from all sides stiffens (its wave
//     speed bound grows as J falls): at J = 0.7 the bound is 3 % above
//     c_p, and the step equals the formula with the material's largest
//     current wave speed and particle speed;
// (d) a fixed Time step is never changed.
#include "../mpm_tests.h"

namespace
{
  using namespace psmpm;

  /// The free neo-Hookean block of prm/rotating_block.prm, lumped P1.
  std::unique_ptr<Simulator::Simulator<2>>
  make_solver(const std::vector<std::string> &overrides)
  {
    ParameterHandler prm;
    App::declare_parameters(prm);
    prm.parse_input(std::string(PSMPM_SOURCE_DIR) + "/prm/rotating_block.prm");
    App::apply_override(prm, "Time/Courant number=0.5");
    for (const auto &o : overrides)
      App::apply_override(prm, o);
    auto solver   = std::make_unique<Simulator::Simulator<2>>(MPI_COMM_WORLD);
    solver->quiet = true;
    solver->parse_parameters(prm);
    solver->setup();
    return solver;
  }

  /// C f h_min / c for the solver's state.
  double
  formula(const Simulator::Simulator<2> &solver, const double c)
  {
    const auto &state = solver.get_state();
    return 0.5 * state.space->stability_factor(!state.grid->uses_matrix()) *
           state.locator.minimum_height() / c;
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");

  auto         rest = make_solver({"Initial conditions/Velocity=0; 0"});
  const double c_p  = rest->get_state().materials.primary().p_wave_speed();
  const double dt0  = rest->next_time_step();
  out << "(a) at rest" << std::endl;
  PSMPM_CHECK(out, std::abs(dt0 / formula(*rest, c_p) - 1) < 1e-12);

  auto moving =
    make_solver({"Initial conditions/Velocity=" + std::to_string(c_p) + "; 0"});
  out << "(b) moving at c_p" << std::endl;
  PSMPM_CHECK(out, std::abs(moving->next_time_step() / dt0 - 0.5) < 1e-6);

  // A soft block (E = 1e4 Pa, c_p = 3.7 m/s) squeezed by v = -4 (x - c)
  // until its most compressed particle reaches J = 0.7.
  auto squeezed =
    make_solver({"Material/Young's modulus=1e4",
                 "Initial conditions/Velocity=-4*(x - 0.5); -4*(y - 0.5)"});
  const auto &s     = squeezed->get_state();
  const auto &p     = s.particles;
  auto        J_min = [&]() {
    double J = 1;
    for (std::size_t i = 0; i < p.size(); ++i)
      {
        const double *F = &p.state[i * s.materials.primary().n_state()];
        J               = std::min(J, F[0] * F[3] - F[1] * F[2]);
      }
    return J;
  };
  for (unsigned int n = 0; n < 2000 && J_min() > 0.7 &&
                           squeezed->get_failure() == Simulator::Failure::none;
       ++n)
    squeezed->do_time_step(squeezed->next_time_step());
  const double last = squeezed->next_time_step();
  double       vmax = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    vmax = std::max(vmax, p.velocity[i].norm());
  const double c_wave = s.materials.primary().max_wave_speed(p.size(),
                                                             p.stress.data(),
                                                             p.state.data());
  const double c_now =
    std::max(c_wave, s.materials.primary().p_wave_speed()) + vmax;
  out << "(c) squeezed neo-Hookean block" << std::endl;
  PSMPM_CHECK(out, squeezed->get_failure() == Simulator::Failure::none);
  PSMPM_CHECK(out, J_min() <= 0.7);
  // Neo-Hookean bound at J = 0.7 (b = 0.7 I), nu = 0.3: sqrt((1.357
  // lambda + 1.7 mu) / (lambda + 2 mu)) = 1.033 times c_p.
  PSMPM_CHECK(out, c_wave > 1.02 * s.materials.primary().p_wave_speed());
  PSMPM_CHECK(out, std::abs(last / formula(*squeezed, c_now) - 1) < 1e-12);

  auto fixed =
    make_solver({"Time/Time step=1e-4",
                 "Initial conditions/Velocity=" + std::to_string(c_p) + "; 0"});
  out << "(d) fixed step" << std::endl;
  PSMPM_CHECK(out, fixed->next_time_step() == 1e-4);
}
