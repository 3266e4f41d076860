// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_postprocess_references_cantilever_fem_h
#define psmpm_postprocess_references_cantilever_fem_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <psmpm/postprocess/reference.h>

#include <map>
#include <memory>
#include <vector>

namespace psmpm
{
  namespace Postprocess
  {
    /**
     * Plane-strain, small-strain linear elastodynamics of the beam
     * [lower, upper] clamped at x = lower[0] (u = 0 on that edge, the
     * other edges traction-free), loaded by its weight and released from
     * rest at t = 0: FE_Q(2)^2 on a uniform subdivided rectangle, Newmark
     * average acceleration (no numerical damping) with a step of 1/
     * steps_per_period of the first period, K + 4M/dt^2 factorised once
     * (SparseDirectUMFPACK); between steps the fields are cubic Hermite
     * interpolants in time.
     *
     * The mesh: n_y x ceil(n_y L / H) square-ish elements, n_y = 1, 2, 4,
     * ... doubled until the static tip deflection and the first natural
     * period (inverse iteration) change by less than convergence_tolerance
     * between two levels (or elements_y fixed). The static deflection is
     * the time mean of the undamped oscillation.
     *
     * evaluate() caches, per evaluated point, the cell's DoFs and shape
     * values and gradients at the point: after the first call a point
     * costs a lookup and a few sums over 18 DoFs.
     */
    class CantileverFEM : public Reference<2>
    {
    public:
      struct Parameters
      {
        Point<2>     lower, upper;
        double       youngs_modulus = 1, poisson_ratio = 0, density = 1;
        Tensor<1, 2> gravity;
        /// Relative change between two mesh levels at which to stop.
        double convergence_tolerance = 1e-4;
        /// Elements across the height; 0: automatic (see above).
        unsigned int elements_y = 0;
        /// Refinements of the cells at the two clamped corners, where the
        /// stress is singular.
        unsigned int corner_refinements = 8;
        /// Largest n_y tried by the automatic choice.
        unsigned int max_elements_y   = 32;
        unsigned int steps_per_period = 400;
      };

      explicit CantileverFEM(const Parameters &parameters);
      ~CantileverFEM() override;

      void
      advance_to(const double t) override;

      /// Displacement, velocity and Cauchy stress at X (clamped to the
      /// beam) at time t, which must lie in the current step (call
      /// advance_to(t) first).
      State
      evaluate(const Point<2> &X, const double t) const override;

      unsigned int
      axis() const override
      {
        return 1;
      }

      bool
      one_dimensional() const override
      {
        return false;
      }

      bool
      oscillates_about_equilibrium() const override
      {
        return true;
      }

      /// The static solution K u = f at X (the mean of the oscillation).
      Tensor<1, 2>
      static_displacement(const Point<2> &X) const;

      /// The discrete first natural period 2 pi / omega_1.
      double
      first_period() const;

      /// Elements across the height and the number of DoFs of the mesh
      /// used; the Newmark step.
      unsigned int
      elements_y() const;
      unsigned int
      n_dofs() const;
      double
      time_step() const;

    private:
      class Implementation;
      std::unique_ptr<Implementation> impl;
    };
  } // namespace Postprocess
} // namespace psmpm

#endif
