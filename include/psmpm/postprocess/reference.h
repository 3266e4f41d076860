// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_postprocess_reference_h
#define psmpm_postprocess_reference_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <psmpm/base/registry.h>
#include <psmpm/material/material.h>

#include <memory>
#include <string>

namespace psmpm
{
  namespace Postprocess
  {
    using namespace dealii;

    /// What a reference solution may depend on.
    template <int dim>
    struct ReferenceContext
    {
      const Material::Material<dim> &material;
      double                         length; ///< Geometry/Length (x)
      double                         height; ///< Geometry/Height (y, 2D)
      Tensor<1, dim>                 gravity;
      double                         amplitude;      ///< Velocity amplitude
      unsigned int                   ulfem_elements; ///< ULFEM elements
    };

    /**
     * A solution to measure errors against (subsection "Reference
     * solution"), evaluated at a particle's initial position X. All
     * references so far are 1D solutions along one axis(); variants
     * register in ReferenceRegistry<dim> (factory argument: the context).
     */
    template <int dim>
    class Reference
    {
    public:
      struct State
      {
        Tensor<1, dim>          displacement;
        Tensor<1, dim>          velocity;
        SymmetricTensor<2, dim> stress;
      };

      virtual ~Reference() = default;

      /// Type (from the registry, plus "none") and the shared entries.
      static void
      declare_parameters(ParameterHandler &prm);

      /// The reference named in Reference solution/Type, or nullptr for
      /// "none"; checks that the scene fits it.
      static std::unique_ptr<Reference<dim>>
      create(ParameterHandler              &prm,
             const Material::Material<dim> &material,
             const double                   length,
             const double                   height,
             const Tensor<1, dim>          &gravity);

      /// References computed alongside the run advance here.
      virtual void
      advance_to(const double)
      {
      }

      virtual State
      evaluate(const Point<dim> &X, const double t) const = 0;

      /// The axis along which the solution varies and moves.
      virtual unsigned int
      axis() const = 0;
    };

    template <int dim>
    using ReferenceRegistry =
      Registry<Reference<dim>, const ReferenceContext<dim> &>;
  } // namespace Postprocess
} // namespace psmpm

#endif
