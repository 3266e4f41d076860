// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/data_out_base.h>
#include <deal.II/base/utilities.h>

#include <psmpm/base/archive.h>
#include <psmpm/base/checked_file.h>
#include <psmpm/postprocess/output_writer.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <tuple>

namespace psmpm
{
  namespace Postprocess
  {
    namespace
    {
      using Ranges = DataRanges;

      const char component_suffix[] = {'x', 'y', 'z'};

      std::string
      piece_name(const std::string &base,
                 const unsigned int step,
                 const unsigned int rank)
      {
        return base + "-" + Utilities::int_to_string(step, 5) + "." +
               Utilities::int_to_string(rank, 3) + ".vtu";
      }

      /// Append the dim components of vector @p name ("name_x", ...).
      template <int dim>
      void
      add_vector(const std::string        &name,
                 std::vector<std::string> &names,
                 Ranges                   &ranges)
      {
        ranges.emplace_back(
          names.size(),
          names.size() + dim - 1,
          name,
          DataComponentInterpretation::component_is_part_of_vector);
        for (unsigned int d = 0; d < dim; ++d)
          names.push_back(name + "_" + component_suffix[d]);
      }

      /// Write this rank's piece and, on rank 0, the .pvtu record; return
      /// the name of the record for the .pvd series.
      template <int patch_dim, int spacedim>
      std::string
      write_pieces(
        const std::string                                          &directory,
        const std::string                                          &base,
        const unsigned int                                          step,
        const std::vector<std::string>                             &names,
        const Ranges                                               &ranges,
        const std::vector<DataOutBase::Patch<patch_dim, spacedim>> &patches,
        MPI_Comm                                                    comm)
      {
        const unsigned int    rank = Utilities::MPI::this_mpi_process(comm);
        const unsigned int    size = Utilities::MPI::n_mpi_processes(comm);
        DataOutBase::VtkFlags flags;
        flags.compression_level = DataOutBase::VtkFlags::best_speed;
        {
          const std::string file =
            directory + "/" + piece_name(base, step, rank);
          // A piece that cannot be written whole is removed.
          std::ofstream out(file);
          try
            {
              check_written(out, file);
              try
                {
                  DataOutBase::write_vtu(patches, names, ranges, flags, out);
                }
              catch (const ExceptionBase &)
                {
                  check_written(out, file); // deal.II's ExcIO: say why
                  throw;
                }
              check_written(out, file);
            }
          catch (const ExcWriteFailed &)
            {
              out.close();
              std::remove(file.c_str());
              throw;
            }
        }
        const std::string record =
          base + "-" + Utilities::int_to_string(step, 5) + ".pvtu";
        if (rank == 0)
          {
            std::vector<std::string> pieces;
            for (unsigned int r = 0; r < size; ++r)
              pieces.push_back(piece_name(base, step, r));
            write_atomically(directory + "/" + record, [&](std::ostream &out) {
              DataOutBase::write_pvtu_record(out, pieces, names, ranges, flags);
            });
          }
        return record;
      }

      /**
       * The sampling points of one cell in real coordinates: in 1D the
       * s + 1 equispaced points from vertex 0 to vertex 1 (the order in
       * which deal.II reads a line patch with n_subdivisions = s); in 2D
       * the (s + 1)(s + 2) / 2 points v0 + i/s (v1 - v0) + j/s (v2 - v0),
       * i + j <= s, row by row in j (see lattice_index()).
       */
      template <int dim>
      std::vector<Point<dim>>
      lattice_points(const std::array<Point<dim>, dim + 1> &v,
                     const unsigned int                     s)
      {
        std::vector<Point<dim>> points;
        if constexpr (dim == 1)
          for (unsigned int i = 0; i <= s; ++i)
            points.push_back(v[0] + (double(i) / s) * (v[1] - v[0]));
        else
          for (unsigned int j = 0; j <= s; ++j)
            for (unsigned int i = 0; i + j <= s; ++i)
              {
                Point<dim> p = v[0];
                p += (double(i) / s) * (v[1] - v[0]);
                p += (double(j) / s) * (v[dim] - v[0]);
                points.push_back(p);
              }
        return points;
      }

      /// The (s + 1)^2 points v0 + i/s (v1 - v0) + j/s (v2 - v0),
      /// 0 <= i, j <= s, i fastest: the order in which deal.II reads a
      /// quadrilateral patch with n_subdivisions = s (2D, rectangles).
      std::vector<Point<2>>
      box_lattice_points(const std::array<Point<2>, 3> &v, const unsigned int s)
      {
        std::vector<Point<2>> points;
        for (unsigned int j = 0; j <= s; ++j)
          for (unsigned int i = 0; i <= s; ++i)
            points.push_back(v[0] + (double(i) / s) * (v[1] - v[0]) +
                             (double(j) / s) * (v[2] - v[0]));
        return points;
      }

      /// Position of lattice point (i, j) in lattice_points() (2D).
      unsigned int
      lattice_index(const unsigned int i,
                    const unsigned int j,
                    const unsigned int s)
      {
        return j * (s + 1) - j * (j - 1) / 2 + i;
      }

      /**
       * The s^2 sub-triangles of the lattice as point triples, oriented as
       * the cell: the "upward" ones (i, j), (i+1, j), (i, j+1) and the
       * "downward" ones (i+1, j), (i+1, j+1), (i, j+1).
       */
      std::vector<std::array<unsigned int, 3>>
      sub_triangles(const unsigned int s)
      {
        std::vector<std::array<unsigned int, 3>> triangles;
        for (unsigned int j = 0; j < s; ++j)
          for (unsigned int i = 0; i + j < s; ++i)
            {
              triangles.push_back({{lattice_index(i, j, s),
                                    lattice_index(i + 1, j, s),
                                    lattice_index(i, j + 1, s)}});
              if (i + j + 1 < s)
                triangles.push_back({{lattice_index(i + 1, j, s),
                                      lattice_index(i + 1, j + 1, s),
                                      lattice_index(i, j + 1, s)}});
            }
        return triangles;
      }

      /// Append the material state to the output components: groups of
      /// scalars <p>_xx, <p>_xy (, <p>_yx), <p>_yy become one dim x dim
      /// tensor, the others stay scalars; @p source receives the state
      /// index of each appended component.
      template <int dim>
      void
      state_layout(const std::vector<std::string> &state_names,
                   std::vector<std::string>       &names,
                   Ranges                         &ranges,
                   std::vector<unsigned int>      &source)
      {
        const auto index = [&state_names](const std::string &n) {
          const auto it = std::find(state_names.begin(), state_names.end(), n);
          return it == state_names.end() ?
                   numbers::invalid_unsigned_int :
                   static_cast<unsigned int>(it - state_names.begin());
        };
        std::vector<bool> used(state_names.size(), false);
        for (unsigned int k = 0; k < state_names.size(); ++k)
          {
            const std::string &n = state_names[k];
            if (used[k] || n.size() < 4 || n.substr(n.size() - 3) != "_xx")
              continue;
            const std::string         prefix = n.substr(0, n.size() - 3);
            std::vector<unsigned int> components;
            for (unsigned int c = 0; c < dim * dim; ++c)
              {
                const auto ind =
                  Tensor<2, dim>::unrolled_to_component_indices(c);
                const std::string suffix = std::string("_") +
                                           component_suffix[ind[0]] +
                                           component_suffix[ind[1]];
                unsigned int j = index(prefix + suffix);
                if (j == numbers::invalid_unsigned_int && ind[0] > ind[1])
                  j = index(prefix + "_" + component_suffix[ind[1]] +
                            component_suffix[ind[0]]); // symmetric
                components.push_back(j);
              }
            if (std::find(components.begin(),
                          components.end(),
                          numbers::invalid_unsigned_int) != components.end())
              continue; // not a complete tensor: scalars
            ranges.emplace_back(
              names.size(),
              names.size() + dim * dim - 1,
              prefix,
              DataComponentInterpretation::component_is_part_of_tensor);
            for (unsigned int c = 0; c < dim * dim; ++c)
              {
                const auto ind =
                  Tensor<2, dim>::unrolled_to_component_indices(c);
                names.push_back(prefix + "_" + component_suffix[ind[0]] +
                                component_suffix[ind[1]]);
                source.push_back(components[c]);
                used[components[c]] = true;
              }
          }
        for (unsigned int k = 0; k < state_names.size(); ++k)
          if (!used[k])
            {
              names.push_back(state_names[k]);
              source.push_back(k);
            }
      }
    } // namespace



    template <int dim>
    OutputWriter<dim>::OutputWriter(const std::string   &directory,
                                    MPI_Comm             comm,
                                    const unsigned int   subdivisions,
                                    const ParticleFormat particle_format)
      : directory(directory)
      , comm(comm)
      , subdivisions(subdivisions)
    {
      AssertThrow(subdivisions >= 1,
                  ExcMessage("psmpm: Output/Subdivisions must be >= 1."));
      // HDF5 (and XDMF) store points in 2 or 3 coordinates only.
      AssertThrow(particle_format == ParticleFormat::vtu || dim >= 2,
                  ExcMessage("Output/Particle format = hdf5 needs "
                             "Geometry/Dimension = 2; use vtu in 1D."));
      if (particle_format == ParticleFormat::hdf5)
        hdf5 = std::make_unique<ParticleHdf5Writer>(directory, comm);
    }



    template <int dim>
    void
    OutputWriter<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      prm.declare_entry(
        "Subdivisions",
        "0",
        Patterns::Integer(0, 16),
        "Each cell of the grid output is split into this many sub-cells per "
        "edge so that quadratic fields (Powell-Sabin) look smooth in "
        "ParaView; 1 shows the field at the corners only; 0: automatic, 1 "
        "for linear spaces and 4 for higher degrees.");
      prm.declare_entry(
        "Particle format",
        "vtu",
        Patterns::Selection("vtu|hdf5"),
        "vtu: one VTU piece per MPI rank and output, a .pvtu record and the "
        "series particles.pvd. hdf5 (2D only): one file particles-<step>.h5 "
        "per output for all ranks and the series particles.xdmf (ParaView: "
        "XDMF reader): one file per output whatever the number of ranks, "
        "but uncompressed, about 6 times larger and 4 times slower to write "
        "on one node (doc/getting_started.md); tensors (stress) are written "
        "as their components. The grid output is VTU either way.");
      prm.leave_subsection();
    }



    template <int dim>
    ParticleFormat
    OutputWriter<dim>::parse_particle_format(const std::string &name)
    {
      AssertThrow(name == "vtu" || name == "hdf5",
                  ExcMessage("Output/Particle format must be vtu or hdf5, "
                             "not '" +
                             name + "'."));
      return name == "vtu" ? ParticleFormat::vtu : ParticleFormat::hdf5;
    }



    template <int dim>
    void
    OutputWriter<dim>::write_pvd(
      const std::string                                 &name,
      const std::vector<std::pair<double, std::string>> &records) const
    {
      if (Utilities::MPI::this_mpi_process(comm) != 0)
        return;
      write_atomically(directory + "/" + name + ".pvd", [&](std::ostream &out) {
        DataOutBase::write_pvd_record(out, records);
      });
    }



    template <int dim>
    void
    OutputWriter<dim>::write_particles(
      const unsigned int                 step,
      const double                       time,
      const Particles::ParticleSet<dim> &particles)
    {
      std::vector<std::string> names =
        {"id", "cell", "rank", "mass", "volume", "density"};
      // Scenes without Bodies keep their fields (every particle is in
      // body 0).
      const bool with_bodies = particles.n_bodies > 0;
      if (with_bodies)
        {
          names.push_back("body_id");
          names.push_back("material_id");
        }
      Ranges             ranges;
      const unsigned int first_displacement = names.size();
      add_vector<dim>("displacement", names, ranges);
      const unsigned int first_velocity = names.size();
      add_vector<dim>("velocity", names, ranges);

      // The full dim x dim tensor in deal.II's unrolled order, so that
      // ParaView shows the symmetric stress as a tensor (eigenvalues,
      // von Mises through the calculator) rather than loose components.
      const unsigned int first_stress = names.size();
      for (unsigned int c = 0; c < dim * dim; ++c)
        {
          const auto ind = Tensor<2, dim>::unrolled_to_component_indices(c);
          names.push_back(std::string("stress_") + component_suffix[ind[0]] +
                          component_suffix[ind[1]]);
        }
      ranges.emplace_back(
        first_stress,
        first_stress + dim * dim - 1,
        "stress",
        DataComponentInterpretation::component_is_part_of_tensor);

      // Material state: scalars named <p>_xx, <p>_xy, ... form a tensor
      // (a symmetric one if <p>_yx is missing), written as such; the rest
      // are scalars. source[k]: the state index of output component k.
      const unsigned int        first_state = names.size();
      std::vector<unsigned int> source;
      state_layout<dim>(particles.get_state_names(), names, ranges, source);
      const double rank = Utilities::MPI::this_mpi_process(comm);
      std::vector<DataOutBase::Patch<0, dim>> patches(particles.size());
      for (std::size_t i = 0; i < particles.size(); ++i)
        {
          auto &patch       = patches[i];
          patch.vertices[0] = particles.position[i];
          patch.patch_index = i;
          patch.data.reinit(names.size(), 1);
          // VTU stores Float32: ids above 2^24 lose their last digits,
          // which is acceptable for picking particles in ParaView.
          patch.data(0, 0) = particles.id[i];
          patch.data(1, 0) = particles.cell[i];
          patch.data(2, 0) = rank;
          patch.data(3, 0) = particles.mass[i];
          patch.data(4, 0) = particles.volume[i];
          patch.data(5, 0) = particles.density[i];
          if (with_bodies)
            {
              patch.data(6, 0) = particles.body_id[i];
              patch.data(7, 0) = particles.body_material[particles.body_id[i]];
            }
          for (unsigned int d = 0; d < dim; ++d)
            {
              patch.data(first_displacement + d, 0) =
                particles.displacement[i][d];
              patch.data(first_velocity + d, 0) = particles.velocity[i][d];
            }
          for (unsigned int c = 0; c < dim * dim; ++c)
            {
              const auto ind = Tensor<2, dim>::unrolled_to_component_indices(c);
              patch.data(first_stress + c, 0) =
                particles.stress[i][ind[0]][ind[1]];
            }
          const double *state = particles.state_of(i);
          for (unsigned int k = 0; k < source.size(); ++k)
            patch.data(first_state + k, 0) = state[source[k]];
        }

      if constexpr (dim >= 2)
        if (hdf5)
          {
            hdf5->write(step, time, names, ranges, patches);
            return;
          }
      particle_records.emplace_back(time,
                                    write_pieces(directory,
                                                 "particles",
                                                 step,
                                                 names,
                                                 ranges,
                                                 patches,
                                                 comm));
      write_pvd("particles", particle_records);
    }



    template <int dim>
    void
    OutputWriter<dim>::write_grid(
      const unsigned int               step,
      const double                     time,
      const DoFHandler<dim>           &dof_handler,
      const Basis::Space<dim>         &space,
      const std::vector<unsigned int> &cell_dofs,
      const std::vector<
        std::pair<std::string, const std::vector<Tensor<1, dim>> *>>
        &vector_fields,
      const std::vector<std::pair<std::string, const std::vector<double> *>>
                                    &scalar_fields,
      const std::vector<Point<dim>> *moved_vertices)
    {
      const unsigned int n = space.dofs_per_cell();
      AssertThrow(moved_vertices == nullptr || n == dim + 1,
                  ExcMessage("psmpm: a moved grid is drawn for P1 (one "
                             "function per vertex) only."));
      std::vector<std::string> names;
      Ranges                   ranges;
      // A moved grid also shows how far it moved (ParaView can colour by
      // it; the points are already at the moved positions).
      if (moved_vertices)
        add_vector<dim>("grid_displacement", names, ranges);
      for (const auto &f : vector_fields)
        add_vector<dim>(f.first, names, ranges);
      for (const auto &f : scalar_fields)
        names.push_back(f.first);
      // A cell field; VTU patches only carry point data, so it is constant
      // on the cell's (unshared) points, which ParaView shows as cells.
      names.push_back("rank");
      const double rank = Utilities::MPI::this_mpi_process(comm);

      const unsigned int                             s = subdivisions;
      const std::vector<std::array<unsigned int, 3>> triangles =
        (dim == 2 ? sub_triangles(s) :
                    std::vector<std::array<unsigned int, 3>>());

      std::vector<DataOutBase::Patch<dim, dim>> patches;
      std::vector<double>                       values;
      std::vector<unsigned int>                 cells;
      // Field values at the lattice points of one cell, point-major.
      std::vector<double> data;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            // Rectangles (Mesh/Type = cartesian) are drawn as one
            // quadrilateral patch each, triangles as s^2 triangles.
            const bool quad =
              dim == 2 &&
              cell->reference_cell() == ReferenceCells::get_hypercube<dim>();
            const unsigned int              c = cell->active_cell_index();
            std::array<Point<dim>, dim + 1> v;
            for (unsigned int i = 0; i <= dim; ++i)
              v[i] = cell->vertex(i);
            std::vector<Point<dim>> points;
            if constexpr (dim == 2)
              points =
                quad ? box_lattice_points(v, s) : lattice_points<dim>(v, s);
            else
              points = lattice_points<dim>(v, s);
            const unsigned int n_points = points.size();
            // On a moved grid the cell is affinely mapped: the lattice
            // point of the same barycentric coordinates carries the same
            // values, drawn at its moved position.
            std::array<Point<dim>, dim + 1> w = v;
            if (moved_vertices)
              for (unsigned int i = 0; i <= dim; ++i)
                w[i] = (*moved_vertices)[cell_dofs[c * n + i]];
            const std::vector<Point<dim>> drawn =
              moved_vertices ? lattice_points<dim>(w, s) : points;

            // One batched (virtual) evaluation per cell.
            cells.assign(n_points, c);
            values.resize(n_points * n);
            space.evaluate(n_points,
                           cells.data(),
                           points.data(),
                           values.data(),
                           nullptr);

            data.assign(n_points * names.size(), 0.);
            for (unsigned int q = 0; q < n_points; ++q)
              {
                const double *phi = values.data() + q * n;
                double       *row = data.data() + q * names.size();
                if (moved_vertices)
                  for (unsigned int d = 0; d < dim; ++d)
                    *row++ = drawn[q][d] - points[q][d];
                for (const auto &f : vector_fields)
                  {
                    Tensor<1, dim> u;
                    for (unsigned int k = 0; k < n; ++k)
                      u += phi[k] * (*f.second)[cell_dofs[c * n + k]];
                    for (unsigned int d = 0; d < dim; ++d)
                      *row++ = u[d];
                  }
                for (const auto &f : scalar_fields)
                  {
                    double u = 0;
                    for (unsigned int k = 0; k < n; ++k)
                      u += phi[k] * (*f.second)[cell_dofs[c * n + k]];
                    *row++ = u;
                  }
                *row = rank;
              }

            const auto fill = [&](DataOutBase::Patch<dim, dim> &patch,
                                  const unsigned int            column,
                                  const unsigned int            q) {
              for (unsigned int r = 0; r < names.size(); ++r)
                patch.data(r, column) = data[q * names.size() + r];
            };

            if constexpr (dim == 1)
              {
                // deal.II subdivides line patches itself: s + 1 points.
                DataOutBase::Patch<dim, dim> patch;
                patch.reference_cell = ReferenceCells::get_hypercube<dim>();
                patch.n_subdivisions = s;
                patch.patch_index    = patches.size();
                patch.vertices[0]    = w[0];
                patch.vertices[1]    = w[1];
                patch.data.reinit(names.size(), n_points);
                for (unsigned int q = 0; q < n_points; ++q)
                  fill(patch, q, q);
                patches.push_back(std::move(patch));
              }
            else if (quad)
              {
                DataOutBase::Patch<dim, dim> patch;
                patch.reference_cell = ReferenceCells::get_hypercube<dim>();
                patch.n_subdivisions = s;
                patch.patch_index    = patches.size();
                for (unsigned int i = 0; i < cell->n_vertices(); ++i)
                  patch.vertices[i] = cell->vertex(i);
                patch.data.reinit(names.size(), n_points);
                for (unsigned int q = 0; q < n_points; ++q)
                  fill(patch, q, q);
                patches.push_back(std::move(patch));
              }
            else
              // Simplex patches with n_subdivisions > 1 are not
              // implemented in deal.II 9.4 (compute_sizes() asserts
              // n_subdivisions == 1), so one patch per sub-triangle.
              for (const auto &t : triangles)
                {
                  DataOutBase::Patch<dim, dim> patch;
                  patch.reference_cell = ReferenceCells::get_simplex<dim>();
                  patch.n_subdivisions = 1;
                  patch.patch_index    = patches.size();
                  patch.data.reinit(names.size(), 3);
                  for (unsigned int k = 0; k < 3; ++k)
                    {
                      patch.vertices[k] = drawn[t[k]];
                      fill(patch, k, t[k]);
                    }
                  patches.push_back(std::move(patch));
                }
          }

      grid_records.emplace_back(
        time,
        write_pieces(directory, "grid", step, names, ranges, patches, comm));
      write_pvd("grid", grid_records);
    }



    namespace
    {
      void
      save_records(const std::vector<std::pair<double, std::string>> &records,
                   const std::string                                 &name,
                   Archive                                           &archive)
      {
        std::vector<double> times;
        std::string         files;
        for (const auto &r : records)
          {
            times.push_back(r.first);
            files += r.second + "\n";
          }
        archive.put("output/" + name + "_times", times);
        archive.put_text("output/" + name + "_files", files);
      }

      std::vector<std::pair<double, std::string>>
      load_records(const std::string &name, const Archive &archive)
      {
        const auto &times = archive.get("output/" + name + "_times");
        const auto  files =
          Utilities::split_string_list(archive.get_text("output/" + name +
                                                        "_files"),
                                       '\n');
        AssertThrow(files.size() >= times.size(),
                    ExcMessage("entry 'output/" + name +
                               "_files' does not match 'output/" + name +
                               "_times'"));
        std::vector<std::pair<double, std::string>> records;
        for (std::size_t i = 0; i < times.size(); ++i)
          records.emplace_back(times[i], files[i]);
        return records;
      }
    } // namespace



    template <int dim>
    void
    OutputWriter<dim>::save(Archive &archive) const
    {
      save_records(particle_records, "particles", archive);
      save_records(grid_records, "grid", archive);
      if (hdf5)
        hdf5->save(archive);
    }



    template <int dim>
    void
    OutputWriter<dim>::load(const Archive &archive)
    {
      particle_records = load_records("particles", archive);
      grid_records     = load_records("grid", archive);
      if (hdf5)
        hdf5->load(archive);
    }



    template <int dim>
    void
    OutputWriter<dim>::restore_files(const unsigned int step) const
    {
      if (hdf5)
        hdf5->write_index();
      else
        write_pvd("particles", particle_records);
      write_pvd("grid", grid_records);
      if (Utilities::MPI::this_mpi_process(comm) != 0)
        return;
      static const std::regex series(
        "(particles|grid)-([0-9]+)(\\.[0-9]+)?\\.(vtu|pvtu|h5)");
      std::error_code ec;
      for (const auto &entry :
           std::filesystem::directory_iterator(directory, ec))
        {
          std::smatch       m;
          const std::string name = entry.path().filename().string();
          if (entry.is_regular_file() && std::regex_match(name, m, series) &&
              std::stoull(m[2].str()) > step)
            std::filesystem::remove(entry.path(), ec);
        }
    }



    template class OutputWriter<1>;
    template class OutputWriter<2>;
  } // namespace Postprocess
} // namespace psmpm
