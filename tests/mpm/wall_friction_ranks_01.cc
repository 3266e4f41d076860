// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Coulomb friction walls give the same run on one and on two MPI ranks
// (the .output and .mpirun=2.output files are identical): the slope of
// prm/frictional_slope.prm (Drucker-Prager with softening, geostatic
// start, floor mu = 0.5, MUSL) for 0.3 s, linear and Powell-Sabin. A wall
// DoF whose cells two ranks hold takes its normal force summed over both,
// so both apply the same friction (and the same hold of a sticking DoF);
// its force and work are counted once, by the owner. The same with
// Boundary conditions/Stop particles at walls (linear): a constrained
// DoF's change sums the momenta and masses of both ranks' cells.
#include "../mpm_tests.h"

#include <filesystem>

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out = root_output();
  for (const std::string basis : {"linear", "powell-sabin", "linear stop"})
    {
      const bool stop = basis == "linear stop";
      auto       solver =
        make_scene_solver("frictional_slope.prm",
                          {"Basis/Type=" + std::string(stop ? "linear" : basis),
                           "Time/End time=0.3",
                           "Output/Interval=0",
                           "Boundary conditions/Stop particles at walls=" +
                             std::string(stop ? "true" : "false")});
      const std::string dir = "run-" + std::string(stop ? "stop" : basis);
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
      if (stop)
        out << "  wall_stop_work " << statistics.column("wall_stop_work").back()
            << std::endl;
      PSMPM_CHECK(out, statistics.column("friction_work").back() < 0);
    }
}
