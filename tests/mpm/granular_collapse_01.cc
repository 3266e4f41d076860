// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// The granular column collapse of prm/granular_column_collapse.prm
// (aluminium rods, Mohr-Coulomb phi 19.8 deg, psi 0, c 0, geostatic
// start, rough floor, 6 x 5 particles per block, Disconnected volume
// ratio 2, MUSL, lumped mass) against the laws of Nguyen, Bui and
// Fukagawa for 2D aluminium-rod columns, h0/h_inf = 1.42 a^(2/3) and
// (d_inf - d0)/d0 = 3.80 a^0.73 (a > 1.5), the run-out measured at the
// deposit's front (body1_x_front, gap one cell), to 12 sqrt(h0/g):
// * Powell-Sabin, a = 4 on 20 cells over h0 (the scene's resolution):
//   within 10 % of both laws (measured +6 % and -1 %);
// * the linear basis, a = 2 on 10 cells over h0: within 10 % of both
//   laws (measured +1 % and -2 %);
// * both: the energy books close (kinetic + strain + gravity + dissipated
//   energy minus the floor's friction work stays at its initial value
//   within 1 % of the released gravitational energy; measured -0.8 %),
//   the floor's friction does negative work, and the front particle
//   (body1_x_max) lies at or beyond the deposit's front.
#include "../mpm_tests.h"

#include <filesystem>

namespace
{
  void
  collapse(std::ofstream     &out,
           const std::string &basis,
           const double       a,
           const unsigned int cells)
  {
    const double       d0 = 0.2, h0 = a * d0, h = h0 / cells;
    const double       runout_law = 3.80 * std::pow(a, 0.73);
    const double       height_law = 1 / (1.42 * std::pow(a, 2. / 3));
    const unsigned int nx = std::ceil((d0 * (1 + 1.5 * runout_law) + 0.05) / h);
    const unsigned int ny = std::ceil(1.5 * h0 / h);
    const std::string  run = "run-" + basis;
    auto               solver =
      make_scene_solver("granular_column_collapse.prm",
                        {"Basis/Type=" + basis,
                         "Geometry/Length=" + std::to_string(nx * h),
                         "Geometry/Height=" + std::to_string(ny * h),
                         "Mesh/Blocks x=" + std::to_string(nx),
                         "Mesh/Blocks y=" + std::to_string(ny),
                         "Bodies/Body 1/Corners=0, 0, " + std::to_string(d0) +
                           ", " + std::to_string(h0),
                         "Time/End time=" +
                           std::to_string(12 * std::sqrt(h0 / 9.81)),
                         "Output/Deposit front gap=" + std::to_string(h),
                         "Output/Interval=0"});
    std::filesystem::create_directories(run);
    const auto status = solver->run(run);
    out << basis << ", a = " << a << ", " << cells
        << " cells over h0: " << psmpm::Simulator::status_name(status)
        << std::endl;
    PSMPM_CHECK(out, status == psmpm::Simulator::Status::completed);

    const StatisticsTable statistics(run);
    const auto            friction = statistics.column("friction_work");
    const auto            x_max    = statistics.column("body1_x_max");
    const auto            x_front  = statistics.column("body1_x_front");
    const auto            y_max    = statistics.column("body1_y_max");
    const EnergyBooks     books(statistics);
    const double          released = books.released, balance = books.balance;
    const double          height = y_max.back() / h0;
    const double          runout = (x_front.back() - d0) / d0;
    std::cout << basis << ": energy balance " << balance << ", h_inf/h0 "
              << height << " (law " << height_law << "), run-out " << runout
              << " (law " << runout_law << "), front particle "
              << (x_max.back() - d0) / d0 << std::endl;
    PSMPM_CHECK(out, released > 0 && std::abs(balance) < 0.01);
    PSMPM_CHECK(out, friction.back() < 0);
    PSMPM_CHECK(out, x_max.back() >= x_front.back());
    PSMPM_CHECK(out, std::abs(height / height_law - 1) < 0.10);
    PSMPM_CHECK(out, std::abs(runout / runout_law - 1) < 0.10);
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");
  collapse(out, "powell-sabin", 4, 20);
  collapse(out, "linear", 2, 10);
}
