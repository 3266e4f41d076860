// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/function_parser.h>
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

      /// Whether @p value is on a space's list of verified mass matrices
      /// or transfers (an empty list: every one is).
      bool
      verified(const std::vector<std::string> &list, const std::string &value)
      {
        return list.empty() ||
               std::find(list.begin(), list.end(), value) != list.end();
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

      // Basis/Type lists the spaces of both dimensions (bspline is 1D
      // only, powell-sabin 2D only); creation rejects the wrong one.
      const auto &registry_1d   = Basis::SpaceRegistry<1>::instance();
      const auto &registry_2d   = Basis::SpaceRegistry<2>::instance();
      std::string selection     = registry_2d.selection();
      std::string documentation = registry_2d.documentation();
      for (const auto &name : registry_1d.variant_names())
        if (!registry_2d.has(name))
          {
            selection += "|" + name;
            documentation +=
              "; " + name + " (1D only): " + registry_1d.description(name);
          }
      prm.enter_subsection("Basis");
      prm.declare_entry("Type",
                        "linear",
                        Patterns::Selection(selection),
                        documentation);
      prm.declare_entry("Degree",
                        "2",
                        Patterns::Integer(1),
                        "Polynomial degree of Basis/Type = bspline (1 to 5; "
                        "lumped mass for 1 and 2 only); linear and "
                        "powell-sabin have a fixed degree and ignore it.");
      prm.leave_subsection();

      prm.enter_subsection("Initial conditions");
      prm.declare_entry(
        "Velocity",
        "v0*sin(pi*x/L); 0",
        Patterns::Anything(),
        "Initial velocity as a function of x, y: one component per "
        "dimension, separated by ';'.");
      prm.declare_entry("Function constants",
                        "v0=0.1, L=25",
                        Patterns::Anything(),
                        "Constants for the velocity expression, name=value, "
                        "comma separated (pi is predefined).");
      prm.leave_subsection();
      InitialStress<2>::declare_parameters(prm);

      prm.enter_subsection("Body force");
      prm.declare_entry("Gravity",
                        "0, 0",
                        Patterns::List(Patterns::Double(), 1, 2),
                        "Gravitational acceleration vector [m/s^2], one "
                        "component per dimension.");
      prm.leave_subsection();

      prm.enter_subsection("Boundary conditions");
      prm.declare_entry("Fixed x",
                        "left, right",
                        Patterns::Anything(),
                        "Boundaries (names) where the x velocity is zero.");
      prm.declare_entry("Fixed y",
                        "left, right, bottom, top",
                        Patterns::Anything(),
                        "Boundaries (names) where the y velocity is zero "
                        "(2D only).");
      BoundaryConditions<2>::declare_parameters(prm);
      prm.leave_subsection();

      prm.enter_subsection("Output");
      prm.declare_entry("Interval",
                        "0",
                        Patterns::Integer(0),
                        "Write VTU output every this many steps (0: first and "
                        "last step only).");
      prm.leave_subsection();
    }

    template <int dim>
    void
    Simulator<dim>::parse_parameters(ParameterHandler &prm)
    {
      mesh_generator.parse_parameters(prm);
      particle_generator.parse_parameters(prm);
      particle_generator.check_count(mesh_generator);
      state.materials.parse_parameters(prm, particle_generator.bodies);
      // A body's own Density, or else its material's, is what its
      // particles get (the generator reads Body::density).
      for (auto &body : particle_generator.bodies.bodies)
        body.density = state.materials.of_body(body.number).density;
      grid_parameters.parse_parameters(prm);
      prm.enter_subsection("Basis");
      basis_name   = prm.get("Type");
      basis_degree = prm.get_integer("Degree");
      prm.leave_subsection();
      AssertThrow(Basis::SpaceRegistry<dim>::instance().has(basis_name),
                  ExcMessage(
                    "Basis/Type = " + basis_name + ": not available in " +
                    std::to_string(dim) + "D (known: " +
                    Basis::SpaceRegistry<dim>::instance().names() + ")."));

      // "automatic" takes the space's measured defaults. An explicit
      // transfer is created first: the mass default depends on whether
      // its grid moves; an automatic transfer follows the mass matrix.
      const auto space = Basis::create_space<dim>(basis_name);
      space->set_degree(basis_degree);
      prm.enter_subsection("Transfer");
      transfer_name       = prm.get("Scheme");
      reconstruction_name = prm.get("Reconstruction");
      reconstruction.reset();
      if (reconstruction_name != "particles")
        reconstruction =
          ReconstructionRegistry<dim>::instance().create(reconstruction_name,
                                                         "Transfer/"
                                                         "Reconstruction",
                                                         prm);
      transfer.reset();
      if (transfer_name != "automatic")
        transfer =
          TransferSchemeRegistry<dim>::instance().create(transfer_name,
                                                         "Transfer/Scheme",
                                                         prm);
      const bool mass_automatic     = grid_parameters.type == "automatic";
      const bool transfer_automatic = transfer_name == "automatic";
      const bool grid_moves         = transfer && transfer->moves_grid();
      if (mass_automatic)
        grid_parameters.type = space->default_mass_matrix(grid_moves);
      // The sampling stabilisation's cell matrices belong to the initial
      // cells: not for a grid that moves with the material.
      if (grid_parameters.sampling_stabilization < 0)
        grid_parameters.sampling_stabilization =
          mass_automatic && !grid_moves ? 0.5 : 0.;
      AssertThrow(!(grid_moves && grid_parameters.sampling_stabilization > 0),
                  ExcMessage("Mass matrix/Sampling stabilization = " +
                             prm_value(grid_parameters.sampling_stabilization) +
                             " with Transfer/Scheme = " + transfer_name +
                             ": its cell matrices are those of the initial "
                             "cells, and this transfer moves the grid; use "
                             "0."));
      if (transfer_automatic)
        {
          transfer_name = space->default_transfer(grid_parameters.type);
          transfer =
            TransferSchemeRegistry<dim>::instance().create(transfer_name,
                                                           "Transfer/Scheme",
                                                           prm);
        }
      // The choice for a closed, filled mesh is made once the mesh is
      // known (setup_space_and_grid); its transfer is created here, where
      // its parameters are.
      // (Not for a space that was not verified with its closed-mesh
      // choice: it keeps its own default.)
      closed_rule =
        mass_automatic && !grid_moves &&
        verified(space->verified_mass_matrices(), space->closed_mass_matrix());
      closed_transfer_name.clear();
      closed_transfer.reset();
      if (closed_rule)
        {
          closed_transfer_name =
            transfer_automatic ?
              space->default_transfer(space->closed_mass_matrix()) :
              transfer_name;
          if (closed_transfer_name != transfer_name)
            closed_transfer =
              TransferSchemeRegistry<dim>::instance()
                .create(closed_transfer_name, "Transfer/Scheme", prm);
        }
      prm.leave_subsection();

      prm.enter_subsection("Initial conditions");
      velocity_expression = prm.get("Velocity");
      velocity_constants  = prm.get("Function constants");
      prm.leave_subsection();

      prm.enter_subsection("Body force");
      const auto g = get_numbers(prm, "Body force", "Gravity");
      prm.leave_subsection();
      // The default "0, 0" must work in 1D too: components beyond dim
      // are accepted only if they are zero.
      bool fits = g.size() >= dim;
      for (unsigned int d = dim; d < g.size(); ++d)
        fits = fits && g[d] == 0;
      AssertThrow(fits,
                  ExcMessage("Body force/Gravity = " + prm_value(g[0]) +
                             (g.size() > 1 ? ", " + prm_value(g[1]) : "") +
                             ": needs " + std::to_string(dim) +
                             " component(s) in " + std::to_string(dim) +
                             "D (further ones must be 0)."));
      for (unsigned int d = 0; d < dim; ++d)
        state.gravity[d] = g[d];
      initial_stress.parse_parameters(prm,
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

      prm.enter_subsection("Output");
      output_interval = prm.get_integer("Interval");
      subdivisions    = prm.get_integer("Subdivisions");
      particle_format = Postprocess::OutputWriter<dim>::parse_particle_format(
        prm.get("Particle format"));
      prm.leave_subsection();
      // Their own entries (Output/Error interval, Output/Tracked point).
      postprocessors.parse_parameters(prm);
      // HDF5 (and XDMF) store points in 2 or 3 coordinates only.
      AssertThrow(particle_format == Postprocess::ParticleFormat::vtu ||
                    dim >= 2,
                  ExcMessage("Output/Particle format = hdf5 needs "
                             "Geometry/Dimension = 2; use vtu in 1D."));

      monitor.parse_parameters(prm);
      checkpoint.parse_parameters(prm);

      // What a checkpoint of this run is compared with on resume.
      std::ostringstream text;
      prm.print_parameters(text, ParameterHandler::ShortPRM);
      parameter_text = text.str();
      // The declarations alone: entries added since a checkpoint was
      // written are accepted on resume at their defaults.
      ParameterHandler declared;
      declare_parameters(declared);
      std::ostringstream defaults;
      declared.print_parameters(defaults, ParameterHandler::ShortPRM);
      default_parameter_text = defaults.str();
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
      refuse(basis_name == "linear" || basis_name == "powell-sabin",
             "Basis/Type = " + basis_name);
      refuse(reconstruction_name == "particles",
             "Transfer/Reconstruction = " + reconstruction_name);
      refuse(!transfer->moves_grid() &&
               !(closed_transfer && closed_transfer->moves_grid()),
             "Transfer/Scheme = " + transfer_name +
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
      state.whole_owner =
        mesh_generator.create_distributed(*tria,
                                          basis_name == "powell-sabin" ? 2 : 1);
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
      transfer->initialize(state);
      if (state.reconstruction)
        state.reconstruction->initialize(state);
    }

    template <int dim>
    void
    Simulator<dim>::setup_space_and_grid()
    {
      state.space = Basis::create_space<dim>(basis_name);
      state.space->set_degree(basis_degree);
      // The space's functions live on one kind of cell (triangles for
      // linear and powell-sabin, rectangles for the 2D bspline).
      if constexpr (dim == 2)
        {
          const bool space_on_quads =
            state.space->dof_layout().reference_cell() ==
            ReferenceCells::Quadrilateral;
          AssertThrow(space_on_quads == state.locator.cartesian(),
                      ExcMessage(
                        "Basis/Type = " + basis_name +
                        (space_on_quads ?
                           " needs a mesh of rectangles (Mesh/Type = "
                           "cartesian); this mesh is of triangles." :
                           " needs a mesh of triangles (Mesh/Type = "
                           "criss-cross, diagonal or gmsh); Mesh/Type = "
                           "cartesian is for Basis/Type = bspline.")));
        }
      state.dof_handler.reinit(*state.triangulation);
      state.dof_handler.distribute_dofs(state.space->dof_layout());
      state.space->reinit(state.dof_handler);
      {
        AffineConstraints<double> ties;
        state.space->make_space_constraints(state.dof_handler, ties);
        n_functions = state.dof_handler.n_dofs() - ties.n_constraints();
      }

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
      boundary_conditions.add_constrained(fixed, mesh_generator);
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
      if (closed_rule &&
          Utilities::MPI::min(
            particle_generator.fills_mesh(*state.triangulation) ? 1 : 0,
            comm) == 1 &&
          Mesh::is_closed<dim>(*state.triangulation, fixed))
        {
          grid_parameters.type = state.space->closed_mass_matrix();
          if (closed_transfer)
            transfer = std::move(closed_transfer);
          transfer_name = closed_transfer_name;
        }
      // A space with a restricted list names what it was verified with
      // (and the degree: bspline's list depends on it).
      const auto refuse = [&](const std::vector<std::string> &accepted,
                              const std::string              &entry,
                              const std::string              &value) {
        if (verified(accepted, value))
          return;
        std::string list;
        for (const auto &v : accepted)
          list += (list.empty() ? "" : ", ") + v;
        AssertThrow(false,
                    ExcMessage(
                      entry + " = " + value +
                      ": not verified with Basis/Type = " + basis_name +
                      ", Basis/Degree = " + std::to_string(basis_degree) +
                      " (verified: " + list + ")."));
      };
      refuse(state.space->verified_mass_matrices(),
             "Mass matrix/Type",
             grid_parameters.type);
      refuse(state.space->verified_transfers(),
             "Transfer/Scheme",
             transfer_name);
      // A reconstruction names what it was verified with as well.
      state.reconstruction.reset();
      if (reconstruction_name != "particles")
        {
          state.reconstruction   = std::move(reconstruction);
          const auto refuse_with = [&](const std::vector<std::string> &list,
                                       const std::string              &entry,
                                       const std::string              &value) {
            std::string names;
            for (const auto &v : list)
              names += (names.empty() ? "" : ", ") + v;
            AssertThrow(verified(list, value),
                        ExcMessage(entry + " = " + value +
                                   ": not verified with Transfer/"
                                   "Reconstruction = " +
                                   reconstruction_name +
                                   " (verified: " + names + ")."));
          };
          refuse_with(state.reconstruction->verified_mass_matrices(),
                      "Mass matrix/Type",
                      grid_parameters.type);
          refuse_with(state.reconstruction->verified_transfers(),
                      "Transfer/Scheme",
                      transfer_name);
        }
      closed_rule = false;
      state.grid  = std::make_unique<Solver::GridSystem<dim>>(grid_parameters,
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
      boundary_conditions.reinit(state,
                                 fixed_names,
                                 mesh_generator,
                                 transfer->moves_grid());
      state.boundary_conditions =
        boundary_conditions.active() ? &boundary_conditions : nullptr;
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
      initial_stress.apply(
        particles,
        state.materials,
        state.gravity,
        InitialStress<dim>::lattice_spacing(mesh_generator, particle_generator),
        comm);

      const auto constants = parse_function_constants(velocity_constants);
      // The affine transfers start from the initial velocity gradient
      // (C_p = grad v): fourth-order differences with h = 1e-4 are exact
      // to round-off for the affine fields they must carry. The others
      // never update C_p, so it stays zero for them (a stale C_p would
      // enter the reported angular momentum). The transfer is final here
      // (setup_space_and_grid). Without Bodies one expression for all
      // particles; with them, each body's own.
      const bool affine       = transfer->carries_affine();
      const auto set_velocity = [&](const std::string &expression,
                                    const std::string &entry,
                                    const unsigned int body) {
        FunctionParser<dim> velocity(dim, 0., 1e-4);
        velocity.set_formula(AutoDerivativeFunction<dim>::FourthOrder);
        try
          {
            velocity.initialize(dim == 1 ? "x" : "x,y", expression, constants);
            for (std::size_t i = 0; i < particles.size(); ++i)
              if (particles.body_id[i] == body)
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    particles.velocity[i][d] =
                      velocity.value(particles.position[i], d);
                    if (affine)
                      particles.affine[i][d] =
                        velocity.gradient(particles.position[i], d);
                  }
          }
        catch (const std::exception &e)
          {
            AssertThrow(false,
                        ExcMessage(entry + " = '" + expression +
                                   "': " + e.what()));
          }
      };
      const auto &bodies = particle_generator.bodies.bodies;
      if (bodies.empty())
        set_velocity(velocity_expression, "Initial conditions/Velocity", 0);
      for (const auto &body : bodies)
        set_velocity(body.velocity,
                     body.name() + "/Initial velocity",
                     body.number);
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
      state.dt = dt;
      transfer->observe_updated_chunks(
        transfer->carries_affine() ||
            !postprocessors.observes_updated_chunks() ?
          nullptr :
          &postprocessors);
      // On a grid that moves with the material the particles keep their
      // cells (and the scheme has evaluated the basis on the moved grid).
      // Otherwise the scheme may locate them chunk by chunk as it moves
      // them; if it did not, they are located here.
      transfer->relocate_with(transfer->moves_grid() ? nullptr : &relocation);
      if (!transfer->step(state, monitor, timer))
        return;
      total_iterations += state.grid->statistics().iterations;
      if (!transfer->moves_grid() && !transfer->relocated())
        locate_particles();
      state.time = time_step_control.snap(state.time + dt);
    }

    template <int dim>
    double
    Simulator<dim>::next_time_step()
    {
      const bool warned = !time_step_control.grid_warning().empty();
      time_step_control.update(state, transfer->minimum_height(state));
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
      v.carries_affine              = transfer && transfer->carries_affine();
      v.last_step                   = time_step_control.finished(state.time);
      v.output_directory            = output_directory;
      return v;
    }

    template <int dim>
    void
    Simulator<dim>::postprocess(const double wall_time)
    {
      PhaseTimer::Scope t(timer, "statistics");
      statistics.add_value("step", state.step);
      statistics.add_value("time", state.time);
      statistics.add_value("dt", state.dt);
      // A reference computed alongside the run (ULFEM, the cantilever)
      // is at the step's time before the postprocessors compare with it.
      if (reference)
        {
          step_times.push_back(state.time);
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
      statistics.add_value("wall_time", wall_offset + wall_time);
      if (monitor.check(total_energy, e.scale, e.momentum, comm) &&
          status == Status::completed)
        {
          status      = Status::unstable;
          failed_step = state.step;
          failed_time = state.time;
        }
    }

    template <int dim>
    void
    Simulator<dim>::write_output()
    {
      PhaseTimer::Scope t(timer, "output");
      writer->write_particles(state.step, state.time, state.particles);
      writer->write_grid(state.step,
                         state.time,
                         state.dof_handler,
                         *state.space,
                         state.grid->cell_dofs(),
                         {{"velocity", &state.grid_velocity},
                          {"acceleration", &state.grid_acceleration}},
                         {{"mass", &state.grid->lumped_mass()}},
                         transfer->moved_vertices());
      write_statistics();
      postprocessors.write(view());
    }

    template <int dim>
    void
    Simulator<dim>::write_statistics()
    {
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        {
          // The postprocessors format their own columns.
          std::vector<std::string> columns = {"time", "dt", "wall_time"};
          if (state.boundary_conditions)
            {
              for (const auto &c : boundary_conditions.statistics_columns())
                columns.push_back(c);
            }
          for (const auto &c : columns)
            {
              statistics.set_scientific(c, true);
              statistics.set_precision(c, 8);
            }
          const std::string file = output_directory + "/statistics.txt";
          if (!statistics_file || statistics_file->name() != file)
            statistics_file = std::make_unique<GrowingTextFile>(file);
          statistics_file->write(
            statistics.layout(),
            statistics.n_rows(),
            [this](std::ostream &out) { statistics.write_header(out); },
            [this](std::ostream      &out,
                   const unsigned int begin,
                   const unsigned int end) {
              statistics.write_rows(out, begin, end);
            });
        }
    }

    template <int dim>
    void
    Simulator<dim>::create_postprocessors(const std::string &directory)
    {
      output_directory = directory;
      // Linear fields are exact at the corners; sub-cells cost output
      // volume (16x for 4) that only higher degrees need.
      const unsigned int s =
        subdivisions > 0 ? subdivisions : (state.space->degree() == 1 ? 1 : 4);
      writer =
        std::make_unique<Postprocess::OutputWriter<dim>>(directory,
                                                         comm,
                                                         s,
                                                         particle_format);
      postprocessors.initialize(view());
    }

    template <int dim>
    Status
    Simulator<dim>::run(const std::string &directory)
    {
      const bool resumed = !resumed_from.empty();
      if (!resumed)
        create_postprocessors(directory);
      AssertThrow(directory == output_directory,
                  ExcMessage("resume() and run() name different output "
                             "directories."));
      wall.reset();
      wall.start();
      // Every rank learns of a failed write (the first message wins) and
      // the run ends with ExcWriteFailed on all of them.
      const auto checked = [this](const auto &write) {
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
      };
      const auto checked_write_output = [&]() {
        checked([this]() { write_output(); });
      };
      // A resumed run keeps the fields of its checkpoint: the initial
      // guesses of its first solves.
      if (!resumed)
        {
          state.grid_velocity.assign(state.grid->relevant_dofs().n_elements(),
                                     Tensor<1, dim>());
          state.grid_acceleration = state.grid_velocity;
        }
      if (!resumed)
        {
          state.dt = 0;
          postprocessors.start(view());
          postprocess(0);
          checked_write_output();
          checkpoint.start(state.step);
        }
      else
        {
          // The files as they were at the checkpoint: a run that went on
          // after it (and was killed) wrote rows and outputs beyond it.
          checked([this]() { restore_files(); });
          if (!quiet)
            pcout << "psmpm: resumed from " << resumed_from << " (step "
                  << state.step << ", t = " << state.time << ")" << std::endl;
        }

      if (!time_step_control.warning().empty())
        pcout << "psmpm: warning: " << time_step_control.warning() << std::endl;
      pcout << "psmpm: " << state.space->name() << " basis, " << n_functions
            << " DoFs, " << Utilities::MPI::sum(state.particles.size(), comm)
            << " particles, dt = " << time_step_control.get_time_step()
            << ", end time = " << time_step_control.get_end_time() << std::endl;

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
      while (!time_step_control.finished(state.time) &&
             status == Status::completed)
        {
          do_time_step(next_time_step());
          ++state.step;
          postprocess(wall.wall_time());
          if (status == Status::completed &&
              (stop_signal = StopRequest::agreed(comm)) != 0)
            status = Status::interrupted;
          bool due = time_step_control.finished(state.time) ||
                     status != Status::completed ||
                     (output_interval > 0 && state.step % output_interval == 0);
          if (output_time_interval > 0)
            {
              const auto passed = static_cast<unsigned int>(
                std::floor(state.time / output_time_interval * (1 + 1e-12)));
              due          = due || passed > time_outputs;
              time_outputs = std::max(time_outputs, passed);
            }
          if (due)
            checked_write_output();
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
      cpu_time_loop = process_cpu_seconds() - cpu_at_start;
      wall.stop();
      if (!quiet)
        {
          timer.print_wall_time_statistics();
          if (status == Status::unstable)
            pcout << "psmpm: UNSTABLE at step " << failed_step << ": "
                  << monitor.reason() << std::endl;
          if (status == Status::interrupted)
            pcout << "psmpm: interrupted by signal " << stop_signal
                  << " after step " << state.step << " (t = " << state.time
                  << "); output written." << std::endl;
        }
      return status;
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

    template <int dim>
    void
    Simulator<dim>::write_checkpoint()
    {
      PhaseTimer::Scope t(timer, "checkpoint");
      Archive           archive;
      archive.put_text("psmpm/format", checkpoint_format);
      archive.put_text("psmpm/version", version());
      archive.put_text("psmpm/parameters", parameter_text);
      archive.put_integer("psmpm/dimension", dim);
      archive.put_integer("psmpm/n_mpi_ranks",
                          Utilities::MPI::n_mpi_processes(comm));

      archive.put("simulator/time", state.time);
      archive.put_integer("simulator/step", state.step);
      archive.put("simulator/dt", state.dt);
      archive.put_integer("simulator/cg_iterations", total_iterations);
      archive.put_integer("simulator/time_outputs", time_outputs);
      archive.put("simulator/wall_time", wall_offset + wall.wall_time());
      archive.put("simulator/step_times", step_times);
      // The rows so far, exactly (doubles, integers and "-" entries with
      // their column formats).
      archive.put_bytes("simulator/statistics", statistics.to_bytes());

      time_step_control.save(archive);
      monitor.save(archive);
      postprocessors.save(archive);
      if (state.boundary_conditions)
        boundary_conditions.save(archive);
      writer->save(archive);
      transfer->save(archive, state);
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
      checkpoint.write(output_directory, state.step, archive, comm);
      if (!quiet)
        pcout << "psmpm: checkpoint " << output_directory << "/"
              << Checkpoint::file_name(state.step) << std::endl;
    }

    template <int dim>
    void
    Simulator<dim>::resume(const std::string              &directory,
                           const std::vector<std::string> &files)
    {
      AssertThrow(!files.empty(), ExcMessage("no checkpoint to resume from"));
      create_postprocessors(directory);

      // Rank 0 reads the newest readable file and checks it; every rank
      // learns the verdict.
      Archive     archive;
      std::string error, file = files[0];
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        {
          std::string damaged;
          for (const auto &f : files)
            {
              file = f;
              try
                {
                  archive = Archive::read_hdf5(f);
                  damaged.clear();
                  break;
                }
              catch (const ExceptionBase &e)
                {
                  std::ostringstream s;
                  e.print_info(s);
                  damaged +=
                    (damaged.empty() ? "" : "; ") + Utilities::trim(s.str());
                  if (!quiet && f != files.back())
                    std::cerr << "psmpm: warning: " << Utilities::trim(s.str())
                              << "; trying the previous checkpoint"
                              << std::endl;
                }
            }
          try
            {
              AssertThrow(damaged.empty(), ExcMessage(damaged));
              AssertThrow(archive.has("psmpm/format") &&
                            archive.get_text("psmpm/format") ==
                              checkpoint_format,
                          ExcMessage("not a psmpm checkpoint of format '" +
                                     std::string(checkpoint_format) + "'"));
              const auto differences =
                Checkpoint::parameter_differences(archive.get_text(
                                                    "psmpm/parameters"),
                                                  parameter_text,
                                                  default_parameter_text);
              std::string list;
              for (const auto &d : differences)
                list += (list.empty() ? "" : "; ") + d;
              AssertThrow(differences.empty(),
                          ExcMessage(
                            "written with other parameters (" + list +
                            "); only Time/End time, the Output and "
                            "Checkpoint intervals and Limits may change "
                            "when resuming"));
            }
          catch (const ExceptionBase &e)
            {
              std::ostringstream s;
              e.print_info(s);
              error = Utilities::trim(s.str());
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

      try
        {
          // Every rank needs everything but the particles, which go to
          // the ranks owning their cells.
          Archive shared = archive;
          shared.erase_prefix("particles/");
          shared = Utilities::MPI::broadcast(comm, shared, 0);
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
              AssertThrow(c != numbers::invalid_unsigned_int,
                          ExcInternalError());
            }
          set_particle_capacity(state.particles, comm);
          archive = Archive();

          state.time       = shared.get_number("simulator/time");
          state.step       = shared.get_integer("simulator/step");
          state.dt         = shared.get_number("simulator/dt");
          total_iterations = shared.get_integer("simulator/cg_iterations");
          time_outputs     = shared.get_integer("simulator/time_outputs");
          wall_offset      = shared.get_number("simulator/wall_time");
          statistics.from_bytes(shared.get_bytes("simulator/statistics"));
          time_step_control.load(shared);
          monitor.load(shared);
          postprocessors.load(shared);
          if (state.boundary_conditions)
            boundary_conditions.load(shared);
          writer->load(shared);
          state.grid->strategy().restore_history(
            shared.get("mass_strategy/history"));
          // The basis at the restored particles; a scheme with its own
          // grid (OTM) evaluates it there in load().
          state.evaluate_shape_functions();
          transfer->load(shared, state);
          get_grid_fields(shared, state, comm);

          // References computed alongside the run (ULFEM, the cantilever)
          // are deterministic in the times they are advanced to.
          step_times = shared.get("simulator/step_times");
          if (reference)
            for (const double t : step_times)
              reference->advance_to(t);
        }
      catch (const ExceptionBase &e)
        {
          std::ostringstream s;
          e.print_info(s);
          AssertThrow(false,
                      ExcMessage("checkpoint " + file + ": " +
                                 Utilities::trim(s.str())));
        }
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
      resumed_from = file;
      resumed_step = state.step;
      checkpoint.start(state.step);
    }

    template <int dim>
    void
    Simulator<dim>::restore_files()
    {
      write_statistics();
      writer->restore_files(state.step);
      postprocessors.write(view());
    }

    template <int dim>
    void
    Simulator<dim>::fill_summary(Summary &summary) const
    {
      summary.set("status", status_name(status));
      if (status == Status::interrupted)
        {
          summary.set("reason",
                      "stopped by signal " + std::to_string(stop_signal) +
                        (stop_signal == SIGINT  ? " (SIGINT)" :
                         stop_signal == SIGTERM ? " (SIGTERM)" :
                         stop_signal == SIGUSR1 ? " (SIGUSR1)" :
                                                  ""));
          summary.set_integer("signal", stop_signal);
        }
      if (status == Status::unstable)
        {
          summary.set("reason", monitor.reason());
          summary.set_integer("failed_step", failed_step);
          summary.set("failed_time", failed_time);
        }
      summary.set_integer("steps", state.step);
      if (!resumed_from.empty())
        {
          summary.set("resumed_from", resumed_from);
          summary.set_integer("resumed_step", resumed_step);
        }
      {
        std::string warning = time_step_control.warning();
        if (!time_step_control.grid_warning().empty())
          warning +=
            (warning.empty() ? "" : " ") + time_step_control.grid_warning();
        if (!warning.empty())
          summary.set("warning", warning);
      }
      summary.set_integer("dimension", dim);
      summary.set_integer("n_dofs", n_functions);
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
      summary.set_integer("cg_iterations", total_iterations);
      summary.set_integer("cell_crossings",
                          Utilities::MPI::sum(relocation.cell_crossings(),
                                              comm));
      summary.set("end_time", state.time);
      summary.set("time_step", time_step_control.get_time_step());
      summary.set("time_step_min", time_step_control.get_min_time_step());
      summary.set("time_step_max", time_step_control.get_max_time_step());
      summary.set("basis", state.space->name());
      summary.set("mass_matrix", grid_parameters.type);
      summary.set("sampling_stabilization", state.grid->sampling_target());
      summary.set("transfer", transfer_name);
      summary.set("reconstruction", reconstruction_name);
      summary.set("material", state.materials.model_names());
      postprocessors.fill_summary(view(), summary);
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
      summary.set("cpu_time_loop_s", cpu_time_loop);
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
