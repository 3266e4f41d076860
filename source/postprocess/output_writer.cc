// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/data_out_base.h>
#include <deal.II/base/utilities.h>

#include <psmpm/postprocess/output_writer.h>

#include <fstream>

namespace psmpm
{
  namespace Postprocess
  {
    namespace
    {
      std::string
      piece_name(const std::string &base,
                 const unsigned int step,
                 const unsigned int rank)
      {
        return base + "-" + Utilities::int_to_string(step, 5) + "." +
               Utilities::int_to_string(rank, 3) + ".vtu";
      }

      /// Write this rank's piece and, on rank 0, the .pvtu record.
      std::string
      write_pieces(
        const std::string              &directory,
        const std::string              &base,
        const unsigned int              step,
        const std::vector<std::string> &names,
        const std::vector<
          std::tuple<unsigned int,
                     unsigned int,
                     std::string,
                     DataComponentInterpretation::DataComponentInterpretation>>
                                                    &ranges,
        const std::vector<DataOutBase::Patch<0, 2>> *point_patches,
        const std::vector<DataOutBase::Patch<2, 2>> *cell_patches,
        MPI_Comm                                     comm)
      {
        const unsigned int    rank = Utilities::MPI::this_mpi_process(comm);
        const unsigned int    size = Utilities::MPI::n_mpi_processes(comm);
        DataOutBase::VtkFlags flags;
        flags.compression_level = DataOutBase::VtkFlags::best_speed;
        {
          std::ofstream out(directory + "/" + piece_name(base, step, rank));
          if (point_patches)
            DataOutBase::write_vtu(*point_patches, names, ranges, flags, out);
          else
            DataOutBase::write_vtu(*cell_patches, names, ranges, flags, out);
        }
        const std::string record =
          base + "-" + Utilities::int_to_string(step, 5) + ".pvtu";
        if (rank == 0)
          {
            std::vector<std::string> pieces;
            for (unsigned int r = 0; r < size; ++r)
              pieces.push_back(piece_name(base, step, r));
            std::ofstream out(directory + "/" + record);
            DataOutBase::write_pvtu_record(out, pieces, names, ranges, flags);
          }
        return record;
      }
    } // namespace

    OutputWriter::OutputWriter(const std::string &directory, MPI_Comm comm)
      : directory(directory)
      , comm(comm)
    {
    }

    void
    OutputWriter::write_pvd(
      const std::string                                 &name,
      const std::vector<std::pair<double, std::string>> &records) const
    {
      if (Utilities::MPI::this_mpi_process(comm) != 0)
        return;
      std::ofstream out(directory + "/" + name + ".pvd");
      DataOutBase::write_pvd_record(out, records);
    }

    void
    OutputWriter::write_particles(const unsigned int            step,
                                  const double                  time,
                                  const Particles::ParticleSet &particles)
    {
      using Field = Particles::ParticleSet::Field;
      std::vector<std::string> names;
      for (unsigned int f = 0; f < Particles::ParticleSet::n_fields; ++f)
        names.push_back(
          Particles::ParticleSet::field_name(static_cast<Field>(f)));
      names.push_back("cell");

      std::vector<DataOutBase::Patch<0, 2>> patches(particles.size());
      for (std::size_t i = 0; i < particles.size(); ++i)
        {
          auto &patch       = patches[i];
          patch.vertices[0] = particles.position[i];
          patch.patch_index = i;
          patch.data.reinit(names.size(), 1);
          for (unsigned int f = 0; f < Particles::ParticleSet::n_fields; ++f)
            patch.data(f, 0) = particles.get(i, static_cast<Field>(f));
          patch.data(names.size() - 1, 0) = particles.cell[i];
        }
      const auto vec = DataComponentInterpretation::component_is_part_of_vector;
      const std::vector<
        std::tuple<unsigned int,
                   unsigned int,
                   std::string,
                   DataComponentInterpretation::DataComponentInterpretation>>
        ranges = {{static_cast<unsigned int>(Field::displacement_x),
                   static_cast<unsigned int>(Field::displacement_y),
                   "displacement",
                   vec},
                  {static_cast<unsigned int>(Field::velocity_x),
                   static_cast<unsigned int>(Field::velocity_y),
                   "velocity",
                   vec}};
      particle_records.emplace_back(time,
                                    write_pieces(directory,
                                                 "particles",
                                                 step,
                                                 names,
                                                 ranges,
                                                 &patches,
                                                 nullptr,
                                                 comm));
      write_pvd("particles", particle_records);
    }

    void
    OutputWriter::write_grid(
      const unsigned int               step,
      const double                     time,
      const DoFHandler<2>             &dof_handler,
      const Basis::Space              &space,
      const std::vector<unsigned int> &cell_dofs,
      const std::vector<
        std::pair<std::string, const std::vector<Tensor<1, 2>> *>>
        &vector_fields,
      const std::vector<std::pair<std::string, const std::vector<double> *>>
        &scalar_fields)
    {
      std::vector<std::string> names;
      std::vector<
        std::tuple<unsigned int,
                   unsigned int,
                   std::string,
                   DataComponentInterpretation::DataComponentInterpretation>>
        ranges;
      for (const auto &f : vector_fields)
        {
          ranges.emplace_back(
            names.size(),
            names.size() + 1,
            f.first,
            DataComponentInterpretation::component_is_part_of_vector);
          names.push_back(f.first + "_x");
          names.push_back(f.first + "_y");
        }
      for (const auto &f : scalar_fields)
        names.push_back(f.first);

      const unsigned int                    n = space.dofs_per_cell();
      std::vector<double>                   values(n);
      std::vector<DataOutBase::Patch<2, 2>> patches;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const unsigned int       c = cell->active_cell_index();
            DataOutBase::Patch<2, 2> patch;
            patch.reference_cell = ReferenceCells::Triangle;
            patch.n_subdivisions = 1;
            patch.patch_index    = patches.size();
            patch.data.reinit(names.size(), 3);
            for (unsigned int v = 0; v < 3; ++v)
              {
                patch.vertices[v] = cell->vertex(v);
                space.evaluate(c, cell->vertex(v), values.data(), nullptr);
                unsigned int row = 0;
                for (const auto &f : vector_fields)
                  {
                    Tensor<1, 2> s;
                    for (unsigned int k = 0; k < n; ++k)
                      s += values[k] * (*f.second)[cell_dofs[c * n + k]];
                    patch.data(row++, v) = s[0];
                    patch.data(row++, v) = s[1];
                  }
                for (const auto &f : scalar_fields)
                  {
                    double s = 0;
                    for (unsigned int k = 0; k < n; ++k)
                      s += values[k] * (*f.second)[cell_dofs[c * n + k]];
                    patch.data(row++, v) = s;
                  }
              }
            patches.push_back(std::move(patch));
          }
      grid_records.emplace_back(time,
                                write_pieces(directory,
                                             "grid",
                                             step,
                                             names,
                                             ranges,
                                             nullptr,
                                             &patches,
                                             comm));
      write_pvd("grid", grid_records);
    }
  } // namespace Postprocess
} // namespace psmpm
