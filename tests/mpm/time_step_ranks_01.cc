// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// The automatic time step does not depend on the number of ranks. It did:
// TimeStepControl took the maximum over ranks of (largest wave speed +
// largest particle speed) of each rank, so which rank held the fastest
// particle and which the stiffest one changed the step. On the spinning
// neo-Hookean block of prm/rotating_block.prm (16 x 16 blocks) two ranks gave
// steps that differed from one rank's by 5e-7 at the third step and 4e-4
// after 32 steps. Now the two maxima are reduced separately and added, as on
// one rank: rank 0 runs the scene alone (MPI_COMM_SELF) and all ranks run it
// together; the steps of statistics.txt agree to round-off.
#include "../mpm_tests.h"

#include <filesystem>

namespace
{
  void
  run(const MPI_Comm comm, const std::string &directory)
  {
    auto solver = make_scene_solver<2>("rotating_block.prm",
                                       {"Mesh/Blocks x=16",
                                        "Mesh/Blocks y=16",
                                        "Time/End time=0.02",
                                        "Output/Interval=0"},
                                       comm);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      std::filesystem::create_directories(directory);
    solver->run(directory);
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  const bool        root = is_root_rank();
  std::ofstream     out  = root_output();
  if (root)
    run(MPI_COMM_SELF, "alone");
  run(MPI_COMM_WORLD, "together");
  if (!root)
    return 0;
  const auto alone    = StatisticsTable("alone").column("dt");
  const auto together = StatisticsTable("together").column("dt");
  double     worst = 0;
  for (std::size_t i = 1; i < std::min(alone.size(), together.size()); ++i)
    worst = std::max(worst, std::abs(together[i] / alone[i] - 1));
  out << Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) << " ranks, "
      << alone.size() - 1 << " steps" << std::endl;
  PSMPM_CHECK(out, alone.size() > 30 && together.size() == alone.size());
  PSMPM_CHECK(out, worst < 1e-12);
}
