// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_postprocess_body_statistics_h
#define psmpm_postprocess_body_statistics_h

#include <psmpm/postprocess/state_view.h>
#include <psmpm/postprocess/statistics_table.h>

namespace psmpm
{
  namespace Postprocess
  {
    using namespace dealii;

    /**
     * Centre of mass of every body of a scene with Bodies: columns
     * body<k>_x (and body<k>_y in 2D), k = 1, 2, ... Whether bodies that
     * met have separated again is read off these (the two-disk impact).
     * Then the largest coordinates of each body's particles,
     * body<k>_x_max (and body<k>_y_max): the run-out and the height of a
     * collapsing column.
     * Nothing for a scene without Bodies, so that its statistics.txt keeps
     * its columns. Collective (sums over the ranks).
     */
    template <int dim>
    class BodyStatistics
    {
    public:
      static void
      add_columns(const StateView<dim> &state, StatisticsTable &statistics);
    };
  } // namespace Postprocess
} // namespace psmpm

#endif
