// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Checkpoint and resume are bit-identical with plastic state, frictional
// walls and prescribed boundaries (as checkpoint_01 for the elastic
// scenes): (a) the granular column collapse (Powell-Sabin, MUSL,
// Mohr-Coulomb from the geostatic stress, frictional floor: friction
// work accumulated across the resume); (b) the biaxial compression
// (linear, Drucker-Prager with softening, prescribed plates with their
// work, local damping).
#include "../checkpoint_tests.h"

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");
  const std::string prm = std::string(PSMPM_SOURCE_DIR) + "/prm/";

  check_resume(out,
               "collapse",
               {prm + "granular_column_collapse.prm",
                "--set",
                "Mesh/Blocks x=30",
                "--set",
                "Mesh/Blocks y=6",
                "--set",
                "Geometry/Length=0.6",
                "--set",
                "Geometry/Height=0.12",
                "--set",
                "Time/End time=0.03",
                "--set",
                "Output/Interval=25",
                "--set",
                "Checkpoint/Interval=20"});

  check_resume(out,
               "biaxial",
               {prm + "biaxial_compression.prm",
                "--set",
                "Material/Model=drucker-prager",
                "--set",
                "Material/Cohesion=2e4",
                "--set",
                "Material/Residual cohesion=0",
                "--set",
                "Material/Softening strain=0.01",
                "--set",
                "Boundary conditions/Local damping=0.1",
                "--set",
                "Time/End time=0.15",
                "--set",
                "Output/Interval=25",
                "--set",
                "Checkpoint/Interval=20"});
}
