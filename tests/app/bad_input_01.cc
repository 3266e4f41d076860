// Bad input is rejected before anything is written: a non-zero exit code
// (2) and a message that names the entry (or option) and the file.
#include "../app_tests.h"

#include <filesystem>
#include <sstream>

struct Case
{
  std::string              name;
  std::string              prm; // parameter file text ("" = no file written)
  std::vector<std::string> extra_args;
  std::vector<std::string> must_mention;
};

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");
  const std::string                head = "set Output directory = bad_output\n";
  const std::vector<Case>          cases = {
             {"unknown entry", head + "set Foo = 1\n", {}, {"Foo", "case.prm"}},
             {"unknown subsection entry",
              head + "subsection Mesh\n set Colour = red\nend\n",
              {},
              {"Colour", "case.prm"}},
             {"value out of range",
              head + "subsection Mesh\n set Blocks x = 0\nend\n",
              {},
              {"Blocks x", "case.prm"}},
             {"not a number",
              head + "subsection Time\n set End time = soon\nend\n",
              {},
              {"End time", "case.prm"}},
             {"negative density",
              head + "subsection Material\n set Density = -1\nend\n",
              {},
              {"Material/Density", "case.prm"}},
             {"Poisson's ratio 0.5",
              head + "subsection Material\n set Poisson's ratio = 0.5\nend\n",
              {},
              {"Poisson's ratio", "case.prm"}},
             {"missing mesh file",
              head + "subsection Mesh\n set Type = gmsh\n set File = nowhere.msh\nend\n",
              {},
              {"Mesh/File", "nowhere.msh", "case.prm"}},
             {"unstable time step",
              head + "subsection Time\n set Time step = 1\nend\n",
              {},
              {"Time/Time step", "stability", "case.prm"}},
             {"unknown boundary",
              head + "subsection Boundary conditions\n set Fixed x = west\nend\n",
              {},
              {"Fixed x", "west", "case.prm"}},
             {"particle region outside the mesh",
              head + "subsection Particles\n set Region = 100, 100, 200, 200\nend\n",
              {},
              {"Particles/Region", "100, 100, 200, 200", "holds no particle",
               "case.prm"}},
             {"tracked point off the mesh",
              head + "subsection Output\n set Tracked point = 1000, 1000\nend\n",
              {},
              {"Output/Tracked point", "1000, 1000", "outside the mesh",
               "case.prm"}},
             {"bad velocity expression",
              head + "subsection Initial conditions\n set Velocity = sin(; 0\nend\n",
              {},
              {"Initial conditions/Velocity", "case.prm"}},
             {"malformed line",
              head + "subsection Mesh\n set Type criss-cross\nend\n",
              {},
              {"case.prm"}},
             {"unterminated subsection",
              head + "subsection Mesh\n set Type = diagonal\n",
              {},
              {"case.prm"}},
             {"missing parameter file", "", {"no_such_file.prm"}, {"no_such_file.prm"}},
             {"bad --set", head, {"--set", "Mesh/Blocks x=-3"}, {"Blocks x"}},
             {"unknown option", head, {"--frobnicate"}, {"--frobnicate"}},
             {"dimension 3",
              head + "subsection Geometry\n set Dimension = 3\nend\n",
              {},
              {"Dimension", "case.prm"}},
             {"Powell-Sabin in 1D",
              head + "subsection Geometry\n set Dimension = 1\nend\n"
                              "subsection Basis\n set Type = powell-sabin\nend\n",
              {},
              {"Basis/Type", "1D", "case.prm"}},
             {"Gmsh mesh in 1D",
              head + "subsection Geometry\n set Dimension = 1\nend\n"
                              "subsection Mesh\n set Type = gmsh\nend\n",
              {},
              {"Mesh/Type", "1D", "case.prm"}},
             {"2D gravity in 1D",
              head + "subsection Geometry\n set Dimension = 1\nend\n"
                              "subsection Initial conditions\n set Velocity = 0\nend\n"
                              "subsection Body force\n set Gravity = 0, -9.81\nend\n",
              {},
              {"Body force/Gravity", "1D", "case.prm"}},
             {"unknown material model",
              head + "subsection Material\n set Model = plasticine\nend\n",
              {},
              {"Model", "plasticine", "case.prm"}},
             {"unknown transfer scheme",
              head + "subsection Transfer\n set Scheme = flip\nend\n",
              {},
              {"Scheme", "flip", "case.prm"}},
             {"2D B-splines on triangles",
              head + "subsection Basis\n set Type = bspline\nend\n",
              {},
              {"Basis/Type = bspline", "cartesian", "case.prm"}},
             {"P1 on rectangles",
              head + "subsection Mesh\n set Type = cartesian\nend\n",
              {},
              {"Basis/Type = linear", "Mesh/Type", "case.prm"}},
             {"L2 projection on rectangles",
              head + "set Problem = l2 projection\n"
                              "subsection Mesh\n set Type = cartesian\nend\n",
              {},
              {"Mesh/Type = cartesian", "case.prm"}},
             {"L2 projection basis function beyond the mesh",
              head + "set Problem = l2 projection\n"
                              "subsection Mesh\n set Blocks x = 1\n"
                              " set Blocks y = 1\nend\n"
                              "subsection Output\n set Basis function = 12, 0\nend\n",
              {},
              {"Output/Basis function", "12, 0", "case.prm"}},
             {"Taylor least squares on rectangles",
              head +
                "subsection Mesh\n set Type = cartesian\nend\n"
                         "subsection Basis\n set Type = bspline\nend\n"
                         "subsection Mass matrix\n set Type = consistent\nend\n"
                         "subsection Transfer\n set Reconstruction = taylor least squares\nend\n",
              {},
              {"Transfer/Reconstruction", "cartesian", "case.prm"}},
             {"mass matrix study with tolerance 0",
              head + "set Problem = mass matrix study\n"
                              "subsection Mass matrix study\n"
                              " set Tolerance = 0\nend\n",
              {},
              {"Mass matrix study/Tolerance", "0", "case.prm"}},
             {"mass matrix study without damping",
              head + "set Problem = mass matrix study\n"
                              "subsection Mass matrix study\n"
                              " subsection Multigrid\n"
                              "  set Jacobi damping = 0\n end\nend\n",
              {},
              {"Jacobi damping", "case.prm"}},
             {"negative sampling stabilization",
              head + "subsection Mass matrix\n"
                              " set Sampling stabilization = -0.5\nend\n",
              {},
              {"Mass matrix/Sampling stabilization", "-0.5", "case.prm"}},
             {"sampling stabilization not a number",
              head + "subsection Mass matrix\n"
                              " set Sampling stabilization = half\nend\n",
              {},
              {"Mass matrix/Sampling stabilization", "half", "case.prm"}},
             {"step tolerance of one",
              head + "subsection Mass matrix\n set Step tolerance = 1\nend\n",
              {},
              {"Mass matrix/Step tolerance", "1", "case.prm"}},
             {"sampling stabilization on a moving grid",
              head + "subsection Basis\n set Type = powell-sabin\nend\n"
                              "subsection Transfer\n set Scheme = otm\nend\n"
                              "subsection Mass matrix\n"
                              " set Sampling stabilization = 0.5\nend\n",
              {},
              {"Mass matrix/Sampling stabilization", "otm", "case.prm"}},
  };
  for (const auto &c : cases)
    {
      std::filesystem::remove_all("bad_output");
      std::vector<std::string> args;
      if (!c.prm.empty())
        {
          std::ofstream prm("case.prm");
          prm << c.prm;
          args.push_back("case.prm");
        }
      args.insert(args.end(), c.extra_args.begin(), c.extra_args.end());
      std::string screen, message;
      const int   code     = run_app(args, screen, message);
      bool        mentions = true;
      for (const auto &m : c.must_mention)
        mentions = mentions && message.find(m) != std::string::npos;
      out << c.name << ": exit code " << code << std::endl;
      PSMPM_CHECK(out, code == psmpm::App::bad_input);
      PSMPM_CHECK(out, mentions);
      PSMPM_CHECK(out, !std::filesystem::exists("bad_output"));
      if (!mentions || code != psmpm::App::bad_input)
        out << "  message: " << message;
    }
}
