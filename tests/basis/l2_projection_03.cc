// ---------------------------------------------------------------------
// psmpm: the scene's parameters: defaults, a valid basis function entry,
// and bad entries rejected with a message that names the entry.
// ---------------------------------------------------------------------
#include <deal.II/base/parameter_handler.h>

#include <psmpm/solver/l2_projection.h>

#include "../tests.h"

int
main()
{
  return run_test([]() {
    std::ofstream out("output");
    using namespace psmpm;

    const auto parse = [&out](const std::string &input) {
      ParameterHandler prm;
      Solver::L2Projection::declare_parameters(prm);
      prm.parse_input_from_string(input);
      Solver::L2Projection projection;
      try
        {
          projection.parse_parameters(prm);
          out << "function '" << projection.function_expression << "', lumped "
              << projection.lumped << ", basis function ";
          if (projection.output_basis_vertex == numbers::invalid_unsigned_int)
            out << "none" << std::endl;
          else
            out << projection.output_basis_vertex << ", "
                << projection.output_basis_function << std::endl;
        }
      catch (const std::exception &e)
        {
          const std::string what = e.what();
          // Print only the message line that names the entry.
          const auto begin = what.find("Projection/") != std::string::npos ?
                               what.find("Projection/") :
                               what.find("Output/");
          out << "error: "
              << (begin == std::string::npos ?
                    std::string("(no entry named)") :
                    what.substr(begin, what.find(':', begin) - begin))
              << std::endl;
        }
    };
    parse("");
    parse("subsection Projection\n set Lumped = true\n end\n"
          "subsection Output\n set Basis function = 4, 1\n end\n");
    parse("subsection Projection\n set Function = x*y + cos(pi*x)\n end\n");
    parse("subsection Projection\n set Function = sin(pi*x\n end\n");
    parse("subsection Output\n set Basis function = four\n end\n");
  });
}
