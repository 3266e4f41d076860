// Every stability monitor stops a run built to trip it: status
// "unstable" with the reason in summary.json and exit code 3.
#include "../app_tests.h"

#include <filesystem>
#include <sstream>

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");
  const std::vector<std::string>   free = {"Boundary conditions/Fixed x=",
                                           "Boundary conditions/Fixed y=",
                                           "Reference solution/Type=none"};
  struct Case
  {
    std::string              name;
    std::vector<std::string> sets;
    std::string              reason;
    int                      code;
  };
  std::vector<Case> cases = {
    {"non-finite values",
     // Finite velocities (a non-finite one is bad input) whose kinetic
     // energy overflows.
     {"Initial conditions/Velocity=1e200*sin(pi*x/25); 0"},
     "non-finite",
     psmpm::App::unstable},
    {"particle leaving the mesh",
     {"Initial conditions/Velocity=0; -20",
      "Mass matrix/Type=lumped",
      "Time/End time=0.5",
      "Time/Time step=1e-3"},
     "left the mesh",
     psmpm::App::unstable_left_mesh},
    {"non-positive volume",
     {"Initial conditions/Velocity=-500*(x-12.5); -500*(y-1)",
      "Mass matrix/Type=lumped",
      "Material/Young's modulus=1e-6",
      "Time/Time step=1e-2",
      "Time/End time=0.05"},
     "non-positive particle volume",
     psmpm::App::unstable_volume},
    {"solver not converging",
     {"Mass matrix/Maximum iterations=1",
      "Mass matrix/Solver tolerance=1e-14",
      "Mass matrix/Direct solver size=0"},
     "did not converge",
     psmpm::App::unstable_solver},
    {"energy growth",
     {"Geometry/Length=4",
      "Geometry/Height=10",
      "Mesh/Blocks x=4",
      "Mesh/Blocks y=10",
      "Particles/Per block x=3",
      "Particles/Per block y=3",
      "Particles/Region=1, 6, 3, 9.5",
      "Initial conditions/Velocity=0; 0",
      "Body force/Gravity=0, -9.81",
      "Material/Young's modulus=1e4",
      "Time/Time step=1e-3",
      "Time/End time=0.8"},
     "total energy grew",
     psmpm::App::unstable_energy}};
  for (auto &c : cases)
    {
      if (c.name != "solver not converging")
        c.sets.insert(c.sets.end(), free.begin(), free.end());
      std::vector<std::string> args = {"--set",
                                       "Output directory=run",
                                       "--set",
                                       "Output/Test output=true"};
      for (const auto &s : c.sets)
        args.insert(args.end(), {"--set", s});
      std::filesystem::remove_all("run");
      std::string       screen, errors;
      const int         code    = run_app(args, screen, errors);
      const std::string summary = read_file("run/summary.json");
      out << c.name << ": exit code " << code << std::endl;
      PSMPM_CHECK(out, code == c.code);
      PSMPM_CHECK(out,
                  summary.find("\"status\": \"unstable\"") !=
                    std::string::npos);
      const bool named = summary.find(c.reason) != std::string::npos;
      PSMPM_CHECK(out, named);
      if (!named)
        out << summary;
    }
}
