// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_postprocess_reference_solution_h
#define psmpm_postprocess_reference_solution_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <psmpm/material/linear_elastic.h>

#include <string>

namespace psmpm
{
  namespace Postprocess
  {
    using namespace dealii;

    /**
     * Exact solutions evaluated at a particle's initial position X
     * (subsection "Reference solution"). "vibrating bar" is the small
     * deformation bar of thesis eq. 4.2 with both ends fixed:
     * u = v0/w sin(w t) sin(pi X/L), w = pi sqrt(E/rho)/L, with velocity
     * and the stress sigma_xx = E du/dx (nu = 0).
     */
    class ReferenceSolution
    {
    public:
      enum class Type
      {
        none,
        vibrating_bar
      };

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler              &prm,
                       const Material::LinearElastic &material,
                       const double                   length);

      bool
      exists() const
      {
        return type != Type::none;
      }

      struct State
      {
        Tensor<1, 2>          displacement;
        Tensor<1, 2>          velocity;
        SymmetricTensor<2, 2> stress;
      };

      State
      evaluate(const Point<2> &X, const double t) const;

      Type   type           = Type::none;
      double amplitude      = 0.1; ///< v0
      double length         = 25;
      double youngs_modulus = 100;
      double density        = 1;
    };
  } // namespace Postprocess
} // namespace psmpm

#endif
