// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/material/material_set.h>

#include <algorithm>
#include <set>

namespace psmpm
{
  namespace Material
  {
    template <int dim>
    void
    MaterialSet<dim>::declare_parameters(ParameterHandler &prm)
    {
      Material<dim>::declare_parameters(prm);
      prm.enter_subsection("Materials");
      for (unsigned int j = 1; j <= max_materials; ++j)
        {
          prm.enter_subsection("Material " + std::to_string(j));
          Material<dim>::declare_entries(prm);
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }



    template <int dim>
    void
    MaterialSet<dim>::parse_parameters(ParameterHandler        &prm,
                                       const Particles::Bodies &bodies)
    {
      instances.clear();
      ids.assign(1, 0);
      instances.push_back(Material<dim>::create(prm));
      for (const auto &body : bodies.bodies)
        {
          const unsigned int             j = body.material;
          std::unique_ptr<Material<dim>> m;
          if (j == 0)
            m = Material<dim>::create(prm);
          else
            {
              // Only the materials that a body names are read, so that the
              // defaults of the others never matter.
              const std::string path =
                "Materials/Material " + std::to_string(j);
              prm.enter_subsection("Materials");
              prm.enter_subsection("Material " + std::to_string(j));
              try
                {
                  m = Material<dim>::create(prm, path);
                }
              catch (...)
                {
                  prm.leave_subsection();
                  prm.leave_subsection();
                  throw;
                }
              prm.leave_subsection();
              prm.leave_subsection();
            }
          if (body.density > 0)
            m->density = body.density;
          instances.push_back(std::move(m));
          ids.push_back(j);
        }

      // The union of the state names, a model's names one contiguous
      // block: a list already present is shared, any other is appended
      // (suffixed with the material id where a name would repeat).
      names.clear();
      offsets.clear();
      for (unsigned int k = 0; k < instances.size(); ++k)
        {
          const auto own = instances[k]->state_names();
          auto       at =
            std::search(names.begin(), names.end(), own.begin(), own.end());
          if (own.empty())
            offsets.push_back(0);
          else if (at != names.end())
            offsets.push_back(at - names.begin());
          else
            {
              offsets.push_back(names.size());
              for (const auto &n : own)
                names.push_back(std::find(names.begin(), names.end(), n) ==
                                    names.end() ?
                                  n :
                                  n + "_" + std::to_string(ids[k]));
            }
        }
      stride = names.size();
      for (auto &m : instances)
        m->set_state_stride(stride);

      // The materials whose particles exist (subsection Material alone
      // without Bodies) and their bounds, fixed for the run: the time
      // step asks for the wave speed every step.
      used.clear();
      for (unsigned int k = (instances.size() == 1 ? 0 : 1);
           k < instances.size();
           ++k)
        used.push_back(instances[k].get());
      density_bound = wave_speed_bound = 0;
      for (const auto *m : used)
        {
          density_bound    = std::max(density_bound, m->density);
          wave_speed_bound = std::max(wave_speed_bound, m->p_wave_speed());
        }
    }



    template <int dim>
    std::string
    MaterialSet<dim>::model_names() const
    {
      std::vector<std::string> seen;
      std::string              r;
      for (const auto *m : used)
        if (std::find(seen.begin(), seen.end(), m->name()) == seen.end())
          {
            seen.push_back(m->name());
            r += (r.empty() ? "" : ", ") + m->name();
          }
      return r;
    }



    template <int dim>
    template <typename F>
    void
    MaterialSet<dim>::for_each_run(const Particles::ParticleSet<dim> &particles,
                                   const F                           &f) const
    {
      for_each_run(particles, 0, particles.size(), f);
    }



    template <int dim>
    template <typename F>
    void
    MaterialSet<dim>::for_each_run(const Particles::ParticleSet<dim> &particles,
                                   const std::size_t                  first,
                                   const std::size_t                  last,
                                   const F                           &f) const
    {
      if (instances.size() == 1)
        {
          if (first < last)
            f(*instances[0], offsets[0], first, last);
          return;
        }
      const auto &body = particles.body_id;
      for (std::size_t begin = first; begin < last;)
        {
          std::size_t end = begin + 1;
          while (end < last && body[end] == body[begin])
            ++end;
          const unsigned int k = body[begin];
          AssertIndexRange(k, instances.size());
          f(*instances[k], offsets[k], begin, end);
          begin = end;
        }
    }



    template <int dim>
    void
    MaterialSet<dim>::initialize(Particles::ParticleSet<dim> &particles) const
    {
      std::fill(particles.state.begin(), particles.state.end(), 0.);
      double *state = particles.state.data();
      for_each_run(particles,
                   [&](const Material<dim> &m,
                       const unsigned int   offset,
                       const std::size_t    begin,
                       const std::size_t    end) {
                     m.initialize(end - begin, state + begin * stride + offset);
                   });
    }



    template <int dim>
    void
    MaterialSet<dim>::set_initial_stress(Particles::ParticleSet<dim> &particles,
                                         const double *out_of_plane) const
    {
      double *state = particles.state.data();
      for_each_run(particles,
                   [&](const Material<dim> &m,
                       const unsigned int   offset,
                       const std::size_t    begin,
                       const std::size_t    end) {
                     m.set_initial_stress(end - begin,
                                          particles.stress.data() + begin,
                                          out_of_plane + begin,
                                          state + begin * stride + offset);
                   });
    }



    template <int dim>
    void
    MaterialSet<dim>::update(Particles::ParticleSet<dim> &particles,
                             const std::size_t            first,
                             const std::size_t            last,
                             const Tensor<2, dim>        *dL,
                             double                      *volume_ratio) const
    {
      double                  *state  = particles.state.data();
      SymmetricTensor<2, dim> *stress = particles.stress.data();
      for_each_run(particles,
                   first,
                   last,
                   [&](const Material<dim> &m,
                       const unsigned int   offset,
                       const std::size_t    begin,
                       const std::size_t    end) {
                     m.update(end - begin,
                              dL + (begin - first),
                              stress + begin,
                              state + begin * stride + offset,
                              volume_ratio + (begin - first));
                   });
    }



    template <int dim>
    void
    MaterialSet<dim>::energy_density(
      const Particles::ParticleSet<dim> &particles,
      const std::size_t                  first,
      const std::size_t                  last,
      double                            *energy) const
    {
      const double *state = particles.state.data();
      for_each_run(particles,
                   first,
                   last,
                   [&](const Material<dim> &m,
                       const unsigned int   offset,
                       const std::size_t    begin,
                       const std::size_t    end) {
                     m.energy_density(end - begin,
                                      particles.stress.data() + begin,
                                      state + begin * stride + offset,
                                      energy + (begin - first));
                   });
    }



    template <int dim>
    void
    MaterialSet<dim>::dissipated_energy(
      const Particles::ParticleSet<dim> &particles,
      const std::size_t                  first,
      const std::size_t                  last,
      double                            *per_unit_mass) const
    {
      const double *state = particles.state.data();
      for_each_run(particles,
                   first,
                   last,
                   [&](const Material<dim> &m,
                       const unsigned int   offset,
                       const std::size_t    begin,
                       const std::size_t    end) {
                     m.dissipated_energy(end - begin,
                                         state + begin * stride + offset,
                                         per_unit_mass + (begin - first));
                   });
    }



    template <int dim>
    bool
    MaterialSet<dim>::dissipates() const
    {
      for (const auto *m : used)
        if (m->dissipates())
          return true;
      return false;
    }



    template <int dim>
    double
    MaterialSet<dim>::max_wave_speed(
      const Particles::ParticleSet<dim> &particles) const
    {
      double        c     = 0;
      const double *state = particles.state.data();
      for_each_run(particles,
                   [&](const Material<dim> &m,
                       const unsigned int   offset,
                       const std::size_t    begin,
                       const std::size_t    end) {
                     c = std::max(
                       c,
                       m.max_wave_speed(end - begin,
                                        particles.stress.data() + begin,
                                        state + begin * stride + offset));
                   });
      return c;
    }



    template class MaterialSet<1>;
    template class MaterialSet<2>;
  } // namespace Material
} // namespace psmpm
