// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// The executable only hands the command line to the application.
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
