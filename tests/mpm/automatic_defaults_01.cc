// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// What `Mass matrix/Type = automatic` and `Transfer/Scheme = automatic`
// resolve to (doc/transfers.md "Defaults"), both bases:
// * a closed mesh (every boundary's normal velocity fixed) that the
//   particles fill: partially lumped mass with MUSL;
// * the same mesh with its top open, or filled only in part (Region),
//   or with Bodies: the space's choice (P1: ghost penalty with MUSL;
//   Powell-Sabin: lumped mass with APIC); a Region containing the whole
//   mesh still fills it;
// * a Gmsh mesh closed by its physical boundaries: partially lumped;
// * explicit choices are kept (a given transfer with automatic mass, a
//   given mass with automatic transfer); with OTM (the grid moves) P1
//   takes partially lumped mass (the ghost penalty needs fixed cells).
#include "../mpm_tests.h"

namespace
{
  void
  check(std::ofstream                  &out,
        const std::string              &label,
        const std::string              &scene,
        std::vector<std::string>        overrides,
        const std::vector<std::string> &expected)
  {
    for (unsigned int b = 0; b < 2; ++b)
      {
        const std::string basis = b == 0 ? "linear" : "powell-sabin";
        if (expected[2 * b].empty())
          continue;
        auto o = overrides;
        o.insert(o.begin(),
                 {"Basis/Type=" + basis,
                  "Mass matrix/Type=automatic",
                  "Transfer/Scheme=automatic"});
        // Later entries override the defaults above.
        const auto        solver   = make_scene_solver(scene, o);
        const std::string mass     = solver->get_mass_matrix_name();
        const std::string transfer = solver->get_transfer_name();
        out << label << ", " << basis << ": " << mass << ", " << transfer
            << std::endl;
        PSMPM_CHECK(out, mass == expected[2 * b]);
        PSMPM_CHECK(out, transfer == expected[2 * b + 1]);
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");
  const std::vector<std::string>   closed = {"partially lumped",
                                             "musl",
                                             "partially lumped",
                                             "musl"};
  const std::vector<std::string>   free   = {"ghost penalty",
                                             "musl",
                                             "lumped",
                                             "apic"};
  const std::string                bar    = "vibrating_bar_small_ps.prm";
  check(out, "closed bar", bar, {"Output/Interval=0"}, closed);
  check(out,
        "bar, top open",
        bar,
        {"Boundary conditions/Fixed y=left, right, bottom"},
        free);
  check(out,
        "bar, top fixed in x only",
        bar,
        {"Boundary conditions/Fixed x=left, right, top",
         "Boundary conditions/Fixed y=left, right, bottom"},
        free);
  check(out,
        "closed bar, half filled",
        bar,
        {"Particles/Region=0, 0, 12.5, 2"},
        free);
  check(out,
        "closed bar, Region containing the mesh",
        bar,
        {"Particles/Region=-1, -1, 30, 3"},
        closed);
  check(out,
        "closed bar, mass given",
        bar,
        {"Mass matrix/Type=consistent"},
        {"consistent", "musl", "consistent", "musl"});
  check(out,
        "closed bar, transfer given",
        bar,
        {"Transfer/Scheme=apic"},
        {"partially lumped", "apic", "partially lumped", "apic"});
  check(out,
        "open bar, mass given",
        bar,
        {"Boundary conditions/Fixed y=left, right, bottom",
         "Mass matrix/Type=lumped"},
        {"lumped", "musl", "lumped", "apic"});
  check(out,
        "closed bar, otm",
        bar,
        {"Transfer/Scheme=otm"},
        {"partially lumped", "otm", "", ""});
  check(out,
        "open bar, otm",
        bar,
        {"Boundary conditions/Fixed y=left, right, bottom",
         "Transfer/Scheme=otm"},
        {"partially lumped", "otm", "", ""});
  check(out,
        "closed Gmsh sliver mesh",
        "sliver_mesh_bar.prm",
        {"Mesh/File=" + std::string(PSMPM_SOURCE_DIR) +
         "/prm/meshes/sliver_bar.msh"},
        closed);
  check(out, "two disks (Bodies, open)", "two_disks.prm", {}, free);
  check(out,
        "two disks in a closed box",
        "two_disks.prm",
        {"Boundary conditions/Fixed x=left, right",
         "Boundary conditions/Fixed y=bottom, top"},
        free);
}
