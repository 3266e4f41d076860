// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/numbers.h>

#include <psmpm/postprocess/reference.h>
#include <psmpm/postprocess/references/bar_amplitude.h>
#include <psmpm/postprocess/updated_lagrangian_1d.h>

#include <cmath>

namespace psmpm
{
  namespace Postprocess
  {
    namespace
    {
      /**
       * The vibrating bar and the soil column with large deformations: a
       * 1D updated Lagrangian FEM run alongside (UpdatedLagrangian1D),
       * along x for the bar and along y for the column.
       */
      template <int dim>
      class ULFEM : public Reference<dim>
      {
      public:
        ULFEM(const ReferenceContext<dim> &c, const bool bar)
          : direction(bar ? 0 : 1)
        {
          UpdatedLagrangian1D::Parameters p;
          p.length         = bar ? c.length : c.height;
          p.density        = c.material.density;
          p.youngs_modulus = c.material.youngs_modulus;
          p.gravity        = bar ? 0. : c.gravity[dim - 1];
          p.fix_end        = bar;
          p.n_elements     = c.ulfem_elements;
          const double v0 = c.amplitude, L = c.length;
          if (bar)
            {
              check_bar_amplitude(c);
              p.initial_velocity = [v0, L](const double X) {
                return v0 * std::sin(numbers::PI * X / L);
              };
            }
          ulfem = std::make_unique<UpdatedLagrangian1D>(p);
        }

        void
        advance_to(const double t) override
        {
          ulfem->advance_to(t);
        }

        typename Reference<dim>::State
        evaluate(const Point<dim> &X, const double) const override
        {
          typename Reference<dim>::State s;
          const auto                     r = ulfem->evaluate(X[direction]);
          s.displacement[direction]        = r.displacement;
          s.velocity[direction]            = r.velocity;
          s.stress[direction][direction]   = r.stress;
          return s;
        }

        unsigned int
        axis() const override
        {
          return direction;
        }

      private:
        const unsigned int                   direction;
        std::unique_ptr<UpdatedLagrangian1D> ulfem;
      };

      template <int dim>
      class BarULFEM : public ULFEM<dim>
      {
      public:
        explicit BarULFEM(const ReferenceContext<dim> &c)
          : ULFEM<dim>(c, true)
        {
        }
      };

      Registration<ReferenceRegistry<2>>
        column({"soil column ulfem",
                "the soil column with large deformations, by a 1D updated "
                "Lagrangian FEM run alongside",
                [](const ReferenceContext<2> &c) {
                  return std::make_unique<ULFEM<2>>(c, false);
                },
                nullptr});
    } // namespace

    RegisterForDims<ReferenceRegistry, BarULFEM> register_bar_ulfem(
      "vibrating bar ulfem",
      "the vibrating bar with large deformations, by a 1D updated "
      "Lagrangian FEM run alongside");
  } // namespace Postprocess
} // namespace psmpm
