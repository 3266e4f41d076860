// ---------------------------------------------------------------------
// psmpm: helpers for the OTM tests (the bar of prm/otm_bar_1d.prm).
// ---------------------------------------------------------------------
#ifndef psmpm_tests_mpm_otm_tests_h
#define psmpm_tests_mpm_otm_tests_h

#include <deal.II/base/parameter_handler.h>

#include <psmpm/app/application.h>
#include <psmpm/simulator/simulator.h>

#include "../tests.h"

#include <memory>
#include <string>
#include <vector>

/// A Simulator<dim> of the scene @p prm_file (relative to the source
/// directory) with the given overrides, set up.
template <int dim>
std::unique_ptr<psmpm::Simulator::Simulator<dim>>
make_simulator(const std::string              &prm_file,
               const std::vector<std::string> &overrides)
{
  ParameterHandler prm;
  psmpm::App::declare_parameters(prm);
  prm.parse_input(std::string(PSMPM_SOURCE_DIR) + "/" + prm_file);
  for (const auto &o : overrides)
    psmpm::App::apply_override(prm, o);
  auto solver =
    std::make_unique<psmpm::Simulator::Simulator<dim>>(MPI_COMM_WORLD);
  solver->quiet = true;
  solver->parse_parameters(prm);
  solver->setup();
  return solver;
}

/// The reference solution of the scene @p prm_file, as the simulator
/// builds it.
template <int dim>
std::unique_ptr<psmpm::Postprocess::Reference<dim>>
make_reference(const std::string                      &prm_file,
               const psmpm::Simulator::Simulator<dim> &solver)
{
  ParameterHandler prm;
  psmpm::App::declare_parameters(prm);
  prm.parse_input(std::string(PSMPM_SOURCE_DIR) + "/" + prm_file);
  prm.enter_subsection("Geometry");
  const double length = prm.get_double("Length");
  prm.leave_subsection();
  return psmpm::Postprocess::Reference<dim>::create(
    prm,
    solver.get_state().materials.primary(),
    length,
    0.,
    Tensor<1, dim>());
}

/// Root mean square over the particles of sigma_xx - sigma_ref_xx at their
/// initial positions and the simulator's time (psmpm's 1D definition).
template <int dim>
double
stress_rms(const psmpm::Simulator::Simulator<dim>   &solver,
           const psmpm::Postprocess::Reference<dim> &reference)
{
  const auto &particles = solver.get_particles();
  double      sum       = 0;
  for (std::size_t p = 0; p < particles.size(); ++p)
    {
      const double d =
        particles.stress[p][0][0] -
        reference.evaluate(particles.initial_position[p], solver.get_time())
          .stress[0][0];
      sum += d * d;
    }
  return std::sqrt(sum / particles.size());
}

#endif
