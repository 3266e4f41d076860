// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include <psmpm/postprocess/deposit_front.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace psmpm
{
  namespace Postprocess
  {
    double
    DepositFront::compute(const std::vector<double> &x,
                          const double               x_min,
                          const double               x_max,
                          const double               gap,
                          const MPI_Comm             comm)
    {
      if (!(x_max > x_min))
        return x_max;
      const double       range       = x_max - x_min;
      const double       bins_wanted = std::ceil(range / gap) + 1;
      const unsigned int n_bins      = bins_wanted < max_bins ?
                                         static_cast<unsigned int>(bins_wanted) :
                                         max_bins;
      const double       width       = range / (n_bins - 1);
      constexpr double   big         = std::numeric_limits<double>::max();
      lowest.assign(n_bins, big);
      highest.assign(n_bins, -big);
      for (const double value : x)
        {
          const double       s = (value - x_min) / width;
          const unsigned int k =
            s <= 0 ?
              0 :
              std::min<unsigned int>(static_cast<unsigned int>(s), n_bins - 1);
          lowest[k]  = std::min(lowest[k], value);
          highest[k] = std::max(highest[k], value);
        }
      dealii::Utilities::MPI::min(lowest, comm, lowest);
      dealii::Utilities::MPI::max(highest, comm, highest);
      double front = x_min;
      for (unsigned int k = 0; k < n_bins; ++k)
        if (lowest[k] <= highest[k])
          {
            if (lowest[k] - front > gap)
              break;
            front = highest[k];
          }
      return front;
    }
  } // namespace Postprocess
} // namespace psmpm
