// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/solver_control.h>

#include <psmpm/base/format.h>
#include <psmpm/solver/mpm_solver.h>

#include <cmath>
#include <fstream>
#include <map>

namespace psmpm
{
  namespace Solver
  {
    namespace
    {
      std::vector<std::string>
      split(const std::string &s)
      {
        return Utilities::split_string_list(s, ',');
      }
    } // namespace

    MPMSolver::MPMSolver(MPI_Comm comm)
      : comm(comm)
      , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
      , triangulation(comm,
                      Triangulation<2>::none,
                      false,
                      parallel::shared::Triangulation<2>::partition_metis)
      , timer(comm, pcout, TimerOutput::never, TimerOutput::wall_times)
    {
    }

    MPMSolver::~MPMSolver()
    {
      dof_handler.clear();
    }

    void
    MPMSolver::declare_parameters(ParameterHandler &prm)
    {
      Mesh::MeshGenerator::declare_parameters(prm);
      Particles::ParticleGenerator::declare_parameters(prm);
      Material::LinearElastic::declare_parameters(prm);
      Postprocess::ReferenceSolution::declare_parameters(prm);
      GridSystem::Parameters::declare_parameters(prm);

      prm.enter_subsection("Basis");
      prm.declare_entry(
        "Type",
        "linear",
        Patterns::Selection("linear|powell-sabin"),
        "Basis functions: linear (P1) or powell-sabin (quadratic "
        "C1 splines).");
      prm.leave_subsection();

      prm.enter_subsection("Initial conditions");
      prm.declare_entry(
        "Velocity",
        "v0*sin(pi*x/L); 0",
        Patterns::Anything(),
        "Initial velocity as a function of x, y: two components "
        "separated by ';'.");
      prm.declare_entry("Function constants",
                        "v0=0.1, L=25",
                        Patterns::Anything(),
                        "Constants for the velocity expression, name=value, "
                        "comma separated (pi is predefined).");
      prm.leave_subsection();

      prm.enter_subsection("Body force");
      prm.declare_entry("Gravity",
                        "0, 0",
                        Patterns::List(Patterns::Double(), 2, 2),
                        "Gravitational acceleration vector [m/s^2].");
      prm.leave_subsection();

      prm.enter_subsection("Boundary conditions");
      prm.declare_entry("Fixed x",
                        "left, right",
                        Patterns::Anything(),
                        "Boundaries (names) where the x velocity is zero.");
      prm.declare_entry("Fixed y",
                        "left, right, bottom, top",
                        Patterns::Anything(),
                        "Boundaries (names) where the y velocity is zero.");
      prm.leave_subsection();

      prm.enter_subsection("Time");
      prm.declare_entry("End time",
                        "0.02",
                        Patterns::Double(0),
                        "End time [s].");
      prm.declare_entry("Time step",
                        "1e-5",
                        Patterns::Double(0),
                        "Fixed time step [s]; 0 = automatic from the Courant "
                        "number. A fixed step above the stability bound is "
                        "an error.");
      prm.declare_entry(
        "Courant number",
        "0.5",
        Patterns::Double(0),
        "dt = C f h_min / c_p for the automatic time step (c_p: p-wave "
        "speed, h_min: smallest triangle height, f: measured stability "
        "factor of the basis and mass matrix, 0.4 to 1.5, doc/stability.md).");
      prm.declare_entry(
        "Check stability bound",
        "true",
        Patterns::Bool(),
        "Reject a fixed Time step above h_min/c_p and a Courant "
        "number above 1 before the run. Switch off only to "
        "measure stability limits (contrib/stability_study.py).");
      prm.leave_subsection();

      prm.enter_subsection("Output");
      prm.declare_entry("Interval",
                        "0",
                        Patterns::Integer(0),
                        "Write VTU output every this many steps (0: first and "
                        "last step only).");
      prm.declare_entry("Error interval",
                        "1",
                        Patterns::Integer(1),
                        "Compute error norms against the reference every this "
                        "many steps (and at the end).");
      prm.declare_entry("Tracked point",
                        "",
                        Patterns::List(Patterns::Double(), 0, 2),
                        "Initial position x, y: the particle that starts "
                        "nearest to it is recorded every step in "
                        "tracked_particle.txt with the reference, and the RMS "
                        "of the differences over time goes into summary.json "
                        "(a grid-crossing noise measure).");
      prm.leave_subsection();

      prm.enter_subsection("Stability");
      prm.declare_entry(
        "Energy tolerance",
        "0.1",
        Patterns::Double(0),
        "Stop as unstable when the total energy rises above its "
        "initial value by more than this fraction of the "
        "largest energy seen so far.");
      prm.leave_subsection();
    }

    void
    MPMSolver::parse_parameters(ParameterHandler &prm)
    {
      mesh_generator.parse_parameters(prm);
      particle_generator.parse_parameters(prm);
      particle_generator.check_count(mesh_generator);
      material.parse_parameters(prm);
      grid_parameters.parse_parameters(prm);
      prm.enter_subsection("Mass matrix");
      mass_type_name = prm.get("Type");
      prm.leave_subsection();

      prm.enter_subsection("Basis");
      basis_name = prm.get("Type");
      prm.leave_subsection();

      prm.enter_subsection("Initial conditions");
      velocity_expression = prm.get("Velocity");
      velocity_constants  = prm.get("Function constants");
      prm.leave_subsection();

      prm.enter_subsection("Body force");
      const auto g = Utilities::string_to_double(split(prm.get("Gravity")));
      gravity      = Tensor<1, 2>({g[0], g[1]});
      prm.leave_subsection();

      reference.parse_parameters(prm,
                                 material,
                                 mesh_generator.length,
                                 mesh_generator.height,
                                 gravity);

      prm.enter_subsection("Boundary conditions");
      fixed_names[0] = split(prm.get("Fixed x"));
      fixed_names[1] = split(prm.get("Fixed y"));
      prm.leave_subsection();

      prm.enter_subsection("Time");
      end_time        = prm.get_double("End time");
      fixed_step      = prm.get_double("Time step");
      courant_number  = prm.get_double("Courant number");
      check_time_step = prm.get_bool("Check stability bound");
      prm.leave_subsection();
      AssertThrow(end_time > 0, ExcMessage("Time/End time must be positive."));
      AssertThrow(
        courant_number > 0 && (courant_number <= 1 || !check_time_step),
        ExcMessage("Time/Courant number = " + prm_value(courant_number) +
                   ": must lie in (0, 1]."));

      prm.enter_subsection("Output");
      output_interval = prm.get_integer("Interval");
      error_interval  = prm.get_integer("Error interval");
      {
        const auto p =
          Utilities::string_to_double(split(prm.get("Tracked point")));
        AssertThrow(p.empty() || p.size() == 2,
                    ExcMessage("Output/Tracked point must be empty or x, y."));
        track = p.size() == 2;
        if (track)
          tracked_point = Point<2>(p[0], p[1]);
      }
      prm.leave_subsection();

      prm.enter_subsection("Stability");
      energy_tolerance = prm.get_double("Energy tolerance");
      prm.leave_subsection();
    }

    void
    MPMSolver::setup()
    {
      mesh_generator.create(triangulation);
      locator.reinit(triangulation);

      space = Basis::create_space(basis_name);
      dof_handler.reinit(triangulation);
      dof_handler.distribute_dofs(space->dof_layout());
      space->reinit(dof_handler);

      std::array<std::set<types::boundary_id>, 2> fixed;
      for (unsigned int d = 0; d < 2; ++d)
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
                              (d == 0 ? "x" : "y") + ": " + e.what()));
              }
          }
      grid = std::make_unique<GridSystem>(grid_parameters,
                                          *space,
                                          dof_handler,
                                          comm);
      grid->reinit(fixed, material.density);

      // Time step: the p-wave must not cross the smallest triangle height
      // in one step (thesis eq. 2.48 with the p-wave speed).
      const double bound = locator.minimum_height() / material.p_wave_speed();
      if (fixed_step > 0)
        {
          AssertThrow(
            fixed_step <= bound || !check_time_step,
            ExcMessage(
              "Time/Time step = " + prm_value(fixed_step) +
              " exceeds the stability bound h_min/c_p = " + prm_value(bound) +
              " (h_min = " + prm_value(locator.minimum_height()) +
              ", c_p = " + prm_value(material.p_wave_speed()) + ")."));
          time_step = fixed_step;
        }
      else
        time_step = courant_number * stability_factor() * bound;
      if (time_step > stability_factor() * bound)
        time_step_warning =
          "Time/Time step = " + prm_value(time_step) +
          " is above the measured stability limit of this basis and mass "
          "matrix, about " +
          prm_value(stability_factor() * bound) +
          " (doc/stability.md); the run may become unstable.";

      // Particles of the locally owned cells, with their initial velocity.
      const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
      cell_owner.resize(triangulation.n_active_cells());
      for (const auto &cell : triangulation.active_cell_iterators())
        cell_owner[cell->active_cell_index()] = cell->subdomain_id();
      particle_generator.generate(
        mesh_generator,
        triangulation,
        locator,
        material.density,
        [this, rank](const unsigned int c) { return cell_owner[c] == rank; },
        particles);

      std::map<std::string, double> constants{{"pi", numbers::PI}};
      for (const auto &c : split(velocity_constants))
        {
          const auto kv = Utilities::split_string_list(c, '=');
          AssertThrow(kv.size() == 2,
                      ExcMessage("Initial conditions/Function constants: '" +
                                 c + "' is not name=value."));
          constants[kv[0]] = Utilities::string_to_double(kv[1]);
        }
      FunctionParser<2> velocity(2);
      try
        {
          velocity.initialize("x,y", velocity_expression, constants);
          for (std::size_t i = 0; i < particles.size(); ++i)
            for (unsigned int d = 0; d < 2; ++d)
              particles.velocity[i][d] =
                velocity.value(particles.position[i], d);
        }
      catch (const std::exception &e)
        {
          AssertThrow(false,
                      ExcMessage("Initial conditions/Velocity = '" +
                                 velocity_expression + "': " + e.what()));
        }
      particles.sort_by_cell(triangulation.n_active_cells());
      evaluate_shape_functions();
    }

    double
    MPMSolver::stability_factor() const
    {
      // Largest stable step over h_min/c_p, measured by bisection on the
      // vibrating bar with criss-cross blocks (contrib/stability_study.py:
      // P1 0.64 consistent, 1.58 lumped; Powell-Sabin 0.43 and 1.61),
      // rounded down.
      const bool lumped = grid_parameters.type == GridSystem::MassType::lumped;
      if (basis_name == "linear")
        return lumped ? 1.5 : 0.6;
      return lumped ? 1.5 : 0.4;
    }

    void
    MPMSolver::evaluate_shape_functions()
    {
      const unsigned int n = space->dofs_per_cell();
      shape_values.resize(particles.size() * n);
      shape_gradients.resize(particles.size() * n);
      space->evaluate(particles.size(),
                      particles.cell.data(),
                      particles.position.data(),
                      shape_values.data(),
                      shape_gradients.data());
    }

    void
    MPMSolver::particles_to_grid()
    {
      TimerOutput::Scope t(timer, "particle to grid");
      grid->zero_cell_mass();
      grid->zero_cell_rhs();
      const unsigned int n          = space->dofs_per_cell();
      const bool         consistent = !grid->cell_mass.empty();
      double            *lumped     = grid->cell_lumped.data();
      double            *mass_mat   = grid->cell_mass.data();
      Tensor<1, 2>      *rhs        = grid->cell_rhs.data();
      for (std::size_t p = 0; p < particles.size(); ++p)
        {
          const unsigned int           base = particles.cell[p] * n;
          const double                 m    = particles.mass[p];
          const double                 V    = particles.volume[p];
          const SymmetricTensor<2, 2> &s    = particles.stress[p];
          const Tensor<1, 2>  external = m * gravity + particles.traction[p];
          const double       *phi      = &shape_values[p * n];
          const Tensor<1, 2> *grad     = &shape_gradients[p * n];
          for (unsigned int k = 0; k < n; ++k)
            {
              lumped[base + k] += m * phi[k];
              rhs[base + k] += phi[k] * external - V * (s * grad[k]);
              if (consistent)
                {
                  double      *row = mass_mat + (base + k) * n;
                  const double mk  = m * phi[k];
                  for (unsigned int l = 0; l < n; ++l)
                    row[l] += mk * phi[l];
                }
            }
        }
      grid->assemble_mass();
    }

    void
    MPMSolver::solve_grid_acceleration()
    {
      TimerOutput::Scope t(timer, "solve");
      grid->solve(grid_acceleration);
    }

    void
    MPMSolver::update_particle_velocities()
    {
      TimerOutput::Scope t(timer, "grid to particle");
      grid->zero_cell_rhs();
      const unsigned int  n    = space->dofs_per_cell();
      const unsigned int *dofs = grid->cell_dofs.data();
      Tensor<1, 2>       *rhs  = grid->cell_rhs.data();
      for (std::size_t p = 0; p < particles.size(); ++p)
        {
          const unsigned int base = particles.cell[p] * n;
          const double      *phi  = &shape_values[p * n];
          Tensor<1, 2>       a;
          for (unsigned int k = 0; k < n; ++k)
            a += phi[k] * grid_acceleration[dofs[base + k]];
          particles.velocity[p] += time_step_now * a;
          const Tensor<1, 2> momentum =
            particles.mass[p] * particles.velocity[p];
          for (unsigned int k = 0; k < n; ++k)
            rhs[base + k] += phi[k] * momentum;
        }
    }

    void
    MPMSolver::project_velocities()
    {
      TimerOutput::Scope t(timer, "solve");
      grid->solve(grid_velocity);
    }

    void
    MPMSolver::update_particle_state(const double dt)
    {
      TimerOutput::Scope  t(timer, "update");
      const unsigned int  n    = space->dofs_per_cell();
      const unsigned int *dofs = grid->cell_dofs.data();
      for (std::size_t p = 0; p < particles.size(); ++p)
        {
          const unsigned int  base = particles.cell[p] * n;
          const double       *phi  = &shape_values[p * n];
          const Tensor<1, 2> *grad = &shape_gradients[p * n];
          Tensor<1, 2>        v;
          Tensor<2, 2>        L; // velocity gradient, L_ij = dv_i/dx_j
          for (unsigned int k = 0; k < n; ++k)
            {
              const Tensor<1, 2> &vk = grid_velocity[dofs[base + k]];
              v += phi[k] * vk;
              L += outer_product(vk, grad[k]);
            }
          const double dvol = material.update(dt * L,
                                              particles.stress[p],
                                              particles.stress_zz[p],
                                              particles.strain[p]);
          particles.volume[p] *= 1 + dvol;
          particles.density[p] /= 1 + dvol;
          if (!(particles.volume[p] > 0) && failure_reason.empty())
            {
              failure        = Failure::non_positive_volume;
              failure_reason = "non-positive particle volume (particle " +
                               std::to_string(particles.id[p]) + ")";
            }
          const Tensor<1, 2> du = dt * v;
          particles.displacement[p] += du;
          particles.position[p] += du;
        }
    }

    void
    MPMSolver::locate_particles()
    {
      TimerOutput::Scope t(timer, "locate");
      const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
      const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
      std::map<unsigned int, std::vector<double>> outgoing;
      std::vector<bool>                           keep(particles.size(), true);
      bool                                        any_leaving = false;
      for (std::size_t p = 0; p < particles.size(); ++p)
        {
          const unsigned int c =
            locator.locate(particles.position[p], particles.cell[p]);
          if (c == Mesh::CellLocator::invalid)
            {
              if (failure_reason.empty())
                {
                  failure        = Failure::left_mesh;
                  failure_reason = "particle " +
                                   std::to_string(particles.id[p]) +
                                   " left the mesh at (" +
                                   prm_value(particles.position[p][0]) + ", " +
                                   prm_value(particles.position[p][1]) + ")";
                }
              continue; // keep its old cell; the run stops after this step
            }
          particles.cell[p] = c;
          if (n_ranks > 1)
            {
              const unsigned int owner = cell_owner[c];
              if (owner != rank)
                {
                  particles.pack(p, outgoing[owner]);
                  keep[p]     = false;
                  any_leaving = true;
                }
            }
        }
      if (n_ranks > 1)
        {
          if (any_leaving)
            particles.compress(keep);
          const auto incoming = Utilities::MPI::some_to_some(comm, outgoing);
          for (const auto &in : incoming)
            {
              const std::size_t first = particles.size();
              particles.unpack(in.second);
              for (std::size_t p = first; p < particles.size(); ++p)
                particles.cell[p] = locator.locate(particles.position[p]);
            }
        }
      evaluate_shape_functions();
    }

    void
    MPMSolver::do_time_step(const double dt)
    {
      time_step_now = dt;
      particles_to_grid();
      try
        {
          solve_grid_acceleration();
          update_particle_velocities();
          project_velocities();
        }
      catch (const SolverControl::NoConvergence &e)
        {
          failure        = Failure::solver;
          failure_reason = "mass matrix solver did not converge (" +
                           std::to_string(e.last_step) +
                           " iterations, residual " +
                           prm_value(e.last_residual) + ")";
          return;
        }
      total_iterations += grid->statistics().iterations;
      update_particle_state(dt);
      locate_particles();
      time += dt;
      // Snap to the end time so that round-off in the sum of steps does
      // not leave a sliver of a last step.
      if (std::abs(end_time - time) < 1e-9 * time_step)
        time = end_time;
    }
  } // namespace Solver
} // namespace psmpm

namespace psmpm
{
  namespace Solver
  {
    MPMSolver::Errors
    MPMSolver::compute_errors() const
    {
      Errors e;
      if (!reference.exists())
        return e;
      for (std::size_t p = 0; p < particles.size(); ++p)
        {
          const auto r =
            reference.evaluate(particles.initial_position[p], time);
          const double V = particles.volume[p];
          e.displacement +=
            V * (particles.displacement[p] - r.displacement).norm_square();
          e.velocity += V * (particles.velocity[p] - r.velocity).norm_square();
          {
            const SymmetricTensor<2, 2> ds = particles.stress[p] - r.stress;
            e.stress += V * (ds * ds);
          }
        }
      e.displacement = std::sqrt(Utilities::MPI::sum(e.displacement, comm));
      e.velocity     = std::sqrt(Utilities::MPI::sum(e.velocity, comm));
      e.stress       = std::sqrt(Utilities::MPI::sum(e.stress, comm));
      return e;
    }

    MPMSolver::Energies
    MPMSolver::compute_energies() const
    {
      Energies e;
      for (std::size_t p = 0; p < particles.size(); ++p)
        {
          const double m = particles.mass[p];
          e.kinetic += 0.5 * m * particles.velocity[p].norm_square();
          e.strain += particles.volume[p] *
                      material.energy_density(particles.stress[p],
                                              particles.stress_zz[p]);
          e.gravity -= m * (gravity * particles.displacement[p]);
          e.momentum += m * particles.velocity[p];
          e.mass += m;
        }
      e.kinetic  = Utilities::MPI::sum(e.kinetic, comm);
      e.strain   = Utilities::MPI::sum(e.strain, comm);
      e.gravity  = Utilities::MPI::sum(e.gravity, comm);
      e.mass     = Utilities::MPI::sum(e.mass, comm);
      e.momentum = Utilities::MPI::sum(e.momentum, comm);
      return e;
    }

    std::string
    MPMSolver::check_stability(const Energies &e)
    {
      // Every rank must agree on the verdict.
      const bool local_failure = !failure_reason.empty();
      const bool any_failure =
        Utilities::MPI::max(local_failure ? 1 : 0, comm) > 0;
      if (any_failure)
        {
          failure = static_cast<Failure>(
            Utilities::MPI::max(static_cast<int>(failure), comm));
          return failure_reason.empty() ? "instability on another MPI rank" :
                                          failure_reason;
        }
      if (!std::isfinite(e.total()) || !std::isfinite(e.momentum.norm()))
        {
          failure = Failure::non_finite;
          return "non-finite energy or momentum";
        }
      energy_scale =
        std::max(energy_scale, e.kinetic + e.strain + std::abs(e.gravity));
      const double growth = e.total() - initial_energy.total();
      if (growth > energy_tolerance * energy_scale && growth > 1e-300)
        {
          failure = Failure::energy_growth;
          return "total energy grew by " + prm_value(growth) + " (" +
                 prm_value(100 * growth / energy_scale) +
                 " % of the energy scale) without external work";
        }
      return "";
    }

    void
    MPMSolver::postprocess(const unsigned int n, const double wall_time)
    {
      const Energies e = compute_energies();
      statistics.add_value("step", n);
      statistics.add_value("time", time);
      statistics.add_value("dt", time_step_now);
      statistics.add_value("kinetic_energy", e.kinetic);
      statistics.add_value("strain_energy", e.strain);
      statistics.add_value("gravity_energy", e.gravity);
      statistics.add_value("total_energy", e.total());
      statistics.add_value("mass", e.mass);
      statistics.add_value("momentum_x", e.momentum[0]);
      statistics.add_value("momentum_y", e.momentum[1]);
      statistics.add_value("cg_iterations", grid->statistics().iterations);
      statistics.add_value("condition_number",
                           grid->statistics().condition_number);
      statistics.add_value("min_relative_diagonal",
                           grid->statistics().min_relative_diagonal);
      statistics.add_value("treated_dofs", grid->statistics().n_treated_dofs);
      statistics.add_value("mass_diag_ratio",
                           grid->statistics().max_diagonal > 0 ?
                             grid->statistics().min_diagonal /
                               grid->statistics().max_diagonal :
                             0.);
      if (reference.exists())
        {
          reference.advance_to(time);
          const bool last = !(time < end_time * (1 - 1e-12));
          if (n % error_interval == 0 || last)
            {
              const Errors err          = compute_errors();
              error_history.latest      = err;
              error_history.latest_step = n;
              statistics.add_value("displacement_L2", err.displacement);
              statistics.add_value("velocity_L2", err.velocity);
              statistics.add_value("stress_L2", err.stress);
              error_history.max_displacement =
                std::max(error_history.max_displacement, err.displacement);
              error_history.sum_displacement2 +=
                err.displacement * err.displacement;
              error_history.sum_velocity2 += err.velocity * err.velocity;
              ++error_history.n;
            }
          else // "-": not computed at this step (see Output/Error interval)
            for (const auto &c :
                 {"displacement_L2", "velocity_L2", "stress_L2"})
              statistics.add_value(c, std::string("-"));
          if (track)
            record_tracked_particle();
        }
      statistics.add_value("wall_time", wall_time);
      if (n == 0)
        initial_energy = e;
      const std::string verdict = check_stability(e);
      if (!verdict.empty() && status == Status::completed)
        {
          status         = Status::unstable;
          failure_reason = verdict;
          failed_step    = n;
          failed_time    = time;
        }
    }

    void
    MPMSolver::find_tracked_particle()
    {
      double        best = std::numeric_limits<double>::max();
      std::uint64_t id   = 0;
      for (std::size_t p = 0; p < particles.size(); ++p)
        {
          const double d =
            particles.initial_position[p].distance(tracked_point);
          if (d < best || (d == best && particles.id[p] < id))
            best = d, id = particles.id[p];
        }
      const auto min = Utilities::MPI::min_max_avg(best, comm).min;
      // Smallest id among the ranks at the minimal distance.
      const double mine = best == min ? double(id) : 1e300;
      tracked_id = static_cast<std::uint64_t>(Utilities::MPI::min(mine, comm));
    }

    void
    MPMSolver::record_tracked_particle()
    {
      // Sum over ranks: only the owner contributes.
      std::vector<double> v(8, 0.);
      for (std::size_t p = 0; p < particles.size(); ++p)
        if (particles.id[p] == tracked_id)
          {
            const auto r =
              reference.evaluate(particles.initial_position[p], time);
            v = {1,
                 particles.initial_position[p][0],
                 particles.initial_position[p][1],
                 particles.displacement[p][track_axis],
                 particles.velocity[p][track_axis],
                 r.displacement[track_axis],
                 r.velocity[track_axis],
                 particles.stress[p][track_axis][track_axis] -
                   r.stress[track_axis][track_axis]};
          }
      {
        std::vector<double> total(v.size());
        MPI_Allreduce(v.data(),
                      total.data(),
                      v.size(),
                      MPI_DOUBLE,
                      MPI_SUM,
                      comm);
        v = total;
      }
      tracked_history.push_back({{time, v[3], v[4], v[5], v[6]}});
      tracked_velocity2 += (v[4] - v[6]) * (v[4] - v[6]);
      tracked_displacement2 += (v[3] - v[5]) * (v[3] - v[5]);
    }

    void
    MPMSolver::write_tracked_particle() const
    {
      if (!track || Utilities::MPI::this_mpi_process(comm) != 0)
        return;
      std::ofstream out(output_directory + "/tracked_particle.txt");
      out
        << "# particle starting nearest to (" << tracked_point << "), id "
        << tracked_id << ", component " << track_axis << "\n"
        << "# time displacement velocity reference_displacement reference_velocity\n";
      out.precision(10);
      for (const auto &r : tracked_history)
        out << r[0] << ' ' << r[1] << ' ' << r[2] << ' ' << r[3] << ' ' << r[4]
            << '\n';
    }

    void
    MPMSolver::write_output(const unsigned int n)
    {
      TimerOutput::Scope t(timer, "output");
      writer->write_particles(n, time, particles);
      writer->write_grid(n,
                         time,
                         dof_handler,
                         *space,
                         grid->cell_dofs,
                         {{"velocity", &grid_velocity},
                          {"acceleration", &grid_acceleration}},
                         {{"mass", &grid->lumped_mass()}});
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        {
          for (const auto &c : {"time",
                                "dt",
                                "kinetic_energy",
                                "strain_energy",
                                "gravity_energy",
                                "total_energy",
                                "mass",
                                "momentum_x",
                                "momentum_y",
                                "mass_diag_ratio",
                                "condition_number",
                                "min_relative_diagonal",
                                "wall_time"})
            {
              statistics.set_scientific(c, true);
              statistics.set_precision(c, 8);
            }
          if (reference.exists())
            for (const auto &c :
                 {"displacement_L2", "velocity_L2", "stress_L2"})
              {
                statistics.set_scientific(c, true);
                statistics.set_precision(c, 8);
              }
          std::ofstream out(output_directory + "/statistics.txt");
          statistics.write_text(
            out,
            TableHandler::table_with_separate_column_description);
        }
      write_tracked_particle();
    }

    MPMSolver::Status
    MPMSolver::run(const std::string &directory)
    {
      output_directory = directory;
      writer = std::make_unique<Postprocess::OutputWriter>(directory, comm);
      Timer wall;
      wall.start();

      if (track && reference.exists())
        {
          track_axis =
            (reference.type ==
               Postprocess::ReferenceSolution::Type::soil_column ||
             reference.type ==
               Postprocess::ReferenceSolution::Type::soil_column_ulfem) ?
              1 :
              0;
          find_tracked_particle();
        }
      grid_velocity.assign(grid->relevant_dofs().n_elements(), Tensor<1, 2>());
      grid_acceleration = grid_velocity;
      time_step_now     = 0;
      postprocess(0, 0);
      write_output(0);

      if (!time_step_warning.empty())
        pcout << "psmpm: warning: " << time_step_warning << std::endl;
      pcout << "psmpm: " << space->name() << " basis, " << dof_handler.n_dofs()
            << " DoFs, " << Utilities::MPI::sum(particles.size(), comm)
            << " particles, dt = " << time_step << ", end time = " << end_time
            << std::endl;

      while (time < end_time * (1 - 1e-12) && status == Status::completed)
        {
          const double dt = std::min(time_step, end_time - time);
          do_time_step(dt);
          ++step;
          postprocess(step, wall.wall_time());
          const bool last =
            !(time < end_time * (1 - 1e-12)) || status != Status::completed;
          if (last || (output_interval > 0 && step % output_interval == 0))
            write_output(step);
        }
      wall.stop();
      if (!quiet)
        {
          timer.print_wall_time_statistics(comm);
          if (status == Status::unstable)
            pcout << "psmpm: UNSTABLE at step " << failed_step << ": "
                  << failure_reason << std::endl;
        }
      return status;
    }

    void
    MPMSolver::fill_summary(Postprocess::Summary &summary) const
    {
      summary.set("status",
                  status == Status::completed ? "completed" : "unstable");
      if (status == Status::unstable)
        {
          summary.set("reason", failure_reason);
          summary.set_integer("failed_step", failed_step);
          summary.set("failed_time", failed_time);
        }
      summary.set_integer("steps", step);
      if (!time_step_warning.empty())
        summary.set("warning", time_step_warning);
      summary.set_integer("n_dofs", dof_handler.n_dofs());
      summary.set_integer("n_cells", triangulation.n_active_cells());
      summary.set_integer("n_particles",
                          Utilities::MPI::sum(particles.size(), comm));
      summary.set_integer("n_mpi_ranks", Utilities::MPI::n_mpi_processes(comm));
      summary.set_integer("cg_iterations", total_iterations);
      summary.set("end_time", time);
      summary.set("time_step", time_step);
      summary.set("basis", space->name());
      summary.set("mass_matrix", mass_type_name);
      if (reference.exists())
        {
          // The last step's errors are usually computed already.
          const Errors e = error_history.latest_step == step ?
                             error_history.latest :
                             compute_errors();
          summary.set("errors.displacement_L2", e.displacement);
          summary.set("errors.velocity_L2", e.velocity);
          summary.set("errors.stress_L2", e.stress);
          summary.set("errors.displacement_L2_max_over_time",
                      error_history.max_displacement);
          if (error_history.n > 0)
            {
              summary.set("errors.displacement_L2_rms_over_time",
                          std::sqrt(error_history.sum_displacement2 /
                                    error_history.n));
              summary.set("errors.velocity_L2_rms_over_time",
                          std::sqrt(error_history.sum_velocity2 /
                                    error_history.n));
            }
          if (track && !tracked_history.empty())
            {
              summary.set("errors.tracked_velocity_rms",
                          std::sqrt(tracked_velocity2 /
                                    tracked_history.size()));
              summary.set("errors.tracked_displacement_rms",
                          std::sqrt(tracked_displacement2 /
                                    tracked_history.size()));
            }
        }
      // Throughput of the time loop proper: every timed phase but output.
      const auto timings = timer.get_summary_data(TimerOutput::total_wall_time);
      double     loop    = 0;
      for (const auto &t : timings)
        {
          std::string key = t.first;
          std::replace(key.begin(), key.end(), ' ', '_');
          summary.set("timers_s." + key, t.second);
          if (t.first != "output")
            loop += t.second;
        }
      summary.set("time_loop_s", loop);
      if (loop > 0)
        summary.set("particle_steps_per_second",
                    summary.get_number("n_particles") * step / loop);
    }
  } // namespace Solver
} // namespace psmpm
