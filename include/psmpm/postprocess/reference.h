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

#include <algorithm>
#include <array>
#include <memory>
#include <string>
#include <vector>

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
      /// The material's box: Particles/Region, or the whole block mesh
      /// {0, 0, length, height} ({0, length} in 1D) if that is empty.
      std::vector<double> region;
      /// Boundary conditions/Fixed x (, Fixed y): boundary names per
      /// direction.
      std::array<std::vector<std::string>, dim> fixed;

      /// Whether boundary @p name is fixed in every direction.
      bool
      clamped(const std::string &name) const
      {
        for (const auto &names : fixed)
          if (std::find(names.begin(), names.end(), name) == names.end())
            return false;
        return true;
      }
    };

    /**
     * A solution to measure errors against (subsection "Reference
     * solution"), evaluated at a particle's initial position X. Most
     * references are 1D solutions along one axis() (one_dimensional());
     * the 2D "cantilever fem" moves mainly along its axis(); variants
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
      /// "none"; checks that the scene fits it. @p region and @p fixed as
      /// in ReferenceContext (region empty: the whole mesh).
      static std::unique_ptr<Reference<dim>>
      create(ParameterHandler                                &prm,
             const Material::Material<dim>                   &material,
             const double                                     length,
             const double                                     height,
             const Tensor<1, dim>                            &gravity,
             const std::vector<double>                       &region = {},
             const std::array<std::vector<std::string>, dim> &fixed  = {});

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

      /// A 1D solution (needs Material/Poisson's ratio = 0).
      virtual bool
      one_dimensional() const
      {
        return true;
      }

      /// The tracked particle oscillates about a static equilibrium
      /// (released from rest under a constant load): its mean
      /// displacement and period go to summary.json (Oscillation).
      virtual bool
      oscillates_about_equilibrium() const
      {
        return false;
      }
    };

    template <int dim>
    using ReferenceRegistry =
      Registry<Reference<dim>, const ReferenceContext<dim> &>;
  } // namespace Postprocess
} // namespace psmpm

#endif
