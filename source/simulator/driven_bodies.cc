// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/utilities.h>

#include <psmpm/simulator/driven_bodies.h>
#include <psmpm/simulator/function_of_time.h>
#include <psmpm/solver/grid_system.h>

#include <algorithm>

namespace psmpm
{
  namespace Simulator
  {
    template <int dim>
    void
    DrivenBodies<dim>::parse(const std::vector<Particles::Body> &bodies,
                             const bool                          contact)
    {
      driven.assign(bodies.size(), 0);
      functions.clear();
      functions.resize(bodies.size());
      entries.assign(bodies.size(), std::string());
      n_driven = 0;
      for (const auto &body : bodies)
        {
          if (!body.prescribed_motion)
            continue;
          const std::string entry =
            body.name() + "/Velocity = " + body.motion_velocity + ": ";
          AssertThrow(contact,
                      ExcMessage(body.name() +
                                 "/Motion = prescribed: a driven body acts "
                                 "on the others only through Contact/Type = "
                                 "multi-velocity."));
          const auto expressions =
            Utilities::split_string_list(body.motion_velocity, ';');
          AssertThrow(expressions.size() == dim,
                      ExcMessage(entry + "needs " + std::to_string(dim) +
                                 " expression(s) of t separated by ';'."));
          std::unique_ptr<FunctionParser<1>> function;
          try
            {
              function = parse_function_of_time(expressions);
            }
          catch (const std::exception &e)
            {
              AssertThrow(false,
                          ExcMessage(entry + "not a function of t (" +
                                     Utilities::trim(e.what()) + ")."));
            }
          driven[body.number - 1]    = 1;
          functions[body.number - 1] = std::move(function);
          entries[body.number - 1] =
            body.name() + "/Velocity = '" + body.motion_velocity + "'";
          ++n_driven;
        }
      AssertThrow(n_driven == 0 || n_driven < bodies.size(),
                  ExcMessage("Bodies/Body k/Motion = prescribed for every "
                             "body (Bodies/Number of bodies = " +
                             std::to_string(bodies.size()) +
                             "): at least one body must move freely."));
      end_velocity.assign(bodies.size(), Tensor<1, dim>());
      mid_velocity.assign(bodies.size(), Tensor<1, dim>());
      shapes.clear();
      for (const auto &body : bodies)
        shapes.push_back(body.shape);
      start_displacement.assign(bodies.size(), Tensor<1, dim>());
      end_displacement.assign(bodies.size(), Tensor<1, dim>());
    }

    template <int dim>
    bool
    DrivenBodies<dim>::inside(const unsigned int b, const Point<dim> &x) const
    {
      // The shape is 2D: a point of a 1D run on the x axis.
      Point<2> y;
      for (unsigned int d = 0; d < dim; ++d)
        y[d] = x[d] - start_displacement[b][d];
      return shapes[b].inside(y);
    }

    template <int dim>
    std::vector<double>
    DrivenBodies<dim>::displacements() const
    {
      std::vector<double> values;
      for (const auto &u : end_displacement)
        for (unsigned int d = 0; d < dim; ++d)
          values.push_back(u[d]);
      return values;
    }

    template <int dim>
    void
    DrivenBodies<dim>::set_displacements(const std::vector<double> &values)
    {
      AssertDimension(values.size(), end_displacement.size() * dim);
      for (unsigned int b = 0; b < end_displacement.size(); ++b)
        for (unsigned int d = 0; d < dim; ++d)
          end_displacement[b][d] = values[b * dim + d];
      start_displacement = end_displacement;
    }

    template <int dim>
    Tensor<1, dim>
    DrivenBodies<dim>::velocity(const unsigned int b, const double t) const
    {
      Tensor<1, dim> v;
      for (unsigned int d = 0; d < dim; ++d)
        v[d] = functions[b]->value(Point<1>(t), d);
      return v;
    }

    template <int dim>
    std::string
    DrivenBodies<dim>::non_finite_velocity(const double t,
                                           const double dt) const
    {
      for (unsigned int b = 0; b < functions.size(); ++b)
        if (functions[b])
          for (const double at : {t + dt / 2, t + dt})
            {
              const std::string bad = non_finite_at(*functions[b], at);
              if (!bad.empty())
                return entries[b] + bad;
            }
      return std::string();
    }

    template <int dim>
    void
    DrivenBodies<dim>::start_step(const State<dim> &state)
    {
      if (n_driven == 0)
        return;
      for (unsigned int b = 0; b < driven.size(); ++b)
        if (driven[b])
          {
            end_velocity[b] = velocity(b, state.time + state.dt);
            mid_velocity[b] = velocity(b, state.time + 0.5 * state.dt);
            start_displacement[b] = end_displacement[b];
            end_displacement[b] += state.dt * mid_velocity[b];
          }
      const auto &set = state.particles;
      particles.clear();
      start_position.clear();
      energy_change = 0;
      for (std::size_t p = 0; p < set.size(); ++p)
        if (driven[set.body_id[p] - 1])
          {
            particles.push_back(p);
            start_position.push_back(set.position[p]);
            energy_change +=
              0.5 * set.mass[p] *
              (end_velocity[set.body_id[p] - 1].norm_square() -
               set.velocity[p].norm_square());
          }
    }

    template <int dim>
    void
    DrivenBodies<dim>::set_velocities(State<dim>       &state,
                                      const bool        affine,
                                      const Point<dim> *control_points,
                                      const bool        to_grid) const
    {
      auto               &set  = state.particles;
      const unsigned int  n    = state.grid->dofs_per_cell;
      const unsigned int *dofs = state.grid->cell_dofs().data();
      Tensor<1, dim>     *rhs  = state.grid->cell_arrays().rhs.data();
      for (const std::size_t p : particles)
        {
          const unsigned int   cell = set.cell[p];
          const double        *phi  = &state.shape_values[p * n];
          const double         m    = set.mass[p];
          const Tensor<1, dim> dv =
            end_velocity[set.body_id[p] - 1] - set.velocity[p];
          set.velocity[p] += dv;
          Tensor<2, dim> dC;
          if (affine)
            {
              dC            = -set.affine[p];
              set.affine[p] = Tensor<2, dim>();
            }
          for (unsigned int k = 0; k < n && to_grid; ++k)
            {
              Tensor<1, dim> dq = dv;
              if (affine)
                dq +=
                  dC * (control_points[dofs[cell * n + k]] - set.position[p]);
              rhs[cell * n + k] += (phi[k] * m) * dq;
            }
        }
    }

    template <int dim>
    void
    DrivenBodies<dim>::move(State<dim>       &state,
                            const std::size_t first,
                            const std::size_t last,
                            Tensor<2, dim>   *increments) const
    {
      auto        &set    = state.particles;
      const double dt     = state.dt;
      const bool   affine = !set.affine.empty();
      for (std::size_t j =
             std::lower_bound(particles.begin(), particles.end(), first) -
             particles.begin();
           j < particles.size() && particles[j] < last;
           ++j)
        {
          const std::size_t  p = particles[j];
          const unsigned int b = set.body_id[p] - 1;
          const Point<dim>   x = start_position[j] + dt * mid_velocity[b];
          set.displacement[p] += x - set.position[p];
          set.position[p] = x;
          set.velocity[p] = end_velocity[b];
          if (affine)
            set.affine[p] = Tensor<2, dim>();
          increments[p - first] = Tensor<2, dim>();
        }
    }

    template class DrivenBodies<1>;
    template class DrivenBodies<2>;
  } // namespace Simulator
} // namespace psmpm
