// Small-deformation vibrating bar (thesis Table 4.1/4.2), P1 consistent
// MPM on 4 and 8 criss-cross blocks, 16 x 14 particles per block,
// dt = 1e-5, t = 0.02: displacement errors within 10 % of thesis
// Table 4.2 and a rate of 2 +- 0.1.
#include "../mpm_tests.h"

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");
  const double                     thesis[2] = {1.80956e-04, 4.44076e-05};
  double                           error[2];
  for (unsigned int i = 0; i < 2; ++i)
    {
      psmpm::Simulator::Simulator<2> solver(MPI_COMM_WORLD);
      configure(solver, {"Mesh/Blocks x=" + std::to_string(4 << i)});
      while (solver.get_time() < 0.02 - 1e-12)
        solver.do_time_step(1e-5);
      error[i] = solver.compute_errors().displacement;
      out << "blocks " << (4 << i)
          << ": E_u / thesis = " << std::setprecision(2) << error[i] / thesis[i]
          << std::endl;
      PSMPM_CHECK(out, std::abs(error[i] / thesis[i] - 1) < 0.1);
    }
  const double rate = std::log2(error[0] / error[1]);
  PSMPM_CHECK(out, std::abs(rate - 2) < 0.1);
}
