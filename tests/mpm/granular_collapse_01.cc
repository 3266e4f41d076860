// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// The granular column collapse of prm/granular_column_collapse.prm
// (aluminium rods, Mohr-Coulomb phi 19.8 deg, psi 0, c 0, geostatic
// start, frictional floor mu 0.36; Powell-Sabin, lumped mass, MUSL) at
// aspect ratio a = h0/d0 = 2 on a coarse mesh (10 criss-cross blocks
// over h0) for 2.4 s = 12 sqrt(h0/g):
// * the energy books close: kinetic + strain + gravity + dissipated
//   energy minus the floor's friction work stays at its initial value
//   within 1 % of the released gravitational energy (measured -0.5 %);
// * final height and run-out against the laws of Nguyen, Bui and
//   Fukagawa for 2D aluminium-rod columns, h0/h_inf = 1.42 a^(2/3) and
//   (d_inf - d0)/d0 = 3.80 a^0.73: measured h_inf/h0 = 0.398 (law 0.444,
//   -10 %) and 7.10 (law 6.30, +13 %); asserted within 15 % and 20 %
//   (the finer meshes of doc/geomechanics.md: -8 % and +15 %).
#include "../mpm_tests.h"

#include <filesystem>

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");
  const double      d0 = 0.2, a = 2, h0 = a * d0, h = h0 / 10;
  auto              solver =
    make_scene_solver("granular_column_collapse.prm",
                      {"Geometry/Length=" + std::to_string(55 * h),
                       "Geometry/Height=" + std::to_string(15 * h),
                       "Mesh/Blocks x=55",
                       "Mesh/Blocks y=15",
                       "Bodies/Body 1/Corners=0, 0, " + std::to_string(d0) +
                         ", " + std::to_string(h0),
                       "Time/End time=2.4",
                       "Output/Interval=0"});
  std::filesystem::create_directories("run");
  const auto status = solver->run("run");
  out << "a = 2: " << psmpm::Simulator::status_name(status) << std::endl;
  PSMPM_CHECK(out, status == psmpm::Simulator::Status::completed);

  const StatisticsTable statistics("run");
  const auto            total    = statistics.column("total_energy");
  const auto            friction = statistics.column("friction_work");
  const auto            gravity  = statistics.column("gravity_energy");
  const auto            x_max    = statistics.column("body1_x_max");
  const auto            y_max    = statistics.column("body1_y_max");
  const double          released = -gravity.back();
  const double          balance =
    (total.back() - friction.back() - total.front()) / released;
  const double height_law = 1 / (1.42 * std::pow(a, 2. / 3));
  const double runout_law = 3.80 * std::pow(a, 0.73);
  const double height     = y_max.back() / h0;
  const double runout     = (x_max.back() - d0) / d0;
  std::cout << "energy balance " << balance << ", h_inf/h0 " << height
            << " (law " << height_law << "), run-out " << runout << " (law "
            << runout_law << ")" << std::endl;
  PSMPM_CHECK(out, released > 0 && std::abs(balance) < 0.01);
  PSMPM_CHECK(out, friction.back() < 0);
  PSMPM_CHECK(out, std::abs(height / height_law - 1) < 0.15);
  PSMPM_CHECK(out, std::abs(runout / runout_law - 1) < 0.20);
}
