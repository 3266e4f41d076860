// A body of one particle flies freely: thrown sideways at 0.5 m/s under
// gravity across several cells of a criss-cross mesh, with each basis and
// its default mass matrix (P1: ghost penalty, whose lone-cell penalty
// keeps the particle mass matrix of a single particle regular;
// Powell-Sabin: lumped). The run must complete, unstrained, at the
// position of the time integration's closed form: with the constant step
// dt, v_n = v_0 + g n dt and x_n = x_0 + v_0 t_n + g dt^2 n (n + 1) / 2.
#include "../checkpoint_tests.h"

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");
  const double      dt = 1e-3, g = -9.81, vx = 0.5;
  const unsigned    n = 250;
  for (const std::string basis : {"linear", "powell-sabin"})
    {
      std::filesystem::remove_all("run");
      const std::vector<std::string> sets = {
        "Output directory=run",
        "Output/Test output=true",
        "Geometry/Length=2",
        "Geometry/Height=2",
        "Mesh/Type=criss-cross",
        "Mesh/Blocks x=4",
        "Mesh/Blocks y=4",
        "Basis/Type=" + basis,
        "Material/Model=linear elastic",
        "Material/Density=1000",
        "Material/Young's modulus=1e5",
        "Particles/Per block x=2",
        "Particles/Per block y=2",
        // One of the block layout's points: (0.625, 1.625).
        "Particles/Region=0.6, 1.6, 0.7, 1.7",
        "Initial conditions/Velocity=0.5; 0",
        "Body force/Gravity=0, -9.81",
        "Boundary conditions/Fixed x=",
        "Boundary conditions/Fixed y=",
        "Reference solution/Type=none",
        "Mass matrix/Type=automatic",
        "Material/Poisson's ratio=0.3",
        "Time/Time step=1e-3",
        "Time/End time=0.25"};
      std::vector<std::string> args;
      for (const auto &s : sets)
        args.insert(args.end(), {"--set", s});
      std::string screen, errors;
      const int   code    = run_app(args, screen, errors);
      const auto  summary = read_file("run/summary.json");
      out << basis << ": exit code " << code << std::endl;
      PSMPM_CHECK(out, code == 0);
      PSMPM_CHECK(out,
                  summary.find("\"status\": \"completed\"") !=
                    std::string::npos);
      PSMPM_CHECK(out,
                  summary.find("\"n_particles\": 1,") != std::string::npos);
      const auto c = psmpm::Archive::read_hdf5(
        "run/" + psmpm::Simulator::Checkpoint::file_name(n));
      const auto   x          = c.get("particles/position");
      const auto   v          = c.get("particles/velocity");
      const auto   s          = c.get("particles/stress");
      const double t          = n * dt;
      const double x_exact[2] = {0.625 + vx * t,
                                 1.625 + g * dt * dt * n * (n + 1) / 2};
      const double v_exact[2] = {vx, g * t};
      double       error = 0, stress = 0;
      for (unsigned int d = 0; d < 2; ++d)
        error = std::max(
          {error, std::abs(x[d] - x_exact[d]), std::abs(v[d] - v_exact[d])});
      for (const double sigma : s)
        stress = std::max(stress, std::abs(sigma));
      out << basis << ": fell " << 1.625 - x_exact[1] << " m, moved "
          << x_exact[0] - 0.625 << " m" << std::endl;
      PSMPM_CHECK(out, x.size() == 2 && v.size() == 2);
      PSMPM_CHECK(out, error < 1e-12);
      PSMPM_CHECK(out, stress < 1e-9);
    }
}
