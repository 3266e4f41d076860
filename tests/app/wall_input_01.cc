// Bad Boundary conditions input for walls and loaded boundaries ends with
// exit code 2 and a message naming the entry and the value: a negative or
// non-numeric friction coefficient, an unknown boundary name in Friction
// coefficient, Prescribed velocity and Boundary parts, friction on a
// boundary without a fixed normal velocity, a prescribed velocity with the
// wrong number of components or with a mass matrix, a boundary part that
// holds no face. Nothing is written.
#include "../app_tests.h"

#include <filesystem>

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");
  const std::string head = "set Output directory = bad_output\n"
                           "subsection Time\n set End time = 1e-4\nend\n"
                           "subsection Boundary conditions\n";

  const std::vector<BadInputCase> cases = {
    {"negative mu",
     head + " set Friction coefficient = bottom: -0.3\nend\n",
     {"Boundary conditions/Friction coefficient = bottom: -0.3",
      "-0.3",
      ">= 0"}},
    {"mu not a number",
     head + " set Friction coefficient = bottom: rough\nend\n",
     {"Boundary conditions/Friction coefficient", "rough"}},
    {"unknown friction boundary",
     head + " set Friction coefficient = floor: 0.3\nend\n",
     {"Boundary conditions/Friction coefficient", "floor", "bottom"}},
    {"friction without fixed normal",
     head + " set Fixed y = left, right\n"
            " set Friction coefficient = bottom: 0.3\nend\n",
     {"Boundary conditions/Friction coefficient", "bottom", "Fixed x"}},
    {"unknown prescribed boundary",
     head + " set Prescribed velocity = footing: 0; -1e-3\nend\n",
     {"Boundary conditions/Prescribed velocity", "footing"}},
    {"prescribed with one component",
     head + " set Prescribed velocity = top: -1e-3\nend\n",
     {"Boundary conditions/Prescribed velocity = top: -1e-3", "';'"}},
    {"prescribed with an unknown variable",
     head + " set Prescribed velocity = top: 0; -q*t\nend\n",
     {"Boundary conditions/Prescribed velocity", "not a function of t"}},
    {"prescribed with a mass matrix",
     head + " set Prescribed velocity = top: 0; -1e-3\nend\n"
            "subsection Mass matrix\n set Type = consistent\nend\n",
     {"Boundary conditions/Prescribed velocity",
      "Mass matrix/Type = lumped",
      "consistent"}},
    {"unknown parent of a part",
     head + " set Boundary parts = footing: roof, 0, 1\nend\n",
     {"Boundary conditions/Boundary parts", "footing", "roof"}},
    {"empty part",
     head + " set Boundary parts = footing: top, 100, 200\nend\n",
     {"Boundary conditions/Boundary parts", "footing", "[100, 200]"}},
  };
  check_bad_inputs(out, cases);
}
