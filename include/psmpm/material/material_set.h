// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_material_material_set_h
#define psmpm_material_material_set_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <psmpm/material/material.h>
#include <psmpm/particles/body.h>
#include <psmpm/particles/particle_set.h>

#include <memory>
#include <string>
#include <vector>

namespace psmpm
{
  namespace Material
  {
    using namespace dealii;

    /**
     * The materials of a run: subsection "Material" and, for scenes built
     * from Bodies, the material each body names (Bodies/Body k/Material =
     * 0 for subsection "Material", j for subsection "Materials/Material
     * j"), each with its own model and constants.
     *
     * One model instance per body (index = the particles' body_id; index
     * 0 is subsection "Material", the material of runs without Bodies), so
     * that a body's own Density enters its wave speed.
     *
     * All particles share one state array. Its columns are the union of
     * the models' state names (a model's names are one contiguous block;
     * models with the same names share it, e.g. hypoelastic and linear
     * elastic); each instance reads and writes its own columns through
     * Material::state_stride(), the other columns of its particles stay
     * zero. With one model this is that model's layout, unchanged.
     *
     * The batch functions walk the particles in runs of equal body_id
     * (particles are sorted by cell, so a run is usually a cell or more)
     * and make one virtual call per run, never one per particle.
     */
    template <int dim>
    class MaterialSet
    {
    public:
      static constexpr unsigned int max_materials =
        Particles::Bodies::max_materials;

      /// Subsection "Materials" with "Material 1" ... "Material 8", each
      /// with the entries of subsection "Material".
      static void
      declare_parameters(ParameterHandler &prm);

      /// Subsection "Material", then the materials that @p bodies name.
      void
      parse_parameters(ParameterHandler &prm, const Particles::Bodies &bodies);

      /// Subsection "Material": what references, defaults and runs
      /// without Bodies use.
      const Material<dim> &
      primary() const
      {
        return *instances[0];
      }

      /// The material of particles with body_id @p body.
      const Material<dim> &
      of_body(const unsigned int body) const
      {
        return *instances[body];
      }

      /// 0: subsection "Material", j: "Materials/Material j".
      unsigned int
      material_id(const unsigned int body) const
      {
        return ids[body];
      }

      /// The material ids indexed by body_id (output).
      const std::vector<unsigned int> &
      material_ids() const
      {
        return ids;
      }

      /// Columns of the particles' state array.
      const std::vector<std::string> &
      state_names() const
      {
        return names;
      }

      /// Model names of the materials in use, without repetitions, joined
      /// by ", " (summary.json).
      std::string
      model_names() const;

      /// Largest density and p-wave speed of the materials in use.
      double
      max_density() const
      {
        return density_bound;
      }
      double
      max_p_wave_speed() const
      {
        return wave_speed_bound;
      }

      /// Initial state of every particle (state_names() columns set).
      void
      initialize(Particles::ParticleSet<dim> &particles) const;

      /**
       * Material::set_initial_stress() for every particle: the in-plane
       * stress is already in particles.stress, @p out_of_plane[i] is the
       * out-of-plane (2D) or lateral (1D) stress of particle i. After
       * initialize().
       */
      void
      set_initial_stress(Particles::ParticleSet<dim> &particles,
                         const double                *out_of_plane) const;

      /// Material::update() for the particles [@p first, @p last), whose
      /// increments and volume ratios start at dL[0] and volume_ratio[0].
      void
      update(Particles::ParticleSet<dim> &particles,
             const std::size_t            first,
             const std::size_t            last,
             const Tensor<2, dim>        *dL,
             double                      *volume_ratio) const;

      /// Material::energy_density() for the particles [@p first, @p last),
      /// into energy[0 .. last - first).
      void
      energy_density(const Particles::ParticleSet<dim> &particles,
                     const std::size_t                  first,
                     const std::size_t                  last,
                     double                            *energy) const;

      /// Material::dissipated_energy() [J/kg] for the particles [@p first,
      /// @p last), into per_unit_mass[0 .. last - first).
      void
      dissipated_energy(const Particles::ParticleSet<dim> &particles,
                        const std::size_t                  first,
                        const std::size_t                  last,
                        double                            *per_unit_mass) const;

      /// Whether a material in use can dissipate energy (plasticity).
      bool
      dissipates() const;

      /// Largest Material::max_wave_speed() over all particles.
      double
      max_wave_speed(const Particles::ParticleSet<dim> &particles) const;

    private:
      /// Call @p f(material, begin, end) for each run [begin, end) of
      /// particles with one body_id.
      template <typename F>
      void
      for_each_run(const Particles::ParticleSet<dim> &particles,
                   const F                           &f) const;

      /// The same within the particles [@p first, @p last).
      template <typename F>
      void
      for_each_run(const Particles::ParticleSet<dim> &particles,
                   const std::size_t                  first,
                   const std::size_t                  last,
                   const F                           &f) const;

      std::vector<std::unique_ptr<Material<dim>>> instances;
      std::vector<unsigned int>                   ids;
      std::vector<unsigned int>                   offsets; ///< per instance
      std::vector<std::string>                    names;
      unsigned int                                stride = 0;
      /// Instances whose particles exist (index 0 alone without Bodies).
      std::vector<const Material<dim> *> used;
      double                             density_bound    = 0;
      double                             wave_speed_bound = 0;
    };
  } // namespace Material
} // namespace psmpm

#endif
