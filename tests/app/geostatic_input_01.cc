// Bad Initial conditions/Stress input ends with exit code 2 and a message
// naming the entry and the value: a geostatic stress for a neo-Hookean
// material (its stress follows from the deformation gradient), a malformed
// Stress function, K0 <= 0 or not a number, geostatic without gravity.
// Nothing is written.
#include "../app_tests.h"

#include <filesystem>

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");
  const std::string head = "set Output directory = bad_output\n"
                           "subsection Body force\n set Gravity = 0, -9.81\n"
                           "end\n";

  const std::vector<BadInputCase> cases = {
    {"geostatic with neo-hookean",
     head + "subsection Material\n set Model = neo-hookean\nend\n"
            "subsection Initial conditions\n set Stress = geostatic\nend\n",
     {"Initial conditions/Stress = geostatic", "Material/Model = neo-hookean"}},
    {"function with neo-hookean",
     head + "subsection Material\n set Model = neo-hookean\nend\n"
            "subsection Initial conditions\n set Stress = function\nend\n",
     {"Initial conditions/Stress = function", "neo-hookean"}},
    {"malformed function",
     head + "subsection Initial conditions\n set Stress = function\n"
            " set Stress function = -1e4*(2-y; 0; 0; 0\nend\n",
     {"Initial conditions/Stress function", "-1e4*(2-y"}},
    {"too few expressions",
     head + "subsection Initial conditions\n set Stress = function\n"
            " set Stress function = 0; 0\nend\n",
     {"Initial conditions/Stress function", "sxx; syy; sxy; szz"}},
    {"K0 zero",
     head + "subsection Initial conditions\n set Stress = geostatic\n"
            " set K0 = 0\nend\n",
     {"Initial conditions/K0 = 0", "> 0"}},
    {"K0 negative",
     head + "subsection Initial conditions\n set Stress = geostatic\n"
            " set K0 = -0.5\nend\n",
     {"Initial conditions/K0 = -0.5"}},
    {"K0 not a number",
     head + "subsection Initial conditions\n set Stress = geostatic\n"
            " set K0 = half\nend\n",
     {"Initial conditions/K0 = half"}},
    {"geostatic without gravity",
     "set Output directory = bad_output\n"
     "subsection Initial conditions\n set Stress = geostatic\nend\n",
     {"Initial conditions/Stress = geostatic", "Body force/Gravity"}},
  };
  check_bad_inputs(out, cases);
}
