// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Bodies/Body k/Motion = prescribed read by a run: bad input ends with
// exit code 2, a message naming the parameter file, the entry and its
// value, and no output: a velocity that does not parse, one with an
// unknown variable, one with too few components, a driven body without
// Contact/Type = multi-velocity, every body driven, Motion not one of
// its choices and Contact/Driven body nodes not one of its choices.
// prm/strip_footing_body.prm itself passes --validate.
#include "../app_tests.h"

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");
  const std::string head = small_bad_input_scene();

  const auto bodies = [](const std::string &motion_1,
                         const std::string &motion_2) {
    return "subsection Bodies\n set Number of bodies = 2\n"
           " subsection Body 1\n  set Shape = rectangle\n"
           "  set Corners = 0, 0, 1, 0.5\n" +
           motion_1 +
           " end\n"
           " subsection Body 2\n  set Shape = rectangle\n"
           "  set Corners = 0.3, 0.5, 0.7, 0.7\n" +
           motion_2 + " end\nend\n";
  };
  const std::string driven =
    "  set Motion = prescribed\n  set Velocity = 0; -0.1*min(t/0.1, 1)\n";
  const std::string contact =
    "subsection Contact\n set Type = multi-velocity\nend\n";
  check_bad_input(out,
                  "velocity that does not parse",
                  head + contact +
                    bodies("",
                           "  set Motion = prescribed\n"
                           "  set Velocity = 0; -0.1*min(t/0.1, 1\n"),
                  {"Bodies/Body 2/Velocity = 0; -0.1*min(t/0.1, 1",
                   "not a function of t"});
  check_bad_input(out,
                  "unknown variable",
                  head + contact +
                    bodies("",
                           "  set Motion = prescribed\n"
                           "  set Velocity = 0; -y\n"),
                  {"Bodies/Body 2/Velocity = 0; -y", "not a function of t"});
  check_bad_input(out,
                  "one component",
                  head + contact +
                    bodies("",
                           "  set Motion = prescribed\n"
                           "  set Velocity = -0.1\n"),
                  {"Bodies/Body 2/Velocity = -0.1", "2 expression(s)"});
  check_bad_input(out,
                  "driven body without contact",
                  head + bodies("", driven),
                  {"Bodies/Body 2/Motion = prescribed",
                   "Contact/Type = multi-velocity"});
  check_bad_input(out,
                  "every body driven",
                  head + contact + bodies(driven, driven),
                  {"Motion = prescribed for every body",
                   "Bodies/Number of bodies = 2"});
  check_bad_input(out,
                  "motion not a choice",
                  head + contact + bodies("", "  set Motion = rigid\n"),
                  {"Motion", "rigid"});
  check_bad_input(out,
                  "driven body nodes not a choice",
                  head +
                    "subsection Contact\n set Type = multi-velocity\n"
                    " set Driven body nodes = vertices\nend\n" +
                    bodies("", driven),
                  {"Driven body nodes", "vertices"});

  std::string screen, message;
  const int   code =
    run_app({std::string(PSMPM_SOURCE_DIR) + "/prm/strip_footing_body.prm",
             "--validate"},
            screen,
            message);
  out << "strip footing body scene: exit code " << code << std::endl;
  PSMPM_CHECK(out, code == 0);
}
