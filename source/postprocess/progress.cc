// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/postprocess/progress.h>

#include <cstdio>

namespace psmpm
{
  namespace Postprocess
  {
    namespace
    {
      std::string
      duration(const double s)
      {
        char buf[64];
        if (s < 120)
          std::snprintf(buf, sizeof(buf), "%.1f s", s);
        else if (s < 7200)
          std::snprintf(buf, sizeof(buf), "%.1f min", s / 60);
        else
          std::snprintf(buf, sizeof(buf), "%.1f h", s / 3600);
        return buf;
      }
    } // namespace

    Progress::Progress(std::ostream &out,
                       const bool    active,
                       const double  interval)
      : out(out)
      , active(active)
      , interval(interval)
      , start(std::chrono::steady_clock::now())
      , last(start)
    {
    }

    void
    Progress::update(const unsigned int step,
                     const double       time,
                     const double       end_time)
    {
      if (!active)
        return;
      const auto now = std::chrono::steady_clock::now();
      if (std::chrono::duration<double>(now - last).count() < interval)
        return;
      last = now;
      out << line(step,
                  time,
                  end_time,
                  std::chrono::duration<double>(now - start).count())
          << std::endl;
    }

    std::string
    Progress::line(const unsigned int step,
                   const double       time,
                   const double       end_time,
                   const double       wall_seconds) const
    {
      const double fraction = end_time > 0 ? time / end_time : 1;
      char         buf[160];
      std::snprintf(
        buf,
        sizeof(buf),
        "psmpm: step %u, t = %.6g s (%.1f %%), wall %s, ETA %s",
        step,
        time,
        100 * fraction,
        duration(wall_seconds).c_str(),
        fraction > 0 ?
          duration(wall_seconds * (1 - fraction) / fraction).c_str() :
          "unknown");
      return buf;
    }
  } // namespace Postprocess
} // namespace psmpm
