// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Subsection Contact read by a run: bad input ends with exit code 2, a
// message naming the parameter file, the entry and its value, and no
// output: a pair naming a body the scene does not have, a negative
// coefficient, contact without two bodies, and the transfers and mass
// matrices contact does not support (Transfer/Scheme = usl, apic with
// Transfer/FLIP fraction = 0.5, Mass matrix/Type = consistent,
// Transfer/Reconstruction = taylor least squares). The two-disk contact scene itself passes --validate.
#include "../app_tests.h"

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");
  const std::string head = small_bad_input_scene();
  const std::string bodies =
    "subsection Bodies\n set Number of bodies = 2\n"
    " subsection Body 1\n  set Shape = disk\n  set Center = 0.25, 0.25\n"
    "  set Radius = 0.15\n end\n"
    " subsection Body 2\n  set Shape = disk\n  set Center = 0.7, 0.7\n"
    "  set Radius = 0.15\n end\nend\n";
  const std::string contact =
    "subsection Contact\n set Type = multi-velocity\n";
  check_bad_input(out,
                  "pair naming a missing body",
                  head + bodies + contact +
                    " set Pair friction = 1-3: 0.2\nend\n",
                  {"Contact/Pair friction = 1-3: 0.2", "Body 3"});
  check_bad_input(out,
                  "negative coefficient",
                  head + bodies + contact +
                    " set Friction coefficient = -0.1\nend\n",
                  {"Contact/Friction coefficient = -0.1"});
  check_bad_input(out,
                  "negative pair coefficient",
                  head + bodies + contact +
                    " set Pair friction = 1-2: -1\nend\n",
                  {"Contact/Pair friction = 1-2: -1", "'-1'"});
  check_bad_input(out,
                  "one body",
                  head + contact + "end\n",
                  {"Contact/Type = multi-velocity", "two bodies"});
  check_bad_input(out,
                  "apic with FLIP",
                  head + bodies + contact +
                    "end\nsubsection Transfer\n set Scheme = apic\n"
                    " set FLIP fraction = 0.5\nend\n",
                  {"Contact/Type = multi-velocity",
                   "Transfer/FLIP fraction = 0.5"});
  check_bad_input(out,
                  "usl",
                  head + bodies + contact +
                    "end\nsubsection Transfer\n set Scheme = usl\nend\n",
                  {"Contact/Type = multi-velocity", "Transfer/Scheme = usl"});
  check_bad_input(out,
                  "consistent mass",
                  head + bodies + contact +
                    "end\nsubsection Mass matrix\n set Type = consistent\n"
                    "end\n",
                  {"Contact/Type = multi-velocity",
                   "Mass matrix/Type = consistent"});
  check_bad_input(out,
                  "reconstruction",
                  head + bodies + contact +
                    "end\nsubsection Transfer\n set Reconstruction = taylor "
                    "least squares\nend\n",
                  {"Contact/Type = multi-velocity",
                   "Transfer/Reconstruction = taylor least squares"});

  std::string screen, message;
  const int   code =
    run_app({std::string(PSMPM_SOURCE_DIR) + "/prm/contact_two_disks.prm",
             "--validate"},
            screen,
            message);
  out << "two-disk contact scene: exit code " << code << std::endl;
  PSMPM_CHECK(out, code == 0);
}
