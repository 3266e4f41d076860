// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_material_material_h
#define psmpm_material_material_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <psmpm/base/prefetch.h>
#include <psmpm/base/registry.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace psmpm
{
  namespace Material
  {
    using namespace dealii;

    /**
     * A constitutive model as MPM sees it (subsection "Material"). The
     * model owns a block of named scalars per particle (its state: strains,
     * deformation gradient, out-of-plane stress, ...), updates the Cauchy
     * stress and that state from the velocity gradient increment, reports
     * the stored energy density and the wave speed for the time step.
     *
     * 2D is plane strain, 1D is uniaxial strain (the lateral strains are
     * zero), so that in both the small-strain wave speed is the p-wave
     * speed sqrt((K + 4G/3) / rho); with Poisson's ratio 0 that is
     * sqrt(E / rho), the 1D bar of the thesis and the book chapter.
     *
     * All per-particle functions work on batches: one virtual call per
     * batch, never per particle, so that models can be plug-ins without
     * a cost in the particle loops.
     *
     * Models register in MaterialRegistry<dim> (one line in their own
     * source file); Material/Model lists what is registered.
     */
    template <int dim>
    class Material
    {
    public:
      virtual ~Material() = default;

      /// Material/Model and the constants every model has, then the
      /// entries of each registered model (inside subsection "Material").
      static void
      declare_parameters(ParameterHandler &prm);

      /// The entries of declare_parameters() in the current subsection
      /// (also used for Materials/Material 1..8).
      static void
      declare_entries(ParameterHandler &prm);

      /// Create the model named in Material/Model and parse it (the
      /// subsection is entered here).
      static std::unique_ptr<Material<dim>>
      create(ParameterHandler &prm);

      /// Create and parse the model of the current subsection, whose path
      /// (e.g. "Materials/Material 2") prefixes every message.
      static std::unique_ptr<Material<dim>>
      create(ParameterHandler &prm, const std::string &path);

      /// Read the common constants (the material's subsection entered);
      /// models with entries of their own override it and call this first.
      virtual void
      parse_parameters(ParameterHandler &prm);

      /// The name under which the model is registered.
      virtual std::string
      name() const = 0;

      /// Names of the per-particle state scalars (output, checkpoints).
      virtual std::vector<std::string>
      state_names() const = 0;

      /// Number of state scalars (allocates: call it once per batch, never
      /// per particle).
      unsigned int
      n_state() const
      {
        return state_names().size();
      }

      /**
       * Distance between two particles' state blocks in the arrays passed
       * to the batch functions: n_state() unless set_state_stride() made it
       * larger (several models sharing one particle array, each in its own
       * columns; see MaterialSet). The i-th particle's block starts at
       * state + i * state_stride().
       */
      unsigned int
      state_stride() const
      {
        return stride != 0 ? stride : n_state();
      }

      void
      set_state_stride(const unsigned int s)
      {
        stride = s;
      }

      /**
       * For update() loops: request the stress and the state block
       * (@p stride apart) of particle @p i + prefetch_distance of the
       * @p n, if there is one. In the update's chunks the material is the
       * first to read them (base/prefetch.h; a hint, no value changes).
       */
      static void
      request_ahead(const unsigned int             n,
                    const SymmetricTensor<2, dim> *stress,
                    const double                  *state,
                    const unsigned int             stride,
                    const unsigned int             i)
      {
        const std::size_t ahead = i + prefetch_distance;
        if (ahead >= n)
          return;
        prefetch_lines(stress + ahead);
        prefetch_lines(state + ahead * stride);
      }

      /// Initial state of @p n particles (the first n_state() values of
      /// each block; default zero, models with a deformation gradient set
      /// the identity).
      virtual void
      initialize(const unsigned int n, double *state) const;

      /**
       * Update @p n particles: @p dL[i] = dt grad v at particle i (L_ij =
       * dv_i/dx_j); @p stress[i] and the i-th state block
       * (state + i * state_stride()) are updated in place and
       * @p volume_ratio[i] receives V_new / V_old.
       */
      virtual void
      update(const unsigned int       n,
             const Tensor<2, dim>    *dL,
             SymmetricTensor<2, dim> *stress,
             double                  *state,
             double                  *volume_ratio) const = 0;

      /**
       * Whether the model can start from a prescribed Cauchy stress (the
       * geostatic or expression initial stress of "Initial conditions").
       * Rate models (hypoelastic, plasticity) can; models whose stress
       * follows from a deformation gradient cannot, and such a scene is
       * refused as bad input.
       */
      virtual bool
      accepts_initial_stress() const
      {
        return false;
      }

      /**
       * Make the state of @p n particles consistent with an initial stress:
       * the in-plane stress is already in @p stress[i]; @p out_of_plane[i]
       * is sigma_zz (2D, plane strain) or the lateral stress (1D). Called
       * after initialize(); only if accepts_initial_stress().
       */
      virtual void
      set_initial_stress(const unsigned int             n,
                         const SymmetricTensor<2, dim> *stress,
                         const double                  *out_of_plane,
                         double                        *state) const;

      /**
       * Energy dissipated so far per unit mass [J/kg] of @p n particles
       * (plastic work); zero for elastic models. The total of a run is
       * sum_p m_p d_p, so that kinetic + strain + gravity + dissipated
       * energy is conserved.
       */
      virtual void
      dissipated_energy(const unsigned int n,
                        const double * /*state*/,
                        double *per_unit_mass) const
      {
        for (unsigned int i = 0; i < n; ++i)
          per_unit_mass[i] = 0;
      }

      /// Whether dissipated_energy() can be non-zero (the statistics skip
      /// the sum otherwise).
      virtual bool
      dissipates() const
      {
        return false;
      }

      /// Stored energy per unit current volume of @p n particles.
      virtual void
      energy_density(const unsigned int             n,
                     const SymmetricTensor<2, dim> *stress,
                     const double                  *state,
                     double                        *energy) const = 0;

      /// Largest wave speed of the current state of one particle (time
      /// step control); the default is the small-strain p-wave speed.
      virtual double
      wave_speed(const SymmetricTensor<2, dim> &stress,
                 const double                  *state) const;

      /// Largest wave_speed() over @p n particles (one virtual call per
      /// batch: the automatic time step asks every step).
      virtual double
      max_wave_speed(const unsigned int             n,
                     const SymmetricTensor<2, dim> *stress,
                     const double                  *state) const;

      double
      bulk_modulus() const
      {
        return youngs_modulus / (3 * (1 - 2 * poisson_ratio));
      }
      double
      shear_modulus() const
      {
        return youngs_modulus / (2 * (1 + poisson_ratio));
      }
      double
      lame_lambda() const
      {
        return bulk_modulus() - 2. / 3 * shear_modulus();
      }
      /// p-wave (constrained) modulus K + 4G/3 = lambda + 2G.
      double
      p_wave_modulus() const
      {
        return bulk_modulus() + 4. / 3 * shear_modulus();
      }
      double
      p_wave_speed() const
      {
        return std::sqrt(p_wave_modulus() / density);
      }

      double density        = 1;
      double youngs_modulus = 100;
      double poisson_ratio  = 0;
      /// The subsection the constants came from, for messages.
      std::string path = "Material";

    private:
      unsigned int stride = 0; ///< 0: n_state()
    };

    template <int dim>
    using MaterialRegistry = Registry<Material<dim>>;
  } // namespace Material
} // namespace psmpm

#endif
