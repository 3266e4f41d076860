// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/distributed/fully_distributed_tria.h>

#include <psmpm/base/archive.h>
#include <psmpm/base/checked_file.h>
#include <psmpm/base/cpu_time.h>
#include <psmpm/base/format.h>
#include <psmpm/base/stop_request.h>
#include <psmpm/base/version.h>
#include <psmpm/mesh/confinement.h>
#include <psmpm/mesh/gmsh_file.h>
#include <psmpm/postprocess/progress.h>
#include <psmpm/simulator/reconstruction.h>
#include <psmpm/simulator/simulator.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <fstream>
#include <map>
#include <sstream>
namespace psmpm
{
  namespace Simulator
  {
    namespace
    {
      std::vector<std::string>
      split(const std::string &s)
      {
        return Utilities::split_string_list(s, ',');
      }

      /// The numbers of the list entry @p entry (of the current
      /// subsection @p path): its pattern takes numbers string_to_double
      /// refuses (subnormals such as 4.9e-324).
      std::vector<double>
      get_numbers(ParameterHandler  &prm,
                  const std::string &path,
                  const std::string &entry)
      {
        try
          {
            return Utilities::string_to_double(split(prm.get(entry)));
          }
        catch (const std::exception &)
          {
            AssertThrow(false,
                        ExcMessage(path + "/" + entry + " = '" +
                                   prm.get(entry) +
                                   "': not a list of numbers."));
          }
        return {};
      }

      /// Body force/Gravity.
      void
      declare_gravity(ParameterHandler &prm)
      {
        prm.enter_subsection("Body force");
        prm.declare_entry("Gravity",
                          "0, 0",
                          Patterns::List(Patterns::Double(), 1, 2),
                          "Gravitational acceleration vector [m/s^2], one "
                          "component per dimension.");
        prm.leave_subsection();
      }

      /// Body force/Gravity in @p dim components: the default "0, 0" must
      /// work in 1D too, so components beyond dim are accepted only if
      /// they are zero.
      template <int dim>
      Tensor<1, dim>
      parse_gravity(ParameterHandler &prm)
      {
        prm.enter_subsection("Body force");
        const auto g = get_numbers(prm, "Body force", "Gravity");
        prm.leave_subsection();
        bool fits = g.size() >= dim;
        for (unsigned int d = dim; d < g.size(); ++d)
          fits = fits && g[d] == 0;
        AssertThrow(fits,
                    ExcMessage("Body force/Gravity = " + prm_value(g[0]) +
                               (g.size() > 1 ? ", " + prm_value(g[1]) : "") +
                               ": needs " + std::to_string(dim) +
                               " component(s) in " + std::to_string(dim) +
                               "D (further ones must be 0)."));
        Tensor<1, dim> gravity;
        for (unsigned int d = 0; d < dim; ++d)
          gravity[d] = g[d];
        return gravity;
      }

      /// Boundary conditions/Fixed x and Fixed y (BoundaryConditions
      /// declares the rest of the subsection).
      void
      declare_fixed(ParameterHandler &prm)
      {
        prm.declare_entry("Fixed x",
                          "left, right",
                          Patterns::Anything(),
                          "Boundaries (names) where the x velocity is zero.");
        prm.declare_entry("Fixed y",
                          "left, right, bottom, top",
                          Patterns::Anything(),
                          "Boundaries (names) where the y velocity is zero "
                          "(2D only).");
      }

      /// The particle arrays' capacity once the particles are made or
      /// loaded, which the per-particle work arrays follow
      /// (Particles::resize_per_particle()): the size on one rank; on
      /// several, where particles cross between ranks from the first step
      /// on, an eighth of headroom, so that the first arrivals do not
      /// reallocate (and first-touch) every array.
      template <int dim>
      void
      set_particle_capacity(Particles::ParticleSet<dim> &particles,
                            MPI_Comm                     comm)
      {
        const std::size_t n = particles.size();
        particles.set_capacity(
          Utilities::MPI::n_mpi_processes(comm) > 1 ? n + n / 8 : n);
      }

      /// The Gmsh files of the bodies (Bodies/Body k/File), which every
      /// rank reads, checked on all ranks before any rank reads them: a
      /// file one rank cannot read then ends every rank with bad input
      /// instead of leaving the others waiting.
      void
      check_body_files(ParameterHandler &prm, MPI_Comm comm)
      {
        prm.enter_subsection("Bodies");
        const unsigned int n = prm.get_integer("Number of bodies");
        for (unsigned int b = 1; b <= n; ++b)
          {
            const std::string name = "Body " + std::to_string(b);
            prm.enter_subsection(name);
            const std::string file = prm.get("File");
            if (prm.get("Shape") == "gmsh" && !file.empty())
              Mesh::check_msh_on_all_ranks(file,
                                           "Bodies/" + name + "/File = " + file,
                                           comm);
            prm.leave_subsection();
          }
        prm.leave_subsection();
      }
    } // namespace

    template <int dim>
    Simulator<dim>::Simulator(MPI_Comm comm)
      : comm(comm)
      , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
      , state(comm)
      , timer(comm, pcout)
    {
    }

    template <int dim>
    void
    Simulator<dim>::declare_parameters(ParameterHandler &prm)
    {
      // Selections list the 2D registries, which hold every variant; a
      // variant without a 1D instance is rejected when created.
      Mesh::MeshGenerator<2>::declare_parameters(prm);
      Particles::ParticleGenerator<2>::declare_parameters(prm);
      Material::MaterialSet<2>::declare_parameters(prm);
      Postprocess::Reference<2>::declare_parameters(prm);
      Solver::GridSystem<2>::Parameters::declare_parameters(prm);
      TransferScheme<2>::declare_parameters(prm);
      TimeStepControl::declare_parameters(prm);
      StabilityMonitor::declare_parameters(prm);
      Checkpoint::declare_parameters(prm);
      Postprocess::OutputWriter<2>::declare_parameters(prm);
      Postprocessors<2>::declare_parameters(prm);
      Discretisation<2>::declare_parameters(prm);
      InitialConditions<2>::declare_parameters(prm);
      declare_gravity(prm);
      prm.enter_subsection("Boundary conditions");
      declare_fixed(prm);
      BoundaryConditions<2>::declare_parameters(prm);
      prm.leave_subsection();
      ContactCoupling<2>::declare_parameters(prm);
      OutputFiles<2>::declare_parameters(prm);
    }

    template <int dim>
    void
    Simulator<dim>::parse_parameters(ParameterHandler &prm)
    {
      mesh_generator.parse_parameters(prm, comm);
      if (Utilities::MPI::n_mpi_processes(comm) > 1)
        check_body_files(prm, comm);
      particle_generator.parse_parameters(prm);
      particle_generator.check_count(mesh_generator);
      state.materials.parse_parameters(prm, particle_generator.bodies);
      // A body's own Density, or else its material's, is what its
      // particles get (the generator reads Body::density).
      for (auto &body : particle_generator.bodies.bodies)
        body.density = state.materials.of_body(body.number).density;
      contact.parse_parameters(prm, particle_generator.bodies.bodies.size());
      contact.parse_driven(particle_generator.bodies.bodies);
      discretisation.parse_parameters(prm);
      contact.choose_automatic(prm, discretisation.grid_parameters.type);
      // "automatic" takes the space's measured defaults; the choice for a
      // closed, filled mesh is made once the mesh is known
      // (setup_space_and_grid).
      transfers.parse_parameters(prm,
                                 *discretisation.create_space(),
                                 discretisation.grid_parameters);

      state.gravity = parse_gravity<dim>(prm);
      initial_conditions.parse_parameters(prm,
                                          state.materials,
                                          particle_generator.bodies,
                                          state.gravity);

      prm.enter_subsection("Boundary conditions");
      const char *fixed_entries[] = {"Fixed x", "Fixed y"};
      for (unsigned int d = 0; d < dim; ++d)
        fixed_names[d] = split(prm.get(fixed_entries[d]));
      boundary_conditions.parse_parameters(prm);
      prm.leave_subsection();

      reference = Postprocess::Reference<dim>::create(prm,
                                                      state.materials.primary(),
                                                      mesh_generator.length,
                                                      mesh_generator.height,
                                                      state.gravity,
                                                      particle_generator.region,
                                                      fixed_names);

      time_step_control.parse_parameters(prm);
      output.parse_parameters(prm);
      // Their own entries (Output/Error interval, Output/Tracked point).
      postprocessors.parse_parameters(prm);
      output.check_particle_format();
      monitor.parse_parameters(prm);
      checkpoint.parse_parameters(prm);
      scene_text.record(prm, &Simulator<dim>::declare_parameters);
    }

    template <int dim>
    void
    Simulator<dim>::check_distribution() const
    {
      if (!mesh_generator.distributed)
        return;
      const auto refuse = [](const bool ok, const std::string &what) {
        AssertThrow(ok,
                    ExcMessage("Mesh/Distribution = distributed: " + what +
                               " is not verified on a distributed mesh (use "
                               "Mesh/Distribution = replicated)."));
      };
      // A B-spline function of a ghost cell reaches cells (knot spans)
      // beyond the ghost layers.
      const std::string &basis = discretisation.basis_name;
      refuse(basis == "linear" || basis == "powell-sabin",
             "Basis/Type = " + basis);
      refuse(transfers.reconstruction_name == "particles",
             "Transfer/Reconstruction = " + transfers.reconstruction_name);
      refuse(!transfers.may_move_grid(),
             "Transfer/Scheme = " + transfers.name +
               " (a grid that moves with the material)");
    }

    template <int dim>
    void
    Simulator<dim>::create_mesh()
    {
      // One rank holds the whole mesh either way: the replicated mesh
      // spares building it twice (and the cell renumbering of the
      // checkpoints).
      if (!mesh_generator.distributed ||
          Utilities::MPI::n_mpi_processes(comm) == 1)
        {
          mesh_generator.create(*state.triangulation);
          return;
        }
      auto tria =
        std::make_unique<parallel::fullydistributed::Triangulation<dim>>(comm);
      // A Powell-Sabin function of a ghost cell (the ghost penalty's
      // pairs) is built from the cells around that cell's vertices.
      state.whole_owner = mesh_generator.create_distributed(
        *tria,
        discretisation.basis_name == "powell-sabin" ? 2 : 1);
      state.whole_index.clear();
      for (const auto &cell : tria->active_cell_iterators())
        state.whole_index.push_back(cell->id().get_coarse_cell_id());
      AssertThrow(std::is_sorted(state.whole_index.begin(),
                                 state.whole_index.end()),
                  ExcInternalError());
      state.triangulation = std::move(tria);
    }

    template <int dim>
    void
    Simulator<dim>::setup()
    {
      check_distribution();
      create_mesh();
      boundary_conditions.mark_boundary_parts(*state.triangulation,
                                              mesh_generator);
      state.locator.reinit(*state.triangulation);
      setup_space_and_grid();
      time_step_control.initialize(state);
      setup_particles();
      state.evaluate_shape_functions();
      transfers.scheme->initialize(state);
      if (state.reconstruction)
        state.reconstruction->initialize(state);
      postprocessors.check_mesh(state.locator, comm);
    }

    template <int dim>
    void
    Simulator<dim>::setup_space_and_grid()
    {
      discretisation.setup_space(state);
      auto fixed = fixed_boundary_ids();
      boundary_conditions.add_constrained(fixed, mesh_generator);
      if (closed_and_filled(fixed))
        transfers.use_closed_choice(*state.space,
                                    discretisation.grid_parameters);
      transfers.check_and_install(state,
                                  discretisation.grid_parameters.type,
                                  discretisation.basis_name,
                                  discretisation.basis_degree);
      create_grid_system(fixed);
      boundary_conditions.reinit(state,
                                 fixed_names,
                                 mesh_generator,
                                 transfers.scheme->moves_grid());
      boundary_conditions.check_transfer(transfers.name);
      state.boundary_conditions =
        boundary_conditions.active() ? &boundary_conditions : nullptr;
      contact.check_transfer(transfers.name,
                             transfers.reconstruction_name,
                             discretisation.grid_parameters.type);
      if (contact.enabled())
        {
          contact.initialize(state);
          state.contact = &contact;
        }
    }

    template <int dim>
    std::array<std::set<types::boundary_id>, dim>
    Simulator<dim>::fixed_boundary_ids() const
    {
      const char *fixed_entries[] = {"x", "y"};
      std::array<std::set<types::boundary_id>, dim> fixed;
      for (unsigned int d = 0; d < dim; ++d)
        for (const auto &name : fixed_names[d])
          {
            try
              {
                fixed[d].insert(mesh_generator.boundary_id(name));
              }
            catch (const ExcMessage &e)
              {
                AssertThrow(false,
                            ExcMessage(
                              std::string("Boundary conditions/Fixed ") +
                              fixed_entries[d] + ": " + e.what()));
              }
          }
      return fixed;
    }

    template <int dim>
    bool
    Simulator<dim>::closed_and_filled(
      const std::array<std::set<types::boundary_id>, dim> &fixed) const
    {
      // Material that fills a mesh whose boundaries are all closed in
      // their normal direction cannot leave it: `automatic` takes
      // partially lumped mass, the consistent matrix wherever no cell
      // empties and lumped rows where one does (thin cells empty as the
      // material moves even in a closed mesh: the consistent matrix alone
      // goes unstable on prm/sliver_mesh_bar.prm). Large vibrating bar,
      // Powell-Sabin: displacement error 3.7e-3 against 9.1e-2 with
      // lumped mass and APIC at the same CPU time (doc/transfers.md
      // "Defaults").
      // Both decided over all ranks: a distributed mesh is seen in part.
      return transfers.closed_rule &&
             Utilities::MPI::min(
               particle_generator.fills_mesh(*state.triangulation) ? 1 : 0,
               comm) == 1 &&
             Mesh::is_closed<dim>(*state.triangulation, fixed);
    }

    template <int dim>
    void
    Simulator<dim>::create_grid_system(
      const std::array<std::set<types::boundary_id>, dim> &fixed)
    {
      const auto &grid_parameters = discretisation.grid_parameters;
      state.grid = std::make_unique<Solver::GridSystem<dim>>(grid_parameters,
                                                             *state.space,
                                                             state.dof_handler,
                                                             comm);
      AssertThrow(!mesh_generator.distributed ||
                    !state.grid->needs_replicated_mesh(),
                  ExcMessage("Mesh/Distribution = distributed: Mass matrix/"
                             "Type = " +
                             grid_parameters.type +
                             " is not verified on a distributed mesh (it "
                             "looks at vertices a rank may not hold; use "
                             "Mesh/Distribution = replicated)."));
      // The heaviest material sets the scale of the nearly-empty thresholds:
      // a lighter body's full cells then count as partly filled (more rows
      // lumped, stable), never a heavier body's nearly empty ones as full.
      state.grid->reinit(fixed, state.materials.max_density());
    }

    template <int dim>
    void
    Simulator<dim>::setup_particles()
    {
      // Particles of the locally owned cells, with their initial state
      // and velocity.
      const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
      state.cell_owner.resize(state.triangulation->n_active_cells());
      for (const auto &cell : state.triangulation->active_cell_iterators())
        state.cell_owner[cell->active_cell_index()] = cell->subdomain_id();
      auto &particles = state.particles;
      particles.set_state_names(state.materials.state_names());
      particles.body_material = state.materials.material_ids();
      particle_generator.generate(
        mesh_generator,
        *state.triangulation,
        state.locator,
        state.materials.primary().density,
        [this, rank](const unsigned int c) {
          return state.cell_owner[c] == rank;
        },
        particles);
      state.materials.initialize(particles);
      // A resumed run replaces these particles by its checkpoint's, whose
      // stress already started from this.
      initial_conditions.stress.apply(
        particles,
        state.materials,
        state.gravity,
        InitialStress<dim>::lattice_spacing(mesh_generator, particle_generator),
        comm);
      // The affine transfers start from the initial velocity gradient
      // (C_p = grad v); the transfer is final here (setup_space_and_grid).
      initial_conditions.set_velocities(
        particles,
        particle_generator.bodies,
        transfers.scheme->carries_affine(),
        state.locator.minimum_height()); // the same on every rank
      particles.sort_by_cell(state.triangulation->n_active_cells());
      set_particle_capacity(particles, comm);
    }

    template <int dim>
    void
    Simulator<dim>::locate_particles()
    {
      PhaseTimer::Scope t(timer, "locate");
      relocation.begin(state);
      relocation.locate(state, monitor, 0, state.particles.size());
      relocation.finish(state);
    }

    template <int dim>
    void
    Simulator<dim>::do_time_step(const double dt)
    {
      TransferScheme<dim> &transfer = *transfers.scheme;
      state.dt                      = dt;
      transfer.observe_updated_chunks(
        transfer.carries_affine() || !postprocessors.observes_updated_chunks() ?
          nullptr :
          &postprocessors);
      // On a grid that moves with the material the particles keep their
      // cells (and the scheme has evaluated the basis on the moved grid).
      // Otherwise the scheme may locate them chunk by chunk as it moves
      // them; if it did not, they are located here.
      transfer.relocate_with(transfer.moves_grid() ? nullptr : &relocation);
      // A velocity of t that is not finite at the times this step takes
      // it stops the run naming its entry, before it reaches the grid
      // (every rank evaluates the same functions).
      const std::string bad =
        boundary_conditions.non_finite_velocity(state.time + dt) +
        contact.driven_bodies.non_finite_velocity(state.time, dt);
      if (!bad.empty())
        {
          monitor.report(Failure::non_finite, bad);
          return;
        }
      transfer.prepare_step(state);
      if (!transfer.step(state, monitor, timer))
        return;
      record.total_iterations += state.grid->statistics().iterations;
      if (!transfer.moves_grid() && !transfer.relocated())
        locate_particles();
      state.time = time_step_control.snap(state.time + dt);
    }

    template <int dim>
    double
    Simulator<dim>::next_time_step()
    {
      const bool warned = !time_step_control.grid_warning().empty();
      time_step_control.update(state, transfers.scheme->minimum_height(state));
      if (!warned && !time_step_control.grid_warning().empty() && !quiet)
        pcout << "psmpm: warning: " << time_step_control.grid_warning()
              << std::endl;
      return time_step_control.next(state.time);
    }

    template <int dim>
    Postprocess::Errors
    Simulator<dim>::compute_errors() const
    {
      if (!reference)
        return {};
      // A reference computed alongside (ULFEM) must be at the state's
      // time; it only moves forward, so this is a no-op after a run step.
      reference->advance_to(state.time);
      return Postprocess::ErrorNorms<dim>::compute(state, *reference);
    }

    template <int dim>
    Postprocess::Energies<dim>
    Simulator<dim>::compute_energies() const
    {
      return Postprocess::EnergyStatistics<dim>().compute(state);
    }

    template <int dim>
    Postprocess::StateView<dim>
    Simulator<dim>::view() const
    {
      Postprocess::StateView<dim> v = state;
      v.reference                   = reference.get();
      v.carries_affine = transfers.scheme && transfers.scheme->carries_affine();
      v.last_step      = time_step_control.finished(state.time);
      v.output_directory = output.directory;
      return v;
    }

    template <int dim>
    void
    Simulator<dim>::postprocess(const double wall_time)
    {
      PhaseTimer::Scope t(timer, "statistics");
      auto             &statistics = output.statistics;
      statistics.add_value("step", state.step);
      statistics.add_value("time", state.time);
      statistics.add_value("dt", state.dt);
      // A reference computed alongside the run (ULFEM, the cantilever)
      // is at the step's time before the postprocessors compare with it.
      if (reference)
        {
          record.step_times.push_back(state.time);
          reference->advance_to(state.time);
        }
      postprocessors.execute(view(), statistics);
      const Postprocess::EnergyBalance e = postprocessors.energy_balance();
      // The walls' work enters the energy book: what they did to the
      // body is no growth of energy.
      double total_energy = e.total;
      if (state.boundary_conditions)
        {
          boundary_conditions.add_columns(statistics);
          total_energy =
            boundary_conditions.monitored_energy(total_energy, state.step);
        }
      if (state.contact)
        {
          contact.add_columns(statistics);
          // Friction of sliding contact dissipates: no loss to report.
          // A driven body's work is external.
          total_energy -= contact.sliding_work() + contact.driven_work();
        }
      statistics.add_value("wall_time", record.wall_offset + wall_time);
      // A row with inf or nan (an error norm against a reference beyond
      // double range, a diverging quantity) is no result: the run stops.
      const std::string non_finite = statistics.non_finite_in_last_entries();
      if (!non_finite.empty())
        monitor.report(Failure::non_finite,
                       "non-finite value in statistics.txt: " + non_finite +
                         " at step " + std::to_string(state.step));
      if (monitor.check(total_energy, e.scale, e.momentum, comm) &&
          record.status == Status::completed)
        {
          record.status      = Status::unstable;
          record.failed_step = state.step;
          record.failed_time = state.time;
        }
    }

    template <int dim>
    void
    Simulator<dim>::write_output()
    {
      PhaseTimer::Scope t(timer, "output");
      output.writer->write_particles(state.step, state.time, state.particles);
      output.writer->write_grid(state.step,
                                state.time,
                                state.dof_handler,
                                *state.space,
                                state.grid->cell_dofs(),
                                {{"velocity", &state.grid_velocity},
                                 {"acceleration", &state.grid_acceleration}},
                                {{"mass", &state.grid->lumped_mass()}},
                                transfers.scheme->moved_vertices());
      write_statistics();
      postprocessors.write(view());
    }

    template <int dim>
    void
    Simulator<dim>::write_statistics()
    {
      if (Utilities::MPI::this_mpi_process(comm) != 0)
        return;
      std::vector<std::string> columns;
      if (state.boundary_conditions)
        columns = boundary_conditions.statistics_columns();
      if (state.contact)
        for (const auto &c : contact.statistics_columns())
          columns.push_back(c);
      output.write_statistics(columns);
    }

    template <int dim>
    void
    Simulator<dim>::create_postprocessors(const std::string &directory)
    {
      output.create_writer(directory, comm, state.space->degree());
      postprocessors.initialize(view());
    }

    template <int dim>
    template <typename Write>
    void
    Simulator<dim>::checked(const Write &write)
    {
      std::string error;
      try
        {
          write();
        }
      catch (const ExcWriteFailed &e)
        {
          error = e.what();
        }
      for (const auto &e : Utilities::MPI::all_gather(comm, error))
        if (!e.empty())
          throw ExcWriteFailed(e);
    }

    template <int dim>
    void
    Simulator<dim>::begin_run(const std::string &directory)
    {
      const bool resumed = !record.resumed_from.empty();
      if (!resumed)
        create_postprocessors(directory);
      AssertThrow(directory == output.directory,
                  ExcMessage("resume() and run() name different output "
                             "directories."));
      record.wall.reset();
      record.wall.start();
      if (!resumed)
        {
          // A resumed run keeps the fields of its checkpoint: the initial
          // guesses of its first solves.
          state.grid_velocity.assign(state.grid->relevant_dofs().n_elements(),
                                     Tensor<1, dim>());
          state.grid_acceleration = state.grid_velocity;
          state.dt                = 0;
          postprocessors.start(view());
          postprocess(0);
          checked([this]() { write_output(); });
          checkpoint.start(state.step);
        }
      else
        {
          // The files as they were at the checkpoint: a run that went on
          // after it (and was killed) wrote rows and outputs beyond it.
          checked([this]() { restore_files(); });
          if (!quiet)
            pcout << "psmpm: resumed from " << record.resumed_from << " (step "
                  << state.step << ", t = " << state.time << ")" << std::endl;
        }

      if (!time_step_control.warning().empty())
        pcout << "psmpm: warning: " << time_step_control.warning() << std::endl;
      if (!contact.note().empty())
        pcout << "psmpm: " << contact.note()
              << ", Transfer/Scheme = " << transfers.name << std::endl;
      pcout << "psmpm: " << state.space->name() << " basis, "
            << discretisation.n_functions << " DoFs, "
            << Utilities::MPI::sum(state.particles.size(), comm)
            << " particles, dt = " << time_step_control.get_time_step()
            << ", end time = " << time_step_control.get_end_time() << std::endl;
    }

    template <int dim>
    bool
    Simulator<dim>::output_due()
    {
      bool due = time_step_control.finished(state.time) ||
                 record.status != Status::completed ||
                 (output.interval > 0 && state.step % output.interval == 0);
      if (output_time_interval > 0)
        {
          const auto passed = static_cast<unsigned int>(
            std::floor(state.time / output_time_interval * (1 + 1e-12)));
          due                 = due || passed > record.time_outputs;
          record.time_outputs = std::max(record.time_outputs, passed);
        }
      return due;
    }

    template <int dim>
    Status
    Simulator<dim>::run(const std::string &directory)
    {
      begin_run(directory);
      // The algorithm: step, measure, check, write. A stop request
      // (SIGINT, SIGTERM) ends the loop after the step in which all ranks
      // learn of it; output is written then, as after the last step.
      Postprocess::Progress progress(std::cout,
                                     !quiet && progress_interval > 0 &&
                                       Utilities::MPI::this_mpi_process(comm) ==
                                         0,
                                     progress_interval);
      // CPU seconds of the loop alone: process start-up (loading deal.II
      // and its ~200 libraries costs ~0.45 CPU s on this machine) and
      // set-up excluded, for error against CPU time on small scenes.
      const double cpu_at_start = process_cpu_seconds();
      Status      &status       = record.status;
      while (!time_step_control.finished(state.time) &&
             status == Status::completed)
        {
          const double dt = next_time_step();
          // The last step is cut to land on the end time: the checkpoint
          // at the end also keeps the state before it, from which a resume
          // with a later end time takes the full step.
          if (time_step_control.ends_run(state.time, dt))
            {
              PhaseTimer::Scope t(timer, "checkpoint");
              checkpoint.keep_state_before_last_step(checkpoint_archive(),
                                                     state.step);
            }
          const double cpu_before_step = process_cpu_seconds();
          do_time_step(dt);
          ++state.step;
          postprocess(record.wall.wall_time());
          record.cpu_time_steps += process_cpu_seconds() - cpu_before_step;
          if (status == Status::completed &&
              (stop_signal = StopRequest::agreed(comm)) != 0)
            status = Status::interrupted;
          if (output_due())
            checked([this]() { write_output(); });
          if (status == Status::completed && checkpoint.due(state.step, comm))
            checked([this]() { write_checkpoint(); });
          progress.update(state.step,
                          state.time,
                          time_step_control.get_end_time());
        }
      // The end of the run and an interruption leave a checkpoint to
      // continue from (an unstable state is not worth continuing).
      if (status != Status::unstable && checkpoint.last_step() != state.step)
        checked([this]() { write_checkpoint(); });
      record.cpu_time_loop = process_cpu_seconds() - cpu_at_start;
      record.wall.stop();
      report_end();
      return status;
    }

    template <int dim>
    void
    Simulator<dim>::report_end() const
    {
      if (quiet)
        return;
      timer.print_wall_time_statistics();
      if (record.status == Status::unstable)
        pcout << "psmpm: UNSTABLE at step " << record.failed_step << ": "
              << monitor.reason() << std::endl;
      if (record.status == Status::interrupted)
        pcout << "psmpm: interrupted by signal " << stop_signal
              << " after step " << state.step << " (t = " << state.time
              << "); output written." << std::endl;
    }

    namespace
    {
      /// The format a checkpoint declares; resume refuses others.
      const char *checkpoint_format = "psmpm checkpoint 1";

      /// The grid velocity and acceleration of the last step, the initial
      /// guesses of the next step's CG solves (Mass matrix/Warm start):
      /// each rank's local (relevant) field as "grid/<name>/rank <r>".
      template <int dim>
      std::array<std::pair<std::string, std::vector<Tensor<1, dim>> *>, 2>
      grid_fields(State<dim> &state)
      {
        return {{{"velocity", &state.grid_velocity},
                 {"acceleration", &state.grid_acceleration}}};
      }

      template <int dim>
      void
      put_grid_fields(State<dim> &state, Archive &archive, MPI_Comm comm)
      {
        for (const auto &[name, field] : grid_fields(state))
          {
            std::vector<double> flat(field->size() * dim);
            for (unsigned int i = 0; i < field->size(); ++i)
              for (unsigned int d = 0; d < dim; ++d)
                flat[i * dim + d] = (*field)[i][d];
            const auto all = Checkpoint::gather_per_rank(flat, comm);
            for (unsigned int r = 0; r < all.size(); ++r)
              if (!all[r].empty())
                archive.put("grid/" + name + "/rank " + std::to_string(r),
                            all[r],
                            dim);
          }
      }

      /// Only on the number of ranks that wrote them: the partition, and
      /// so the local numbering, is then the same. Otherwise (or for a
      /// checkpoint without them) the first solves start from zero, and
      /// the resumed run agrees with the uninterrupted one to the solver
      /// tolerance instead of bit for bit.
      template <int dim>
      void
      get_grid_fields(const Archive &shared, State<dim> &state, MPI_Comm comm)
      {
        const bool same_ranks = shared.get_integer("psmpm/n_mpi_ranks") ==
                                Utilities::MPI::n_mpi_processes(comm);
        const std::string rank =
          std::to_string(Utilities::MPI::this_mpi_process(comm));
        for (const auto &[name, field] : grid_fields(state))
          {
            const std::string entry = "grid/" + name + "/rank " + rank;
            field->assign(state.grid->relevant_dofs().n_elements(),
                          Tensor<1, dim>());
            if (!same_ranks || !shared.has(entry))
              continue;
            const std::vector<double> flat = shared.get(entry);
            if (flat.size() != field->size() * dim)
              continue;
            for (unsigned int i = 0; i < field->size(); ++i)
              for (unsigned int d = 0; d < dim; ++d)
                (*field)[i][d] = flat[i * dim + d];
          }
      }
    } // namespace

    namespace
    {
      /// "what" of @p e, trimmed.
      std::string
      message(const ExceptionBase &e)
      {
        std::ostringstream s;
        e.print_info(s);
        return Utilities::trim(s.str());
      }

      /// Read the first readable of @p files (newest first) into
      /// @p archive; @p file is set to it (or the last one tried). A
      /// damaged newer file is reported on std::cerr if @p warn. Returns
      /// the errors of all files if none could be read.
      std::string
      read_first_readable(const std::vector<std::string> &files,
                          const bool                      warn,
                          Archive                        &archive,
                          std::string                    &file)
      {
        std::string damaged;
        for (const auto &f : files)
          {
            file = f;
            try
              {
                archive = Archive::read_hdf5(f);
                return "";
              }
            catch (const ExceptionBase &e)
              {
                damaged += (damaged.empty() ? "" : "; ") + message(e);
                if (warn && f != files.back())
                  std::cerr << "psmpm: warning: " << message(e)
                            << "; trying the previous checkpoint" << std::endl;
              }
          }
        return damaged;
      }

      /// Throw ExcMessage unless @p archive is a checkpoint of this format
      /// written with the parameters of @p scene (but those that may
      /// change on resume).
      void
      check_archive(const Archive &archive, const SceneText &scene)
      {
        AssertThrow(archive.has("psmpm/format") &&
                      archive.get_text("psmpm/format") == checkpoint_format,
                    ExcMessage("not a psmpm checkpoint of format '" +
                               std::string(checkpoint_format) + "'"));
        const auto differences =
          Checkpoint::parameter_differences(archive.get_text(
                                              "psmpm/parameters"),
                                            scene.parameters,
                                            scene.defaults);
        std::string list;
        for (const auto &d : differences)
          list += (list.empty() ? "" : "; ") + d;
        AssertThrow(differences.empty(),
                    ExcMessage("written with other parameters (" + list +
                               "); only Time/End time, the Output and "
                               "Checkpoint intervals and Limits may change "
                               "when resuming"));
        // A scene that names no file stores none (as older checkpoints).
        if (archive.has("psmpm/files"))
          for (const auto &d :
               Checkpoint::file_differences(archive.get_text("psmpm/files"),
                                            scene.files))
            AssertThrow(false,
                        ExcMessage(d + "; resume with the files the run "
                                       "started with, or start a new run"));
      }
    } // namespace

    template <int dim>
    void
    Simulator<dim>::write_checkpoint()
    {
      PhaseTimer::Scope t(timer, "checkpoint");
      Archive           archive = checkpoint_archive();
      checkpoint.write(output.directory, state.step, archive, comm);
      if (!quiet)
        pcout << "psmpm: checkpoint " << output.directory << "/"
              << Checkpoint::file_name(state.step) << std::endl;
    }

    template <int dim>
    Archive
    Simulator<dim>::checkpoint_archive()
    {
      Archive archive;
      archive.put_text("psmpm/format", checkpoint_format);
      archive.put_text("psmpm/version", version());
      archive.put_text("psmpm/parameters", scene_text.parameters);
      if (!scene_text.files.empty())
        archive.put_text("psmpm/files", scene_text.files);
      archive.put_integer("psmpm/dimension", dim);
      archive.put_integer("psmpm/n_mpi_ranks",
                          Utilities::MPI::n_mpi_processes(comm));

      archive.put("simulator/time", state.time);
      archive.put_integer("simulator/step", state.step);
      archive.put("simulator/dt", state.dt);
      record.save(archive);
      archive.put_integer("simulator/cell_crossings",
                          record.cell_crossings_offset +
                            Utilities::MPI::sum(relocation.cell_crossings(),
                                                comm));
      // The rows so far, exactly (doubles, integers and "-" entries with
      // their column formats).
      archive.put_bytes("simulator/statistics", output.statistics.to_bytes());

      time_step_control.save(archive);
      monitor.save(archive);
      postprocessors.save(archive);
      if (state.boundary_conditions)
        boundary_conditions.save(archive);
      if (state.contact)
        contact.save(archive);
      output.writer->save(archive);
      transfers.scheme->save(archive, state);
      // The same on every rank where a vertex is seen, 0 elsewhere.
      std::vector<double> history = state.grid->strategy().history();
      history.resize(Utilities::MPI::max(history.size(), comm), 0.);
      std::vector<double> combined(history.size());
      Utilities::MPI::max(history, comm, combined);
      archive.put("mass_strategy/history", combined);

      put_grid_fields(state, archive, comm);

      Checkpoint::gather_particles(state.particles,
                                   archive,
                                   comm,
                                   state.whole_index);
      return archive;
    }

    template <int dim>
    void
    Simulator<dim>::resume(const std::string              &directory,
                           const std::vector<std::string> &files)
    {
      AssertThrow(!files.empty(), ExcMessage("no checkpoint to resume from"));
      create_postprocessors(directory);
      Archive           archive;
      const std::string file = read_checkpoint(files, archive);
      try
        {
          restore(archive);
        }
      catch (const ExceptionBase &e)
        {
          AssertThrow(false,
                      ExcMessage("checkpoint " + file + ": " + message(e)));
        }
      check_end_time(file);
      record.resumed_from = file;
      record.resumed_step = state.step;
      checkpoint.start(state.step);
    }

    template <int dim>
    std::string
    Simulator<dim>::read_checkpoint(const std::vector<std::string> &files,
                                    Archive                        &archive)
    {
      // Rank 0 reads the newest readable file and checks it; every rank
      // learns the verdict.
      std::string error, file = files[0];
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        {
          const std::string damaged =
            read_first_readable(files, !quiet, archive, file);
          try
            {
              AssertThrow(damaged.empty(), ExcMessage(damaged));
              check_archive(archive, scene_text);
              // A later end time: the run continues from the state before
              // its last step, which was cut to land on the earlier one.
              if (!time_step_control.finished(
                    archive.get_number("simulator/time")))
                Checkpoint::restart_before_last_step(archive);
            }
          catch (const ExceptionBase &e)
            {
              error = message(e);
            }
          catch (const std::exception &e)
            {
              error = e.what();
            }
        }
      error = Utilities::MPI::broadcast(comm, error, 0);
      file  = Utilities::MPI::broadcast(comm, file, 0);
      if (!error.empty())
        {
          // Archive::read_hdf5() names the file itself.
          if (error.rfind("checkpoint ", 0) != 0)
            error = "checkpoint " + file + ": " + error;
          AssertThrow(false, ExcMessage(error));
        }
      return file;
    }

    template <int dim>
    void
    Simulator<dim>::restore(Archive &archive)
    {
      // Every rank needs everything but the particles, which go to the
      // ranks owning their cells.
      Archive shared = archive;
      shared.erase_prefix("particles/");
      shared = Utilities::MPI::broadcast(comm, shared, 0);
      restore_particles(archive);
      archive = Archive();
      restore_components(shared);
    }

    template <int dim>
    void
    Simulator<dim>::restore_particles(const Archive &archive)
    {
      // The file names cells by their index in the whole mesh.
      Checkpoint::scatter_particles(archive,
                                    state.whole_index.empty() ?
                                      state.cell_owner :
                                      state.whole_owner,
                                    state.particles,
                                    comm);
      for (auto &c : state.particles.cell)
        {
          c = state.local_cell(c);
          AssertThrow(c != numbers::invalid_unsigned_int, ExcInternalError());
        }
      set_particle_capacity(state.particles, comm);
    }

    template <int dim>
    void
    Simulator<dim>::restore_components(const Archive &shared)
    {
      state.time = shared.get_number("simulator/time");
      state.step = shared.get_integer("simulator/step");
      state.dt   = shared.get_number("simulator/dt");
      record.load(shared);
      output.statistics.from_bytes(shared.get_bytes("simulator/statistics"));
      time_step_control.load(shared);
      monitor.load(shared);
      postprocessors.load(shared);
      if (state.boundary_conditions)
        boundary_conditions.load(shared);
      if (state.contact)
        contact.load(shared);
      output.writer->load(shared);
      state.grid->strategy().restore_history(
        shared.get("mass_strategy/history"));
      // The basis at the restored particles; a scheme with its own grid
      // (OTM) evaluates it there in load().
      state.evaluate_shape_functions();
      transfers.scheme->load(shared, state);
      get_grid_fields(shared, state, comm);

      // References computed alongside the run (ULFEM, the cantilever) are
      // deterministic in the times they are advanced to.
      record.step_times = shared.get("simulator/step_times");
      if (reference)
        for (const double t : record.step_times)
          reference->advance_to(t);
    }

    template <int dim>
    void
    Simulator<dim>::check_end_time(const std::string &file) const
    {
      // A checkpoint past the end asked for (by more than the sliver of
      // round-off that snap() forgives at the end of a run) would run no
      // step and end "completed" at the checkpoint's time, not at Time/End
      // time.
      const double end_time = time_step_control.get_end_time();
      AssertThrow(!(state.time > end_time &&
                    time_step_control.snap(state.time) != end_time),
                  ExcMessage("checkpoint " + file +
                             " is at t = " + prm_value(state.time) + " (step " +
                             std::to_string(state.step) +
                             "), after Time/End time = " + prm_value(end_time) +
                             "; a resumed run continues from its checkpoint, "
                             "so Time/End time must be at least " +
                             prm_value(state.time) + "."));
    }

    template <int dim>
    void
    Simulator<dim>::restore_files()
    {
      write_statistics();
      output.writer->restore_files(state.step);
      postprocessors.write(view());
    }

    template <int dim>
    void
    Simulator<dim>::fill_status(Summary &summary) const
    {
      summary.set("status", status_name(record.status));
      if (record.status == Status::interrupted)
        {
          summary.set("reason",
                      "stopped by signal " + std::to_string(stop_signal) +
                        (stop_signal == SIGINT  ? " (SIGINT)" :
                         stop_signal == SIGTERM ? " (SIGTERM)" :
                         stop_signal == SIGUSR1 ? " (SIGUSR1)" :
                                                  ""));
          summary.set_integer("signal", stop_signal);
        }
      if (record.status == Status::unstable)
        {
          summary.set("reason", monitor.reason());
          summary.set_integer("failed_step", record.failed_step);
          summary.set("failed_time", record.failed_time);
        }
      summary.set_integer("steps", state.step);
      if (!record.resumed_from.empty())
        {
          summary.set("resumed_from", record.resumed_from);
          summary.set_integer("resumed_step", record.resumed_step);
        }
      std::string warning = time_step_control.warning();
      if (!time_step_control.grid_warning().empty())
        warning +=
          (warning.empty() ? "" : " ") + time_step_control.grid_warning();
      if (!warning.empty())
        summary.set("warning", warning);
    }

    template <int dim>
    void
    Simulator<dim>::fill_summary(Summary &summary) const
    {
      fill_status(summary);
      summary.set_integer("dimension", dim);
      summary.set_integer("n_dofs", discretisation.n_functions);
      summary.set_integer("n_cells",
                          state.triangulation->n_global_active_cells());
      // What a rank holds: every cell (replicated) or its part with the
      // ghost layer (distributed).
      summary.set("mesh_distribution",
                  mesh_generator.distributed ? "distributed" : "replicated");
      summary.set_integer(
        "max_cells_per_rank",
        Utilities::MPI::max(state.triangulation->n_active_cells(), comm));
      summary.set_integer("n_particles",
                          Utilities::MPI::sum(state.particles.size(), comm));
      summary.set_integer("n_mpi_ranks", Utilities::MPI::n_mpi_processes(comm));
      summary.set_integer("cg_iterations", record.total_iterations);
      summary.set_integer("cell_crossings",
                          record.cell_crossings_offset +
                            Utilities::MPI::sum(relocation.cell_crossings(),
                                                comm));
      summary.set("end_time", state.time);
      summary.set("time_step", time_step_control.get_time_step());
      summary.set("time_step_min", time_step_control.get_min_time_step());
      summary.set("time_step_max", time_step_control.get_max_time_step());
      summary.set("basis", state.space->name());
      summary.set("mass_matrix", discretisation.grid_parameters.type);
      summary.set("sampling_stabilization", state.grid->sampling_target());
      summary.set("transfer", transfers.name);
      summary.set("reconstruction", transfers.reconstruction_name);
      summary.set("material", state.materials.model_names());
      postprocessors.fill_summary(view(), summary);
      fill_timings(summary);
    }

    template <int dim>
    void
    Simulator<dim>::fill_timings(Summary &summary) const
    {
      // Throughput of the time loop proper: every timed phase but output
      // and checkpoints (the per-step statistics included: on large
      // scenes they cost as much as a particle loop).
      const auto timings = timer.wall_times();
      double     loop    = 0;
      for (const auto &t : timings)
        {
          std::string key = t.first;
          std::replace(key.begin(), key.end(), ' ', '_');
          summary.set("timers_s." + key, t.second);
          if (t.first != "output" && t.first != "checkpoint")
            loop += t.second;
        }
      summary.set("time_loop_s", loop);
      summary.set("cpu_time_loop_s", record.cpu_time_loop);
      summary.set("cpu_time_steps_s", record.cpu_time_steps);
      if (loop > 0)
        summary.set("particle_steps_per_second",
                    summary.get_number("n_particles") * state.step / loop);
    }

    std::unique_ptr<SimulatorBase>
    create_simulator(const unsigned int dimension, MPI_Comm comm)
    {
      if (dimension == 1)
        return std::make_unique<Simulator<1>>(comm);
      return std::make_unique<Simulator<2>>(comm);
    }

    template class Simulator<1>;
    template class Simulator<2>;
  } // namespace Simulator
} // namespace psmpm
