// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/auto_derivative_function.h>
#include <deal.II/base/function_parser.h>

#include <psmpm/simulator/initial_conditions.h>

#include <algorithm>

namespace psmpm
{
  namespace Simulator
  {
    namespace
    {
      /// The velocity (and with @p affine its gradient) of @p expression
      /// at the particles of body @p body; @p entry names it in errors.
      template <int dim>
      void
      set_body_velocity(Particles::ParticleSet<dim>         &particles,
                        const std::map<std::string, double> &constants,
                        const bool                           affine,
                        const std::string                   &expression,
                        const std::string                   &entry,
                        const unsigned int                   body,
                        const double                         step)
      {
        FunctionParser<dim> velocity(dim, 0., step);
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
      }
    } // namespace

    template <int dim>
    void
    InitialConditions<dim>::declare_parameters(ParameterHandler &prm)
    {
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
    }

    template <int dim>
    void
    InitialConditions<dim>::parse_parameters(
      ParameterHandler                 &prm,
      const Material::MaterialSet<dim> &materials,
      const Particles::Bodies          &bodies,
      const Tensor<1, dim>             &gravity)
    {
      prm.enter_subsection("Initial conditions");
      velocity_expression = prm.get("Velocity");
      velocity_constants  = prm.get("Function constants");
      prm.leave_subsection();
      const std::string constants =
        " (Initial conditions/Function constants = '" + velocity_constants +
        "')";
      velocity_entries.assign(1,
                              "Initial conditions/Velocity = '" +
                                velocity_expression + "'" + constants);
      for (const auto &body : bodies.bodies)
        {
          velocity_entries.resize(
            std::max<std::size_t>(velocity_entries.size(), body.number + 1));
          velocity_entries[body.number] = body.name() +
                                          "/Initial velocity = '" +
                                          body.velocity + "'" + constants;
        }
      stress.parse_parameters(prm, materials, bodies, gravity);
    }

    template <int dim>
    void
    InitialConditions<dim>::set_velocities(
      Particles::ParticleSet<dim> &particles,
      const Particles::Bodies     &bodies,
      const bool                   affine,
      const double                 length) const
    {
      const double step      = 1e-3 * length;
      const auto   constants = parse_function_constants(velocity_constants);
      // The transfers that are not affine never update C_p, so it stays
      // zero for them (a stale C_p would enter the reported angular
      // momentum). Without Bodies one expression for all particles; with
      // them, each body's own.
      if (bodies.bodies.empty())
        set_body_velocity(particles,
                          constants,
                          affine,
                          velocity_expression,
                          "Initial conditions/Velocity",
                          0,
                          step);
      for (const auto &body : bodies.bodies)
        set_body_velocity(particles,
                          constants,
                          affine,
                          body.velocity,
                          body.name() + "/Initial velocity",
                          body.number,
                          step);
    }

    template <int dim>
    std::string
    InitialConditions<dim>::velocity_entry(const unsigned int body_id) const
    {
      return body_id < velocity_entries.size() ? velocity_entries[body_id] :
                                                 "Initial conditions/Velocity";
    }

    template struct InitialConditions<1>;
    template struct InitialConditions<2>;
  } // namespace Simulator
} // namespace psmpm
