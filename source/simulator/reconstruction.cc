// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/simulator/reconstruction.h>

namespace psmpm
{
  namespace Simulator
  {
    template <int dim>
    void
    Reconstruction<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Reconstruction",
        "particles",
        Patterns::Selection(
          "particles|" + ReconstructionRegistry<dim>::instance().selection()),
        "How particle data reach the grid integrals. particles: every "
        "particle is a quadrature point of mass matrix, momentum and "
        "internal force (classical MPM); " +
          ReconstructionRegistry<dim>::instance().documentation() + ".");
      ReconstructionRegistry<dim>::instance().declare_parameters(prm);
    }

    template class Reconstruction<1>;
    template class Reconstruction<2>;
  } // namespace Simulator
} // namespace psmpm
