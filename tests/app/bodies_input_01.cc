// Hostile Bodies: a body naming a material with invalid constants, Gmsh
// bodies without a file, with a missing or binary file, an unknown
// physical surface or one without cells, a non-positive radius, a body outside
// the mesh or partly outside it, a body too small to hold a particle,
// overlapping bodies, polygons with fewer than 3 vertices or crossing edges, a
// negative density and swapped rectangle corners each end with exit code 2 and
// a message that names the body's entry, the offending value and the parameter
// file; nothing is written. The two-disk scene is valid.
#include "../app_tests.h"

#include <filesystem>

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");
  std::filesystem::remove_all("never");
  const std::string head =
    "set Output directory = never\n"
    "subsection Geometry\n set Length = 1\n set Height = 1\nend\n"
    "subsection Mesh\n set Blocks x = 10\n set Blocks y = 10\nend\n"
    "subsection Particles\n set Per block x = 4\n set Per block y = 4\nend\n"
    "subsection Boundary conditions\n set Fixed x =\n set Fixed y =\nend\n"
    "subsection Reference solution\n set Type = none\nend\n"
    "subsection Bodies\n set Number of bodies = 2\n"
    " subsection Body 1\n  set Shape = disk\n  set Center = 0.25, 0.25\n"
    "  set Radius = 0.15\n end\n"
    " subsection Body 2\n";
  // Materials/Material 2 is invalid: only a body that names it fails.
  const std::string tail = " end\nend\n"
                           "subsection Materials\n subsection Material 2\n"
                           "  set Poisson's ratio = 0.5\n end\nend\n";
  const std::string ring =
    std::string(PSMPM_SOURCE_DIR) + "/prm/geometry/ring.msh";
  std::ofstream("binary.msh") << "$MeshFormat\n4.1 1 8\n$EndMeshFormat\n";
  struct Case
  {
    std::string              name;
    std::string              body2;
    std::vector<std::string> expected; ///< in the message
  };
  const std::vector<Case> cases = {
    {"negative radius",
     "  set Shape = disk\n  set Center = 0.7, 0.7\n  set Radius = -0.1\n",
     {"Bodies/Body 2/Radius", "-0.1", "positive"}},
    {"zero radius",
     "  set Shape = disk\n  set Center = 0.7, 0.7\n  set Radius = 0\n",
     {"Bodies/Body 2/Radius = 0"}},
    {"outside the mesh",
     "  set Shape = disk\n  set Center = 1.5, 0.5\n  set Radius = 0.2\n",
     {"Bodies/Body 2", "Center = 1.5, 0.5", "outside the mesh"}},
    {"partly outside",
     "  set Shape = rectangle\n  set Corners = 0.8, 0.2, 1.3, 0.4\n",
     {"Bodies/Body 2", "Corners = 0.8, 0.2, 1.3, 0.4", "outside the mesh"}},
    {"smaller than the particle spacing",
     "  set Shape = disk\n  set Center = 0.5, 0.5\n  set Radius = 0.005\n",
     {"Bodies/Body 2", "Radius = 0.005", "holds no particle"}},
    {"overlap",
     "  set Shape = disk\n  set Center = 0.45, 0.45\n  set Radius = 0.2\n",
     {"Bodies/Body 2 (Shape = disk, Center = 0.45, 0.45, Radius = 0.2) "
      "overlaps Bodies/Body 1 (Shape = "}},
    {"two vertices",
     "  set Shape = polygon\n  set Vertices = 0.6, 0.6, 0.9, 0.9\n",
     {"Bodies/Body 2/Vertices", "0.6, 0.6, 0.9, 0.9", "at least 3"}},
    {"self-intersecting",
     "  set Shape = polygon\n"
     "  set Vertices = 0.6, 0.6, 0.9, 0.9, 0.9, 0.6, 0.6, 0.9\n",
     {"Bodies/Body 2/Vertices", "intersects itself"}},
    {"negative density",
     "  set Shape = disk\n  set Center = 0.7, 0.7\n  set Radius = 0.1\n"
     "  set Density = -5\n",
     {"Bodies/Body 2/Density = -5"}},
    {"swapped corners",
     "  set Shape = rectangle\n  set Corners = 0.9, 0.6, 0.6, 0.9\n",
     {"Bodies/Body 2/Corners", "x0 < x1"}},
    {"bad velocity",
     "  set Shape = disk\n  set Center = 0.7, 0.7\n  set Radius = 0.1\n"
     "  set Initial velocity = 1 +; 0\n",
     {"Bodies/Body 2/Initial velocity", "1 +"}},
    {"material with bad constants",
     "  set Shape = disk\n  set Center = 0.7, 0.7\n  set Radius = 0.1\n"
     "  set Material = 2\n",
     {"Materials/Material 2/Poisson's ratio = 0.5"}},
    {"gmsh body without a file",
     "  set Shape = gmsh\n",
     {"Bodies/Body 2/File", ".msh"}},
    {"gmsh body, missing file",
     "  set Shape = gmsh\n  set File = no_such_ring.msh\n",
     {"Bodies/Body 2/File = no_such_ring.msh", "cannot open"}},
    {"gmsh body, binary file",
     "  set Shape = gmsh\n  set File = binary.msh\n",
     {"Bodies/Body 2/File = binary.msh", "binary"}},
    {"gmsh body, unknown surface",
     "  set Shape = gmsh\n  set File = " + ring +
       "\n  set Physical surfaces = core\n",
     {"Bodies/Body 2/Physical surfaces", "'core'", "outer (1)"}},
    {"gmsh body, surface without cells",
     "  set Shape = gmsh\n  set File = " + ring +
       "\n  set Physical surfaces = 7\n",
     {"Bodies/Body 2/Physical surfaces", "(tag 7) has no cells"}}};
  std::string screen, message;
  for (const auto &c : cases)
    {
      std::ofstream("bodies.prm") << head << c.body2 << tail;
      const int code = run_app({"bodies.prm", "--validate"}, screen, message);
      out << c.name << ": exit code " << code << std::endl;
      PSMPM_CHECK(out, code == psmpm::App::bad_input);
      PSMPM_CHECK(out, message.find("bodies.prm") != std::string::npos);
      for (const auto &e : c.expected)
        {
          const bool found = message.find(e) != std::string::npos;
          PSMPM_CHECK(out, found);
          if (!found)
            out << "  '" << e << "' not in: " << message << std::endl;
        }
    }

  // The same head with a valid polygon and with a Gmsh ring (whose
  // Material 1 has the defaults; the invalid Material 2 is not read), and
  // the two-disk scene.
  std::ofstream("bodies.prm")
    << head
    << "  set Shape = polygon\n"
       "  set Vertices = 0.6, 0.6, 0.9, 0.6, 0.9, 0.9, 0.75, 0.7, 0.6, 0.9\n"
    << tail;
  int code = run_app({"bodies.prm", "--validate"}, screen, message);
  out << "valid polygon: exit code " << code << std::endl;
  if (code != 0)
    out << message << std::endl;
  std::ofstream("bodies.prm")
    << head
    << "  set Shape = gmsh\n  set File = " + ring + "\n  set Material = 1\n"
    << tail;
  code = run_app({"bodies.prm", "--validate"}, screen, message);
  out << "valid gmsh ring: exit code " << code << std::endl;
  if (code != 0)
    out << message << std::endl;
  code = run_app({std::string(PSMPM_SOURCE_DIR) + "/prm/two_disks.prm",
                  "--validate"},
                 screen,
                 message);
  out << "two_disks.prm: exit code " << code << std::endl;
  if (code != 0)
    out << message << std::endl;
  PSMPM_CHECK(out, !std::filesystem::exists("never"));
}
