// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include <psmpm/base/phase_timer.h>

#include <cstring>
#include <iomanip>
#include <sstream>

namespace psmpm
{
  PhaseTimer::PhaseTimer(const MPI_Comm comm, const ConditionalOStream &stream)
    : comm(comm)
    , out(stream)
  {
  }

  unsigned int
  PhaseTimer::find(const char *name)
  {
    // A handful of sections: a linear search by address first (the same
    // literal every step), by content for a literal seen elsewhere.
    for (unsigned int i = 0; i < sections.size(); ++i)
      if (sections[i].name == name)
        return i;
    for (unsigned int i = 0; i < sections.size(); ++i)
      if (std::strcmp(sections[i].name, name) == 0)
        return i;
    sections.push_back({name, 0., 0});
    return sections.size() - 1;
  }

  PhaseTimer::Scope::Scope(PhaseTimer &timer, const char *name)
    : timer(timer)
    , section(timer.find(name))
    , start(std::chrono::steady_clock::now())
  {
  }

  PhaseTimer::Scope::~Scope()
  {
    const std::chrono::duration<double> elapsed =
      std::chrono::steady_clock::now() - start;
    // An index, not a reference: a nested scope may have grown the vector.
    timer.sections[section].seconds += elapsed.count();
    ++timer.sections[section].calls;
  }

  PhaseTimer::Laps::Laps(PhaseTimer &timer)
    : timer(timer)
    , last(std::chrono::steady_clock::now())
  {
  }

  void
  PhaseTimer::Laps::lap(const char *name)
  {
    const auto                          now = std::chrono::steady_clock::now();
    const std::chrono::duration<double> elapsed = now - last;
    last                                        = now;
    const unsigned int section                  = timer.find(name);
    timer.sections[section].seconds += elapsed.count();
    ++timer.sections[section].calls;
  }

  std::map<std::string, double>
  PhaseTimer::wall_times() const
  {
    std::map<std::string, double> times;
    for (const auto &s : sections)
      times[s.name] += s.seconds;
    return times;
  }

  void
  PhaseTimer::print_wall_time_statistics() const
  {
    // Sorted by name, so that every rank reduces the same sections in the
    // same order.
    const auto         times = wall_times();
    std::ostringstream table;
    table << std::left << std::setw(24) << "Section" << std::right
          << std::setw(12) << "min (s)" << std::setw(12) << "avg (s)"
          << std::setw(12) << "max (s)" << '\n';
    for (const auto &t : times)
      {
        const auto stats = Utilities::MPI::min_max_avg(t.second, comm);
        table << std::left << std::setw(24) << t.first << std::right
              << std::fixed << std::setprecision(4) << std::setw(12)
              << stats.min << std::setw(12) << stats.avg << std::setw(12)
              << stats.max << '\n';
      }
    out << table.str() << std::flush;
  }
} // namespace psmpm
