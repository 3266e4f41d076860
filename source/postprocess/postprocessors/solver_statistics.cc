// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/postprocess/postprocessor.h>

namespace psmpm
{
  namespace Postprocess
  {
    namespace
    {
      /// The step's mass solves (Solver::GridSystem::statistics()): CG
      /// iterations, condition number estimate, smallest relative
      /// diagonal, DoFs the mass strategy treated, stabilised cells and
      /// the ratio of the smallest to the largest mass diagonal.
      template <int dim>
      class SolverStatistics : public Postprocessor<dim>
      {
      public:
        unsigned int
        order() const override
        {
          return 300;
        }

        void
        execute(const StateView<dim> &state,
                StatisticsTable      &statistics) override
        {
          const auto &gs = state.grid->statistics();
          statistics.add_value("cg_iterations", gs.iterations);
          statistics.add_value("condition_number", gs.condition_number);
          statistics.add_value("min_relative_diagonal",
                               gs.min_relative_diagonal);
          statistics.add_value("treated_dofs", gs.n_treated_dofs);
          statistics.add_value("stabilized_cells", gs.n_stabilized_cells);
          statistics.add_value("mass_diag_ratio",
                               gs.max_diagonal > 0 ?
                                 gs.min_diagonal / gs.max_diagonal :
                                 0.);
          for (const char *c :
               {"mass_diag_ratio", "condition_number", "min_relative_diagonal"})
            {
              statistics.set_scientific(c, true);
              statistics.set_precision(c, 8);
            }
        }
      };
    } // namespace

    RegisterForDims<PostprocessorRegistry, SolverStatistics>
      register_solver_statistics("solver statistics",
                                 "CG iterations and conditioning of the "
                                 "step's mass solves");
  } // namespace Postprocess
} // namespace psmpm
