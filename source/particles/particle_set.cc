// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <psmpm/particles/particle_set.h>

#include <numeric>

namespace psmpm
{
  namespace Particles
  {
    std::string
    ParticleSet::field_name(const Field f)
    {
      static const char *names[] = {"id",
                                    "mass",
                                    "volume",
                                    "density",
                                    "position_x",
                                    "position_y",
                                    "initial_position_x",
                                    "initial_position_y",
                                    "displacement_x",
                                    "displacement_y",
                                    "velocity_x",
                                    "velocity_y",
                                    "traction_x",
                                    "traction_y",
                                    "stress_xx",
                                    "stress_yy",
                                    "stress_xy",
                                    "stress_zz",
                                    "strain_xx",
                                    "strain_yy",
                                    "strain_xy"};
      static_assert(sizeof(names) / sizeof(names[0]) == n_fields,
                    "one name per field");
      return names[static_cast<unsigned int>(f)];
    }

    void
    ParticleSet::add(const std::uint64_t new_id,
                     const unsigned int  new_cell,
                     const Point<2>     &x,
                     const double        new_volume,
                     const double        new_density)
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
      traction.emplace_back();
      stress.emplace_back();
      stress_zz.push_back(0);
      strain.emplace_back();
    }

    double
    ParticleSet::get(const std::size_t i, const Field f) const
    {
      switch (f)
        {
          case Field::id:
            return static_cast<double>(id[i]);
          case Field::mass:
            return mass[i];
          case Field::volume:
            return volume[i];
          case Field::density:
            return density[i];
          case Field::position_x:
            return position[i][0];
          case Field::position_y:
            return position[i][1];
          case Field::initial_position_x:
            return initial_position[i][0];
          case Field::initial_position_y:
            return initial_position[i][1];
          case Field::displacement_x:
            return displacement[i][0];
          case Field::displacement_y:
            return displacement[i][1];
          case Field::velocity_x:
            return velocity[i][0];
          case Field::velocity_y:
            return velocity[i][1];
          case Field::traction_x:
            return traction[i][0];
          case Field::traction_y:
            return traction[i][1];
          case Field::stress_xx:
            return stress[i][0][0];
          case Field::stress_yy:
            return stress[i][1][1];
          case Field::stress_xy:
            return stress[i][0][1];
          case Field::stress_zz:
            return stress_zz[i];
          case Field::strain_xx:
            return strain[i][0][0];
          case Field::strain_yy:
            return strain[i][1][1];
          case Field::strain_xy:
            return strain[i][0][1];
          default:
            Assert(false, ExcInternalError());
            return 0;
        }
    }

    void
    ParticleSet::set(const std::size_t i, const Field f, const double value)
    {
      switch (f)
        {
          case Field::id:
            id[i] = static_cast<std::uint64_t>(value);
            break;
          case Field::mass:
            mass[i] = value;
            break;
          case Field::volume:
            volume[i] = value;
            break;
          case Field::density:
            density[i] = value;
            break;
          case Field::position_x:
            position[i][0] = value;
            break;
          case Field::position_y:
            position[i][1] = value;
            break;
          case Field::initial_position_x:
            initial_position[i][0] = value;
            break;
          case Field::initial_position_y:
            initial_position[i][1] = value;
            break;
          case Field::displacement_x:
            displacement[i][0] = value;
            break;
          case Field::displacement_y:
            displacement[i][1] = value;
            break;
          case Field::velocity_x:
            velocity[i][0] = value;
            break;
          case Field::velocity_y:
            velocity[i][1] = value;
            break;
          case Field::traction_x:
            traction[i][0] = value;
            break;
          case Field::traction_y:
            traction[i][1] = value;
            break;
          case Field::stress_xx:
            stress[i][0][0] = value;
            break;
          case Field::stress_yy:
            stress[i][1][1] = value;
            break;
          case Field::stress_xy:
            stress[i][0][1] = value;
            break;
          case Field::stress_zz:
            stress_zz[i] = value;
            break;
          case Field::strain_xx:
            strain[i][0][0] = value;
            break;
          case Field::strain_yy:
            strain[i][1][1] = value;
            break;
          case Field::strain_xy:
            strain[i][0][1] = value;
            break;
          default:
            Assert(false, ExcInternalError());
        }
    }

    void
    ParticleSet::pack(const std::size_t i, std::vector<double> &buffer) const
    {
      for (unsigned int f = 0; f < n_fields; ++f)
        buffer.push_back(get(i, static_cast<Field>(f)));
    }

    void
    ParticleSet::unpack(const std::vector<double> &buffer)
    {
      AssertThrow(buffer.size() % n_fields == 0, ExcInternalError());
      for (std::size_t start = 0; start < buffer.size(); start += n_fields)
        {
          const std::size_t i = size();
          add(0, 0, Point<2>(), 0, 0);
          for (unsigned int f = 0; f < n_fields; ++f)
            set(i, static_cast<Field>(f), buffer[start + f]);
        }
    }

    template <typename F>
    void
    ParticleSet::for_each_array(F &&f)
    {
      f(id);
      f(cell);
      f(mass);
      f(volume);
      f(density);
      f(position);
      f(initial_position);
      f(displacement);
      f(velocity);
      f(traction);
      f(stress);
      f(stress_zz);
      f(strain);
    }

    void
    ParticleSet::compress(const std::vector<bool> &keep)
    {
      for_each_array([&keep](auto &array) {
        std::size_t j = 0;
        for (std::size_t i = 0; i < array.size(); ++i)
          if (keep[i])
            array[j++] = array[i];
        array.resize(j);
      });
    }

    void
    ParticleSet::sort_by_cell(const unsigned int n_cells)
    {
      std::vector<std::size_t> start(n_cells + 1, 0);
      for (const unsigned int c : cell)
        ++start[c + 1];
      std::partial_sum(start.begin(), start.end(), start.begin());
      std::vector<std::size_t> order(size());
      for (std::size_t i = 0; i < size(); ++i)
        order[start[cell[i]]++] = i;
      for_each_array([&order](auto &array) {
        auto copy = array;
        for (std::size_t i = 0; i < order.size(); ++i)
          array[i] = copy[order[i]];
      });
    }
  } // namespace Particles
} // namespace psmpm
