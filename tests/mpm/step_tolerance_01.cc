// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Mass matrix/Step tolerance (a warm-started CG solve also ends once its
// residual has dropped by this factor from the guess'):
// (a) the closed vibrating bar of prm/vibrating_bar_large.prm on 32 x 2
//     blocks, partially lumped mass, every system through CG: the default
//     (1e-6) needs at most 0.75 of the CG iterations of Step tolerance = 0,
//     and its displacement and velocity errors against the ULFEM
//     reference agree with those of Step tolerance = 0 to 1e-6 relative;
// (b) the free spinning block of prm/rotating_block.prm, P1 with the
//     ghost penalty, every system through CG: no DoF is fixed, so the
//     step tolerance does not apply (exact solves conserve the angular
//     momentum to round-off): the same CG iterations and the same final
//     angular momentum, bit for bit, as Step tolerance = 0, and a change
//     of the angular momentum below 1e-13.
#include <psmpm/base/summary.h>

#include "../mpm_tests.h"

#include <filesystem>

namespace
{
  psmpm::Summary
  run(const std::string       &scene,
      std::vector<std::string> overrides,
      const std::string       &directory)
  {
    overrides.push_back("Output/Interval=0");
    auto solver = make_scene_solver<2>(scene, overrides);
    std::filesystem::create_directories(directory);
    const auto status = solver->run(directory);
    AssertThrow(status == psmpm::Simulator::Status::completed,
                ExcMessage(directory + " did not complete"));
    psmpm::Summary summary;
    solver->fill_summary(summary);
    return summary;
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");
  return run_test([&out]() {
    const std::vector<std::string> bar   = {"Mesh/Blocks x=32",
                                            "Mesh/Blocks y=2",
                                            "Particles/Per block x=4",
                                            "Particles/Per block y=4",
                                            "Time/End time=2",
                                            "Mass matrix/Type=partially lumped",
                                            "Mass matrix/Direct solver size=0"};
    auto                           tight = bar, loose = bar;
    tight.push_back("Mass matrix/Step tolerance=0");
    const auto   a0   = run("vibrating_bar_large.prm", tight, "bar-tight");
    const auto   a1   = run("vibrating_bar_large.prm", loose, "bar-default");
    const double its0 = a0.get_number("cg_iterations"),
                 its1 = a1.get_number("cg_iterations");
    out << "closed bar: CG iterations " << its0 << " -> " << its1 << std::endl;
    PSMPM_CHECK(out, its1 <= 0.75 * its0);
    for (const std::string e : {"displacement_L2", "velocity_L2_rms_over_time"})
      {
        const double e0 = a0.get_number("errors." + e),
                     e1 = a1.get_number("errors." + e);
        out << e << " " << std::setprecision(6) << e0 << std::endl;
        PSMPM_CHECK(out, std::abs(e1 / e0 - 1) < 1e-6);
      }

    const std::vector<std::string> block = {"Basis/Type=linear",
                                            "Mass matrix/Type=ghost penalty",
                                            "Transfer/Scheme=musl",
                                            "Mass matrix/Direct solver size=0",
                                            "Time/End time=0.1"};
    auto                           exact = block;
    exact.push_back("Mass matrix/Step tolerance=0");
    const auto b0 = run("rotating_block.prm", exact, "block-tight");
    const auto b1 = run("rotating_block.prm", block, "block-default");
    out << "free block: CG iterations " << b0.get_number("cg_iterations")
        << std::endl;
    PSMPM_CHECK(out, b0.get_number("cg_iterations") > 0);
    PSMPM_CHECK(out,
                b1.get_number("cg_iterations") ==
                  b0.get_number("cg_iterations"));
    PSMPM_CHECK(out,
                b1.get_number("angular_momentum_final") ==
                  b0.get_number("angular_momentum_final"));
    PSMPM_CHECK(out,
                std::abs(b1.get_number("angular_momentum_relative_change")) <
                  1e-13);
  });
}
