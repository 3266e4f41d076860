// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_postprocess_deposit_front_h
#define psmpm_postprocess_deposit_front_h

#include <deal.II/base/mpi.h>

#include <vector>

namespace psmpm
{
  namespace Postprocess
  {
    /**
     * The front of a deposit along one coordinate: the particles sorted by
     * that coordinate from the smallest, the largest value before the first
     * gap wider than @p gap between neighbours. A run-out measured at the
     * front particle is set by a few particles thrown ahead of a granular
     * flow; this is the front of the connected deposit (the run-out the
     * column-collapse experiments report).
     *
     * Without sorting: the range [x_min, x_max] is cut into bins no wider
     * than the gap, and each bin keeps its smallest and largest value.
     * Inside a bin no gap exceeds the gap; between two consecutive
     * occupied bins the gap is exactly the next bin's smallest minus the
     * last bin's largest. One pass over the values, reductions over the
     * ranks of two arrays of at most max_bins numbers. Where the range
     * holds more than max_bins gaps, the bins are wider than the gap and
     * a gap up to one bin wide inside a bin goes unseen.
     */
    class DepositFront
    {
    public:
      static constexpr unsigned int max_bins = 1u << 16;

      /**
       * The front of the values @p x (this rank's; a collective over
       * @p comm, every rank gets the same result). @p x_min and @p x_max
       * are the range over all ranks (x_min > x_max: no values anywhere;
       * then x_max is returned, as body<k>_x_max does).
       */
      double
      compute(const std::vector<double> &x,
              const double               x_min,
              const double               x_max,
              const double               gap,
              const MPI_Comm             comm);

    private:
      std::vector<double> lowest;
      std::vector<double> highest;
    };
  } // namespace Postprocess
} // namespace psmpm

#endif
