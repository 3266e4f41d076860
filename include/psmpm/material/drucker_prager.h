// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_material_drucker_prager_h
#define psmpm_material_drucker_prager_h

#include <psmpm/material/plastic_hypoelastic.h>

namespace psmpm
{
  namespace Material
  {
    /**
     * Drucker-Prager plasticity, registered as "drucker-prager" (Friction
     * angle 0: von Mises). With p = tr(sigma) / 3 (tension positive) and
     * J2 the second invariant of the deviator,
     *   f = sqrt(J2) + eta p - xi c,   g = sqrt(J2) + eta_bar p,
     * where eta, xi (and eta_bar from psi) match Mohr-Coulomb as
     * `Drucker-Prager fit` says (de Souza Neto, Peric and Owen 2008,
     * sec. 6.4.3): "plane strain" (the same plane-strain limit loads for
     * associated flow: eta = 3 tan phi / sqrt(9 + 12 tan^2 phi), xi = 3 /
     * sqrt(9 + 12 tan^2 phi)), "outer" (the cone through the compressive
     * corners: eta = 6 sin phi / (sqrt 3 (3 - sin phi)), xi = 6 cos phi /
     * (sqrt 3 (3 - sin phi))) or "inner" (the tensile corners, 3 + sin
     * phi).
     *
     * The return is the closed-form implicit one for linear elasticity
     * and the strength of the step: onto the cone, or to its apex xi c /
     * eta when the cone return would pass it. Tension cutoff is
     * Mohr-Coulomb's only: the cone's apex bounds the tension here.
     */
    template <int dim>
    class DruckerPrager : public PlasticHypoelastic<dim>
    {
    public:
      static void
      declare_entries(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm) override;

      std::string
      name() const override
      {
        return "drucker-prager";
      }

      void
      update(const unsigned int       n,
             const Tensor<2, dim>    *dL,
             SymmetricTensor<2, dim> *stress,
             double                  *state,
             double                  *volume_ratio) const override;

      /// eta, xi c, eta_bar of @p strength, G, K, 1 / (G + K eta
      /// eta_bar), 1 / (2 G) and 1 / (3 K) into strength.derived.
      void
      prepare(typename PlasticHypoelastic<dim>::Strength &strength) const;

      /// The return of the principal stresses @p sigma (any order) for
      /// @p strength (prepared); false if they are inside the cone.
      bool
      return_stress(const typename PlasticHypoelastic<dim>::Strength &strength,
                    std::array<double, 3> &sigma) const;

      enum class Fit
      {
        plane_strain,
        outer,
        inner
      };
      Fit fit = Fit::plane_strain;
    };
  } // namespace Material
} // namespace psmpm

#endif
