// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// A completed run resumed with a later Time/End time is bit-identical to
// a run that had the later End time from the start. The completed run's
// last step was cut to land on its End time (or its time snapped to it);
// its final checkpoint also holds the state before that step, from which
// the resumed run takes the full step. Compared: statistics.txt (but for
// wall_time), the .pvd series, every VTU file (and no stale one of the cut
// step), tracked_particle.txt, summary.json (but for timings and the
// resume keys) and every entry of the final checkpoint.
//
// (a) The linear bar with a fixed step, End time half a step past a
// multiple of it (the last step cut to half), with a tracked particle and
// outputs every 4 steps, so that the cut step's output must go; (b) the
// same with End time a multiple of the step (the time snapped to it);
// (c) two Powell-Sabin disks with the automatic time step.
#include "../checkpoint_tests.h"


int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");

  const std::vector<std::string> bar = {"--set",
                                        "Time/Time step=1e-5",
                                        "--set",
                                        "Output/Interval=4",
                                        "--set",
                                        "Output/Tracked point=12.5, 1"};
  check_extended_resume(out, "bar_cut", bar, "0.000105", "0.0002");
  check_extended_resume(out, "bar_snapped", bar, "0.0001", "0.0002");

  check_extended_resume(out,
                        "disks_ps",
                        {std::string(PSMPM_SOURCE_DIR) + "/prm/two_disks.prm",
                         "--set",
                         "Basis/Type=powell-sabin",
                         "--set",
                         "Mesh/Blocks x=8",
                         "--set",
                         "Mesh/Blocks y=8",
                         "--set",
                         "Particles/Per block x=3",
                         "--set",
                         "Particles/Per block y=3",
                         "--set",
                         "Output/Interval=4"},
                        "0.3",
                        "0.6");
}
