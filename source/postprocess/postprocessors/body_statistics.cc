// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/postprocess/body_statistics.h>
#include <psmpm/postprocess/postprocessor.h>

namespace psmpm
{
  namespace Postprocess
  {
    namespace
    {
      /// Centre of mass and largest coordinates of every body
      /// (BodyStatistics; nothing for a scene without Bodies).
      template <int dim>
      class Bodies : public Postprocessor<dim>
      {
      public:
        unsigned int
        order() const override
        {
          return 200;
        }

        void
        execute(const StateView<dim> &state,
                StatisticsTable      &statistics) override
        {
          BodyStatistics<dim>::add_columns(state, statistics);
        }
      };
    } // namespace

    RegisterForDims<PostprocessorRegistry, Bodies>
      register_bodies("body statistics",
                      "centre of mass and largest coordinates of every body "
                      "(scenes with Bodies)");
  } // namespace Postprocess
} // namespace psmpm
