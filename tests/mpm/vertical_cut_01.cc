// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// The vertical cut in undrained clay of prm/vertical_cut.prm (Tresca,
// H = 1 m, geostatic start with K0 = 1, E = 750 c_u) on a coarser mesh (12
// criss-cross blocks over H) for 1 s = 3.1 sqrt(H/g), linear basis with
// the lumped mass matrix: at H = 0.7 H_c (c_u = rho g H / (3.78 0.7)) the
// cut stands, at H = 1.3 H_c it collapses (H_c = 3.78 c_u / (rho g)).
// u_top is the horizontal displacement of the particle that starts
// nearest the top of the face (2, 1), over H; late the growth of the
// soil's largest x (statistics' body1_x_max) from T/2 to T, over H; D the
// plastic dissipation over rho g H^3. Measured: 0.7 H_c: u_top = 0.0028,
// late = 2e-5, D = 0.0011; 1.3 H_c: u_top = 0.17, D = 0.11; the total
// energy (with the dissipation) changes by 2e-6 and 5e-5 rho g H^3.
#include "../mpm_tests.h"

#include <filesystem>

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");
  const double      rho = 2000, g = 9.81, H = 1, gamma_h3 = rho * g * H * H * H;
  for (const double ratio : {0.7, 1.3})
    {
      const double c_u = rho * g * H / (3.78 * ratio);
      auto         solver =
        make_scene_solver("vertical_cut.prm",
                          {"Mesh/Blocks x=42",
                           "Mesh/Blocks y=15",
                           "Material/Cohesion=" + std::to_string(c_u),
                           "Material/Young's modulus=" +
                             std::to_string(750 * c_u),
                           "Time/End time=1",
                           "Output/Interval=0"});
      const auto &p   = solver->get_particles();
      std::size_t top = 0;
      for (std::size_t i = 0; i < p.size(); ++i)
        if (p.initial_position[i].distance(Point<2>(2, 1)) <
            p.initial_position[top].distance(Point<2>(2, 1)))
          top = i;
      const std::string dir = "run-" + std::to_string(ratio).substr(0, 3);
      std::filesystem::create_directories(dir);
      const auto status = solver->run(dir);
      out << "H/H_c = " << ratio << ": "
          << psmpm::Simulator::status_name(status) << std::endl;
      PSMPM_CHECK(out, status == psmpm::Simulator::Status::completed);
      const double          u_top = p.displacement[top][0] / H;
      const StatisticsTable statistics(dir);
      const auto            front      = statistics.column("body1_x_max");
      const auto            dissipated = statistics.column("dissipated_energy");
      const auto            energy     = statistics.column("total_energy");
      PSMPM_CHECK(out, front.size() > 10 && dissipated.size() == front.size());
      const double late = (front.back() - front[front.size() / 2]) / H;
      const double D    = dissipated.back() / gamma_h3;
      std::cout << "H/H_c = " << ratio << ": u_top = " << u_top
                << ", late front motion = " << late << ", D = " << D
                << ", energy drift = "
                << (energy.back() - energy.front()) / gamma_h3 << std::endl;
      if (ratio < 1)
        {
          // Stands: the face top moves well below 1 % of H, and no longer.
          PSMPM_CHECK(out, std::abs(u_top) < 0.01);
          PSMPM_CHECK(out, std::abs(late) < 0.003);
          PSMPM_CHECK(out, D < 0.01);
        }
      else
        {
          // Collapses: the face top moves out by more than 5 % of H.
          PSMPM_CHECK(out, u_top > 0.05);
          PSMPM_CHECK(out, D > 0.02);
        }
      PSMPM_CHECK(out,
                  std::abs(energy.back() - energy.front()) < 1e-3 * gamma_h3);
    }
}
