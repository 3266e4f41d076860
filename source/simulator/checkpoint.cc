// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/utilities.h>

#include <psmpm/base/checked_file.h>
#include <psmpm/base/fnv1a.h>
#include <psmpm/base/root_errors.h>
#include <psmpm/simulator/checkpoint.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <regex>
#include <sstream>
#include <unistd.h>

namespace psmpm
{
  namespace Simulator
  {
    namespace fs = std::filesystem;

    namespace
    {
      const std::regex checkpoint_pattern("checkpoint-([0-9]+)\\.h5");

      /// Make a rename in @p directory durable.
      void
      sync_directory(const std::string &directory)
      {
        const int fd = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY);
        if (fd >= 0)
          {
            ::fsync(fd);
            ::close(fd);
          }
      }

      /// "Subsection/Entry" -> value of a parameter file printed as
      /// ShortPRM (subsection / set / end lines).
      std::map<std::string, std::string>
      entries_of(const std::string &text)
      {
        std::map<std::string, std::string> entries;
        std::vector<std::string>           path;
        std::istringstream                 in(text);
        std::string                        line;
        while (std::getline(in, line))
          {
            line = Utilities::trim(line);
            if (line.empty() || line[0] == '#')
              continue;
            if (line.rfind("subsection ", 0) == 0)
              path.push_back(Utilities::trim(line.substr(11)));
            else if (line == "end")
              {
                if (!path.empty())
                  path.pop_back();
              }
            else if (line.rfind("set ", 0) == 0)
              {
                const auto  eq   = line.find('=');
                std::string name = Utilities::trim(line.substr(4, eq - 4));
                std::string key;
                for (const auto &p : path)
                  key += p + "/";
                entries[key + name] = eq == std::string::npos ?
                                        "" :
                                        Utilities::trim(line.substr(eq + 1));
              }
          }
        return entries;
      }

      /// Entries a resumed run may change: they do not change results.
      bool
      may_change(const std::string &key)
      {
        static const std::vector<std::string> keys = {
          "Time/End time",
          "Output directory",
          "Output/Interval",
          "Output/Time interval",
          "Output/Subdivisions",
          "Output/Progress interval",
          "Output/Test output"};
        return std::find(keys.begin(), keys.end(), key) != keys.end() ||
               key.rfind("Checkpoint/", 0) == 0 || key.rfind("Limits/", 0) == 0;
      }

      /// The 64-bit FNV-1a checksum of the bytes of @p file, in
      /// hexadecimal; empty if it cannot be read.
      std::string
      checksum_of(const std::string &file)
      {
        const auto hash = fnv1a_of_file(file);
        if (!hash)
          return "";
        std::ostringstream hex;
        hex << std::hex << std::setw(16) << std::setfill('0') << *hash;
        return hex.str();
      }

      /// "entry" -> (file, checksum) of a text of file_checksums().
      std::map<std::string, std::pair<std::string, std::string>>
      checksums_of(const std::string &text)
      {
        std::map<std::string, std::pair<std::string, std::string>> files;
        std::istringstream                                         in(text);
        std::string                                                line;
        while (std::getline(in, line))
          {
            const auto a = line.find('\t');
            const auto b = line.rfind('\t');
            if (a != std::string::npos && b > a)
              files[line.substr(0, a)] = {line.substr(a + 1, b - a - 1),
                                          line.substr(b + 1)};
          }
        return files;
      }

      /// Particle @p i with its cell first: the cell is part of the state
      /// (the locator's answer depends on the cell it starts from).
      template <int dim>
      void
      pack_with_cell(const Particles::ParticleSet<dim> &particles,
                     const std::size_t                  i,
                     std::vector<double>               &buffer,
                     const std::vector<unsigned int>   &whole_index = {})
      {
        const unsigned int c = particles.cell[i];
        buffer.push_back(whole_index.empty() ? c : whole_index[c]);
        particles.pack(i, buffer);
      }

      template <int dim>
      void
      unpack_with_cells(const std::vector<double>   &buffer,
                        Particles::ParticleSet<dim> &particles)
      {
        const std::size_t   n = 1 + particles.n_packed();
        std::vector<double> packed;
        std::vector<double> cells;
        packed.reserve(buffer.size());
        for (std::size_t k = 0; k + n <= buffer.size(); k += n)
          {
            cells.push_back(buffer[k]);
            packed.insert(packed.end(),
                          buffer.begin() + k + 1,
                          buffer.begin() + k + n);
          }
        const std::size_t first = particles.size();
        particles.unpack(packed);
        for (std::size_t j = 0; j < cells.size(); ++j)
          particles.cell[first + j] = static_cast<unsigned int>(cells[j]);
      }

      /// Every rank's @p local concatenated on rank 0, in rank order (empty
      /// elsewhere). Raw MPI_Gatherv: Utilities::MPI::gather would serialize
      /// and gzip the buffers (5.5 s of a 980,000-particle checkpoint on two
      /// ranks against 1.8 s on one).
      std::vector<double>
      gather_doubles(const std::vector<double>  &local,
                     MPI_Comm                    comm,
                     std::vector<std::uint64_t> *sizes_out = nullptr)
      {
        const unsigned int  rank    = Utilities::MPI::this_mpi_process(comm);
        const unsigned int  n_ranks = Utilities::MPI::n_mpi_processes(comm);
        const std::uint64_t my_size = local.size();
        std::vector<std::uint64_t> sizes(rank == 0 ? n_ranks : 0);
        int                        ierr = MPI_Gather(&my_size,
                              1,
                              MPI_UINT64_T,
                              sizes.data(),
                              1,
                              MPI_UINT64_T,
                              0,
                              comm);
        AssertThrowMPI(ierr);
        std::vector<int> counts(sizes.size());
        std::vector<int> offsets(sizes.size(), 0);
        std::uint64_t    total = 0;
        for (unsigned int r = 0; r < sizes.size(); ++r)
          {
            offsets[r] = static_cast<int>(total);
            counts[r]  = static_cast<int>(sizes[r]);
            total += sizes[r];
          }
        // MPI counts are int: refuse rather than wrap (about 2.1e9 doubles,
        // 1.3e8 particles gathered on rank 0).
        const int too_large =
          Utilities::MPI::max(total > static_cast<std::uint64_t>(
                                        std::numeric_limits<int>::max()) ?
                                1 :
                                0,
                              comm);
        AssertThrow(too_large == 0,
                    ExcMessage("Checkpoint: the particles do not fit into one "
                               "MPI_Gatherv on rank 0 (more than 2^31 - 1 "
                               "values); use fewer particles per checkpoint "
                               "or turn checkpoints off (Checkpoint/Interval "
                               "= 0 still writes the final one)."));
        std::vector<double> all(rank == 0 ? total : 0);
        ierr = MPI_Gatherv(local.data(),
                           static_cast<int>(local.size()),
                           MPI_DOUBLE,
                           all.data(),
                           counts.data(),
                           offsets.data(),
                           MPI_DOUBLE,
                           0,
                           comm);
        AssertThrowMPI(ierr);
        if (sizes_out != nullptr)
          *sizes_out = sizes;
        return all;
      }

      /// Entry @p e of another archive into @p archive as @p name.
      void
      copy_entry(const Archive::Entry &e,
                 const std::string    &name,
                 Archive              &archive)
      {
        switch (e.type)
          {
            case Archive::Type::real:
              archive.put(name,
                          e.reals,
                          e.shape.size() == 2 ?
                            static_cast<unsigned int>(e.shape[1]) :
                            0);
              break;
            case Archive::Type::integer:
              archive.put_integers(name, e.integers);
              break;
            case Archive::Type::bytes:
              archive.put_bytes(name, e.data);
              break;
            case Archive::Type::text:
              archive.put_text(name, e.data);
              break;
          }
      }
    } // namespace



    std::vector<std::vector<double>>
    Checkpoint::gather_per_rank(const std::vector<double> &local, MPI_Comm comm)
    {
      std::vector<std::uint64_t> sizes;
      const std::vector<double>  all = gather_doubles(local, comm, &sizes);
      std::vector<std::vector<double>> pieces(sizes.size());
      std::size_t                      offset = 0;
      for (unsigned int r = 0; r < sizes.size(); ++r)
        {
          pieces[r].assign(all.begin() + offset,
                           all.begin() + offset + sizes[r]);
          offset += sizes[r];
        }
      return pieces;
    }



    void
    Checkpoint::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Checkpoint");
      prm.declare_entry(
        "Interval",
        "0",
        Patterns::Integer(0),
        "Write a checkpoint (checkpoint-<step>.h5 in the output directory, "
        "HDF5) every this many steps; 0: off. A checkpoint is also written "
        "at the end of a run and when a run is interrupted (SIGINT, SIGTERM, "
        "SIGUSR1); psmpm scene.prm --resume continues from the newest one "
        "with the same results (doc/checkpoints.md).");
      prm.declare_entry("Wall interval",
                        "0",
                        Patterns::Double(0),
                        "Also write a checkpoint whenever this many minutes "
                        "of wall time have passed since the last one; 0: off.");
      prm.leave_subsection();
    }



    void
    Checkpoint::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Checkpoint");
      interval      = prm.get_integer("Interval");
      wall_interval = 60 * prm.get_double("Wall interval");
      prm.leave_subsection();
    }



    void
    Checkpoint::start(const unsigned int step)
    {
      last      = step;
      last_wall = std::chrono::steady_clock::now();
    }



    bool
    Checkpoint::due(const unsigned int step, MPI_Comm comm) const
    {
      if (step == last)
        return false;
      if (interval > 0 && step % interval == 0)
        return true;
      if (wall_interval > 0)
        {
          // Rank 0's clock decides, so that every rank writes together.
          int passed = std::chrono::duration<double>(
                         std::chrono::steady_clock::now() - last_wall)
                         .count() >= wall_interval;
          MPI_Bcast(&passed, 1, MPI_INT, 0, comm);
          return passed != 0;
        }
      return false;
    }



    void
    Checkpoint::keep_state_before_last_step(Archive          &&archive,
                                            const unsigned int step)
    {
      before_last_step        = std::move(archive);
      before_last_step_number = step;
    }



    bool
    Checkpoint::restart_before_last_step(Archive &archive)
    {
      const std::string prefix = before_last_step_prefix;
      if (!archive.has(prefix + "simulator/step"))
        return false;
      Archive before;
      for (const auto &[name, e] : archive.get_entries())
        if (name.rfind(prefix, 0) == 0)
          copy_entry(e, name.substr(prefix.size()), before);
      archive = std::move(before);
      return true;
    }



    void
    Checkpoint::write(const std::string &directory,
                      const unsigned int step,
                      Archive           &archive,
                      MPI_Comm           comm)
    {
      std::string error;
      if (!before_last_step.get_entries().empty() &&
          step == before_last_step_number + 1)
        {
          for (const auto &[name, e] : before_last_step.get_entries())
            copy_entry(e, before_last_step_prefix + name, archive);
          before_last_step = Archive();
        }
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        {
          const std::string file = directory + "/" + file_name(step);
          const std::string tmp  = directory + "/" + temporary_name;
          try
            {
              archive.write_hdf5(tmp, file);
              if (std::rename(tmp.c_str(), file.c_str()) != 0)
                throw ExcWriteFailed("cannot write " + file + ": rename from " +
                                     tmp + " failed (" + std::strerror(errno) +
                                     ")");
              sync_directory(directory);
              // The new checkpoint is complete and durable: of the older
              // ones, only the previous is kept (a fallback).
              const auto      files = list(directory);
              std::error_code ec;
              for (std::size_t i = 0; i < files.size(); ++i)
                if (i >= 2 && files[i] != file)
                  fs::remove(files[i], ec);
            }
          catch (const ExcWriteFailed &e)
            {
              std::remove(tmp.c_str());
              error = e.what();
            }
        }
      error = Utilities::MPI::broadcast(comm, error, 0);
      if (!error.empty())
        throw ExcWriteFailed(error);
      start(step);
    }



    std::string
    Checkpoint::file_name(const unsigned int step)
    {
      return "checkpoint-" + Utilities::int_to_string(step, 8) + ".h5";
    }



    bool
    Checkpoint::is_checkpoint_file(const std::string &name)
    {
      return name == temporary_name ||
             std::regex_match(name, checkpoint_pattern);
    }



    std::vector<std::string>
    Checkpoint::list(const std::string &directory)
    {
      std::vector<std::pair<unsigned long long, std::string>> found;
      std::error_code                                         ec;
      for (const auto &entry : fs::directory_iterator(directory, ec))
        {
          std::smatch       m;
          const std::string name = entry.path().filename().string();
          if (entry.is_regular_file() &&
              std::regex_match(name, m, checkpoint_pattern))
            found.emplace_back(std::stoull(m[1].str()), directory + "/" + name);
        }
      std::sort(found.rbegin(), found.rend());
      std::vector<std::string> files;
      for (const auto &f : found)
        files.push_back(f.second);
      return files;
    }



    std::vector<std::string>
    Checkpoint::parameter_differences(const std::string &saved,
                                      const std::string &current,
                                      const std::string &defaults)
    {
      const auto               a = entries_of(saved);
      const auto               b = entries_of(current);
      const auto               d = entries_of(defaults);
      std::vector<std::string> differences;
      for (const auto &[key, value] : a)
        {
          if (may_change(key))
            continue;
          const auto it = b.find(key);
          if (it == b.end())
            differences.push_back(key + ": '" + value + "' -> (not declared)");
          else if (it->second != value)
            differences.push_back(key + ": '" + value + "' -> '" + it->second +
                                  "'");
        }
      for (const auto &[key, value] : b)
        if (!may_change(key) && a.count(key) == 0 &&
            !(d.count(key) && d.at(key) == value))
          differences.push_back(key + ": (not in the checkpoint) -> '" + value +
                                "'");
      return differences;
    }



    std::string
    Checkpoint::file_checksums(const std::string &parameters)
    {
      std::string text;
      for (const auto &[key, value] : entries_of(parameters))
        {
          const bool is_file =
            key == "File" ||
            (key.size() > 5 && key.compare(key.size() - 5, 5, "/File") == 0);
          if (!is_file || value.empty())
            continue;
          const std::string sum = checksum_of(value);
          if (!sum.empty())
            text += key + "\t" + value + "\t" + sum + "\n";
        }
      return text;
    }



    std::vector<std::string>
    Checkpoint::file_differences(const std::string &saved,
                                 const std::string &current)
    {
      const auto               now = checksums_of(current);
      std::vector<std::string> differences;
      for (const auto &[key, then] : checksums_of(saved))
        {
          const auto it = now.find(key);
          if (it != now.end() && it->second.first != then.first)
            continue; // another file: a parameter difference
          if (it == now.end())
            differences.push_back(key + ": the file " + then.first +
                                  " cannot be read any more (it was read "
                                  "when the run started)");
          else if (it->second.second != then.second)
            differences.push_back(key + ": the content of " + then.first +
                                  " changed since the checkpoint (FNV-1a "
                                  "checksum " +
                                  then.second + " at the run's start, " +
                                  it->second.second + " now)");
        }
      return differences;
    }



    template <int dim>
    void
    Checkpoint::gather_particles(const Particles::ParticleSet<dim> &particles,
                                 Archive                           &archive,
                                 MPI_Comm                           comm,
                                 const std::vector<unsigned int>   &whole_index)
    {
      if (Utilities::MPI::n_mpi_processes(comm) == 1 && whole_index.empty())
        {
          particles.save(archive);
          return;
        }
      std::vector<double> buffer;
      buffer.reserve(particles.size() * (1 + particles.n_packed()));
      for (std::size_t i = 0; i < particles.size(); ++i)
        pack_with_cell(particles, i, buffer, whole_index);
      const std::vector<double> all = gather_doubles(buffer, comm);
      if (Utilities::MPI::this_mpi_process(comm) != 0)
        return;
      Particles::ParticleSet<dim> global;
      global.set_state_names(particles.get_state_names());
      global.n_bodies = particles.n_bodies;
      unpack_with_cells(all, global);
      global.save(archive);
    }



    template <int dim>
    void
    Checkpoint::scatter_particles(const Archive                   &archive,
                                  const std::vector<unsigned int> &cell_owner,
                                  Particles::ParticleSet<dim>     &particles,
                                  MPI_Comm                         comm)
    {
      Particles::ParticleSet<dim> all;
      all.set_state_names(particles.get_state_names());
      on_root_or_throw_everywhere(comm, [&]() {
        all.load(archive);
        for (const unsigned int c : all.cell)
          AssertThrow(c < cell_owner.size(),
                      ExcMessage("entry 'particles/cell' holds cell " +
                                 std::to_string(c) + " of a mesh with " +
                                 std::to_string(cell_owner.size()) + " cells"));
      });

      // A new set with the old state names: the material is the same.
      Particles::ParticleSet<dim> mine;
      mine.set_state_names(particles.get_state_names());
      if (Utilities::MPI::n_mpi_processes(comm) == 1)
        mine = std::move(all);
      else
        {
          std::map<unsigned int, std::vector<double>> outgoing;
          for (std::size_t i = 0; i < all.size(); ++i)
            pack_with_cell(all, i, outgoing[cell_owner[all.cell[i]]]);
          // Every rank receives from rank 0 only: the file's order.
          const auto incoming = Utilities::MPI::some_to_some(comm, outgoing);
          for (const auto &in : incoming)
            unpack_with_cells(in.second, mine);
        }
      // The scene's number of bodies and their materials are not
      // particle data (without the table, the output's material_id read
      // past its end after a resume).
      const unsigned int        n_bodies      = particles.n_bodies;
      std::vector<unsigned int> body_material = particles.body_material;
      particles                               = std::move(mine);
      particles.n_bodies                      = n_bodies;
      particles.body_material                 = std::move(body_material);
    }



    template void
    Checkpoint::gather_particles(const Particles::ParticleSet<1> &,
                                 Archive &,
                                 MPI_Comm,
                                 const std::vector<unsigned int> &);
    template void
    Checkpoint::gather_particles(const Particles::ParticleSet<2> &,
                                 Archive &,
                                 MPI_Comm,
                                 const std::vector<unsigned int> &);
    template void
    Checkpoint::scatter_particles(const Archive &,
                                  const std::vector<unsigned int> &,
                                  Particles::ParticleSet<1> &,
                                  MPI_Comm);
    template void
    Checkpoint::scatter_particles(const Archive &,
                                  const std::vector<unsigned int> &,
                                  Particles::ParticleSet<2> &,
                                  MPI_Comm);
  } // namespace Simulator
} // namespace psmpm
