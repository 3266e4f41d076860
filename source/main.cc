// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// The executable only hands the command line to the application.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include <psmpm/app/application.h>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  return psmpm::App::run(argc, argv, MPI_COMM_WORLD);
}
