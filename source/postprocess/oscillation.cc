// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <psmpm/postprocess/oscillation.h>

#include <algorithm>
#include <cmath>

namespace psmpm
{
  namespace Postprocess
  {
    namespace
    {
      /// Crossings of @p m (times), alternating in direction, with
      /// hysteresis @p delta.
      std::vector<double>
      crossings(const std::vector<double> &t,
                const std::vector<double> &x,
                const double               m,
                const double               delta)
      {
        std::vector<double> c;
        int    side    = 0; // -1: below m - delta, +1: above m + delta
        double last_up = -1, last_down = -1;
        for (std::size_t i = 0; i < x.size(); ++i)
          {
            if (i > 0 && (x[i - 1] < m) != (x[i] < m))
              {
                const double tc = t[i - 1] + (m - x[i - 1]) /
                                               (x[i] - x[i - 1]) *
                                               (t[i] - t[i - 1]);
                (x[i] > x[i - 1] ? last_up : last_down) = tc;
              }
            if (x[i] > m + delta && side <= 0)
              {
                if (side < 0 && last_up >= 0)
                  c.push_back(last_up);
                side = 1;
              }
            else if (x[i] < m - delta && side >= 0)
              {
                if (side > 0 && last_down >= 0)
                  c.push_back(last_down);
                side = -1;
              }
          }
        return c;
      }

      /// Time average of the piecewise linear x over [a, b].
      double
      average(const std::vector<double> &t,
              const std::vector<double> &x,
              const double               a,
              const double               b)
      {
        double integral = 0;
        for (std::size_t i = 1; i < t.size(); ++i)
          {
            const double lo = std::max(a, t[i - 1]), hi = std::min(b, t[i]);
            if (hi <= lo)
              continue;
            const double dt = t[i] - t[i - 1];
            const auto   at = [&](const double s) {
              return x[i - 1] + (x[i] - x[i - 1]) * (s - t[i - 1]) / dt;
            };
            integral += 0.5 * (at(lo) + at(hi)) * (hi - lo);
          }
        return integral / (b - a);
      }
    } // namespace

    Oscillation::Result
    Oscillation::measure(const std::vector<double> &t,
                         const std::vector<double> &x)
    {
      AssertThrow(t.size() == x.size(),
                  dealii::ExcMessage("Oscillation: t and x differ in size."));
      if (t.size() < 3 || !(t.back() > t.front()))
        return Result();
      for (const double v : x)
        if (!std::isfinite(v))
          return Result();
      const auto   range = std::minmax_element(x.begin(), x.end());
      const double delta = 0.25 * 0.5 * (*range.second - *range.first);
      if (!(delta > 0))
        return Result();
      Result r;
      double m = average(t, x, t.front(), t.back());
      for (unsigned int pass = 0; pass < 2; ++pass)
        {
          const auto c = crossings(t, x, m, delta);
          if (c.size() < 3)
            return Result();
          // Same-direction spans: c_0 -> the last even one, c_1 -> the
          // last odd one.
          const std::size_t even   = (c.size() - 1) / 2 * 2;
          double            span   = c[even] - c[0];
          double            cycles = even / 2;
          if (c.size() >= 4)
            {
              const std::size_t odd = (c.size() - 2) / 2 * 2 + 1;
              span += c[odd] - c[1];
              cycles += (odd - 1) / 2;
            }
          m           = average(t, x, c[0], c[even]);
          r.valid     = true;
          r.mean      = m;
          r.period    = span / cycles;
          r.crossings = c.size();
        }
      return r;
    }

    void
    Oscillation::fill_summary(const std::vector<double> &t,
                              const std::vector<double> &x,
                              const std::vector<double> &x_reference,
                              Summary                   &summary)
    {
      const Result run = measure(t, x), ref = measure(t, x_reference);
      if (run.valid)
        {
          summary.set("oscillation.tip_mean_deflection", run.mean);
          summary.set("oscillation.period", run.period);
        }
      if (ref.valid)
        {
          summary.set("oscillation.tip_mean_deflection_reference", ref.mean);
          summary.set("oscillation.period_reference", ref.period);
        }
      if (run.valid && ref.valid)
        {
          summary.set("oscillation.tip_mean_deflection_error",
                      run.mean / ref.mean - 1);
          summary.set("oscillation.period_error", run.period / ref.period - 1);
        }
    }
  } // namespace Postprocess
} // namespace psmpm
