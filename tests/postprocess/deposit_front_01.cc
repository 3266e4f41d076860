// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Postprocess::DepositFront (Output/Deposit front gap, the columns
// body<k>_x_front) against its definition: the values sorted, the last one
// before the first gap wider than g. Random deposits (a dense part, then
// sparser particles thrown ahead, gaps drawn around g so that some are
// wider and some narrower), the values dealt to the ranks in turn (the
// .mpirun=2 variant: every rank must get the front of all values), gaps
// equal to g exactly (not wider: the deposit goes on), one value, a rank
// without values, no values anywhere (then x_max, as body<k>_x_max), and a
// range of more than max_bins gaps (bins wider than g: the front can only
// lie further out, never short of the definition's).
#include <deal.II/base/mpi.h>

#include <psmpm/postprocess/deposit_front.h>

#include "../tests.h"

#include <algorithm>
#include <limits>
#include <random>
#include <vector>

namespace
{
  double
  front_by_sorting(std::vector<double> x, const double gap)
  {
    std::sort(x.begin(), x.end());
    for (std::size_t i = 0; i + 1 < x.size(); ++i)
      if (x[i + 1] - x[i] > gap)
        return x[i];
    return x.back();
  }

  // This rank's share of the values, and the range over all of them.
  double
  front_on_ranks(const std::vector<double> &all, const double gap)
  {
    const unsigned int  rank = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    const unsigned int  size = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    std::vector<double> mine;
    for (std::size_t i = rank; i < all.size(); i += size)
      mine.push_back(all[i]);
    double low = std::numeric_limits<double>::max(), high = -low;
    for (const double x : all)
      low = std::min(low, x), high = std::max(high, x);
    psmpm::Postprocess::DepositFront front;
    return front.compute(mine, low, high, gap, MPI_COMM_WORLD);
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out = root_output();
  return run_test([&out]() {
    std::mt19937 random(7);
    unsigned int agree = 0, cases = 0, beyond_some_gap = 0;
    for (unsigned int trial = 0; trial < 200; ++trial)
      {
        const double                           gap = 0.001 * (1 + trial % 17);
        std::uniform_real_distribution<double> dense(0, 0.5 * gap);
        std::uniform_real_distribution<double> sparse(0.5 * gap, 1.6 * gap);
        std::vector<double>                    x;
        double                                 at = -0.3 + 0.01 * (trial % 5);
        const unsigned int n_dense = 50 + trial % 300, n_sparse = trial % 12;
        for (unsigned int i = 0; i < n_dense + n_sparse; ++i)
          {
            at += i < n_dense ? dense(random) : sparse(random);
            x.push_back(at);
          }
        std::shuffle(x.begin(), x.end(), random);
        const double expected = front_by_sorting(x, gap);
        agree += front_on_ranks(x, gap) == expected;
        beyond_some_gap += expected < *std::max_element(x.begin(), x.end());
        ++cases;
      }
    out << "random deposits: " << agree << " of " << cases
        << " fronts equal the sorted definition's (" << beyond_some_gap
        << " with particles beyond the front)" << std::endl;
    PSMPM_CHECK(out, agree == cases && beyond_some_gap > cases / 4);

    // Gaps of exactly g are not wider than g; 0.25 is exact in binary.
    PSMPM_CHECK(out, front_on_ranks({0, 0.25, 0.5, 0.75, 2}, 0.25) == 0.75);
    PSMPM_CHECK(out, front_on_ranks({0, 0.25, 0.5, 0.75, 2}, 0.2) == 0);
    PSMPM_CHECK(out, front_on_ranks({1.5}, 0.1) == 1.5);
    // Two values: rank 1 of two ranks gets one, rank 0 the other.
    PSMPM_CHECK(out, front_on_ranks({3, 1}, 1.5) == 1);
    PSMPM_CHECK(out, front_on_ranks({3, 1}, 2) == 3);
    psmpm::Postprocess::DepositFront front;
    const double                     big = std::numeric_limits<double>::max();
    PSMPM_CHECK(out, front.compute({}, big, -big, 0.1, MPI_COMM_WORLD) == -big);

    // More than max_bins gaps in the range: a front at or beyond the
    // definition's (a gap narrower than a bin can hide inside one).
    std::vector<double> wide;
    for (unsigned int i = 0; i < 1000; ++i)
      wide.push_back(1e-7 * i);
    wide.push_back(1e-7 * 999 + 2e-7);
    wide.push_back(1);
    const double coarse = front_on_ranks(wide, 1.5e-7);
    PSMPM_CHECK(out, coarse >= front_by_sorting(wide, 1.5e-7) && coarse < 1);
  });
}
