// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/mesh/gmsh_physical_names.h>

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
  } // namespace Mesh
} // namespace psmpm
