// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_simulator_dof_body_masks_h
#define psmpm_simulator_dof_body_masks_h

#include <psmpm/simulator/state.h>

#include <algorithm>
#include <vector>

namespace psmpm
{
  namespace Simulator
  {
    /**
     * Which bodies have particles in the support of each DoF: bit b - 1
     * of @p dof_mask[l] (one entry per locally relevant DoF) is set where
     * a particle of body b lies in a cell of DoF l, on any rank (bit 0
     * for every particle without Bodies); @p cell_mask[c] the same for the
     * rank's cells (both resized). A DoF with two body bits or more is
     * where bodies meet (the contact DoFs of ContactCoupling). With
     * @p owned_cells (one flag per cell: the rank owns it), an owned cell
     * without particles sets bit empty_bit(state) of its DoFs: a DoF
     * without it has particles in every cell of its support. At most 31
     * bodies.
     */
    template <int dim>
    void
    dof_body_masks(const State<dim>          &state,
                   std::vector<unsigned int> &cell_mask,
                   std::vector<unsigned int> &dof_mask,
                   const std::vector<char>   *owned_cells = nullptr);

    /// The bit of dof_body_masks() for an empty cell in a DoF's support.
    template <int dim>
    unsigned int
    empty_bit(const State<dim> &state)
    {
      return 1u << std::max(state.particles.n_bodies, 1u);
    }
  } // namespace Simulator
} // namespace psmpm

#endif
