// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_particles_particle_set_h
#define psmpm_particles_particle_set_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace psmpm
{
  namespace Particles
  {
    using namespace dealii;

    /**
     * The material points owned by this MPI rank, stored as a structure
     * of arrays so that the transfer loops stream through contiguous
     * memory. (deal.II's ParticleHandler sorts particles into triangles
     * wrongly in 9.4.1 and its ghost exchange is broken on simplices, see
     * doc/design.md; ownership here follows the cell's subdomain.)
     * Every particle always knows its cell (active cell index).
     */
    class ParticleSet
    {
    public:
      /// Scalar layout of one particle for MPI transfer and output; the
      /// fields are addressed by name, never by bare offsets.
      enum class Field : unsigned int
      {
        id,
        mass,
        volume,
        density,
        position_x,
        position_y,
        initial_position_x,
        initial_position_y,
        displacement_x,
        displacement_y,
        velocity_x,
        velocity_y,
        traction_x,
        traction_y,
        stress_xx,
        stress_yy,
        stress_xy,
        stress_zz,
        strain_xx,
        strain_yy,
        strain_xy,
        n_fields
      };
      static constexpr unsigned int n_fields =
        static_cast<unsigned int>(Field::n_fields);

      /// Name of a field for output.
      static std::string
      field_name(const Field f);

      std::size_t
      size() const
      {
        return mass.size();
      }

      /// Append one particle at @p x in @p cell with all other fields zero.
      void
      add(const std::uint64_t id,
          const unsigned int  cell,
          const Point<2>     &x,
          const double        volume,
          const double        density);

      /// The value of field @p f of particle @p i.
      double
      get(const std::size_t i, const Field f) const;
      void
      set(const std::size_t i, const Field f, const double value);

      /// Append particle @p i's fields to @p buffer.
      void
      pack(const std::size_t i, std::vector<double> &buffer) const;
      /// Append the particles in @p buffer; the caller locates their cells.
      void
      unpack(const std::vector<double> &buffer);

      /// Keep only particles with keep[i] true (preserves order).
      void
      compress(const std::vector<bool> &keep);

      /// Reorder particles by cell for locality (counting sort).
      void
      sort_by_cell(const unsigned int n_cells);

      std::vector<std::uint64_t> id;
      std::vector<unsigned int>  cell;
      std::vector<double>        mass;
      std::vector<double>        volume;
      std::vector<double>        density;
      std::vector<Point<2>>      position;
      std::vector<Point<2>>      initial_position;
      std::vector<Tensor<1, 2>>  displacement;
      std::vector<Tensor<1, 2>>  velocity;
      std::vector<Tensor<1, 2>>  traction; ///< force of boundary particles
      std::vector<SymmetricTensor<2, 2>> stress; ///< in-plane Cauchy stress
      std::vector<double> stress_zz; ///< out-of-plane (plane strain)
      std::vector<SymmetricTensor<2, 2>> strain;

    private:
      template <typename F>
      void
      for_each_array(F &&f);
    };
  } // namespace Particles
} // namespace psmpm

#endif
