// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/utilities.h>

#include <psmpm/base/archive.h>
#include <psmpm/base/checked_file.h>
#include <psmpm/postprocess/particle_hdf5_writer.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <sstream>

namespace psmpm
{
  namespace Postprocess
  {
    namespace
    {
      /// The shortest decimal form of @p x that reads back as @p x:
      /// consecutive output times must stay distinct in the series.
      /// (deal.II's XDMFEntry prints 6 digits, the .pvd record 12.)
      std::string
      exact(const double x)
      {
        std::ostringstream s;
        for (int digits = 12; digits <= 17; ++digits)
          {
            s.str("");
            s.precision(digits);
            s << x;
            if (std::stod(s.str()) == x)
              break;
          }
        return s.str();
      }

      /**
       * One output of the temporal collection: the particles as a
       * Polyvertex grid (one vertex per element) with every field as a
       * node attribute, the layout that deal.II 9.4's XDMFEntry writes for
       * 0-dimensional patches. We write it ourselves because XDMFEntry
       * prints the time with 6 digits (close outputs of a long run would
       * share a time), DataOutInterface::create_xdmf_entry() takes the
       * fields from rank 0's DataOutFilter (none if rank 0 holds no
       * particle) and write_xdmf_file() needs a DataOutInterface and does
       * not write atomically.
       */
      void
      write_xdmf_grid(
        std::ostream                                            &out,
        const double                                             time,
        const std::string                                       &file,
        const std::uint64_t                                      n,
        const std::vector<std::pair<std::string, unsigned int>> &fields)
      {
        const auto item = [&](const std::string &indent,
                              const unsigned int columns,
                              const char        *type,
                              const std::string &dataset) {
          out << indent << "<DataItem Dimensions=\"" << n << " " << columns
              << "\" NumberType=\"" << type << "\""
              << (std::string(type) == "Float" ? " Precision=\"8\"" : "")
              << " Format=\"HDF\">\n"
              << indent << "  " << file << ":/" << dataset << "\n"
              << indent << "</DataItem>\n";
        };
        out << "      <Grid Name=\"particles\" GridType=\"Uniform\">\n"
            << "        <Time Value=\"" << exact(time) << "\"/>\n"
            << "        <Geometry GeometryType=\"XY\">\n";
        item("          ", 2, "Float", "nodes");
        out << "        </Geometry>\n"
            << "        <Topology TopologyType=\"Polyvertex\" "
            << "NumberOfElements=\"" << n << "\" NodesPerElement=\"1\">\n";
        item("          ", 1, "UInt", "cells");
        out << "        </Topology>\n";
        for (const auto &[name, columns] : fields)
          {
            out << "        <Attribute Name=\"" << name << "\" AttributeType=\""
                << (columns > 1 ? "Vector" : "Scalar")
                << "\" Center=\"Node\">\n";
            item("          ", columns, "Float", name);
            out << "        </Attribute>\n";
          }
        out << "      </Grid>\n";
      }

      /// Disk full on demand (inject_write_failure()), decided on rank 0
      /// for all ranks of @p comm before the collective write.
      void
      inject_on_all_ranks(const std::string &path, MPI_Comm comm)
      {
        std::string injected;
        if (Utilities::MPI::this_mpi_process(comm) == 0)
          try
            {
              inject_write_failure(path);
            }
          catch (const ExcWriteFailed &e)
            {
              injected = e.what();
            }
        injected = Utilities::MPI::broadcast(comm, injected, 0);
        if (!injected.empty())
          throw ExcWriteFailed(injected);
      }
    } // namespace



    ParticleHdf5Writer::ParticleHdf5Writer(const std::string &directory,
                                           MPI_Comm           comm)
      : directory(directory)
      , comm(comm)
    {
    }



    std::string
    ParticleHdf5Writer::file_name(const unsigned int step)
    {
      return "particles-" + Utilities::int_to_string(step, 5) + ".h5";
    }



    template <int spacedim>
    void
    ParticleHdf5Writer::write(
      const unsigned int                                  step,
      const double                                        time,
      const std::vector<std::string>                     &names,
      const DataRanges                                   &ranges,
      const std::vector<DataOutBase::Patch<0, spacedim>> &patches)
    {
      const std::string  file = file_name(step);
      const std::string  path = directory + "/" + file;
      const std::string  tmp  = path + ".tmp";
      const unsigned int rank = Utilities::MPI::this_mpi_process(comm);

      // Vectors stay vectors (ParaView glyphs); tensors become their
      // scalar components (see the class documentation).
      DataRanges vectors;
      for (const auto &r : ranges)
        if (std::get<3>(r) ==
            DataComponentInterpretation::component_is_part_of_vector)
          vectors.push_back(r);
      // The fields as write_filtered_data() names them (vectors padded
      // to 3 components); known on every rank, also one without
      // particles, whose DataOutFilter stays empty.
      std::vector<std::pair<std::string, unsigned int>> fields;
      for (unsigned int k = 0, v = 0; k < names.size();)
        if (v < vectors.size() && std::get<0>(vectors[v]) == k)
          {
            fields.emplace_back(std::get<2>(vectors[v]), 3);
            k = std::get<1>(vectors[v]) + 1;
            ++v;
          }
        else
          fields.emplace_back(names[k++], 1);

      const std::uint64_t n_local = patches.size();
      const std::uint64_t n       = Utilities::MPI::sum(n_local, comm);
      if (n == 0)
        return; // nothing to show

      // deal.II 9.4 cannot write for a rank without patches (it reads
      // patches[0] and an unset cell count, and skips the collective
      // dataset creation), so only the ranks with particles write, in
      // rank order. Two particles at the same position stay two points.
      inject_on_all_ranks(path, comm);
      std::string error;
      MPI_Comm    writers;
      MPI_Comm_split(comm, n_local > 0 ? 0 : MPI_UNDEFINED, rank, &writers);
      if (n_local > 0)
        {
          try
            {
              DataOutBase::DataOutFilter filter(
                DataOutBase::DataOutFilterFlags(false, true));
              DataOutBase::write_filtered_data(patches, names, vectors, filter);
              errno = 0;
              DataOutBase::write_hdf5_parallel(patches, filter, tmp, writers);
            }
          catch (const ExceptionBase &)
            {
              // deal.II says ExcIO only; errno of the failed call says why
              // if it is set (HDF5's own messages are silenced, Archive).
              const int e = errno;
              error       = "cannot write " + path + " (written as " + tmp +
                      "): " + (e != 0 ? std::strerror(e) : "HDF5 error");
            }
          MPI_Comm_free(&writers);
        }

      // Every rank has closed the file here; one failure fails all.
      for (const auto &e : Utilities::MPI::all_gather(comm, error))
        if (!e.empty())
          {
            if (rank == 0)
              std::remove(tmp.c_str());
            throw ExcWriteFailed(e);
          }
      if (rank == 0 && std::rename(tmp.c_str(), path.c_str()) != 0)
        {
          const int e = errno;
          std::remove(tmp.c_str());
          throw ExcWriteFailed("cannot write " + path + ": rename from " + tmp +
                               " failed (" + std::strerror(e) + ")");
        }

      records.push_back({time, file, n, fields});
      write_index();
    }



    void
    ParticleHdf5Writer::write_index() const
    {
      if (Utilities::MPI::this_mpi_process(comm) != 0)
        return;
      write_atomically(directory + "/particles.xdmf", [&](std::ostream &out) {
        out << "<?xml version=\"1.0\" ?>\n"
            << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
            << "<Xdmf Version=\"2.0\">\n"
            << "  <Domain>\n"
            << "    <Grid Name=\"particles\" GridType=\"Collection\" "
            << "CollectionType=\"Temporal\">\n";
        for (const auto &r : records)
          write_xdmf_grid(out, r.time, r.file, r.n_points, r.fields);
        out << "    </Grid>\n"
            << "  </Domain>\n"
            << "</Xdmf>\n";
      });
    }



    void
    ParticleHdf5Writer::save(Archive &archive) const
    {
      std::vector<double>        times;
      std::vector<std::uint64_t> points;
      std::string                files, fields;
      for (const auto &r : records)
        {
          times.push_back(r.time);
          points.push_back(r.n_points);
          files += r.file + "\n";
          for (std::size_t k = 0; k < r.fields.size(); ++k)
            fields += (k > 0 ? " " : "") + r.fields[k].first + ":" +
                      std::to_string(r.fields[k].second);
          fields += "\n";
        }
      archive.put("output/xdmf_times", times);
      archive.put_integers("output/xdmf_points", points);
      archive.put_text("output/xdmf_files", files);
      archive.put_text("output/xdmf_fields", fields);
    }



    void
    ParticleHdf5Writer::load(const Archive &archive)
    {
      records.clear();
      if (!archive.has("output/xdmf_times"))
        return;
      const auto &times = archive.get("output/xdmf_times");
      const auto &points =
        archive.get_integers("output/xdmf_points", times.size());
      const auto files =
        Utilities::split_string_list(archive.get_text("output/xdmf_files"),
                                     '\n');
      const auto fields =
        Utilities::split_string_list(archive.get_text("output/xdmf_fields"),
                                     '\n');
      AssertThrow(files.size() >= times.size() && fields.size() >= times.size(),
                  ExcMessage("entries 'output/xdmf_files' and "
                             "'output/xdmf_fields' do not match "
                             "'output/xdmf_times'"));
      for (std::size_t i = 0; i < times.size(); ++i)
        {
          Record r{times[i], files[i], points[i], {}};
          for (const auto &f : Utilities::split_string_list(fields[i], ' '))
            {
              const auto colon = f.rfind(':');
              AssertThrow(colon != std::string::npos,
                          ExcMessage("entry 'output/xdmf_fields' is damaged"));
              r.fields.emplace_back(f.substr(0, colon),
                                    std::stoul(f.substr(colon + 1)));
            }
          records.push_back(std::move(r));
        }
    }



    template void
    ParticleHdf5Writer::write<2>(const unsigned int,
                                 const double,
                                 const std::vector<std::string> &,
                                 const DataRanges &,
                                 const std::vector<DataOutBase::Patch<0, 2>> &);
  } // namespace Postprocess
} // namespace psmpm
