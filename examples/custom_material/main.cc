// ---------------------------------------------------------------------
// custom_material: psmpm's executable, linked with one more material.
// The model registers itself (small_strain_elastic.cc), so main() is the
// same as psmpm's own and Material/Model lists the new name.
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
