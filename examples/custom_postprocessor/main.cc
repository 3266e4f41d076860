// ---------------------------------------------------------------------
// custom_postprocessor: psmpm's executable with one more postprocessor.
// The postprocessor registers itself (run_out.cc), so main() is the
// same as psmpm's own and every 2D run writes column run_out.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include <psmpm/app/application.h>
#include <psmpm/base/mpi_session.h>

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  return psmpm::App::run(argc, argv, MPI_COMM_WORLD);
}
