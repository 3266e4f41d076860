// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Postprocess::StepSums: the per-step statistics that a run sums on the
// chunks of particles its transfer scheme updates are those of a pass over
// the particles after the step, to the bit. The spinning block of
// prm/rotating_block.prm with 12 x 12 particles per block (2,304 particles,
// five chunks of 512), its right half a body of another material (the
// particles are sorted by cell, so the runs of one material cross the
// chunk boundaries): after a run of ten
// steps, the final angular momentum (summary) equals a fresh pass on the
// final state, and the last row's energies equal the pass's to the
// printed digits. MUSL, USL and OTM sum on chunks; APIC and the P1 and
// Powell-Sabin bases alike.
#include <deal.II/base/mpi.h>

#include <psmpm/postprocess/energies.h>
#include <psmpm/postprocess/rotation_statistics.h>
#include <psmpm/base/summary.h>

#include "../mpm_tests.h"

#include <filesystem>


int
main(int argc, char **argv)
{
  using namespace psmpm;
  MPISession    mpi(argc, argv);
  std::ofstream out("output");
  for (const std::string scheme : {"musl", "usl", "otm", "apic"})
    for (const std::string basis : {"linear", "powell-sabin"})
      {
        if (scheme == "otm" && basis != "linear")
          continue; // OTM moves a P1 grid
        const std::string directory = "output-" + scheme + "-" + basis;
        auto              solver    = make_scene_solver<2>(
          "rotating_block.prm",
          {"Transfer/Scheme=" + scheme,
                           "Basis/Type=" + basis,
                           "Particles/Per block x=12",
                           "Particles/Per block y=12",
                           "Particles/Region=",
                           "Bodies/Number of bodies=2",
                           "Bodies/Body 1/Shape=rectangle",
                           "Bodies/Body 1/Corners=0.25, 0.25, 0.5, 0.75",
                           "Bodies/Body 1/Initial velocity=-(y - 0.5); x - 0.5",
                           "Bodies/Body 2/Shape=rectangle",
                           "Bodies/Body 2/Corners=0.5, 0.25, 0.75, 0.75",
                           "Bodies/Body 2/Initial velocity=-(y - 0.5); x - 0.5",
                           "Bodies/Body 2/Material=1",
                           "Materials/Material 1/Model=hypoelastic",
                           "Materials/Material 1/Density=1000",
                           "Materials/Material 1/Young's modulus=3e6",
                           "Time/Time step=2e-4",
                           "Time/End time=2e-3",
                           "Output/Interval=0"});
        std::filesystem::create_directories(directory);
        const auto           status = solver->run(directory);
        Summary summary;
        solver->fill_summary(summary);
        const auto  &state  = solver->get_state();
        const double chunks = summary.get_number("angular_momentum_final");
        Postprocess::RotationStatistics<2> rotation;
        const double                       pass =
          rotation.compute(state, scheme == "apic").angular_momentum;
        const Postprocess::Energies<2> e    = solver->compute_energies();
        const StatisticsTable          table(directory);
        const double kinetic = table.column("kinetic_energy").back();
        const double strain  = table.column("strain_energy").back();
        out << scheme << ", " << basis << ": " << state.particles.size()
            << " particles, angular momentum " << std::setprecision(6) << pass
            << std::endl;
        PSMPM_CHECK(out, status == Simulator::Status::completed);
        PSMPM_CHECK(out, state.particles.size() > 4 * 512);
        PSMPM_CHECK(out, chunks == pass);
        PSMPM_CHECK(out, std::abs(kinetic / e.kinetic - 1) < 1e-7);
        PSMPM_CHECK(out, std::abs(strain / e.strain - 1) < 1e-7);
        // The strain energies compared are not round-off (APIC's affine
        // transfer keeps the rigid rotation nearly strain-free).
        if (scheme != "apic")
          PSMPM_CHECK(out, e.strain > 1e-6 * e.kinetic);
      }
}
