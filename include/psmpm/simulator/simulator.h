// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_simulator_simulator_h
#define psmpm_simulator_simulator_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <psmpm/base/growing_text_file.h>
#include <psmpm/base/phase_timer.h>
#include <psmpm/base/summary.h>
#include <psmpm/mesh/mesh_generator.h>
#include <psmpm/particles/particle_generator.h>
#include <psmpm/postprocess/energies.h>
#include <psmpm/postprocess/error_norms.h>
#include <psmpm/postprocess/output_writer.h>
#include <psmpm/postprocess/reference.h>
#include <psmpm/postprocess/statistics_table.h>
#include <psmpm/simulator/boundary_conditions.h>
#include <psmpm/simulator/checkpoint.h>
#include <psmpm/simulator/contact_coupling.h>
#include <psmpm/simulator/discretisation.h>
#include <psmpm/simulator/initial_conditions.h>
#include <psmpm/simulator/output_files.h>
#include <psmpm/simulator/particle_relocation.h>
#include <psmpm/simulator/postprocessors.h>
#include <psmpm/simulator/reconstruction.h>
#include <psmpm/simulator/run_record.h>
#include <psmpm/simulator/scene_text.h>
#include <psmpm/simulator/stability_monitor.h>
#include <psmpm/simulator/state.h>
#include <psmpm/simulator/time_step_control.h>
#include <psmpm/simulator/transfer_scheme.h>
#include <psmpm/simulator/transfer_setup.h>

#include <array>
#include <cstdint>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace psmpm
{
  namespace Simulator
  {
    using namespace dealii;

    /// What a run will cost, estimated before it starts (RunLimits).
    struct RunSize
    {
      double steps        = 0; ///< time steps to the end time
      double n_cells      = 0;
      double n_particles  = 0; ///< over all ranks
      double n_outputs    = 0; ///< VTU outputs written
      double output_bytes = 0; ///< all VTU outputs and statistics
      double end_time     = 0;
      /// Where the time step comes from, for messages: "Time/Time step =
      /// ..." or the automatic step and the material that sets it.
      std::string time_step;
    };

    /// What the application needs of a run, whatever its dimension.
    class SimulatorBase
    {
    public:
      virtual ~SimulatorBase() = default;
      virtual void
      parse_parameters(ParameterHandler &prm) = 0;
      virtual void
      setup() = 0;
      virtual Status
      run(const std::string &output_directory) = 0;
      /// Continue from the first readable of @p checkpoint_files (newest
      /// first; after setup(), before run(); collective). Throws
      /// ExcMessage naming the files if none can be read or the one read
      /// was written with other parameters.
      virtual void
      resume(const std::string              &output_directory,
             const std::vector<std::string> &checkpoint_files) = 0;
      virtual void
      fill_summary(Summary &summary) const = 0;
      virtual Failure
      get_failure() const = 0;
      /// Estimated steps and output volume (after setup(); collective).
      virtual RunSize
      estimate_size() const = 0;
      /// Throw ExcMessage naming the entry if the initial state (after
      /// setup()) is not finite, e.g. Initial conditions/Velocity = 1/0.
      virtual void
      check_initial_state() const = 0;

      /// Quiet mode: no screen output (tests).
      bool quiet = false;
      /// Output/Time interval: also write output whenever the simulated
      /// time passes a multiple of this (0: only Output/Interval).
      double output_time_interval = 0;
      /// Seconds of wall time between progress lines (0: none).
      double progress_interval = 0;
      /// The signal that ended an interrupted run (0 otherwise).
      int stop_signal = 0;
    };

    /**
     * An MPM run in @p dim dimensions: reads the scene, builds the State
     * and the components (space, mass strategy, material, transfer
     * scheme, time step control, stability monitor, reference and
     * postprocessors, each from its registry or subsection) and runs the
     * time loop.
     */
    template <int dim>
    class Simulator : public SimulatorBase
    {
    public:
      explicit Simulator(MPI_Comm comm);

      /// Every entry of an MPM scene (the same for all dimensions).
      static void
      declare_parameters(ParameterHandler &prm);

      /// Parse and check everything; throws ExcMessage naming the entry.
      void
      parse_parameters(ParameterHandler &prm) override;

      /// Mesh, DoFs, particles, time step; throws on invalid input. No
      /// file is written.
      void
      setup() override;

      /// Time loop; writes output into @p output_directory (which exists).
      /// Stops after the step in which any rank received a StopRequest
      /// signal (Status::interrupted); throws ExcWriteFailed on every rank
      /// if any rank could not write a file. Writes a checkpoint when
      /// Checkpoint says so, at the end and when interrupted (not when
      /// unstable).
      Status
      run(const std::string &output_directory) override;

      /**
       * Replace the state set up from the scene by that of the first of
       * @p checkpoint_files that can be read (a damaged newer one is
       * reported as a warning and skipped): particles (handed to the ranks
       * owning their cells), time, step and step size, and the history of every
       * component (statistics rows, .pvd records, tracked particle,
       * energy, rotation and error statistics, mass strategy); references
       * computed alongside the run are advanced again through the
       * checkpointed step times. run() then continues the time loop.
       */
      void
      resume(const std::string              &output_directory,
             const std::vector<std::string> &checkpoint_files) override;

      /// Write a checkpoint of the current state now (collective; run()
      /// must have started or resume() been called).
      void
      write_checkpoint();
      /// The checkpoint of the current state (collective; the particles
      /// on rank 0 only).
      Archive
      checkpoint_archive();

      /// One time step (public for tests): transfer, locate, advance time.
      void
      do_time_step(const double dt);

      /// The length of the next step: the automatic step recomputed from
      /// the current state (or the fixed one), cut at the end time.
      double
      next_time_step();

      /// Status, errors, counts and timers (the caller adds wall time).
      void
      fill_summary(Summary &summary) const override;

      Postprocess::Errors
      compute_errors() const;
      Postprocess::Energies<dim>
      compute_energies() const;

      RunSize
      estimate_size() const override;
      void
      check_initial_state() const override;

      Failure
      get_failure() const override
      {
        return monitor.get_failure();
      }
      /// The mass matrix and transfer in use (`automatic` resolved).
      const std::string &
      get_mass_matrix_name() const
      {
        return discretisation.grid_parameters.type;
      }
      const std::string &
      get_transfer_name() const
      {
        return transfers.name;
      }
      const State<dim> &
      get_state() const
      {
        return state;
      }
      const Particles::ParticleSet<dim> &
      get_particles() const
      {
        return state.particles;
      }
      const Mesh::CellLocator<dim> &
      get_locator() const
      {
        return state.locator;
      }
      const ParticleRelocation<dim> &
      get_relocation() const
      {
        return relocation;
      }
      double
      get_time_step() const
      {
        return time_step_control.get_time_step();
      }
      double
      get_time() const
      {
        return state.time;
      }
      unsigned int
      get_n_dofs() const
      {
        return discretisation.n_functions;
      }

    private:
      /// RunSize::time_step: the fixed step's entry, or the automatic
      /// step with the material whose wave speed sets it.
      std::string
      describe_time_step() const;
      /// Mesh/Distribution = distributed: refuse what is not verified on
      /// a mesh that each rank holds only in part.
      void
      check_distribution() const;
      /// Build the triangulation (replicated or distributed).
      void
      create_mesh();
      /// Space, DoFs, the mass matrix and transfer for this mesh, the grid
      /// system and the boundary conditions.
      void
      setup_space_and_grid();
      /// The boundary ids of Boundary conditions/Fixed x (and y).
      std::array<std::set<types::boundary_id>, dim>
      fixed_boundary_ids() const;
      /// Whether the closed-mesh choice applies: automatic mass, and
      /// material that fills a mesh whose boundaries are all closed in
      /// their normal direction (@p fixed; decided over all ranks).
      bool
      closed_and_filled(
        const std::array<std::set<types::boundary_id>, dim> &fixed) const;
      void
      create_grid_system(
        const std::array<std::set<types::boundary_id>, dim> &fixed);
      void
      setup_particles();
      void
      locate_particles();
      void
      postprocess(const double wall_time);
      void
      write_output();
      void
      write_statistics();
      void
      create_postprocessors(const std::string &directory);
      /// What the postprocessors read now: the state, the reference, the
      /// transfer's affine matrices, the last step, the output directory.
      Postprocess::StateView<dim>
      view() const;

      /// Run @p write on every rank; every rank learns of a failed write
      /// (the first message wins) and throws ExcWriteFailed.
      template <typename Write>
      void
      checked(const Write &write);
      /// Before the first step: the initial output, or after resume() the
      /// files as of the checkpoint; the run's header line.
      void
      begin_run(const std::string &directory);
      /// Whether output is due after this step (counts the multiples of
      /// Output/Time interval passed).
      bool
      output_due();
      /// The timers and, for a run that did not complete, why.
      void
      report_end() const;

      /// Rank 0 reads the first readable of @p files into @p archive and
      /// checks it; every rank learns the verdict and the file's name
      /// (returned), and throws ExcMessage naming it if none is usable.
      std::string
      read_checkpoint(const std::vector<std::string> &files, Archive &archive);
      /// Particles and components from @p archive (read on rank 0).
      void
      restore(Archive &archive);
      /// The archive's particles, handed to the ranks owning their cells.
      void
      restore_particles(const Archive &archive);
      /// Everything but the particles, from the archive every rank has.
      void
      restore_components(const Archive &shared);
      /// Throw ExcMessage if the checkpoint @p file is past Time/End time.
      void
      check_end_time(const std::string &file) const;
      /// After resume(): statistics.txt, the .pvd series and
      /// tracked_particle.txt as of the checkpoint; later VTU files removed.
      void
      restore_files();

      /// Status, reason, steps and resume of summary.json.
      void
      fill_status(Summary &summary) const;
      /// The phase timers and the throughput of the time loop.
      void
      fill_timings(Summary &summary) const;

      MPI_Comm           comm;
      ConditionalOStream pcout;
      State<dim>         state;

      // Scene description.
      Mesh::MeshGenerator<dim>          mesh_generator;
      Particles::ParticleGenerator<dim> particle_generator;
      Discretisation<dim>               discretisation;
      TransferSetup<dim>                transfers;
      InitialConditions<dim>            initial_conditions;
      /// Boundary conditions/Fixed x (and y): the boundaries by name.
      std::array<std::vector<std::string>, dim> fixed_names;
      /// Reactions, friction, prescribed velocities, boundary parts.
      BoundaryConditions<dim> boundary_conditions;
      /// Multi-velocity contact between the bodies (subsection Contact).
      ContactCoupling<dim> contact;
      /// What checkpoints of this run are compared with.
      SceneText scene_text;

      // Components.
      /// Locates the moved particles; counts the particles that changed
      /// cells on this rank since the run (or its resume) started: grid
      /// crossings, the source of MPM's grid-crossing noise (summary.json
      /// "cell_crossings").
      ParticleRelocation<dim>                      relocation;
      Checkpoint                                   checkpoint;
      TimeStepControl                              time_step_control;
      StabilityMonitor                             monitor;
      std::unique_ptr<Postprocess::Reference<dim>> reference;
      /// Every registered postprocessor (energies, rotation, bodies, mass
      /// solves, error norms, tracked particle, ...).
      Postprocessors<dim> postprocessors;

      // Run record.
      OutputFiles<dim> output;
      PhaseTimer       timer;
      RunRecord        record;
    };

    /// A Simulator<1> or Simulator<2> (Geometry/Dimension).
    std::unique_ptr<SimulatorBase>
    create_simulator(const unsigned int dimension, MPI_Comm comm);
  } // namespace Simulator
} // namespace psmpm

#endif
