// MPISession: a process that no process manager started (ctest runs this
// test alone) gets Open MPI's cheap singleton start-up (no helper daemon,
// the ob1 point-to-point layer); under mpirun (the mpirun=2 variant) the
// environment is left as the launcher set it. Either way MPI works: a sum
// over the ranks.
#include "../tests.h"

#include <cstdlib>

namespace
{
  std::string
  variable(const char *name)
  {
    const char *v = std::getenv(name);
    return v == nullptr ? "(unset)" : v;
  }
} // namespace

int
main(int argc, char **argv)
{
  // What the environment held before MPISession, to tell its settings
  // from the user's (which win).
  const std::string isolated_before =
    variable("OMPI_MCA_ess_singleton_isolated");
  const std::string  pml_before = variable("OMPI_MCA_pml");
  psmpm::MPISession  mpi(argc, argv);
  const unsigned int rank = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  std::ofstream      out(rank == 0 ? "output" : "/dev/null");
  return run_test([&]() {
    const bool         managed = psmpm::launched_by_process_manager();
    const unsigned int n       = Utilities::MPI::sum(1u, MPI_COMM_WORLD);
    out << "ranks " << n << ", launched by a process manager: " << managed
        << std::endl;
    const std::string isolated =
      !managed && isolated_before == "(unset)" ? "1" : isolated_before;
    const std::string pml =
      !managed && pml_before == "(unset)" ? "ob1" : pml_before;
    PSMPM_CHECK(out, variable("OMPI_MCA_ess_singleton_isolated") == isolated);
    PSMPM_CHECK(out, variable("OMPI_MCA_pml") == pml);
  });
}
