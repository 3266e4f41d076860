// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/grid/tria.h>

#include <psmpm/mesh/gmsh_file.h>
#include <psmpm/particles/body.h>

#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace psmpm
{
  namespace Particles
  {
    namespace
    {
      /// "$PhysicalNames" entries of dimension 2: name -> tag.
      std::map<std::string, int>
      surface_names(std::istream &in)
      {
        std::map<std::string, int> names;
        for (const auto &entry : Mesh::read_physical_names(in))
          if (entry.dimension == 2)
            names[entry.name] = entry.tag;
        return names;
      }

      std::string
      known(const std::map<std::string, int> &names, const std::set<int> &tags)
      {
        std::string s;
        for (const auto &[name, tag] : names)
          s +=
            (s.empty() ? "" : ", ") + name + " (" + std::to_string(tag) + ")";
        for (const int tag : tags)
          s += (s.empty() ? "" : ", ") + std::to_string(tag);
        return s.empty() ? "none" : s;
      }



      /// The format line of the .msh stream @p in: psmpm reads ASCII
      /// files only.
      void
      check_ascii(std::istream &in, const std::string &where)
      {
        std::string line, version;
        int         file_type = 0;
        std::getline(in, line);
        AssertThrow(line.rfind("$MeshFormat", 0) == 0,
                    ExcMessage(where + ": not a Gmsh .msh file (it does not "
                                       "start with $MeshFormat)."));
        in >> version >> file_type;
        AssertThrow(file_type == 0,
                    ExcMessage(where + ": a binary Gmsh file (format " +
                               version +
                               "); psmpm reads ASCII .msh files only (save it "
                               "again without -bin)."));
      }



      /**
       * The physical tags that @p surfaces select (each a name of @p names
       * or a number), each with cells in @p tags_present; empty for all
       * cells.
       */
      std::set<int>
      selected_tags(const std::vector<std::string>   &surfaces,
                    const std::map<std::string, int> &names,
                    const std::set<int>              &tags_present,
                    const std::string                &file,
                    const std::string                &entry)
      {
        std::set<int> selected;
        for (const auto &s : surfaces)
          {
            if (names.count(s))
              selected.insert(names.at(s));
            else
              {
                std::size_t used = 0;
                int         tag  = -1;
                try
                  {
                    tag = std::stoi(s, &used);
                  }
                catch (...)
                  {
                    used = 0;
                  }
                AssertThrow(used == s.size() && used > 0,
                            ExcMessage(entry + "/Physical surfaces: '" + s +
                                       "' is not a physical surface of " +
                                       file + " (known: " + known(names, {}) +
                                       ")."));
                selected.insert(tag);
              }
            const int tag = names.count(s) ? names.at(s) : std::stoi(s);
            AssertThrow(tags_present.count(tag),
                        ExcMessage(
                          entry + "/Physical surfaces: '" + s + "' (tag " +
                          std::to_string(tag) + ") has no cells in " + file +
                          " (tags with cells: " + known({}, tags_present) +
                          ")."));
          }
        return selected;
      }



      /// The outline of the cells of @p tria that @p selected selects
      /// (all if empty) into @p shape: the edges of exactly one selected
      /// cell, by vertex index, their bounding box and the cells' area.
      void
      add_outline(const Triangulation<2> &tria,
                  const std::set<int>    &selected,
                  const std::string      &where,
                  Shape                  &shape)
      {
        std::map<std::pair<unsigned int, unsigned int>, std::array<Point<2>, 2>>
          once;
        for (const auto &cell : tria.active_cell_iterators())
          if (selected.empty() || selected.count(cell->material_id()))
            {
              shape.gmsh_area += cell->measure();
              for (const unsigned int f : cell->face_indices())
                {
                  const auto         face = cell->face(f);
                  const unsigned int a    = face->vertex_index(0),
                                     b    = face->vertex_index(1);
                  const auto key =
                    std::make_pair(std::min(a, b), std::max(a, b));
                  const auto found = once.find(key);
                  if (found != once.end())
                    once.erase(found);
                  else
                    once[key] = {{face->vertex(0), face->vertex(1)}};
                }
            }
        AssertThrow(shape.gmsh_area > 0,
                    ExcMessage(where + ": the selected cells have no area."));
        shape.box_lower = shape.box_upper = once.begin()->second[0];
        for (const auto &[key, e] : once)
          {
            shape.edges.push_back(e);
            for (const auto &p : e)
              for (unsigned int d = 0; d < 2; ++d)
                {
                  shape.box_lower[d] = std::min(shape.box_lower[d], p[d]);
                  shape.box_upper[d] = std::max(shape.box_upper[d], p[d]);
                }
          }
      }
    } // namespace



    Shape
    Shape::from_gmsh(const std::string              &file,
                     const std::vector<std::string> &surfaces,
                     const std::string              &entry)
    {
      const std::string where = entry + "/File = " + file;
      Mesh::check_msh(file, where);
      std::ifstream in(file);
      AssertThrow(in.good(),
                  ExcMessage(where + ": cannot open the geometry file."));
      check_ascii(in, where);
      in.clear();
      in.seekg(0);
      const auto names = surface_names(in);
      in.clear();
      in.seekg(0);

      Triangulation<2> tria;
      Mesh::read_cells(in, tria, where);
      std::set<int> tags_present;
      for (const auto &cell : tria.active_cell_iterators())
        tags_present.insert(cell->material_id());
      const std::set<int> selected =
        selected_tags(surfaces, names, tags_present, file, entry);

      Shape shape;
      shape.type     = Type::gmsh;
      shape.file     = file;
      shape.surfaces = surfaces.empty() ? std::string("(all)") : "";
      for (std::size_t i = 0; i < surfaces.size(); ++i)
        shape.surfaces += (i ? ", " : "") + surfaces[i];
      add_outline(tria, selected, where, shape);
      return shape;
    }
  } // namespace Particles
} // namespace psmpm
