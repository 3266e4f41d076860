// ---------------------------------------------------------------------
// psmpm: helpers for the tests of the strip footing scenes.
// ---------------------------------------------------------------------
#ifndef psmpm_tests_footing_tests_h
#define psmpm_tests_footing_tests_h

#include "mpm_tests.h"

#include <algorithm>
#include <string>
#include <vector>

/**
 * A strip footing run read from its statistics.txt: per row the
 * settlement s / B (the footing moved down at v0, ramped linearly over
 * the time ramp) and the load q / c_u = -2 F / (B c_u) of the column
 * @p load (the half model's force on the soil), and the run's figures:
 * the floor's reaction against the footing's load once the load is up
 * (s > 0.02 B), the largest kinetic energy and the energy closure
 * (work - dissipated - strain - kinetic) / work of the work column
 * @p work.
 */
struct FootingRun
{
  FootingRun(const StatisticsTable &statistics,
             const std::string     &load,
             const std::string     &work,
             const double           B,
             const double           c_u,
             const double           v0,
             const double           ramp)
    : t(statistics.column("time"))
    , footing(statistics.column(load))
    , floor(statistics.column("reaction_bottom_y"))
    , kinetic(statistics.column("kinetic_energy"))
    , work(statistics.column(work))
    , s(t.size())
    , q(t.size())
  {
    for (std::size_t i = 0; i < t.size(); ++i)
      {
        s[i] = (t[i] < ramp ? v0 * t[i] * t[i] / (2 * ramp) :
                              v0 * (t[i] - ramp / 2)) /
               B;
        q[i] = -2 * footing[i] / B / c_u;
      }
    if (t.empty() || footing.size() != t.size())
      return;
    double footing_sum = 0, floor_sum = 0;
    for (std::size_t i = 0; i < s.size(); ++i)
      {
        if (s[i] > 0.02)
          footing_sum += footing[i], floor_sum += floor[i];
        kinetic_max = std::max(kinetic_max, kinetic[i]);
      }
    balance = -floor_sum / footing_sum - 1;
    closure =
      (this->work.back() - statistics.column("dissipated_energy").back() -
       statistics.column("strain_energy").back() - kinetic.back()) /
      this->work.back();
  }

  /// The mean of q over the rows with lo <= s < hi (0 if none).
  double
  window_mean(const double lo, const double hi) const
  {
    double sum = 0;
    int    n   = 0;
    for (std::size_t i = 0; i < s.size(); ++i)
      if (s[i] >= lo && s[i] < hi)
        sum += q[i], ++n;
    return n > 0 ? sum / n : 0.;
  }

  /// q_u: the largest window_mean() over settlement windows of 0.01 B
  /// (every 0.0025 B); @p at the centre of its window.
  double
  largest_window_mean(double &at) const
  {
    double q_u = 0;
    for (double lo = 0; lo + 0.01 <= s.back() + 1e-12; lo += 0.0025)
      {
        const double mean = window_mean(lo, lo + 0.01);
        if (mean > q_u)
          q_u = mean, at = lo + 0.005;
      }
    return q_u;
  }

  std::vector<double> t, footing, floor, kinetic, work, s, q;
  double              balance = 0, kinetic_max = 0, closure = 0;
};

#endif
