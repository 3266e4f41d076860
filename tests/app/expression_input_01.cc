// Hostile function expressions end with exit code 2 and a message that
// names the entry and its value, nothing written:
//  * an initial velocity that is not finite at some particles only (nan
//    beyond x = 0.5, the square root of a negative number) names its own
//    entry: Initial conditions/Velocity, or Bodies/Body k/Initial velocity
//    for the particles of body k, with the Function constants;
//  * a constant an expression uses, removed from Function constants;
//  * a component of a function of t (Boundary conditions/Prescribed
//    velocity) that is a variable of space, a syntax error, not finite
//    at t = 0 (0/0: without the check a run that stops mid-way as
//    unstable, output written), or one component too many;
//  * a Stress function with one component too few.
#include "../app_tests.h"

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");
  const std::string head = small_bad_input_scene();
  const auto        body = [&](const std::string &velocity) {
    return head +
           "subsection Bodies\n set Number of bodies = 1\n"
                  " subsection Body 1\n  set Shape = rectangle\n"
                  "  set Corners = 0, 0, 1, 0.5\n"
                  "  set Initial velocity = " +
           velocity + "\n end\nend\n";
  };
  const auto initial = [&](const std::string &entries) {
    return head + "subsection Initial conditions\n" + entries + "end\n";
  };
  const std::string walls =
    "set Output directory = bad_output\n"
    "subsection Time\n set End time = 1e-4\nend\n"
    "subsection Boundary conditions\n set Prescribed velocity = ";

  const std::vector<BadInputCase> cases = {
    {"body velocity nan beyond x = 0.5",
     body("x > 0.5 ? 0/0 : 0; 0"),
     {"Bodies/Body 1/Initial velocity = 'x > 0.5 ? 0/0 : 0; 0'",
      "Initial conditions/Function constants",
      "not finite"}},
    {"body velocity sqrt(0.5 - x)",
     body("0; sqrt(0.5-x)"),
     {"Bodies/Body 1/Initial velocity = '0; sqrt(0.5-x)'", "not finite"}},
    {"initial velocity sqrt(0.5 - x)",
     initial(" set Velocity = sqrt(0.5-x); 0\n"),
     {"Initial conditions/Velocity = 'sqrt(0.5-x); 0'", "not finite"}},
    {"constant removed",
     initial(" set Velocity = v0*sin(pi*x/L); 0\n"
             " set Function constants = v0=0.1\n"),
     {"Initial conditions/Velocity", "v0*sin(pi*x/L); 0", "L"}},
    {"prescribed velocity of x",
     walls + "top: 0; x\nend\n",
     {"Boundary conditions/Prescribed velocity = top: 0; x",
      "not a function of t"}},
    {"prescribed velocity syntax error",
     walls + "top: 0; sin(\nend\n",
     {"Boundary conditions/Prescribed velocity = top: 0; sin(",
      "not a function of t"}},
    {"prescribed velocity nan at t = 0",
     walls + "top: 0; 0/0\nend\n",
     {"Boundary conditions/Prescribed velocity = top: 0; 0/0",
      "component 2, '0/0', is nan at t = 0"}},
    {"prescribed velocity with three components",
     walls + "top: 0; 0; 0\nend\n",
     {"Boundary conditions/Prescribed velocity = top: 0; 0; 0", "';'"}},
    {"stress function with three components",
     initial(" set Stress = function\n set Stress function = 0; 0; 0\n") +
       "subsection Material\n set Model = hypoelastic\nend\n",
     {"Initial conditions/Stress function = '0; 0; 0'", "4 expressions"}},
  };
  check_bad_inputs(out, cases);
}
