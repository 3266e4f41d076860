// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/grid/grid_in.h>

#include <psmpm/mesh/gmsh_file.h>

namespace psmpm
{
  namespace Mesh
  {
    std::vector<PhysicalName>
    read_physical_names(std::istream &in)
    {
      std::vector<PhysicalName> names;
      std::string               line;
      while (std::getline(in, line))
        if (line.rfind("$PhysicalNames", 0) == 0)
          {
            unsigned int n = 0;
            in >> n;
            for (unsigned int i = 0; i < n && in; ++i)
              {
                PhysicalName entry;
                std::string  rest;
                in >> entry.dimension >> entry.tag;
                std::getline(in, rest);
                const auto a = rest.find('"'), b = rest.rfind('"');
                if (a != std::string::npos && b > a)
                  {
                    entry.name = rest.substr(a + 1, b - a - 1);
                    names.push_back(entry);
                  }
              }
            break;
          }
      return names;
    }



    void
    read_cells(std::istream             &in,
               dealii::Triangulation<2> &tria,
               const std::string        &where)
    {
      dealii::GridIn<2> grid_in;
      grid_in.attach_triangulation(tria);
      try
        {
          grid_in.read_msh(in);
        }
      catch (const std::exception &e)
        {
          AssertThrow(false,
                      dealii::ExcMessage(where +
                                         ": not a readable Gmsh mesh (" +
                                         e.what() + ")."));
        }
    }
  } // namespace Mesh
} // namespace psmpm
