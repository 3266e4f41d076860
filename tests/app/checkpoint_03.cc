// A checkpoint written by two ranks (rank 0 gathers the particles into
// one file) resumes on two ranks and on one: the particles are handed to
// the ranks owning their cells. On two ranks (the same partition and the
// file's order) the run is bit-identical to the uninterrupted one; on one
// rank the sums run in another order and the final particle state agrees
// to round-off.
#include "../checkpoint_tests.h"

namespace fs = std::filesystem;

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  const bool                     root  = is_root_rank();
  std::ofstream                  out   = root_output();
  const std::vector<std::string> scene = {"--set",
                                          "Time/End time=0.0003",
                                          "--set",
                                          "Reference solution/Type=none",
                                          "--set",
                                          "Checkpoint/Interval=20"};
  const auto with = [&scene](const std::vector<std::string> &more) {
    std::vector<std::string> args = scene;
    args.insert(args.end(), more.begin(), more.end());
    return args;
  };
  std::string screen, message;

  if (root)
    fs::remove_all("two");
  MPI_Barrier(MPI_COMM_WORLD);
  int code = run_app(with({"--set", "Output directory=two"}), screen, message);
  out << "two ranks, 30 steps: exit codes "
      << Utilities::MPI::max(code, MPI_COMM_WORLD) << std::endl;

  // What a run killed after the checkpoint of step 20 leaves, twice.
  const std::string last = "/" + psmpm::Simulator::Checkpoint::file_name(30);
  if (root)
    {
      PSMPM_CHECK(out, fs::exists("two" + last));
      PSMPM_CHECK(out, fs::exists("two/checkpoint-00000020.h5"));
      for (const std::string d : {"again_two", "again_one"})
        {
          copy_directory("two", d);
          fs::remove(d + last);
        }
    }
  MPI_Barrier(MPI_COMM_WORLD);

  code = run_app(with({"--set", "Output directory=again_two", "--resume"}),
                 screen,
                 message);
  out << "resumed on two ranks: exit code "
      << Utilities::MPI::max(code, MPI_COMM_WORLD) << std::endl;

  // On one rank: rank 0 alone.
  MPI_Comm self;
  MPI_Comm_split(MPI_COMM_WORLD, root ? 0 : MPI_UNDEFINED, 0, &self);
  if (root)
    {
      std::ostringstream o, e;
      auto              *old_out = std::cout.rdbuf(o.rdbuf());
      auto              *old_err = std::cerr.rdbuf(e.rdbuf());
      code =
        psmpm::App::run(with(
                          {"--set", "Output directory=again_one", "--resume"}),
                        self);
      std::cout.rdbuf(old_out);
      std::cerr.rdbuf(old_err);
      out << "resumed on one rank: exit code " << code << std::endl;
      if (code != 0)
        out << e.str() << std::endl;
      MPI_Comm_free(&self);

      const auto reference = psmpm::Archive::read_hdf5("two" + last);
      const auto two       = psmpm::Archive::read_hdf5("again_two" + last);
      const auto one       = psmpm::Archive::read_hdf5("again_one" + last);
      const auto differ    = differing_entries(reference, two);
      out << "two ranks -> two ranks: entries differing: " << differ.size()
          << std::endl;
      for (const auto &d : differ)
        out << "  differs: " << d << std::endl;
      PSMPM_CHECK(out,
                  statistics_rows("two/statistics.txt") ==
                    statistics_rows("again_two/statistics.txt"));
      PSMPM_CHECK(out, one.get_integer("psmpm/n_mpi_ranks") == 1);
      const double d = particle_difference(reference, one);
      out << "two ranks -> one rank: largest relative particle difference "
          << (d < 0     ? "(different particles)" :
              d < 1e-10 ? "below 1e-10" :
                          std::to_string(d))
          << std::endl;
      std::cout << "two ranks -> one rank: largest relative particle "
                   "difference "
                << d << std::endl;
      PSMPM_CHECK(out,
                  statistics_rows("two/statistics.txt").size() ==
                    statistics_rows("again_one/statistics.txt").size());
    }
}
