// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_simulator_driven_bodies_h
#define psmpm_simulator_driven_bodies_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <psmpm/particles/body.h>
#include <psmpm/simulator/state.h>

#include <memory>
#include <vector>

namespace psmpm
{
  namespace Simulator
  {
    /**
     * The bodies with Bodies/Body k/Motion = prescribed (doc/contact.md,
     * "Driven bodies"): rigid bodies whose particles move with a given
     * velocity v(t). Their particles still take part in the step as any
     * others (their mass and momentum go to the grid, so that contact
     * sees them); after the grid update this class overrides them, in
     * passes over the driven particles alone: velocity v(t^{n+1}), affine
     * matrix 0, position x^n + dt v(t^n + dt/2) (the midpoint rule, exact
     * for a velocity linear in t over the step), no strain increment.
     */
    template <int dim>
    class DrivenBodies
    {
    public:
      /// The velocities of the driven bodies of @p bodies; throws
      /// ExcMessage naming the entry for a velocity that is not a function
      /// of t, a driven body without @p contact (Contact/Type =
      /// multi-velocity) or bodies that are all driven.
      void
      parse(const std::vector<Particles::Body> &bodies, const bool contact);

      bool
      any() const
      {
        return n_driven > 0;
      }

      /// Per body (0-based): 1 if driven (empty without bodies).
      const std::vector<char> &
      flags() const
      {
        return driven;
      }

      /// v(t) of driven body @p b (0-based).
      Tensor<1, dim>
      velocity(const unsigned int b, const double t) const;

      /// For a step from @p t over @p dt: the entry of the first driven
      /// body whose velocity is not finite at a time the step takes it
      /// at (t + dt/2, t + dt), with that time; empty if none.
      std::string
      non_finite_velocity(const double t, const double dt) const;

      /// At the start of a step from t = state.time over state.dt: the
      /// driven particles (in the particle set's current order), their
      /// positions x^n, and each driven body's v(t^{n+1}) and midpoint
      /// velocity.
      void
      start_step(const State<dim> &state);

      /// The change of the driven particles' kinetic energy that the
      /// step's override makes, sum over this rank's particles of
      /// m_p (|v(t^{n+1})|^2 - |v_p|^2) / 2, valid after start_step().
      double
      kinetic_energy_change() const
      {
        return energy_change;
      }

      /// v(t^{n+1}) of driven body @p b, valid after start_step().
      const Tensor<1, dim> &
      new_velocity(const unsigned int b) const
      {
        return end_velocity[b];
      }

      /// Whether @p x lies inside (or on the outline of) driven body @p b's
      /// shape (Bodies/Body k) moved by its displacement at the start of
      /// the step, valid after start_step(). A rigid body that translates
      /// fills exactly that region (a 1D point is taken on the x axis).
      bool
      inside(const unsigned int b, const Point<dim> &x) const;

      /// The displacement of every body at the end of the step (the
      /// integral of v over the steps so far, 0 for free bodies), which
      /// a checkpoint keeps; set_displacements() restores it.
      std::vector<double>
      displacements() const;
      void
      set_displacements(const std::vector<double> &values);

      /**
       * After the particle velocity update (MUSL's accelerate, apic's
       * grid-to-particle): v_p = v(t^{n+1}) and, with @p affine, C_p = 0;
       * the change of the particles' momentum (of their affine field,
       * with @p control_points) goes into the cell right-hand sides, so
       * that the grid velocity the particles move with sees the driven
       * velocity (unless @p to_grid is false).
       */
      void
      set_velocities(State<dim>       &state,
                     const bool        affine,
                     const Point<dim> *control_points,
                     const bool        to_grid) const;

      /// For the moved particles [@p first, @p last) of a chunk: the
      /// driven ones' positions, displacements, velocities, affine
      /// matrices and (zero) strain increments.
      void
      move(State<dim>       &state,
           const std::size_t first,
           const std::size_t last,
           Tensor<2, dim>   *increments) const;

    private:
      std::vector<char>                               driven;
      std::vector<std::unique_ptr<FunctionParser<1>>> functions;
      /// Per body: "Bodies/Body k/Velocity = '...'" (driven ones).
      std::vector<std::string> entries;
      unsigned int                                    n_driven = 0;
      /// Per step: the driven particles (ascending), their positions at
      /// the start of the step, and per body v(t^{n+1}) and v(t^n+dt/2).
      std::vector<std::size_t>    particles;
      std::vector<Point<dim>>     start_position;
      std::vector<Tensor<1, dim>> end_velocity, mid_velocity;
      /// Per body: its shape as given, and its displacement at the start
      /// and at the end of the step (sum of dt v(t^n + dt/2), the
      /// particles' own midpoint rule).
      std::vector<Particles::Shape> shapes;
      std::vector<Tensor<1, dim>>   start_displacement, end_displacement;
      double                      energy_change = 0;
    };
  } // namespace Simulator
} // namespace psmpm

#endif
