// Checkpoint and resume are bit-identical in serial: a run of N steps
// with Checkpoint/Interval = k keeps its last two checkpoints; a copy of
// its output directory without the last one is what a run killed after
// the checkpoint of step N - k leaves (statistics rows, VTU outputs and
// tracked history beyond it). `--resume` continues from there and must
// reproduce statistics.txt (but for the wall_time column), the .pvd
// series, tracked_particle.txt and every entry of the final checkpoint
// (particles, time, step, dt and the history of every component) bit for
// bit.
//
// Two scenes: (a) the vibrating bar (consistent mass, musl) with the
// ULFEM reference (advanced alongside the run: replayed on resume), a
// tracked particle, error norms every 3 steps and an output time interval;
// (b) a neo-Hookean block slumping over empty cells with the automatic
// time step, apic and the extrapolate mass strategy (whose hysteresis is
// part of the checkpoint); (c) the 1D bar with the OTM scheme, whose moved
// grid is part of the checkpoint.
#include "../checkpoint_tests.h"


int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");

  check_resume(out,
               "bar",
               {"--set",
                "Time/End time=0.0006",
                "--set",
                "Reference solution/Type=vibrating bar ulfem",
                "--set",
                "Reference solution/ULFEM elements=200",
                "--set",
                "Output/Tracked point=12.5, 1",
                "--set",
                "Output/Error interval=3",
                "--set",
                "Output/Time interval=0.00007",
                "--set",
                "Checkpoint/Interval=20"});

  check_resume(out, "block", {"--set", "Geometry/Length=3",
                              "--set", "Geometry/Height=1.5",
                              "--set", "Mesh/Blocks x=6",
                              "--set", "Mesh/Blocks y=3",
                              "--set", "Material/Model=neo-hookean",
                              "--set", "Material/Density=1000",
                              "--set", "Material/Young's modulus=2e4",
                              "--set", "Material/Poisson's ratio=0.3",
                              "--set", "Particles/Per block x=3",
                              "--set", "Particles/Per block y=3",
                              "--set", "Particles/Region=0, 0, 1, 1",
                              "--set", "Initial conditions/Velocity=0; 0",
                              "--set", "Body force/Gravity=0, -9.81",
                              "--set", "Boundary conditions/Fixed x=left",
                              "--set", "Boundary conditions/Fixed y=bottom",
                              "--set", "Reference solution/Type=none",
                              "--set", "Time/End time=0.3",
                              "--set", "Time/Time step=0",
                              "--set", "Mass matrix/Type=extrapolate",
                              "--set", "Transfer/Scheme=apic",
                              "--set", "Output/Interval=4",
                              "--set", "Checkpoint/Interval=5"});

  // (c) OTM: the moved grid and the last nodal velocity are the scheme's
  // own state (TransferScheme::save/load).
  check_resume(out,
               "otm",
               {std::string(PSMPM_SOURCE_DIR) + "/prm/otm_bar_1d.prm",
                "--set",
                "Time/End time=0.003",
                "--set",
                "Output/Interval=10",
                "--set",
                "Checkpoint/Interval=10"});
}
