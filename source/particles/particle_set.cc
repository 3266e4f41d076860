// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <psmpm/base/archive.h>
#include <psmpm/particles/particle_set.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <type_traits>

namespace psmpm
{
  namespace Particles
  {
    namespace
    {
      /**
       * Apply @p f to every per-particle array (one entry per particle).
       * The state block (n_state() entries per particle) is not among
       * them: callers move it with its stride.
       */
      template <int dim, typename F>
      void
      for_each_array(ParticleSet<dim> &particles, F &&f)
      {
        f(particles.id);
        f(particles.cell);
        f(particles.mass);
        f(particles.volume);
        f(particles.density);
        f(particles.position);
        f(particles.initial_position);
        f(particles.displacement);
        f(particles.velocity);
        f(particles.stress);
        f(particles.affine);
        f(particles.body_id);
      }

      constexpr unsigned int
      n_stress_components(const unsigned int dim)
      {
        return dim * (dim + 1) / 2;
      }
    } // namespace



    template <int dim>
    void
    ParticleSet<dim>::set_state_names(const std::vector<std::string> &names)
    {
      // The state block's stride is n_state(): changing it would scramble
      // the state of particles already stored.
      AssertThrow(size() == 0 || names.size() == state_names.size(),
                  ExcMessage("ParticleSet: the number of state scalars "
                             "cannot change once particles exist."));
      state_names = names;
    }



    template <int dim>
    void
    ParticleSet<dim>::add(const std::uint64_t new_id,
                          const unsigned int  new_cell,
                          const Point<dim>   &x,
                          const double        new_volume,
                          const double        new_density,
                          const unsigned int  body)
    {
      id.push_back(new_id);
      cell.push_back(new_cell);
      mass.push_back(new_volume * new_density);
      volume.push_back(new_volume);
      density.push_back(new_density);
      position.push_back(x);
      initial_position.push_back(x);
      displacement.emplace_back();
      velocity.emplace_back();
      stress.emplace_back();
      affine.emplace_back();
      body_id.push_back(body);
      state.resize(state.size() + n_state(), 0.);
    }



    template <int dim>
    unsigned int
    ParticleSet<dim>::n_packed() const
    {
      static_assert(SymmetricTensor<2, dim>::n_independent_components ==
                      n_stress_components(dim),
                    "stress is packed by its independent components");
      // id, mass, volume, density; four vectors; stress; state; affine
      // matrix (after the others, so that their offsets do not depend on
      // it); body id.
      return 4 + 4 * dim + n_stress_components(dim) + n_state() + dim * dim + 1;
    }



    template <int dim>
    void
    ParticleSet<dim>::pack(const std::size_t    i,
                           std::vector<double> &buffer) const
    {
      buffer.push_back(static_cast<double>(id[i]));
      buffer.push_back(mass[i]);
      buffer.push_back(volume[i]);
      buffer.push_back(density[i]);
      for (unsigned int d = 0; d < dim; ++d)
        buffer.push_back(position[i][d]);
      for (unsigned int d = 0; d < dim; ++d)
        buffer.push_back(initial_position[i][d]);
      for (unsigned int d = 0; d < dim; ++d)
        buffer.push_back(displacement[i][d]);
      for (unsigned int d = 0; d < dim; ++d)
        buffer.push_back(velocity[i][d]);
      for (unsigned int k = 0; k < n_stress_components(dim); ++k)
        buffer.push_back(stress[i].access_raw_entry(k));
      buffer.insert(buffer.end(), state_of(i), state_of(i) + n_state());
      for (unsigned int d = 0; d < dim; ++d)
        for (unsigned int e = 0; e < dim; ++e)
          buffer.push_back(affine[i][d][e]);
      buffer.push_back(body_id[i]);
    }



    template <int dim>
    void
    ParticleSet<dim>::set_capacity(const std::size_t n)
    {
      const std::size_t target = std::max(n, size());
      const auto        resize = [](auto &array, const std::size_t c) {
        if (array.capacity() == c)
          return;
        std::remove_reference_t<decltype(array)> copy;
        copy.reserve(c);
        copy.assign(array.begin(), array.end());
        array.swap(copy);
      };
      for_each_array(*this, [&](auto &array) { resize(array, target); });
      resize(state, target * n_state());
    }



    template <int dim>
    void
    ParticleSet<dim>::unpack(const std::vector<double> &buffer)
    {
      const unsigned int n = n_packed();
      AssertThrow(buffer.size() % n == 0, ExcInternalError());
      const std::size_t needed = size() + buffer.size() / n;
      if (needed > capacity())
        set_capacity(needed + needed / 8);
      for (std::size_t start = 0; start < buffer.size(); start += n)
        {
          const double *in          = buffer.data() + start;
          const auto    next        = [&in]() { return *in++; };
          const auto    read_vector = [&next]() {
            Tensor<1, dim> v;
            for (unsigned int d = 0; d < dim; ++d)
              v[d] = next();
            return v;
          };
          // The cell is the caller's to find; 0 is a placeholder.
          id.push_back(static_cast<std::uint64_t>(next()));
          cell.push_back(0);
          mass.push_back(next());
          volume.push_back(next());
          density.push_back(next());
          position.emplace_back(read_vector());
          initial_position.emplace_back(read_vector());
          displacement.push_back(read_vector());
          velocity.push_back(read_vector());
          SymmetricTensor<2, dim> s;
          for (unsigned int k = 0; k < n_stress_components(dim); ++k)
            s.access_raw_entry(k) = next();
          stress.push_back(s);
          state.insert(state.end(), in, in + n_state());
          in += n_state();
          Tensor<2, dim> c;
          for (unsigned int d = 0; d < dim; ++d)
            for (unsigned int e = 0; e < dim; ++e)
              c[d][e] = next();
          affine.push_back(c);
          body_id.push_back(static_cast<unsigned int>(next()));
        }
    }



    template <int dim>
    void
    ParticleSet<dim>::compress(const std::vector<bool> &keep)
    {
      AssertDimension(keep.size(), size());
      compress_per_particle(state, keep, n_state());
      for_each_array(*this, [&keep](auto &array) {
        compress_per_particle(array, keep);
      });
    }



    template <int dim>
    void
    ParticleSet<dim>::sort_by_cell(const unsigned int n_cells)
    {
      // Counting sort: stable, so particles of one cell keep their order.
      std::vector<std::size_t> start(n_cells + 1, 0);
      for (const unsigned int c : cell)
        ++start[c + 1];
      std::partial_sum(start.begin(), start.end(), start.begin());
      std::vector<std::size_t> order(size());
      for (std::size_t i = 0; i < size(); ++i)
        order[start[cell[i]]++] = i;

      for_each_array(*this, [&order](auto &array) {
        auto copy = array;
        for (std::size_t i = 0; i < order.size(); ++i)
          array[i] = copy[order[i]];
      });
      const unsigned int        n_s = n_state();
      const std::vector<double> copy(state);
      for (std::size_t i = 0; i < order.size(); ++i)
        std::copy(copy.begin() + order[i] * n_s,
                  copy.begin() + (order[i] + 1) * n_s,
                  state.begin() + i * n_s);
    }



    template <int dim>
    void
    ParticleSet<dim>::save(Archive &archive) const
    {
      const std::size_t n = size();
      archive.put_integers("particles/id", id);
      archive.put_integers("particles/cell",
                           std::vector<std::uint64_t>(cell.begin(),
                                                      cell.end()));
      archive.put("particles/mass", mass);
      archive.put("particles/volume", volume);
      archive.put("particles/density", density);
      const auto vectors = [&](const std::string &name, const auto &array) {
        std::vector<double> v;
        v.reserve(n * dim);
        for (const auto &x : array)
          for (unsigned int d = 0; d < dim; ++d)
            v.push_back(x[d]);
        archive.put("particles/" + name, v, dim);
      };
      vectors("position", position);
      vectors("initial_position", initial_position);
      vectors("displacement", displacement);
      vectors("velocity", velocity);
      const auto tensors = [&](const std::string &name, const auto &array) {
        std::vector<double> v;
        v.reserve(n * dim * dim);
        for (const auto &t : array)
          for (unsigned int d = 0; d < dim; ++d)
            for (unsigned int e = 0; e < dim; ++e)
              v.push_back(t[d][e]);
        archive.put("particles/" + name, v, dim * dim);
      };
      tensors("stress", stress);
      tensors("affine", affine);
      archive.put("particles/state", state, n_state());
      std::string names;
      for (const auto &s : state_names)
        names += s + "\n";
      archive.put_text("particles/state_names", names);
      // Only scenes with Bodies: the checkpoints of the others keep their
      // entries.
      if (n_bodies > 0)
        archive.put_integers("particles/body_id",
                             std::vector<std::uint64_t>(body_id.begin(),
                                                        body_id.end()));
    }



    template <int dim>
    void
    ParticleSet<dim>::load(const Archive &archive)
    {
      std::string names;
      for (const auto &s : state_names)
        names += s + "\n";
      AssertThrow(archive.get_text("particles/state_names") == names,
                  ExcMessage("the material state of the particles differs "
                             "(another Material/Model?)"));
      const auto     &ids = archive.get_integers("particles/id");
      const long long n   = ids.size();
      const auto     &c   = archive.get_integers("particles/cell", n);
      for (const auto v : c)
        AssertThrow(v <= std::numeric_limits<unsigned int>::max(),
                    ExcMessage("entry 'particles/cell' is out of range"));
      id = ids;
      cell.assign(c.begin(), c.end());
      mass               = archive.get("particles/mass", n);
      volume             = archive.get("particles/volume", n);
      density            = archive.get("particles/density", n);
      const auto vectors = [&](const std::string &name, auto &array) {
        const auto &v = archive.get("particles/" + name, n * dim);
        array.resize(n);
        for (long long i = 0; i < n; ++i)
          for (unsigned int d = 0; d < dim; ++d)
            array[i][d] = v[i * dim + d];
      };
      vectors("position", position);
      vectors("initial_position", initial_position);
      vectors("displacement", displacement);
      vectors("velocity", velocity);
      const auto &s = archive.get("particles/stress", n * dim * dim);
      stress.resize(n);
      for (long long i = 0; i < n; ++i)
        for (unsigned int d = 0; d < dim; ++d)
          for (unsigned int e = d; e < dim; ++e)
            stress[i][d][e] = s[(i * dim + d) * dim + e];
      const auto &a = archive.get("particles/affine", n * dim * dim);
      affine.resize(n);
      for (long long i = 0; i < n; ++i)
        for (unsigned int d = 0; d < dim; ++d)
          for (unsigned int e = 0; e < dim; ++e)
            affine[i][d][e] = a[(i * dim + d) * dim + e];
      state = archive.get("particles/state", n * n_state());
      if (archive.has("particles/body_id"))
        {
          const auto &b = archive.get_integers("particles/body_id", n);
          body_id.assign(b.begin(), b.end());
        }
      else
        body_id.assign(n, 0);
    }



    template class ParticleSet<1>;
    template class ParticleSet<2>;
  } // namespace Particles
} // namespace psmpm
