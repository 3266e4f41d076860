// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_simulator_volumetric_averaging_h
#define psmpm_simulator_volumetric_averaging_h

#include <deal.II/base/tensor.h>

#include <psmpm/simulator/state.h>

#include <vector>

namespace psmpm
{
  namespace Simulator
  {
    using namespace dealii;

    /**
     * The volumetric strain averaged over cells (Transfer/Volumetric
     * strain = cell average): every particle's strain increment dt L_p
     * keeps its deviatoric part and takes as its trace the
     * volume-weighted mean trace of the particles of its body in its cell,
     *
     *   dt Lbar_p = dt L_p + (e_c - tr(dt L_p)) / dim I,
     *   e_c = sum_{q in c, body} V_q tr(dt L_q) / sum V_q,
     *
     * the F-bar idea for the material point method (Coombs, Charlton,
     * Cortis and Augarde 2018, "Overcoming volumetric locking in material
     * point methods", CMAME 333). Why: isochoric plastic flow (Tresca,
     * psi = 0) and nearly incompressible elasticity ask the velocity to be
     * divergence-free at every particle, which a Powell-Sabin space (whose
     * divergence is linear on each of the six sub-triangles) can only
     * meet by stiffening: it locks, and a footing carries too much. With
     * the mean, the constraint is one per cell and body. Where the
     * gradients are constant on cells (P1) every particle of a cell has
     * the mean already, and TransferScheme skips the average. The trace
     * is what the hypoelastic update
     * takes as the volume change (volume ratio 1 + tr), so the particle
     * volumes of a cell change by the same ratio.
     *
     * Local to a rank: a cell's particles live on the rank that owns it.
     */
    template <int dim>
    class VolumetricAveraging
    {
    public:
      /// Replace the trace of @p increments[p] (one per particle of the
      /// state, its cell and volume as before the move) by the mean of
      /// its cell and body.
      void
      apply(const State<dim> &state, Tensor<2, dim> *increments);

      /**
       * Into @p averaged (resized): every particle's stress with its
       * in-plane mean m_p = tr(sigma_p) / dim replaced by the
       * volume-weighted mean of its cell and body, sigma_p + (m_c - m_p)
       * I. The internal forces of these stresses are work-conjugate to
       * the averaged increments of apply() on the same cells: sum_p V_p
       * sigma_p : Lbar_p = sum_p V_p sigmabar_p : L_p (B-bar), so the
       * scheme keeps the energy balance of the particles' own strain
       * (with the particles' stresses in the forces and the averaged
       * strain in the update, the discrete system is not conservative,
       * and a collapsing column gains energy).
       */
      void
      average_stress(const State<dim>                     &state,
                     std::vector<SymmetricTensor<2, dim>> &averaged);

    private:
      /// Per cell and body: sum of V_p and of V_p tr(dt L_p) (or V_p m_p).
      std::vector<double> volume, trace;

      /// The trace of each particle's @p values[p] (increments, stresses)
      /// replaced by the volume-weighted mean of its cell and body.
      template <typename T>
      void
      replace_mean_trace(const State<dim> &state, T *values);

      /// Zeroed sums for the particles of @p state; the slot of particle
      /// p is slot(p).
      std::size_t
      start_sums(const State<dim> &state);
      std::size_t
      slot(const State<dim> &state, const std::size_t p) const
      {
        return std::size_t(state.particles.cell[p]) * n_ids +
               (by_body ? state.particles.body_id[p] : 0u);
      }
      unsigned int n_ids   = 1;
      bool         by_body = false;
    };
  } // namespace Simulator
} // namespace psmpm

#endif
