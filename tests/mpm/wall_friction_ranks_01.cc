// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Coulomb friction walls give the same run on one and on two MPI ranks
// (the .output and .mpirun=2.output files are identical): the slope of
// prm/frictional_slope.prm (Drucker-Prager with softening, geostatic
// start, floor mu = 0.5, MUSL) for 0.3 s, linear and Powell-Sabin. A wall
// DoF whose cells two ranks hold takes its normal force summed over both,
// so both apply the same friction (and the same hold of a sticking DoF);
// its force and work are counted once, by the owner.
#include "../mpm_tests.h"

#include <filesystem>

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out = root_output();
  for (const std::string basis : {"linear", "powell-sabin"})
    {
      auto solver = make_scene_solver("frictional_slope.prm",
                                      {"Basis/Type=" + basis,
                                       "Time/End time=0.3",
                                       "Output/Interval=0"});
      const std::string dir = "run-" + basis;
      if (is_root_rank())
        std::filesystem::create_directories(dir);
      MPI_Barrier(MPI_COMM_WORLD);
      const auto status = solver->run(dir);
      out << basis << ": " << psmpm::Simulator::status_name(status)
          << std::endl;
      if (!is_root_rank())
        continue;
      const StatisticsTable statistics(dir);
      out << std::setprecision(7);
      for (const std::string name : {"kinetic_energy",
                                     "strain_energy",
                                     "gravity_energy",
                                     "dissipated_energy",
                                     "reaction_bottom_x",
                                     "reaction_bottom_y",
                                     "friction_work"})
        out << "  " << name << " " << statistics.column(name).back()
            << std::endl;
      PSMPM_CHECK(out, statistics.column("friction_work").back() < 0);
    }
}
