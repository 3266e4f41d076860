// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// The 20-step stress error of the bar of Wobbes et al. (2019)
// (prm/otm_bar_1d.prm) with otm, the paper's MPM (usl) and psmpm's musl:
// * psmpm's definition, the RMS over the particles of sigma_p minus the
//   exact stress at the particle's initial position after 20 steps: 6.41
//   for all three, otm lowest (by 0.002);
// * the definition that reproduces the paper's 3.8684 (OTM) and 3.8693
//   (MPM) within 2 %: the same RMS, but over all particles AND the
//   steps 1 to 20 (doc/otm.md): otm 3.836, usl 3.837.
#include "otm_tests.h"

#include <map>

using psmpm::Simulator::Simulator;

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");
  const std::string                scene     = "prm/otm_bar_1d.prm";
  const double                     paper_otm = 3.8684, paper_mpm = 3.8693;
  std::map<std::string, std::pair<double, double>> errors;
  for (const std::string scheme : {"otm", "usl", "musl"})
    {
      auto   solver = make_simulator<1>(scene, {"Transfer/Scheme=" + scheme});
      auto   reference     = make_reference<1>(scene, *solver);
      double sum_over_time = 0;
      for (unsigned int k = 1; k <= 20; ++k)
        {
          solver->do_time_step(1e-4);
          const double e = stress_rms(*solver, *reference);
          sum_over_time += e * e;
        }
      errors[scheme] = {stress_rms(*solver, *reference),
                        std::sqrt(sum_over_time / 20)};
      out << std::fixed << std::setprecision(3) << scheme
          << ": stress RMS after 20 steps " << errors[scheme].first
          << ", over steps 1-20 " << errors[scheme].second << std::endl;
    }
  const auto &otm = errors["otm"], &usl = errors["usl"];
  PSMPM_CHECK(out, std::abs(otm.first - 6.41) < 0.01);
  PSMPM_CHECK(out, otm.first < usl.first && usl.first - otm.first < 0.005);
  PSMPM_CHECK(out, std::abs(otm.second - paper_otm) < 0.02 * paper_otm);
  PSMPM_CHECK(out, std::abs(usl.second - paper_mpm) < 0.02 * paper_mpm);
  // The paper's difference, 0.0009, with the paper's sign.
  PSMPM_CHECK(out, std::abs((usl.second - otm.second) - 0.0009) < 0.0003);
}
