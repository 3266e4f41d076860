// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_particles_particle_set_h
#define psmpm_particles_particle_set_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

namespace psmpm
{
  class Archive;

  namespace Particles
  {
    using namespace dealii;

    /**
     * The material points owned by this MPI rank, stored as a structure
     * of arrays so that the transfer loops stream through contiguous
     * memory. (deal.II's ParticleHandler sorts particles into triangles
     * wrongly in 9.4.1 and its ghost exchange is broken on simplices, see
     * doc/design.md; ownership here follows the cell's subdomain.)
     *
     * Two parts: the kinematics every MPM needs (position, velocity,
     * displacement, mass, volume, Cauchy stress, the cell, the affine
     * velocity matrix of the affine transfers), and a block of
     * n_state() scalars per particle that belongs to the material model
     * (its names come from Material::state_names()). Every particle always
     * knows its cell (active cell index).
     */
    template <int dim>
    class ParticleSet
    {
    public:
      /// Name the material's state scalars (before particles are added).
      void
      set_state_names(const std::vector<std::string> &names);

      const std::vector<std::string> &
      get_state_names() const
      {
        return state_names;
      }

      unsigned int
      n_state() const
      {
        return state_names.size();
      }

      std::size_t
      size() const
      {
        return mass.size();
      }

      /// Particles the arrays hold without reallocating.
      std::size_t
      capacity() const
      {
        return mass.capacity();
      }

      /// Capacity for exactly max(@p n, size()) particles in every array:
      /// at set-up, drops the slack that add()'s doubling left (up to the
      /// size again), or leaves headroom for particles arriving from other
      /// MPI ranks.
      void
      set_capacity(const std::size_t n);

      /// Append one particle at @p x in @p cell with zero velocity,
      /// displacement, stress and state, belonging to body @p body (0:
      /// the scene has no Bodies).
      void
      add(const std::uint64_t id,
          const unsigned int  cell,
          const Point<dim>   &x,
          const double        volume,
          const double        density,
          const unsigned int  body = 0);

      /// The state block of particle @p i (n_state() values).
      double *
      state_of(const std::size_t i)
      {
        return state.data() + i * n_state();
      }
      const double *
      state_of(const std::size_t i) const
      {
        return state.data() + i * n_state();
      }

      /// Number of doubles pack() appends per particle.
      unsigned int
      n_packed() const;

      /// Append particle @p i (all arrays but the cell) to @p buffer.
      void
      pack(const std::size_t i, std::vector<double> &buffer) const;
      /// Append the particles in @p buffer; the caller locates their cells.
      /// Growth beyond the capacity reserves an eighth more than needed
      /// (not std::vector's doubling, see resize_per_particle()).
      void
      unpack(const std::vector<double> &buffer);

      /// Keep only particles with keep[i] true (preserves order).
      void
      compress(const std::vector<bool> &keep);

      /// Reorder particles by cell for locality (counting sort).
      void
      sort_by_cell(const unsigned int n_cells);

      /**
       * Every array, in the current order, into @p archive under
       * "particles/" (checkpoints): id and cell (integers), mass, volume,
       * density (one value per particle), the vectors (n x dim), stress and
       * affine matrix (n x dim^2, row-major), the state block (n x
       * n_state(), names in "particles/state_names", one per line) and
       * body_id (integers; only if n_bodies > 0, absent: 0).
       */
      void
      save(Archive &archive) const;

      /// Replace all particles by those save() wrote; throws ExcMessage
      /// naming the entry if one is missing or inconsistent, or if the
      /// state names differ from get_state_names().
      void
      load(const Archive &archive);

      // Kinematics.
      std::vector<std::uint64_t>           id;
      std::vector<unsigned int>            cell;
      std::vector<double>                  mass;
      std::vector<double>                  volume;
      std::vector<double>                  density;
      std::vector<Point<dim>>              position;
      std::vector<Point<dim>>              initial_position;
      std::vector<Tensor<1, dim>>          displacement;
      std::vector<Tensor<1, dim>>          velocity;
      std::vector<SymmetricTensor<2, dim>> stress; ///< Cauchy stress
      /// Affine velocity matrix C_p of the affine transfers (APIC): the
      /// particle carries v(x) = v_p + C_p (x - x_p). Zero for the others.
      std::vector<Tensor<2, dim>> affine;
      /// Material state, n_state() per particle, particle-major.
      std::vector<double> state;
      /// The Bodies entry (1, 2, ...) each particle was made in; 0 when
      /// the scene has no Bodies.
      std::vector<unsigned int> body_id;
      /// Number of bodies of the scene (0: none); decides whether the
      /// output carries body_id. Not per particle: every rank knows it.
      unsigned int n_bodies = 0;
      /// Material id (0: subsection Material, j: Materials/Material j) of
      /// each body id, for output; set by the simulator.
      std::vector<unsigned int> body_material{0};

    private:
      std::vector<std::string> state_names;
    };



    /**
     * Resize a per-particle work array (basis cache, increments, ...) to
     * @p per_particle entries for each of @p particles, reallocating to the
     * particle arrays' capacity when it must. On an MPI rank the particle
     * set grows when particles arrive; std::vector's doubling then copied
     * and first-touched twice every array on a rank that gained a single
     * particle (125 ms in one step of a 2-rank run with 490,000 particles
     * per rank, the steady step being 2 ms). Work arrays follow the
     * particle arrays, which grow by an eighth (ParticleSet::unpack()).
     */
    template <int dim, typename T>
    void
    resize_per_particle(std::vector<T>         &array,
                        const ParticleSet<dim> &particles,
                        const unsigned int      per_particle = 1)
    {
      const std::size_t n = particles.size() * per_particle;
      if (n > array.capacity())
        array.reserve(std::max(n, particles.capacity() * per_particle));
      array.resize(n);
    }

    /**
     * Keep the blocks of @p per_particle entries of a per-particle array
     * whose keep[i] is set, in order: ParticleSet::compress() for an
     * array beside the particle set (the basis cache) or inside it (the
     * material state).
     */
    template <typename T>
    void
    compress_per_particle(std::vector<T>          &array,
                          const std::vector<bool> &keep,
                          const unsigned int       per_particle = 1)
    {
      const unsigned int n = per_particle;
      std::size_t        j = 0;
      for (std::size_t i = 0; i < keep.size(); ++i)
        if (keep[i])
          {
            // j <= i: moving blocks left, front to back, is safe.
            for (unsigned int k = 0; k < n; ++k)
              array[j * n + k] = array[i * n + k];
            ++j;
          }
      array.resize(j * n);
    }
  } // namespace Particles
} // namespace psmpm

#endif
