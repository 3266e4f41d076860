// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_base_cpu_time_h
#define psmpm_base_cpu_time_h

#include <sys/resource.h>

namespace psmpm
{
  /// User + system CPU seconds of this process so far (getrusage): the
  /// cost of a run that other load on the machine hardly changes, unlike
  /// its wall time.
  inline double
  process_cpu_seconds()
  {
    rusage usage;
    getrusage(RUSAGE_SELF, &usage);
    const auto seconds = [](const timeval &t) {
      return t.tv_sec + 1e-6 * t.tv_usec;
    };
    return seconds(usage.ru_utime) + seconds(usage.ru_stime);
  }
} // namespace psmpm

#endif
