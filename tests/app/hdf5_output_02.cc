// Output/Particle format = hdf5 on two ranks: every output is ONE file
// that holds the particles of both ranks (no piece per rank): as many as
// the two VTU pieces of the same scene run with vtu output, each rank's
// count in the "rank" field equal to its piece, every particle id of the
// run's final checkpoint once, and at the last step its positions exactly
// (its fields in Float32, as deal.II's patches hold them).
// A run resumed on two ranks gives the same particles.xdmf. A scene whose
// particles all lie in cells of one rank (the other writes nothing) gives
// a file with all of them.
#include "../checkpoint_tests.h"
#include "../vtu_tests.h"
#include "../xdmf_tests.h"

#include <set>

namespace fs = std::filesystem;
using psmpm::Simulator::Checkpoint;

const std::vector<std::string> scene = {"--set",
                                        "Time/End time=0.0003",
                                        "--set",
                                        "Reference solution/Type=none",
                                        "--set",
                                        "Output/Interval=10",
                                        "--set",
                                        "Checkpoint/Interval=20"};

std::vector<std::string>
with(const std::vector<std::string> &more)
{
  std::vector<std::string> args = scene;
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

int
run(const std::vector<std::string> &args)
{
  std::string screen, message;
  const int   code = run_app(args, screen, message);
  return Utilities::MPI::max(code, MPI_COMM_WORLD);
}

/// The final checkpoint of the run in @p directory (its last output step
/// in particles.xdmf).
psmpm::Archive
final_checkpoint(const std::string &directory)
{
  const auto grids = read_xdmf(directory + "/particles.xdmf");
  return psmpm::Archive::read_hdf5(
    directory + "/" +
    Checkpoint::file_name(output_step(grids.back().nodes.file)));
}

/// The particles of @p h5 against checkpoint @p c: every id once and, with
/// @p exact, the same position and the same velocity and mass in Float32.
bool
same_particles(const std::string &h5, const psmpm::Archive &c, const bool exact)
{
  const auto   &ids = c.get_integers("particles/id");
  const H5Table id = read_h5_table(h5, "id"), x = read_h5_table(h5, "nodes"),
                v = read_h5_table(h5, "velocity"),
                m = read_h5_table(h5, "mass");
  std::map<std::uint64_t, std::size_t> where;
  for (std::size_t i = 0; i < ids.size(); ++i)
    where[ids[i]] = i;
  std::set<std::uint64_t> seen;
  bool                    ok = id.rows == ids.size() && x.rows == ids.size();
  for (std::uint64_t i = 0; ok && i < id.rows; ++i)
    {
      const auto key = static_cast<std::uint64_t>(id(i, 0));
      const auto it  = where.find(key);
      ok             = it != where.end() && seen.insert(key).second;
      if (ok && exact)
        {
          const std::size_t j = it->second;
          // Positions are doubles, fields Float32 (deal.II's patches).
          ok = m(i, 0) == static_cast<float>(c.get("particles/mass")[j]);
          for (unsigned int d = 0; d < 2; ++d)
            ok = ok && x(i, d) == c.get("particles/position")[2 * j + d] &&
                 v(i, d) ==
                   static_cast<float>(c.get("particles/velocity")[2 * j + d]);
        }
    }
  return ok;
}

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  const bool        root = is_root_rank();
  std::ofstream     out  = root_output();
  if (root)
    for (const std::string d : {"vtu", "hdf5", "hdf5_resumed", "corner"})
      fs::remove_all(d);
  MPI_Barrier(MPI_COMM_WORLD);

  out << "vtu run: exit code " << run(with({"--set", "Output directory=vtu"}))
      << std::endl;
  out << "hdf5 run: exit code "
      << run(with({"--set",
                   "Output directory=hdf5",
                   "--set",
                   "Output/Particle format=hdf5"}))
      << std::endl;

  if (root)
    {
      const auto grids = read_xdmf("hdf5/particles.xdmf");
      const auto pvd   = read_pvd("vtu/particles.pvd");
      out << "outputs: " << grids.size() << std::endl;
      PSMPM_CHECK(out, grids.size() == pvd.size() && grids.size() >= 3);
      unsigned int files = 0;
      for (const auto &e : fs::directory_iterator("hdf5"))
        files += e.path().filename().string().rfind("particles-", 0) == 0;
      PSMPM_CHECK(out, files == grids.size());

      // Each output: one file with the particles of both VTU pieces.
      bool counts = true, per_rank = true, ids = true;
      for (const auto &g : grids)
        {
          const std::string step =
            Utilities::int_to_string(output_step(g.nodes.file), 5);
          std::vector<unsigned int> pieces;
          for (const std::string r : {"000", "001"})
            pieces.push_back(piece_attribute(read_file("vtu/particles-" + step +
                                                       "." + r + ".vtu"),
                                             "NumberOfPoints"));
          const H5Table rank = read_h5_table("hdf5/" + g.nodes.file, "rank");
          std::vector<unsigned int> held(2, 0);
          for (const double r : rank.values)
            ++held.at(static_cast<unsigned int>(r));
          counts = counts && g.n_elements == pieces[0] + pieces[1] &&
                   rank.rows == g.n_elements;
          per_rank =
            per_rank && held == pieces && pieces[0] > 0 && pieces[1] > 0;
        }
      const auto c = final_checkpoint("hdf5");
      ids          = same_particles("hdf5/" + grids.back().nodes.file, c, true);
      out << "particles in the last file: " << grids.back().n_elements
          << ", in the final checkpoint: "
          << c.get_integers("particles/id").size() << std::endl;
      PSMPM_CHECK(out, counts);
      PSMPM_CHECK(out, per_rank);
      PSMPM_CHECK(out, ids);

      copy_directory("hdf5", "hdf5_resumed");
      fs::remove("hdf5_resumed/" +
                 Checkpoint::file_name(output_step(grids.back().nodes.file)));
    }
  MPI_Barrier(MPI_COMM_WORLD);
  out << "resumed on two ranks: exit code "
      << run(with({"--set",
                   "Output directory=hdf5_resumed",
                   "--set",
                   "Output/Particle format=hdf5",
                   "--resume"}))
      << std::endl;
  if (root)
    PSMPM_CHECK(out,
                read_file("hdf5/particles.xdmf") ==
                  read_file("hdf5_resumed/particles.xdmf"));

  // Particles in the first block only: the other rank owns none of them.
  out << "corner run: exit code "
      << run(with({"--set",
                   "Output directory=corner",
                   "--set",
                   "Output/Particle format=hdf5",
                   "--set",
                   "Particles/Region=0, 0, 6.25, 2"}))
      << std::endl;
  if (root)
    {
      const auto       grids = read_xdmf("corner/particles.xdmf");
      const auto       c     = final_checkpoint("corner");
      bool             all   = grids.size() >= 3;
      std::set<double> ranks;
      for (const auto &g : grids)
        {
          const H5Table rank = read_h5_table("corner/" + g.nodes.file, "rank");
          ranks.insert(rank.values.begin(), rank.values.end());
          all = all && g.n_elements == c.get_integers("particles/id").size();
        }
      out << "corner: ranks holding particles: " << ranks.size() << std::endl;
      PSMPM_CHECK(out, ranks.size() == 1);
      PSMPM_CHECK(out, all);
      PSMPM_CHECK(out,
                  same_particles("corner/" + grids.back().nodes.file, c, true));
    }
}
