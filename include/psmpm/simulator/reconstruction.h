// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_simulator_reconstruction_h
#define psmpm_simulator_reconstruction_h

#include <deal.II/base/parameter_handler.h>

#include <psmpm/base/registry.h>
#include <psmpm/simulator/state.h>

#include <string>
#include <vector>

namespace psmpm
{
  namespace Simulator
  {
    /**
     * How particle data reach the grid integrals (subsection "Transfer",
     * entry "Reconstruction"). The default, "particles", is the classical
     * MPM mapping: every particle is a quadrature point of the mass
     * matrix, the momentum and the internal force (TransferScheme's own
     * loops; no object exists for it). A Reconstruction replaces it: it
     * fits fields to the particle data of each cell and integrates them
     * with a quadrature rule of its own (Wobbes et al. 2019, section 4.4),
     * filling the same per-cell arrays of the GridSystem, so that mass
     * strategies, solvers and the grid-to-particle update stay unchanged.
     *
     * Variants register in ReconstructionRegistry<dim>.
     */
    template <int dim>
    class Reconstruction
    {
    public:
      virtual ~Reconstruction() = default;

      /// Entry "Reconstruction" (inside subsection "Transfer").
      static void
      declare_parameters(ParameterHandler &prm);

      /// Called once the state is complete (mesh, space, grid, particles):
      /// checks that the reconstruction can work with it (throws
      /// ExcMessage naming the entry otherwise) and precomputes what does
      /// not change from step to step.
      virtual void
      initialize(const State<dim> &state) = 0;

      /// The mass strategies and transfer schemes this reconstruction has
      /// been verified with (empty: all).
      virtual std::vector<std::string>
      verified_mass_matrices() const = 0;
      virtual std::vector<std::string>
      verified_transfers() const = 0;

      /**
       * The per-cell arrays as TransferScheme::particles_to_grid() fills
       * them (the arrays are zeroed by the caller): lumped and, if the
       * strategy uses it, consistent mass, and the right-hand sides
       * momentum_weight p_i + force_weight f_i.
       */
      virtual void
      mass_and_forces(State<dim>  &state,
                      const double momentum_weight,
                      const double force_weight) = 0;

      /// Whether momentum() replaces the particles' mapping of momentum
      /// (and with it the mass matrix of the velocity).
      virtual bool
      fits_momentum() const = 0;

      /// Whether the acceleration (M^{-1} f) takes the lumped mass of
      /// mass_and_forces() whatever the mass strategy, the consistent
      /// matrix then serving the velocity mapping alone (the chapter's
      /// combination, Wobbes et al. 2019 eqs. 4.8 and 4.44).
      virtual bool
      lumped_acceleration() const
      {
        return false;
      }

      /// The per-cell right-hand sides p_i of the particles' current
      /// momentum (zeroed by the caller), if fits_momentum(); may assemble
      /// a mass matrix of its own for the velocity.
      virtual void
      momentum(State<dim> &state) = 0;
    };

    /// The factory gets the parameters inside subsection "Transfer".
    template <int dim>
    using ReconstructionRegistry =
      Registry<Reconstruction<dim>, ParameterHandler &>;
  } // namespace Simulator
} // namespace psmpm

#endif
