// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/material/drucker_prager.h>
#include <psmpm/material/plastic_hypoelastic.templates.h>

namespace psmpm
{
  namespace Material
  {
    namespace
    {
      template <int dim>
      std::unique_ptr<Material<dim>>
      create_drucker_prager()
      {
        return std::make_unique<DruckerPrager<dim>>();
      }

      const char *const description =
        "Drucker-Prager plasticity matched to Mohr-Coulomb (Drucker-Prager "
        "fit: plane strain, outer, inner; Friction angle, Dilatancy angle, "
        "Cohesion, optional linear softening); Friction angle 0 is von Mises";

      const Registration<MaterialRegistry<1>>
        registration_1d({"drucker-prager",
                         description,
                         create_drucker_prager<1>,
                         DruckerPrager<1>::declare_entries});
      const Registration<MaterialRegistry<2>>
        registration_2d({"drucker-prager",
                         description,
                         create_drucker_prager<2>,
                         DruckerPrager<2>::declare_entries});

      /// The return of the principal stresses @p sigma (any order) onto
      /// the cone of the prepared @p s; false if they are inside it.
      /// Inline in the particle loop, without a division: a yielding
      /// particle's update is a chain of dependent operations whose
      /// latency is its cost.
      template <typename Strength>
      DEAL_II_ALWAYS_INLINE inline bool
      return_to_cone(const Strength &s, std::array<double, 3> &sigma)
      {
        const double eta = s.derived[0], xi_c = s.derived[1],
                     eta_bar = s.derived[2];
        const double p       = (sigma[0] + sigma[1] + sigma[2]) * (1. / 3);
        const std::array<double, 3> dev = {
          {sigma[0] - p, sigma[1] - p, sigma[2] - p}};
        const double q = std::sqrt(
          0.5 * (dev[0] * dev[0] + dev[1] * dev[1] + dev[2] * dev[2]));
        const double f = q + eta * p - xi_c;
        if (f <= 0)
          return false;
        const double G     = s.derived[3];
        const double K     = s.derived[4];
        const double gamma = f * s.derived[5];
        if (q - G * gamma >= 0 && q > 0)
          {
            // Onto the cone: the deviator shrinks radially, the mean stress
            // moves by the potential's dilatancy.
            const double factor = 1 - G * gamma / q;
            const double p_new  = p - K * eta_bar * gamma;
            for (unsigned int d = 0; d < 3; ++d)
              sigma[d] = factor * dev[d] + p_new;
          }
        else
          {
            // Past the apex (eta > 0 here: for eta = 0, q - G gamma = xi c
            // >= 0): the stress is the apex.
            const double apex = xi_c / eta;
            sigma             = {{apex, apex, apex}};
          }
        return true;
      }



      template <int dim>
      struct DruckerPragerReturn
      {
        const DruckerPrager<dim> &model;

        /// The return scales the deviator: in_plane() maps a plane-strain
        /// stress in its own frame.
        static constexpr bool returns_in_plane = true;

        void
        prepare(typename PlasticHypoelastic<dim>::Strength &s) const
        {
          model.prepare(s);
        }

        /// The elastic test without a square root: sqrt(J2) <= xi c -
        /// eta p.
        bool
        inside(const typename PlasticHypoelastic<dim>::Strength &s,
               const std::array<double, 3>                      &sigma) const
        {
          const double p     = (sigma[0] + sigma[1] + sigma[2]) * (1. / 3);
          const double bound = s.derived[1] - s.derived[0] * p;
          const double d0 = sigma[0] - p, d1 = sigma[1] - p, d2 = sigma[2] - p;
          return bound >= 0 &&
                 0.5 * (d0 * d0 + d1 * d1 + d2 * d2) <= bound * bound;
        }

        /// The same from the centre c and squared radius r^2 of the
        /// in-plane Mohr circle and sigma_zz = z: J2 = (c - p)^2 + r^2 +
        /// (z - p)^2 / 2.
        bool
        inside_plane(const typename PlasticHypoelastic<dim>::Strength &s,
                     const double                                      c,
                     const double                                      r2,
                     const double                                      z) const
        {
          const double p     = (2 * c + z) * (1. / 3);
          const double bound = s.derived[1] - s.derived[0] * p;
          const double j2    = (c - p) * (c - p) + r2 + 0.5 * (z - p) * (z - p);
          return bound >= 0 && j2 <= bound * bound;
        }

        bool
        operator()(const typename PlasticHypoelastic<dim>::Strength &s,
                   std::array<double, 3> &sigma) const
        {
          return return_to_cone(s, sigma);
        }

        /// in_plane_pair() and inside_plane_pair() for Lanes::width particles
        /// (the constants of a batch: its Strength).
        static constexpr bool returns_pairs = true;

        /// The cone's constants in both lanes, made once per batch (a
        /// scalar constant is broadcast where it is used, two
        /// instructions per use and pair).
        struct LaneConstants
        {
          explicit LaneConstants(
            const typename PlasticHypoelastic<dim>::Strength &s)
            : eta(Lanes::broadcast(s.derived[0]))
            , xi_c(Lanes::broadcast(s.derived[1]))
            , eta_bar(Lanes::broadcast(s.derived[2]))
            , G(Lanes::broadcast(s.derived[3]))
            , K_eta_bar(Lanes::broadcast(s.derived[4] * s.derived[2]))
            , inv_modulus(Lanes::broadcast(s.derived[5]))
          {
          }

          Lanes::Value eta, xi_c, eta_bar, G;
          /// K eta_bar: the product the scalar return forms first.
          Lanes::Value K_eta_bar;
          /// 1 / (G + K eta eta_bar): gamma = f times this.
          Lanes::Value inv_modulus;
        };

        static LaneConstants
        lane_constants(const typename PlasticHypoelastic<dim>::Strength &s)
        {
          return LaneConstants(s);
        }

        /// inside_plane() of Lanes::width particles in Lanes.
        Lanes::Mask
        inside_plane_pair(const LaneConstants &s,
                          const Lanes::Value   c,
                          const Lanes::Value   r2,
                          const Lanes::Value   z) const
        {
          const Lanes::Value p     = (2. * c + z) * (1. / 3);
          const Lanes::Value bound = s.xi_c - s.eta * p;
          const Lanes::Value j2 =
            (c - p) * (c - p) + r2 + 0.5 * (z - p) * (z - p);
          return Lanes::both(bound >= 0, j2 <= bound * bound);
        }

        /// in_plane() of Lanes::width particles in Lanes onto the cone (not the
        /// apex): the lanes where that is the answer, with @p t, @p ep and
        /// @p d_kappa there (operation by operation in_plane()'s).
        Lanes::Mask
        in_plane_pair(const LaneConstants &s,
                      Lanes::Value         t[4],
                      Lanes::Value         ep[4],
                      Lanes::Value        &d_kappa) const
        {
          using Lanes::Value;
          const Value eta = s.eta, xi_c = s.xi_c, eta_bar = s.eta_bar;
          const Value p   = (t[0] + t[1] + t[3]) * (1. / 3);
          const Value dxx = t[0] - p, dyy = t[1] - p, dzz = t[3] - p,
                      dxy = t[2];
          const Value q =
            Lanes::sqrt(0.5 * (dxx * dxx + dyy * dyy + dzz * dzz) + dxy * dxy);
          const Value       f         = q + eta * p - xi_c;
          constexpr double  inv_sqrt3 = 0.57735026918962576451;
          const Value       G         = s.G;
          const Value       gamma     = f * s.inv_modulus;
          const Lanes::Mask cone =
            Lanes::and_not(f <= 0, Lanes::both(q - G * gamma >= 0, q > 0));
          if (!Lanes::any(cone))
            return cone;
          const Value r          = gamma / q;
          const Value h          = 0.5 * r;
          const Value volumetric = eta_bar * gamma * (1. / 3);
          const Value factor     = 1 - G * r;
          const Value p_new      = p - s.K_eta_bar * gamma;
          d_kappa                = gamma * inv_sqrt3;
          ep[0]                  = h * dxx + volumetric;
          ep[1]                  = h * dyy + volumetric;
          ep[2]                  = h * dxy;
          ep[3]                  = h * dzz + volumetric;
          t[0]                   = factor * dxx + p_new;
          t[1]                   = factor * dyy + p_new;
          t[2]                   = factor * dxy;
          t[3]                   = factor * dzz + p_new;
          return cone;
        }

        /// return_to_cone() of the plane-strain stress t = (xx, yy, xy,
        /// zz) in its own frame: false if it is inside the cone (t
        /// unchanged); otherwise t returned, the plastic strain @p ep =
        /// C^-1 (trial - t) (tensor shear) in closed form, dev(ep) =
        /// gamma dev(t) / (2 q) and tr(ep) = eta_bar gamma on the cone
        /// (dev(t) / (2 G) and (p - apex) / K at the apex), and its
        /// equivalent d_kappa = sqrt(2/3 |dev(ep)|^2) = gamma / sqrt(3)
        /// (q / (sqrt(3) G) at the apex). One square root and one
        /// division.
        bool
        in_plane(const typename PlasticHypoelastic<dim>::Strength &s,
                 std::array<double, 4>                            &t,
                 std::array<double, 4>                            &ep,
                 double &d_kappa) const
        {
          const double eta = s.derived[0], xi_c = s.derived[1],
                       eta_bar = s.derived[2];
          const double p       = (t[0] + t[1] + t[3]) * (1. / 3);
          const double dxx = t[0] - p, dyy = t[1] - p, dzz = t[3] - p,
                       dxy = t[2];
          const double q =
            std::sqrt(0.5 * (dxx * dxx + dyy * dyy + dzz * dzz) + dxy * dxy);
          const double f = q + eta * p - xi_c;
          if (f <= 0)
            return false;
          constexpr double inv_sqrt3 = 0.57735026918962576451;
          const double     G = s.derived[3], gamma = f * s.derived[5];
          double           h, volumetric, factor, p_new;
          if (q - G * gamma >= 0 && q > 0)
            {
              const double r = gamma / q;
              h              = 0.5 * r;
              volumetric     = eta_bar * gamma * (1. / 3);
              factor         = 1 - G * r;
              p_new          = p - s.derived[4] * eta_bar * gamma;
              d_kappa        = gamma * inv_sqrt3;
            }
          else
            {
              // Past the apex (eta > 0, see return_to_cone()).
              p_new      = xi_c / eta;
              h          = s.derived[6];
              volumetric = (p - p_new) * s.derived[7];
              factor     = 0;
              d_kappa    = 2 * q * h * inv_sqrt3;
            }
          ep = {{h * dxx + volumetric,
                 h * dyy + volumetric,
                 h * dxy,
                 h * dzz + volumetric}};
          t  = {{factor * dxx + p_new,
                 factor * dyy + p_new,
                 factor * dxy,
                 factor * dzz + p_new}};
          return true;
        }
      };

      /// eta and xi of the cone that matches Mohr-Coulomb with the angle
      /// of sine @p s and cosine @p c as @p fit says.
      template <typename Fit>
      std::pair<double, double>
      cone(const Fit fit, const double s, const double c)
      {
        switch (fit)
          {
            case Fit::plane_strain:
              {
                const double tan = s / c;
                const double r   = std::sqrt(9 + 12 * tan * tan);
                return {3 * tan / r, 3 / r};
              }
            case Fit::outer:
              return {6 * s / (std::sqrt(3.) * (3 - s)),
                      6 * c / (std::sqrt(3.) * (3 - s))};
            default:
              return {6 * s / (std::sqrt(3.) * (3 + s)),
                      6 * c / (std::sqrt(3.) * (3 + s))};
          }
      }
    } // namespace



    template <int dim>
    void
    DruckerPrager<dim>::declare_entries(ParameterHandler &prm)
    {
      PlasticHypoelastic<dim>::declare_entries(prm);
      prm.declare_entry("Drucker-Prager fit",
                        "plane strain",
                        Patterns::Selection("plane strain|outer|inner"),
                        "drucker-prager: which Mohr-Coulomb surface the cone "
                        "matches: plane strain (the same plane-strain limit "
                        "loads for associated flow), outer (through the "
                        "compressive corners) or inner (the tensile ones).");
    }



    template <int dim>
    void
    DruckerPrager<dim>::parse_parameters(ParameterHandler &prm)
    {
      PlasticHypoelastic<dim>::parse_parameters(prm);
      const std::string f = prm.get("Drucker-Prager fit");
      fit                 = f == "outer" ? Fit::outer :
                            f == "inner" ? Fit::inner :
                                           Fit::plane_strain;
    }



    template <int dim>
    void
    DruckerPrager<dim>::prepare(
      typename PlasticHypoelastic<dim>::Strength &s) const
    {
      const auto [eta, xi] = cone(fit, s.sin_phi, s.cos_phi);
      const double cos_psi = std::sqrt(1 - s.sin_psi * s.sin_psi);
      s.derived[0]         = eta;
      s.derived[1]         = xi * s.cohesion;
      s.derived[2]         = cone(fit, s.sin_psi, cos_psi).first;
      s.derived[3]         = this->shear_modulus();
      s.derived[4]         = this->bulk_modulus();
      s.derived[5] = 1 / (s.derived[3] + s.derived[4] * eta * s.derived[2]);
      s.derived[6] = 1 / (2 * s.derived[3]);
      s.derived[7] = 1 / (3 * s.derived[4]);
    }



    template <int dim>
    bool
    DruckerPrager<dim>::return_stress(
      const typename PlasticHypoelastic<dim>::Strength &s,
      std::array<double, 3>                            &sigma) const
    {
      return return_to_cone(s, sigma);
    }



    template <int dim>
    void
    DruckerPrager<dim>::update(const unsigned int       n,
                               const Tensor<2, dim>    *dL,
                               SymmetricTensor<2, dim> *stress,
                               double                  *state,
                               double                  *volume_ratio) const
    {
      // Two loops, chosen once per batch: the one without the option
      // compiles as if the option did not exist.
      if (this->recoverable_apex_dilation)
        this->update_with_recoverable(DruckerPragerReturn<dim>{*this},
                                      n,
                                      dL,
                                      stress,
                                      state,
                                      volume_ratio);
      else
        this->update_with(DruckerPragerReturn<dim>{*this},
                          n,
                          dL,
                          stress,
                          state,
                          volume_ratio);
    }



    template class DruckerPrager<1>;
    template class DruckerPrager<2>;
  } // namespace Material
} // namespace psmpm
