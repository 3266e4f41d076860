// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_simulator_checkpoint_h
#define psmpm_simulator_checkpoint_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <psmpm/base/archive.h>
#include <psmpm/particles/particle_set.h>

#include <chrono>
#include <string>
#include <vector>

namespace psmpm
{
  namespace Simulator
  {
    using namespace dealii;

    /**
     * The checkpoint files of a run (subsection "Checkpoint";
     * doc/checkpoints.md): when they are due, how an Archive becomes a
     * file that is either complete or absent, which file a resumed run
     * reads, and whether its scene is the one that wrote it.
     *
     * A checkpoint is written by rank 0 into "checkpoint.h5.tmp" in the
     * output directory, flushed, closed and fsynced, then renamed to
     * "checkpoint-<step>.h5" (the directory is fsynced too); only then are
     * older checkpoints removed, all but the previous one, which remains
     * as a fallback should the newest be damaged later. A process killed
     * at any moment therefore leaves the last complete checkpoint in
     * place, and at most a stale .tmp file that resuming ignores.
     *
     * Particles of all ranks are gathered on rank 0 (which must hold them
     * all in memory once) and, on resume, handed to the ranks that own
     * their cells, whatever the number of ranks that wrote them.
     */
    class Checkpoint
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      /// Whether any checkpoint is written before the end of the run.
      bool
      periodic() const
      {
        return interval > 0 || wall_interval > 0;
      }

      /// Start counting steps and wall time from @p step (run start or
      /// resume).
      void
      start(const unsigned int step);

      /// Whether a checkpoint is due after @p step: every Interval steps,
      /// or once Wall interval minutes have passed since the last one (rank
      /// 0's clock; collective if Wall interval is set).
      bool
      due(const unsigned int step, MPI_Comm comm) const;

      /// The last step written or resumed from.
      unsigned int
      last_step() const
      {
        return last;
      }

      /**
       * Write @p archive of rank 0 as checkpoint-<step>.h5 in @p directory
       * (collective). If @p step is the one after the state kept by
       * keep_state_before_last_step(), that state is added to @p archive
       * first, under before_last_step_prefix. Throws ExcWriteFailed naming
       * the file on every rank if it could not be written; the previous
       * checkpoint is then kept.
       */
      void
      write(const std::string &directory,
            const unsigned int step,
            Archive           &archive,
            MPI_Comm           comm);

      /// Where a checkpoint at the end of a run holds the state before the
      /// run's last step.
      static constexpr const char *before_last_step_prefix =
        "before_last_step/";

      /**
       * Keep @p archive, the checkpoint of the state after @p step, taken
       * just before the step that ends the run, until the checkpoint of the
       * next step (the run's last) is written, which then carries it too.
       *
       * The last step is cut to land on Time/End time (or the time is
       * snapped to it), so it is not the step a run with a later End time
       * takes. A resume with a later End time therefore restarts from the
       * state before it (restart_before_last_step()) and takes the full
       * step, bit-identical to a run that had the later End time from the
       * start; its files of the cut step (statistics row, outputs) are
       * replaced as after any resume.
       */
      void
      keep_state_before_last_step(Archive &&archive, const unsigned int step);

      /**
       * If @p archive (a checkpoint at the end of its run) holds the state
       * before the run's last step, replace @p archive by that checkpoint
       * and return true; otherwise leave it and return false (a checkpoint
       * of an older psmpm, or of a run that took no step).
       */
      static bool
      restart_before_last_step(Archive &archive);

      /// "checkpoint-<step>.h5" (at least 8 digits).
      static std::string
      file_name(const unsigned int step);

      /// The name of the temporary file a checkpoint is written into.
      static constexpr const char *temporary_name = "checkpoint.h5.tmp";

      /// Whether @p name is a checkpoint file (or its temporary file).
      static bool
      is_checkpoint_file(const std::string &name);

      /// The checkpoints in @p directory, newest (largest step) first.
      static std::vector<std::string>
      list(const std::string &directory);

      /**
       * The entries ("Subsection/Entry: saved -> current") in which two
       * parameter files printed as ShortPRM differ, except those that a
       * resumed run may change without changing its results: Time/End
       * time (to extend a run), Output directory, Output/Interval, Time
       * interval, Subdivisions, Progress interval, Test output, and the
       * subsections Checkpoint and Limits.
       *
       * An entry missing from @p saved (a checkpoint written before the
       * entry existed) is no difference if its current value is its
       * default, as printed in @p defaults (the declarations alone, as
       * ShortPRM; empty: no defaults known).
       */
      static std::vector<std::string>
      parameter_differences(const std::string &saved,
                            const std::string &current,
                            const std::string &defaults = "");

      /**
       * One line "Subsection/File<TAB>file<TAB>checksum" for every entry
       * named File in the ShortPRM text @p parameters (the mesh, the
       * bodies' geometry; paths as the readers open them, already
       * resolved against the parameter file) that names a readable file:
       * the 64-bit FNV-1a checksum of its bytes, in hexadecimal.
       */
      static std::string
      file_checksums(const std::string &parameters);

      /**
       * The files of @p saved (file_checksums() at the start of the run
       * that wrote a checkpoint) whose content differs in @p current (the
       * same now), each as "<entry>: the content of <file> changed since
       * the checkpoint (...)". A File entry whose path differs is a
       * parameter difference instead (parameter_differences()).
       */
      static std::vector<std::string>
      file_differences(const std::string &saved, const std::string &current);

      /**
       * Every rank's @p local on rank 0, one vector per rank in rank order
       * (no vectors on the other ranks): the raw MPI_Gatherv that also
       * gathers the particles (Utilities::MPI::gather serializes and
       * gzips). For per-rank data such as the solvers' warm-start fields.
       */
      static std::vector<std::vector<double>>
      gather_per_rank(const std::vector<double> &local, MPI_Comm comm);

      /// Gather the particles of all ranks, in rank order, into
      /// @p archive of rank 0 (ParticleSet::save()). Cells are written
      /// as their index in the whole mesh: @p whole_index of the rank's
      /// cells on a distributed mesh, empty on a replicated one.
      template <int dim>
      static void
      gather_particles(const Particles::ParticleSet<dim> &particles,
                       Archive                           &archive,
                       MPI_Comm                           comm,
                       const std::vector<unsigned int>   &whole_index = {});

      /**
       * Replace @p particles by those of @p archive (read on rank 0) whose
       * cells @p cell_owner gives to this rank, in the order of the file.
       * Throws ExcMessage on every rank if rank 0 finds the particle
       * entries missing or inconsistent (e.g. a cell beyond the mesh).
       */
      template <int dim>
      static void
      scatter_particles(const Archive                   &archive,
                        const std::vector<unsigned int> &cell_owner,
                        Particles::ParticleSet<dim>     &particles,
                        MPI_Comm                         comm);

    private:
      unsigned int                          interval      = 0;
      double                                wall_interval = 0; ///< seconds
      unsigned int                          last          = 0;
      std::chrono::steady_clock::time_point last_wall;
      /// keep_state_before_last_step(): the state and its step.
      Archive      before_last_step;
      unsigned int before_last_step_number = 0;
    };
  } // namespace Simulator
} // namespace psmpm

#endif
