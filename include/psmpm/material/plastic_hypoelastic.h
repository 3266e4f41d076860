// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_material_plastic_hypoelastic_h
#define psmpm_material_plastic_hypoelastic_h

#include <psmpm/material/lanes.h>
#include <psmpm/material/material.h>

#include <array>
#include <cmath>

namespace psmpm
{
  namespace Material
  {
    /**
     * What the soil models share: isotropic linear elasticity in rate form
     * with an exactly objective rotation, a return map in principal stress
     * space done by the derived model, and the plastic state.
     *
     * Update of one particle (plane strain in 2D, uniaxial strain in 1D):
     * 1. the stress is rotated by the Hughes-Winget rotation of the spin
     *    increment, R = (I - W/2)^-1 (I + W/2): R is orthogonal to
     *    round-off, so a body in rigid rotation keeps its principal
     *    stresses (and its yield state) exactly, where the first-order
     *    Jaumann terms of Hypoelastic change them by O(dt^2) per step;
     * 2. the elastic trial stress sigma + lambda tr(de) I + 2 G de (the
     *    Jaumann rate of the Cauchy stress, without the -tr(de) sigma term
     *    of Hypoelastic: the yield function is one of the Cauchy stress);
     * 3. if the trial stress is outside the yield surface, the model's
     *    return in principal stress space (the principal directions do
     *    not change for an isotropic model), mapped back with the trial
     *    stress' eigenvectors. The plastic strain increment is the
     *    elastic compliance times the stress correction, so that the
     *    elastic strain stays C^-1 sigma.
     *
     * Softening: cohesion and friction angle fall linearly from their
     * values to the residual ones as the equivalent plastic strain
     * kappa = sum sqrt(2/3 de_p^dev : de_p^dev) goes from 0 to Softening
     * strain. The return is then implicit in kappa (a fixed-point
     * iteration on kappa_{n+1}, each iterate an exact return for its
     * parameters), so the stress ends on the surface of the parameters
     * of the stored kappa.
     *
     * State (2D): {"stress_zz", "plastic_strain_xx", "plastic_strain_yy",
     * "plastic_strain_xy", "plastic_strain_zz",
     * "equivalent_plastic_strain", "plastic_work", "volume_ratio"}
     * (tensor shear strain; plastic_work: dissipated energy per unit mass
     * [J/kg]; volume_ratio: J = V / V_0). 1D: {"stress_lateral",
     * "plastic_strain_xx", "plastic_strain_lateral",
     * "equivalent_plastic_strain", "plastic_work", "volume_ratio"}.
     * With Apex dilation = recoverable one more column, "apex_dilation".
     *
     * Recoverable apex dilation (cohesionless material only): a return
     * that ends at zero stress, the apex, opens the grains by its
     * volumetric plastic strain, kept as the gap e_a >= 0 (the grains out
     * of contact of Dunatunga and Kamrin, J. Fluid Mech. 779, 2015, with
     * the separation measured from where the particle was last dense). A
     * separated particle (e_a > 0) carries no stress, normal or shear: its
     * whole strain increment is plastic (the plastic strain columns, not
     * the equivalent plastic strain, which measures frictional flow), the
     * volumetric part changes e_a, nothing is stored or dissipated; the
     * elastic energy a particle held when it reached the apex goes to its
     * plastic work (the opening contacts release it into the grains, not
     * into the flow). When a compression closes the gap
     * within a step, the part of the increment after closure (the same
     * fraction of every component) is the elastic trial from zero stress,
     * as for a dense particle. With Apex dilation = permanent (default) the
     * volume gained at the apex is never given back: compressed again, the
     * particle takes the dense material's stress at once.
     */
    template <int dim>
    class PlasticHypoelastic : public Material<dim>
    {
    public:
      /// The yield and softening constants at one equivalent plastic
      /// strain, and what the returns derive from them once per batch.
      struct Strength
      {
        double cohesion       = 0;
        double sin_phi        = 0;
        double cos_phi        = 1;
        double sin_psi        = 0;
        double tension_cutoff = 0; ///< +infinity: none
        /// Constants the return derives from the above and the elastic
        /// constants in its prepare() (once per batch, or per softened
        /// particle), so that a particle's return divides by nothing.
        std::array<double, 28> derived = {};
      };

      /// Friction angle, Dilatancy angle, Cohesion, Tension cutoff,
      /// Residual cohesion, Residual friction angle, Softening strain.
      static void
      declare_entries(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm) override;

      std::vector<std::string>
      state_names() const override;

      void
      initialize(const unsigned int n, double *state) const override;

      bool
      accepts_initial_stress() const override
      {
        return true;
      }

      void
      set_initial_stress(const unsigned int             n,
                         const SymmetricTensor<2, dim> *stress,
                         const double                  *out_of_plane,
                         double                        *state) const override;

      void
      energy_density(const unsigned int             n,
                     const SymmetricTensor<2, dim> *stress,
                     const double                  *state,
                     double                        *energy) const override;

      void
      dissipated_energy(const unsigned int n,
                        const double      *state,
                        double            *per_unit_mass) const override;

      bool
      dissipates() const override
      {
        return true;
      }

      double
      max_wave_speed(const unsigned int,
                     const SymmetricTensor<2, dim> *,
                     const double *) const override
      {
        return this->p_wave_speed();
      }

      /// The strength at equivalent plastic strain @p kappa.
      Strength
      strength(const double kappa) const;

      /// Columns of the state block (offsets within a particle's block).
      enum Column : unsigned int
      {
        out_of_plane = 0,
        plastic_xx   = 1,
        // 2D: plastic_yy = 2, plastic_xy = 3, plastic_zz = 4; 1D: the
        // lateral plastic strain is column 2.
      };
      static constexpr unsigned int kappa_column = dim == 1 ? 3 : 5;
      static constexpr unsigned int work_column  = kappa_column + 1;
      static constexpr unsigned int ratio_column = kappa_column + 2;
      /// The gap e_a, present with recoverable apex dilation only.
      static constexpr unsigned int apex_column = kappa_column + 3;

      double friction_angle  = 30; ///< degrees
      double dilatancy_angle = 0;  ///< degrees
      double cohesion        = 0;
      double tension_cutoff  = HUGE_VAL;
      double residual_cohesion;
      double residual_friction_angle;
      double softening_strain = 0; ///< 0: no softening
      /// Above this volume ratio J = V/V0 the particle carries no stress
      /// (+infinity: never).
      double disconnected_volume_ratio = HUGE_VAL;
      /// Apex dilation = recoverable: the volume a return to the apex adds
      /// is a gap that compression closes at zero stress (apex_column).
      bool recoverable_apex_dilation = false;

    protected:
      /**
       * The batched update with the return @p ret, called as
       * `ret(strength, sigma)` with the principal trial stresses sigma
       * (any order); it returns false for an elastic trial stress, or
       * true and sigma returned. Templated so that the return is inlined
       * in the particle loop (no virtual call per particle). In plane
       * strain without softening, a Return with returns_in_plane = true
       * instead maps the trial stress t = (xx, yy, xy, zz) in its own
       * frame, `ret.in_plane(strength, t, ep, d_kappa)`, and gives the
       * plastic strain increment ep = C^-1 (trial - t) (tensor shear) and
       * its equivalent d_kappa in closed form (tests/material/
       * plastic_in_plane_01 checks both against the principal return).
       * A Return with returns_pairs = true also has lane_constants(),
       * inside_plane_pair() and in_plane_pair(): in plane strain without
       * softening the particles are then updated Lanes::width (two or four) at
       * a time (update_plane_strain_pair()), bit for bit as one at a time.
       */
      template <typename Return>
      void
      update_with(const Return            &ret,
                  const unsigned int       n,
                  const Tensor<2, dim>    *dL,
                  SymmetricTensor<2, dim> *stress,
                  double                  *state,
                  double                  *volume_ratio) const;

      /// update_with() with recoverable apex dilation: runs of dense
      /// particles through update_with() itself (unchanged, also its pairs),
      /// then separate_at_apex() for each; separated particles one at a
      /// time, update_separated().
      template <typename Return>
      void
      update_with_recoverable(const Return            &ret,
                              const unsigned int       n,
                              const Tensor<2, dim>    *dL,
                              SymmetricTensor<2, dim> *stress,
                              double                  *state,
                              double                  *volume_ratio) const;

      /// What the update of every particle of a batch uses: the Lame
      /// constants, the reference density, 1 / E and nu for the elastic
      /// compliance, and 1 / rho0.
      struct BatchConstants
      {
        double lambda;
        double two_g;
        double rho0;
        double inv_e;
        double nu;
        double inv_rho0;
        /// Disconnected volume ratio (+infinity: none).
        double disconnected_ratio;
      };

      /// This material's BatchConstants.
      BatchConstants
      batch_constants() const
      {
        return {this->lame_lambda(),
                2 * this->shear_modulus(),
                this->density,
                1 / this->youngs_modulus,
                this->poisson_ratio,
                1 / this->density,
                disconnected_volume_ratio};
      }

      /// After the return of the principal stresses @p trial to @p sigma:
      /// the plastic strain increment C^-1 (trial - sigma) (principal
      /// frame) and the equivalent plastic strain of @p block, with
      /// softening the return iterated on kappa_{n+1}.
      template <typename Return>
      void
      finish_return(const Return                &ret,
                    const BatchConstants        &c,
                    const std::array<double, 3> &trial,
                    std::array<double, 3>       &sigma,
                    double                      *block,
                    std::array<double, 3>       &plastic_increment) const;

    private:
      /// The strength of the particle with state @p block: @p base, or
      /// with softening and kappa > 0 its own, prepared by @p ret in
      /// @p softened (no copy per particle otherwise).
      template <typename Return>
      const Strength &
      particle_strength(const Return   &ret,
                        const Strength &base,
                        const double   *block,
                        Strength       &softened) const;

      /// The part of a separated particle's increment that goes into its
      /// gap: the fraction of the increment (the whole of it while the
      /// gap stays open) at zero stress, all plastic; the particle's
      /// stress is set to zero. Returns the fraction of the increment
      /// left after the gap has closed (0: still separated).
      static double
      close_gap(const double             tr,
                const Tensor<2, dim>    &dL,
                SymmetricTensor<2, dim> &stress,
                double                  *block);

      /// After the update of a dense particle whose plastic volumetric
      /// strain was @p volumetric_before and whose stored energy per unit
      /// mass was @p stored: if it returned to the apex (stress zero up to
      /// round-off against the volumetric plastic increment), the
      /// particle separates: its volumetric plastic increment becomes the
      /// gap, its stress exactly zero, and the stored energy, which the
      /// opening contacts release into the grains and not into the flow,
      /// is added to its plastic work.
      static void
      separate_at_apex(const BatchConstants    &c,
                       const double             volumetric_before,
                       const double             stored,
                       SymmetricTensor<2, dim> &stress,
                       double                  *block);

      /// The elastic (complementary) energy per unit volume of the stress
      /// @p st with the out-of-plane (1D: lateral) stress @p zz.
      static double
      stored_energy(const BatchConstants          &c,
                    const SymmetricTensor<2, dim> &st,
                    const double                   zz);

      /// The update of a separated particle (gap > 0) with the velocity
      /// gradient increment @p dL: close_gap(), and the rest of the
      /// increment, if any, through update_with() from zero stress.
      template <typename Return>
      void
      update_separated(const Return            &ret,
                       const BatchConstants    &c,
                       const Tensor<2, dim>    &dL,
                       SymmetricTensor<2, dim> &stress,
                       double                  *block,
                       double                  &volume_ratio) const;

      /// The plastic volumetric strain of the state @p block.
      static double
      plastic_volumetric(const double *block)
      {
        if constexpr (dim == 1)
          return block[plastic_xx] + 2 * block[2];
        else
          return block[plastic_xx] + block[2] + block[4];
      }

      /// The update of one particle in uniaxial strain (1D) with the
      /// strain increment @p de: axial stress @p stress_xx, state
      /// @p block, V_new / V_old in @p volume_ratio.
      template <typename Return>
      void
      update_uniaxial(const Return         &ret,
                      const Strength       &s,
                      const BatchConstants &c,
                      const double          de,
                      double               &stress_xx,
                      double               *block,
                      double               &volume_ratio) const;

      /// The update of one particle in plane strain (2D) with the
      /// velocity gradient increment @p dL.
      template <typename Return>
      void
      update_plane_strain(const Return          &ret,
                          const Strength        &s,
                          const BatchConstants  &c,
                          const Tensor<2, 2>    &dL,
                          SymmetricTensor<2, 2> &stress,
                          double                *block,
                          double                &volume_ratio) const;

      /// The plane-strain trial stress t = (txx, tyy, txy, tzz): the
      /// stress @p st and out-of-plane stress @p szz rotated by the
      /// Hughes-Winget rotation of @p dL's spin, plus the elastic
      /// increment of @p dL's symmetric part, whose trace goes to @p tr.
      static void
      plane_strain_trial(const BatchConstants        &c,
                         const Tensor<2, 2>          &dL,
                         const SymmetricTensor<2, 2> &st,
                         const double                 szz,
                         double                      &tr,
                         std::array<double, 4>       &t);

      /// After the return of the principal trial stresses @p trial (the
      /// in-plane Mohr circle's centre + and - its @p radius, and
      /// sigma_zz) to @p sigma: the stress back in the x-y frame of the
      /// trial stress t (half difference (txx - tyy) / 2 @p half, shear
      /// t[2]) into @p t, and the plastic strain and work into @p block.
      template <typename Return>
      void
      plane_strain_return(const Return                &ret,
                          const BatchConstants        &c,
                          const std::array<double, 3> &trial,
                          std::array<double, 3>       &sigma,
                          const double                 half,
                          const double                 radius,
                          double                      *block,
                          std::array<double, 4>       &t) const;

      /**
       * update_plane_strain() of Lanes::width particles at once (a
       * Return with returns_pairs, plane strain without softening): the
       * trial stresses, the elastic test and the return's common path
       * (the Return's in_plane_pair(), which says in which lanes its
       * result is the answer) for all of them in Lanes; a yielding
       * particle whose return leaves that path takes the one-particle
       * in_plane(). Bit for bit update_plane_strain() of each particle.
       * @p lanes: the Return's lane_constants() of @p s (once per batch);
       * @p dL and @p stress point to the first particle's, @p block0 is
       * its state block and the others follow @p stride values apart.
       */
      template <typename Return, typename LaneConstants>
      void
      update_plane_strain_pair(const Return          &ret,
                               const Strength        &s,
                               const LaneConstants   &lanes,
                               const BatchConstants  &c,
                               const Tensor<2, 2>    *dL,
                               SymmetricTensor<2, 2> *stress,
                               double                *block0,
                               const unsigned int     stride,
                               double                *volume_ratio) const;

      /// plane_strain_trial() of the Lanes::width particles' @p dL and
      /// @p st (the out-of-plane stresses @p szz) in Lanes.
      static void
      plane_strain_trial_pair(const BatchConstants        &c,
                              const Tensor<2, 2>          *dL,
                              const SymmetricTensor<2, 2> *st,
                              const Lanes::Value           szz,
                              Lanes::Value                &tr,
                              Lanes::Value                 t[4]);

      /// After a return that mapped the plane-strain trial stress in its
      /// own x-y frame (a Return with returns_in_plane, see
      /// update_plane_strain()): the plastic strain increment @p ep =
      /// (xx, yy, xy, zz) (tensor shear), its equivalent @p d_kappa and the
      /// plastic work at the returned stress @p t into @p block.
      static void
      add_plastic_increment(const BatchConstants        &c,
                            const std::array<double, 4> &t,
                            const std::array<double, 4> &ep,
                            const double                 d_kappa,
                            double                      *block);

      /// add_plastic_increment() of Lanes::width particles (the state
      /// blocks @p block) with the volume ratios @p J, operation by
      /// operation, the increments transposed into the state's rows.
      static void
      add_plastic_increment_pair(const BatchConstants &c,
                                 const Lanes::Value    J,
                                 const Lanes::Value    t[4],
                                 const Lanes::Value    ep[4],
                                 const Lanes::Value    d_kappa,
                                 double *const         block[Lanes::width]);

    protected:
      bool
      softens() const
      {
        return softening_strain > 0;
      }
    };
  } // namespace Material
} // namespace psmpm

#endif
