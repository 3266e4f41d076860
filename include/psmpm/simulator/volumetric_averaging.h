// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_simulator_volumetric_averaging_h
#define psmpm_simulator_volumetric_averaging_h

#include <deal.II/base/tensor.h>

#include <psmpm/simulator/cell_gradient_integrals.h>
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
     * keeps its deviatoric part and takes as its trace the volume change
     * of its cell, and the internal forces take the cell's mean pressure
     * in place of the particles' own (B-bar), the F-bar idea for the
     * material point method (Coombs, Charlton, Cortis and Augarde 2018,
     * "Overcoming volumetric locking in material point methods", CMAME
     * 333). Why: isochoric plastic flow (Tresca, psi = 0) and nearly
     * incompressible elasticity ask the velocity to be divergence-free at
     * every particle, which a Powell-Sabin space (whose divergence is
     * linear on each of the six sub-triangles) can only meet by
     * stiffening: it locks, and a footing carries too much. With the
     * mean, the constraint is one per cell and body.
     *
     * Two kinds of cells:
     *  - A cell inside one body (its particles hold at least min_fill
     *    of the cell's area, and every cell in the support of its
     *    functions holds particles of that body and of no other; no
     *    free surface or contact DoF touches it): the cell's mean
     *    pressure m_c
     *    (volume-weighted over its particles) acts through the exact
     *    integrals, force -m_c G_{c,k} on function k
     *    (CellGradientIntegrals), and the trace of every increment is
     *    the cell's exact volume change dt sum_k v_k . G_{c,k} / |c|.
     *    Why exact: the particles' own quadrature sum_p V_p grad N_k(x_p)
     *    does not sum to zero over the cells around an interior
     *    coefficient, so a uniform pressure pushes it. The particle
     *    pressures (one per particle) balance that push where every
     *    particle has its own volume change; one pressure per cell cannot,
     *    and under plastic flow, which offers no deviatoric stiffness,
     *    the push turns into a velocity that the particles read as a
     *    volume change the geometry does not have: a biaxial sample
     *    deformed at constant volume with 5 particles per cell loses all
     *    of its confining pressure with the particle means, and holds it
     *    with the exact cells (tests/mpm/biaxial_01).
     *  - Any other cell (partly filled, next to a free surface, shared
     *    by bodies or next to a contact): the volume-weighted means over the
     *    particles of each body, e_c = sum_q V_q tr(dt L_q) / sum_q V_q
     *    for the increments and the mean pressure in each particle's
     *    force stress. The body's real extent in such a cell is known
     *    only through its particles.
     * Both are work-conjugate pairs: the forces' power is the particles'
     * stress power of the averaged increments (up to the cell's particle
     * volume against its area for the exact cells).
     *
     * Where the gradients are constant on cells (P1) every particle of a
     * cell has the mean already, and TransferScheme skips the average.
     * Local to a rank: a cell's particles live on the rank that owns it;
     * the contact DoFs are found over all ranks (dof_body_masks()).
     */
    template <int dim>
    class VolumetricAveraging
    {
    public:
      /// @p exact_cells: integrate the pressure of the cells one body
      /// fills exactly (a fixed grid; a grid that moves with the material
      /// (otm) keeps the particle means everywhere).
      explicit VolumetricAveraging(const bool exact_cells);

      /**
       * At the start of a step, on the cells the particles are in: which
       * cells are integrated exactly, state.force_stress (each particle's
       * stress with its in-plane mean m_p = tr(sigma_p) / dim replaced by
       * the mean of its cell and body, or removed in the exact cells) and
       * state.cell_forces (the exact cells' pressure forces).
       */
      void
      prepare(State<dim> &state);

      /// Replace the trace of @p increments[p] (one per particle of the
      /// state, its cell and volume as at prepare(), the grid velocity
      /// that made them in state.grid_velocity) by its cell's volume
      /// change.
      void
      apply(const State<dim> &state, Tensor<2, dim> *increments);

    private:
      /// The share of a cell's area its body's particles must hold for
      /// the cell to count as filled. Interior cells hold about 1 (a
      /// particle crossing moves 1 / (particles per cell) of it), cells at
      /// a free surface less; half keeps the first and drops the cells
      /// the surface leaves mostly empty.
      static constexpr double min_fill = 0.5;

      const bool                 exact_cells;
      CellGradientIntegrals<dim> integrals;

      /// Per cell and body: sum of V_p and of V_p tr(values[p]).
      std::vector<double> volume, trace;
      /// The cells integrated exactly in this step (their slot's body
      /// alone), and per cell whether it is one.
      std::vector<unsigned int> exact;
      /// Per exact cell: its slot; per cell: its place in exact or
      /// numbers::invalid_unsigned_int.
      std::vector<std::size_t>  exact_slot;
      std::vector<unsigned int> exact_index;
      /// Scratch of apply(): the exact cells' volume changes.
      std::vector<double> change;
      /// Per cell: whether the rank owns it; scratch of dof_body_masks().
      std::vector<char>         owned_cells;
      std::vector<unsigned int> cell_mask, dof_mask;

      /// The trace of each particle's @p values[p] (increments, stresses)
      /// replaced by the volume-weighted mean of its cell and body.
      template <typename T>
      void
      replace_mean_trace(const State<dim> &state, T *values);

      /// The sums of replace_mean_trace() for @p values.
      template <typename T>
      void
      sum_traces(const State<dim> &state, const T *values);

      /// exact, exact_slot and exact_index for the particles as they are
      /// now (after sum_traces()).
      void
      find_exact_cells(const State<dim> &state);

      /// The slot of particle p: its cell and body.
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
