// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/lac/solver_control.h>

#include <psmpm/base/format.h>
#include <psmpm/simulator/transfer_scheme.h>

namespace psmpm
{
  namespace Simulator
  {
    template <int dim>
    void
    TransferScheme<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Transfer");
      prm.declare_entry(
        "Scheme",
        "automatic",
        Patterns::Selection(
          "automatic|" + TransferSchemeRegistry<dim>::instance().selection()),
        "automatic: the basis' measured default (apic for powell-sabin with "
        "lumped mass, musl otherwise; doc/transfers.md); " +
          TransferSchemeRegistry<dim>::instance().documentation());
      TransferSchemeRegistry<dim>::instance().declare_parameters(prm);
      prm.leave_subsection();
    }

    template <int dim>
    bool
    TransferScheme<dim>::solve(State<dim>                  &state,
                               std::vector<Tensor<1, dim>> &solution,
                               StabilityMonitor            &monitor,
                               TimerOutput                 &timer)
    {
      try
        {
          TimerOutput::Scope t(timer, "solve");
          state.grid->solve(solution);
        }
      catch (const SolverControl::NoConvergence &e)
        {
          monitor.report(Failure::solver,
                         "mass matrix solver did not converge (" +
                           std::to_string(e.last_step) +
                           " iterations, residual " +
                           prm_value(e.last_residual) + ")");
          return false;
        }
      return true;
    }

    template <int dim>
    void
    TransferScheme<dim>::update_material(
      State<dim>                        &state,
      const std::vector<Tensor<2, dim>> &increments,
      std::vector<double>               &volume_ratio,
      StabilityMonitor                  &monitor)
    {
      auto &particles = state.particles;
      volume_ratio.resize(particles.size());
      state.material->update(particles.size(),
                             increments.data(),
                             particles.stress.data(),
                             particles.state.data(),
                             volume_ratio.data());
      for (std::size_t p = 0; p < particles.size(); ++p)
        {
          particles.volume[p] *= volume_ratio[p];
          particles.density[p] /= volume_ratio[p];
          if (!(particles.volume[p] > 0))
            monitor.report(Failure::non_positive_volume,
                           "non-positive particle volume (particle " +
                             std::to_string(particles.id[p]) + ")");
        }
    }

    template class TransferScheme<1>;
    template class TransferScheme<2>;
  } // namespace Simulator
} // namespace psmpm
