// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_base_phase_timer_h
#define psmpm_base_phase_timer_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>

#include <chrono>
#include <map>
#include <string>
#include <vector>

namespace psmpm
{
  using namespace dealii;

  /**
   * Wall-clock time of the named phases of a time step ("particle to
   * grid", "solve", ...), summed over the run, and their minimum, average
   * and maximum over the MPI ranks at the end.
   *
   * Why not deal.II's TimerOutput: it also measures CPU time, with two
   * getrusage() system calls per section entered. A time step enters about
   * nine sections; strace counted 36,065 getrusage calls in 2000 steps of
   * the large vibrating bar, 2.5 us each on this machine, which was the
   * whole 1.6 s of system time of that run. This timer reads the
   * steady clock only (a vDSO call, no system call) and finds its section
   * by the address of the name literal, without building a std::string.
   * The CPU time of the run as a whole is measured once, by the caller.
   */
  class PhaseTimer
  {
  public:
    PhaseTimer(const MPI_Comm comm, const ConditionalOStream &stream);

    /**
     * Times the enclosing block as section @p name, which must outlive
     * the timer (a string literal). Every rank must enter every section
     * at least once (open a Scope unconditionally, even around work that
     * is empty on some ranks): the statistics at the end reduce section
     * by section over the ranks, and a section missing on one rank makes
     * the others wait for it forever.
     */
    class Scope
    {
    public:
      Scope(PhaseTimer &timer, const char *name);
      ~Scope();

      Scope(const Scope &) = delete;
      Scope &
      operator=(const Scope &) = delete;

    private:
      PhaseTimer                           &timer;
      unsigned int                          section;
      std::chrono::steady_clock::time_point start;
    };

    /**
     * Splits the time of a loop that interleaves phases chunk by chunk
     * (move, locate, particle to grid: TransferScheme::
     * move_and_update_material()) among their sections: lap(name) charges
     * the time since the previous lap (or since construction) to section
     * @p name. One clock read per lap, against two for a Scope; the
     * enclosing code must not hold a Scope of its own (its time would be
     * counted twice).
     */
    class Laps
    {
    public:
      explicit Laps(PhaseTimer &timer);
      void
      lap(const char *name);

    private:
      PhaseTimer                           &timer;
      std::chrono::steady_clock::time_point last;
    };

    /// Total wall seconds per section on this rank.
    std::map<std::string, double>
    wall_times() const;

    /// Minimum, average and maximum over the ranks of every section's
    /// wall time, written to the stream (collective).
    void
    print_wall_time_statistics() const;

  private:
    struct Section
    {
      const char  *name;
      double       seconds;
      unsigned int calls;
    };

    unsigned int
    find(const char *name);

    MPI_Comm             comm;
    ConditionalOStream   out;
    std::vector<Section> sections;
  };
} // namespace psmpm

#endif
