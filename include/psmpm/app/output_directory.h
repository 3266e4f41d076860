// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_app_output_directory_h
#define psmpm_app_output_directory_h

#include <deal.II/base/mpi.h>

#include <fstream>
#include <iostream>
#include <memory>
#include <string>

namespace psmpm
{
  namespace App
  {
    /**
     * The output directory of a run. Policy: the directory is created if
     * needed; the files an earlier psmpm run wrote into it (VTU/PVTU/PVD
     * series, the particle HDF5/XDMF series, statistics.txt, summary.json,
     * parameters.prm, log.txt, tracked_particle.txt, checkpoints and leftover
     * *.tmp; regular files only) are removed before the new run writes
     * anything, other files are left alone. A resumed run (--resume) keeps
     * them: it continues that run's files from its newest checkpoint; only
     * leftover *.tmp files (of a run killed while writing) are removed. A lock
     * file (psmpm.lock, with the process id and host) refuses a second run into
     * the same directory while the first one lives; a lock left by a process
     * that no longer exists on this host is taken over. The lock is removed by
     * the destructor.
     */
    class OutputDirectory
    {
    public:
      /// Name of the lock file inside the directory.
      static constexpr const char *lock_name = "psmpm.lock";

      /// Check the name without creating anything (--validate): not
      /// empty, not an existing non-directory. Throws ExcMessage.
      static void
      check_name(const std::string &directory);

      /// Create, lock and clear the directory on rank 0 (@p resume: keep
      /// the earlier run's files); collective: if rank 0 fails, every rank
      /// throws ExcMessage with its message.
      void
      open(const std::string &directory,
           MPI_Comm           comm,
           const bool         resume = false);

      ~OutputDirectory();

      /// Remove the lock (also done by the destructor).
      void
      release();

    private:
      std::string lock_file;
    };

    /**
     * While it exists, everything written to std::cout and std::cerr on
     * this rank is also written to @p file (log.txt of the output
     * directory; appended to if @p append, for a resumed run). Inactive
     * (no file) on other ranks than 0.
     */
    class LogFile
    {
    public:
      LogFile(const std::string &file,
              const bool         active,
              const bool         append = false);
      ~LogFile();

    private:
      std::ofstream                   log;
      std::unique_ptr<std::streambuf> out_tee, err_tee;
      std::streambuf                 *old_out = nullptr, *old_err = nullptr;
    };
  } // namespace App
} // namespace psmpm

#endif
