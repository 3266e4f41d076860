// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
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

    template class TransferScheme<1>;
    template class TransferScheme<2>;
  } // namespace Simulator
} // namespace psmpm
