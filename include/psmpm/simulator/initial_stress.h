// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_simulator_initial_stress_h
#define psmpm_simulator_initial_stress_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <psmpm/material/material_set.h>
#include <psmpm/mesh/mesh_generator.h>
#include <psmpm/particles/particle_generator.h>
#include <psmpm/particles/particle_set.h>

#include <map>
#include <string>
#include <vector>

namespace psmpm
{
  namespace Simulator
  {
    using namespace dealii;

    /// The constants of Initial conditions/Function constants
    /// (name=value, comma separated) with pi: for the initial velocity
    /// and the stress function alike.
    std::map<std::string, double>
    parse_function_constants(const std::string &text);

    /**
     * The stress the particles start with (entries Stress, K0 and Stress
     * function of subsection "Initial conditions"; doc/geomechanics.md,
     * "Initial stress").
     *
     * - none: zero stress (the default; nothing is computed).
     * - geostatic: every body at rest under Body force/Gravity. "Up" is
     *   u = -g / |g| (any direction of g), the depth of a particle is
     *   measured along u from the body's free surface above it: the top
     *   (along u) of the body's particles within half a particle spacing
     *   across u, plus half the particle spacing along u (what the
     *   particles' own weight puts above the particle on a regular
     *   layout). sigma_v = -rho |g| depth (compressive), the stress across
     *   u and the out-of-plane (2D) or lateral (1D) stress K0 sigma_v, no
     *   shear in the (u, u-perp) frame. A body whose bottom lies within one
     *   particle spacing of another body's top in the same column rests on
     *   it and adds its column weight (its own and what rests on it) to
     *   the stress of every particle of the lower body in that column.
     * - function: Stress function = sxx; syy; sxy; szz (2D) or sxx;
     *   lateral (1D), expressions of x, y with Initial conditions/Function
     *   constants.
     *
     * The stress is particle state: applied once when the particles are
     * made (a resumed run loads its particles instead). Refused for a
     * material whose stress follows from a deformation gradient
     * (Material::accepts_initial_stress()).
     */
    template <int dim>
    class InitialStress
    {
    public:
      enum class Type
      {
        none,
        geostatic,
        function
      };

      /// Entries Stress, K0 and Stress function of "Initial conditions".
      static void
      declare_parameters(ParameterHandler &prm);

      /**
       * Read the entries, check them against the materials of the scene
       * (@p bodies: empty, or the Bodies whose materials @p materials
       * holds) and the gravity, and find K0 per body. Throws ExcMessage
       * naming the entry on bad input.
       */
      void
      parse_parameters(ParameterHandler                 &prm,
                       const Material::MaterialSet<dim> &materials,
                       const Particles::Bodies          &bodies,
                       const Tensor<1, dim>             &gravity);

      bool
      active() const
      {
        return type != Type::none;
      }

      /**
       * The distance between neighbouring particles of the regular layout
       * of block meshes per coordinate direction; zero on Gmsh meshes
       * (there each particle's own size, volume^(1/dim), is used).
       */
      static Tensor<1, dim>
      lattice_spacing(const Mesh::MeshGenerator<dim>          &mesh,
                      const Particles::ParticleGenerator<dim> &generator);

      /**
       * Set the stress of every particle (after MaterialSet::initialize());
       * collective over @p comm (the free surface of the geostatic stress
       * is reduced over all ranks).
       */
      void
      apply(Particles::ParticleSet<dim>      &particles,
            const Material::MaterialSet<dim> &materials,
            const Tensor<1, dim>             &gravity,
            const Tensor<1, dim>             &spacing,
            MPI_Comm                          comm) const;

      Type type = Type::none;
      /// K0 by body id (index 0: the material of a scene without Bodies).
      std::vector<double> k0;

    private:
      void
      apply_geostatic(Particles::ParticleSet<dim> &particles,
                      const std::vector<double>   &densities,
                      const Tensor<1, dim>        &gravity,
                      const Tensor<1, dim>        &spacing,
                      std::vector<double>         &out_of_plane,
                      MPI_Comm                     comm) const;

      void
      apply_function(Particles::ParticleSet<dim> &particles,
                     std::vector<double>         &out_of_plane,
                     MPI_Comm                     comm) const;

      std::string function_expression;
      std::string function_constants;
    };
  } // namespace Simulator
} // namespace psmpm

#endif
