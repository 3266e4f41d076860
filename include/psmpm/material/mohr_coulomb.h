// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_material_mohr_coulomb_h
#define psmpm_material_mohr_coulomb_h

#include <psmpm/material/plastic_hypoelastic.h>

namespace psmpm
{
  namespace Material
  {
    /**
     * Mohr-Coulomb plasticity with a tension cutoff, registered as
     * "mohr-coulomb" (Friction angle 0: Tresca). With tension positive and
     * sigma_1 >= sigma_2 >= sigma_3 the yield function is
     *   f = (1 + sin phi) sigma_1 - (1 - sin phi) sigma_3 - 2 c cos phi,
     * the potential the same with the dilatancy angle psi, and the cutoff
     * sigma_1 <= t (associated).
     *
     * The return is the exact implicit one in principal stress space for
     * linear elasticity (de Souza Neto, Peric and Owen 2008, ch. 8;
     * Clausen, Damkilde and Andersen 2006): every surface is a plane there,
     * so the return onto a set of active planes (the main plane, the two
     * edges where sigma_1 = sigma_2 or sigma_2 = sigma_3, the apex, the
     * cutoff planes and their intersections) is a linear system of at
     * most 3 x 3 in the plastic multipliers. The active set is the first,
     * in order of size, whose multipliers are non-negative and whose
     * result violates no plane; where none is (the apex of a
     * non-associated potential) the stress goes to the apex
     * min(t, c cot phi) (1, 1, 1). An active set is accepted when its
     * result violates no plane by more than 1e-13 (|sigma| + c), after one
     * step of iterative refinement (in the closed forms only where the
     * unrefined result is not accepted: near the apex);
     * tests/material/mohr_coulomb_01 asserts f <= 1e-10 (|sigma| + c)
     * after every update. The main plane and the two edges, where most
     * returns end, are solved in closed form first; where the main
     * plane's result would leave the sextant (known from its multiplier)
     * the edge comes first. In plane strain the plastic strain of a main
     * plane or edge return is the multipliers times the flow directions.
     */
    template <int dim>
    class MohrCoulomb : public PlasticHypoelastic<dim>
    {
    public:
      std::string
      name() const override
      {
        return "mohr-coulomb";
      }

      void
      update(const unsigned int       n,
             const Tensor<2, dim>    *dL,
             SymmetricTensor<2, dim> *stress,
             double                  *state,
             double                  *volume_ratio) const override;

      /// The return's constants of @p strength into strength.derived:
      /// k = 2 c cos phi, the Lame constants, and the closed forms' D b
      /// vectors, matrices and inverses for the main plane and the edges.
      void
      prepare(typename PlasticHypoelastic<dim>::Strength &strength) const;

      /// The return of the principal stresses @p sigma (any order) for
      /// @p strength (prepared here); false if they are inside the surface
      /// (unchanged).
      bool
      return_stress(const typename PlasticHypoelastic<dim>::Strength &strength,
                    std::array<double, 3> &sigma) const;
    };
  } // namespace Material
} // namespace psmpm

#endif
