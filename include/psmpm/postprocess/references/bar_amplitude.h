// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_postprocess_references_bar_amplitude_h
#define psmpm_postprocess_references_bar_amplitude_h

#include <psmpm/postprocess/reference.h>

namespace psmpm
{
  namespace Postprocess
  {
    /**
     * Check Reference solution/Velocity amplitude v0 of the vibrating bar
     * (v = v0 sin(pi x/L) at t = 0) against the range of double numbers:
     * the error norms integrate squared velocities (v0), displacements
     * (v0/omega) and stresses (v0 sqrt(E rho)) over the material's box, so
     * each of these, squared and times the box's measure, must be finite.
     * Throws ExcMessage naming the entry and its value otherwise (a run
     * would write inf into statistics.txt).
     */
    template <int dim>
    void
    check_bar_amplitude(const ReferenceContext<dim> &context);
  } // namespace Postprocess
} // namespace psmpm

#endif
