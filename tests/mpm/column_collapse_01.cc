// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// The soft column of prm/column_collapse.prm, first 0.4 s, both bases with
// the defaults: the run completes, the mass is exact, the column slumps
// (height below 0.8 m) and runs out (front beyond 0.55 m; 0.479 m at the
// start), and the statistics' run-out and height columns (body1_x_max,
// body1_y_max of the last row) are the largest coordinates of the
// particles at the end.
#include "../mpm_tests.h"

#include <filesystem>

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");
  for (const std::string basis : {"linear", "powell-sabin"})
    {
      auto        solver = make_scene_solver("column_collapse.prm",
                                      {"Basis/Type=" + basis,
                                              "Time/End time=0.4",
                                              "Output/Interval=0"});
      const auto &p      = solver->get_particles();
      double      m0     = 0;
      for (const double m : p.mass)
        m0 += m;
      const std::string dir = "run-" + basis;
      std::filesystem::create_directories(dir);
      const auto status = solver->run(dir);
      out << basis << ": " << psmpm::Simulator::status_name(status)
          << std::endl;
      PSMPM_CHECK(out, status == psmpm::Simulator::Status::completed);
      double m = 0, x_max = -1e300, y_max = -1e300;
      for (std::size_t i = 0; i < p.size(); ++i)
        {
          m += p.mass[i];
          x_max = std::max(x_max, p.position[i][0]);
          y_max = std::max(y_max, p.position[i][1]);
        }
      PSMPM_CHECK(out, m == m0);
      PSMPM_CHECK(out, x_max > 0.55);
      PSMPM_CHECK(out, y_max < 0.8);
      const StatisticsTable statistics(dir);
      const auto            column = [&](const std::string &name) {
        const auto c = statistics.column(name);
        return c.empty() ? std::nan("") : c.back();
      };
      PSMPM_CHECK(out, std::abs(column("body1_x_max") - x_max) < 1e-7);
      PSMPM_CHECK(out, std::abs(column("body1_y_max") - y_max) < 1e-7);
    }
}
