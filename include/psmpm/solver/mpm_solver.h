// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_solver_mpm_solver_h
#define psmpm_solver_mpm_solver_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/table_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>

#include <psmpm/basis/space.h>
#include <psmpm/material/linear_elastic.h>
#include <psmpm/mesh/cell_locator.h>
#include <psmpm/mesh/mesh_generator.h>
#include <psmpm/particles/particle_generator.h>
#include <psmpm/particles/particle_set.h>
#include <psmpm/postprocess/output_writer.h>
#include <psmpm/postprocess/reference_solution.h>
#include <psmpm/postprocess/summary.h>
#include <psmpm/solver/grid_system.h>

#include <memory>
#include <string>

namespace psmpm
{
  namespace Solver
  {
    using namespace dealii;

    /**
     * Material Point Method with the modified update of thesis Fig. 2.5
     * (Sulsky's MUSL): one function per phase of the time step. The
     * basis is any Basis::Space; the mass matrix is consistent or lumped.
     */
    class MPMSolver
    {
    public:
      /// How a run ended; unstable runs carry the reason.
      enum class Status
      {
        completed,
        unstable
      };

      /// Which stability monitor stopped the run (each has its own exit
      /// code, see App::ExitCode).
      enum class Failure : int
      {
        none = 0,
        non_finite,
        energy_growth,
        left_mesh,
        non_positive_volume,
        solver
      };

      Failure
      get_failure() const
      {
        return failure;
      }

      MPMSolver(MPI_Comm comm);
      ~MPMSolver();

      static void
      declare_parameters(ParameterHandler &prm);
      /// Parse and check everything; throws ExcMessage naming the entry.
      void
      parse_parameters(ParameterHandler &prm);

      /// Mesh, DoFs, particles, time step; throws on invalid input. No
      /// file is written.
      void
      setup();

      /// Time loop; writes output into @p output_directory (which exists).
      Status
      run(const std::string &output_directory);

      /// Fill the summary (status, errors, counts; the caller adds time).
      void
      fill_summary(Postprocess::Summary &summary) const;

      /// Global error norms (thesis eq. 4.4) against the reference.
      struct Errors
      {
        double displacement = 0, velocity = 0, stress = 0;
      };
      Errors
      compute_errors() const;

      struct Energies
      {
        double       kinetic = 0, strain = 0, gravity = 0;
        Tensor<1, 2> momentum;
        double       mass = 0;
        double
        total() const
        {
          return kinetic + strain + gravity;
        }
      };
      Energies
      compute_energies() const;

      const Particles::ParticleSet &
      get_particles() const
      {
        return particles;
      }
      const Mesh::CellLocator &
      get_locator() const
      {
        return locator;
      }
      double
      get_time_step() const
      {
        return time_step;
      }
      double
      get_time() const
      {
        return time;
      }
      unsigned int
      get_n_dofs() const
      {
        return dof_handler.n_dofs();
      }
      /// Do one time step (public for tests).
      void
      do_time_step(const double dt);

      /// Quiet mode: no screen output (tests).
      bool quiet = false;

    private:
      /// Largest stable time step of the basis and mass matrix over
      /// h_min / c_p (measured, see doc/stability.md).
      double
      stability_factor() const;
      void
      evaluate_shape_functions();
      void
      particles_to_grid();
      void
      solve_grid_acceleration();
      void
      update_particle_velocities();
      void
      project_velocities();
      void
      update_particle_state(const double dt);
      void
      locate_particles();
      void
      postprocess(const unsigned int step, const double wall_time);
      void
      write_output(const unsigned int step);
      std::string
      check_stability(const Energies &e);
      void
      find_tracked_particle();
      void
      record_tracked_particle();
      void
      write_tracked_particle() const;

      MPI_Comm           comm;
      ConditionalOStream pcout;

      // Parameters.
      Mesh::MeshGenerator                     mesh_generator;
      Particles::ParticleGenerator            particle_generator;
      Material::LinearElastic                 material;
      Postprocess::ReferenceSolution          reference;
      GridSystem::Parameters                  grid_parameters;
      std::string                             basis_name;
      std::string                             mass_type_name;
      bool                                    check_time_step = true;
      std::string                             time_step_warning;
      std::string                             velocity_expression;
      std::string                             velocity_constants;
      Tensor<1, 2>                            gravity;
      std::array<std::vector<std::string>, 2> fixed_names;
      double                                  end_time        = 0.02;
      double                                  fixed_step      = 0;
      double                                  courant_number  = 0.5;
      unsigned int                            output_interval = 0;
      unsigned int                            error_interval  = 1;
      bool                                    track           = false;
      Point<2>                                tracked_point;
      std::uint64_t                           tracked_id = 0;
      unsigned int                            track_axis = 0;
      std::vector<std::array<double, 5>>      tracked_history;
      double                                  tracked_velocity2     = 0;
      double                                  tracked_displacement2 = 0;
      struct ErrorHistory
      {
        double       max_displacement  = 0;
        double       sum_displacement2 = 0;
        double       sum_velocity2     = 0;
        unsigned int n                 = 0;
        Errors       latest;
        unsigned int latest_step = numbers::invalid_unsigned_int;
      } error_history;
      double energy_tolerance = 0.1;

      // Discretisation.
      parallel::shared::Triangulation<2> triangulation;
      DoFHandler<2>                      dof_handler;
      std::unique_ptr<Basis::Space>      space;
      Mesh::CellLocator                  locator;
      std::unique_ptr<GridSystem>        grid;
      Particles::ParticleSet             particles;

      // Per-step caches: basis values and gradients at the particles.
      std::vector<double>       shape_values;
      std::vector<Tensor<1, 2>> shape_gradients;
      std::vector<Tensor<1, 2>> grid_acceleration; // local relevant numbering
      std::vector<Tensor<1, 2>> grid_velocity;

      std::vector<unsigned int> cell_owner; // MPI rank of each cell
      double                    time_step     = 0;
      double                    time_step_now = 0; // of the step under way
      double                    time          = 0;
      unsigned int              step          = 0;
      std::string               output_directory;
      std::unique_ptr<Postprocess::OutputWriter> writer;
      TableHandler                               statistics;
      TimerOutput                                timer;
      Energies                                   initial_energy;
      double                                     energy_scale = 0;
      Status                                     status = Status::completed;
      std::string                                failure_reason;
      Failure                                    failure     = Failure::none;
      unsigned int                               failed_step = 0;
      double                                     failed_time = 0;
      unsigned int                               total_iterations = 0;
    };
  } // namespace Solver
} // namespace psmpm

#endif
