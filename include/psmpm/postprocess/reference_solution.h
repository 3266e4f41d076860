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
#include <psmpm/postprocess/updated_lagrangian_1d.h>

#include <memory>
#include <string>

namespace psmpm
{
  namespace Postprocess
  {
    using namespace dealii;

    /**
     * Reference solutions evaluated at a particle's initial position X
     * (subsection "Reference solution"):
     * - "vibrating bar": thesis eq. 4.2, small deformation, ends fixed;
     * - "soil column": small-deformation column under self-weight, bottom
     *   fixed, top free (the corrected thesis eq. 4.6, evaluated in the
     *   equivalent closed d'Alembert form, see soil_column_series());
     * - "vibrating bar ulfem", "soil column ulfem": the same set-ups with
     *   large deformations, computed by a 1D updated Lagrangian FEM run
     *   alongside (UpdatedLagrangian1D).
     */
    class ReferenceSolution
    {
    public:
      enum class Type
      {
        none,
        vibrating_bar,
        soil_column,
        vibrating_bar_ulfem,
        soil_column_ulfem
      };

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler              &prm,
                       const Material::LinearElastic &material,
                       const double                   length,
                       const double                   height,
                       const Tensor<1, 2>            &gravity);

      bool
      exists() const
      {
        return type != Type::none;
      }

      /// Bring a numerical reference to time @p t (no-op for analytic ones).
      void
      advance_to(const double t);

      struct State
      {
        Tensor<1, 2>          displacement;
        Tensor<1, 2>          velocity;
        SymmetricTensor<2, 2> stress;
      };

      /// The state at time @p t (for ULFEM: at its current time).
      State
      evaluate(const Point<2> &X, const double t) const;

      /// Displacement of the soil column by the series of eq. 4.6
      /// (corrected) with @p n_terms terms, for checking the closed form.
      double
      soil_column_series(const double       y,
                         const double       t,
                         const unsigned int n_terms) const;

      Type         type           = Type::none;
      double       amplitude      = 0.1; ///< v0 of the bar
      double       length         = 25;  ///< bar length (x)
      double       height         = 25;  ///< column height (y)
      double       youngs_modulus = 100;
      double       density        = 1;
      double       g = 9.81; ///< downward gravity magnitude (column)
      unsigned int ulfem_elements = 2000;

    private:
      std::unique_ptr<UpdatedLagrangian1D> ulfem;
    };
  } // namespace Postprocess
} // namespace psmpm

#endif
