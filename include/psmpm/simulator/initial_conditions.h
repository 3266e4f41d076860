// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_simulator_initial_conditions_h
#define psmpm_simulator_initial_conditions_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <psmpm/material/material_set.h>
#include <psmpm/particles/body.h>
#include <psmpm/particles/particle_set.h>
#include <psmpm/simulator/initial_stress.h>

#include <string>
#include <vector>

namespace psmpm
{
  namespace Simulator
  {
    using namespace dealii;

    /**
     * The state the particles start with (subsection "Initial
     * conditions"): the velocity, one expression for all particles or
     * each body's own (Bodies/.../Initial velocity), and the stress
     * (InitialStress). Applied once when the particles are made; a
     * resumed run loads its particles instead.
     */
    template <int dim>
    struct InitialConditions
    {
      /// Velocity, Function constants and InitialStress's entries.
      static void
      declare_parameters(ParameterHandler &prm);

      /// The entries; the stress is checked against @p materials,
      /// @p bodies and @p gravity (InitialStress::parse_parameters()).
      void
      parse_parameters(ParameterHandler                 &prm,
                       const Material::MaterialSet<dim> &materials,
                       const Particles::Bodies          &bodies,
                       const Tensor<1, dim>             &gravity);

      /**
       * Set the velocity of every particle and, if @p affine (the
       * affine transfers start from C_p = grad v), its affine matrix by
       * fourth-order differences with a step of 1e-3 @p length (the
       * mesh's smallest triangle height, the same on every rank): exact
       * to round-off for affine fields, and relative to the mesh so that
       * a scene in micrometres or in kilometres gets the same gradient
       * (a fixed step is wider than a body of micrometres). Throws
       * ExcMessage naming the entry if an expression does not parse.
       */
      void
      set_velocities(Particles::ParticleSet<dim> &particles,
                     const Particles::Bodies     &bodies,
                     const bool                   affine,
                     const double                 length) const;

      /**
       * The entry and value that give the initial velocity of the
       * particles of body @p body_id (0 without Bodies), with the
       * Function constants, for a message about a value it gave:
       * "Bodies/Body 2/Initial velocity = '...' (Initial conditions/
       * Function constants = '...')".
       */
      std::string
      velocity_entry(const unsigned int body_id) const;

      /// Initial conditions/Velocity and Function constants.
      std::string velocity_expression;
      std::string velocity_constants;
      /// velocity_entry() of each body id.
      std::vector<std::string> velocity_entries;
      /// Initial conditions/Stress.
      InitialStress<dim> stress;
    };
  } // namespace Simulator
} // namespace psmpm

#endif
