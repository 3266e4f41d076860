// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria_description.h>

#include <psmpm/mesh/gmsh_file.h>
#include <psmpm/mesh/mesh_generator.h>
#include <psmpm/mesh/triangle_geometry.h>

#include <fstream>
#include <map>
#include <sstream>

namespace psmpm
{
  namespace Mesh
  {
    template <int dim>
    void
    MeshGenerator<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      {
        prm.declare_entry("Length",
                          "25",
                          Patterns::Double(),
                          "Length (x extent) of the rectangular domain [m].");
        prm.declare_entry("Height",
                          "2",
                          Patterns::Double(),
                          "Height (y extent) of the rectangular domain [m].");
      }
      prm.leave_subsection();
      prm.enter_subsection("Mesh");
      {
        prm.declare_entry(
          "Type",
          "criss-cross",
          Patterns::Selection("criss-cross|diagonal|cartesian|gmsh"),
          "criss-cross: each block split into 4 triangles around its "
          "centre; diagonal: each block split into 2 triangles; cartesian: "
          "each block one quadrilateral (for Basis/Type = bspline, the "
          "tensor-product B-splines); gmsh: read 'File'.");
        prm.declare_entry("Blocks x",
                          "4",
                          Patterns::Integer(1),
                          "Number of blocks in x direction.");
        prm.declare_entry("Blocks y",
                          "1",
                          Patterns::Integer(1),
                          "Number of blocks in y direction.");
        prm.declare_entry("File",
                          "",
                          Patterns::Anything(),
                          "Gmsh .msh file (Type = gmsh); relative paths are "
                          "taken relative to the parameter file.");
        prm.declare_entry(
          "Distribution",
          "replicated",
          Patterns::Selection("replicated|distributed"),
          "With several MPI ranks: replicated: every rank holds the whole "
          "mesh (parallel::shared); distributed: a rank holds its own cells "
          "and the cells sharing a vertex with one "
          "(parallel::fullydistributed): memory per rank follows the rank's "
          "share of the mesh (with Powell-Sabin two layers of ghost cells; "
          "Mesh/Partitioner says who builds the parts). Verified "
          "with Basis/Type = linear and powell-sabin, Transfer/"
          "Reconstruction = particles and the transfers on a fixed grid; "
          "a particle must stay within its rank's cells and ghost layers "
          "in one step. The automatic step (Time/Courant number) keeps "
          "every particle within a cell; with a fixed Time/Time step, a "
          "particle that moves further stops the run as unstable, naming "
          "the particle and its rank, where the replicated mesh would "
          "have found it.");
        prm.declare_entry(
          "Partitioner",
          "automatic",
          Patterns::Selection("automatic|blocks|metis"),
          "How Mesh/Distribution = distributed splits the mesh between "
          "ranks. blocks (Mesh/Type = criss-cross or diagonal): the ranks "
          "tile the rectangle of blocks (px by py rectangles of whole "
          "blocks, px py = the number of ranks, the fewest cut edges), "
          "and every rank builds only its own tile and ghost layers, so no "
          "rank ever holds the whole mesh; it needs px <= Blocks x and "
          "py <= Blocks y for some such tiling. metis: rank 0 builds the "
          "whole mesh, partitions it with METIS (as the replicated mesh "
          "does) and sends each rank its part. automatic: blocks where it "
          "applies, else metis. Ignored with one rank or a replicated mesh.");
      }
      prm.leave_subsection();
    }

    template <int dim>
    void
    MeshGenerator<dim>::parse_parameters(ParameterHandler &prm, MPI_Comm comm)
    {
      prm.enter_subsection("Geometry");
      length = prm.get_double("Length");
      height = prm.get_double("Height");
      prm.leave_subsection();
      prm.enter_subsection("Mesh");
      const std::string t = prm.get("Type");
      type                = (t == "criss-cross" ? Type::criss_cross :
                             t == "diagonal"    ? Type::diagonal :
                             t == "cartesian"   ? Type::cartesian :
                                                  Type::gmsh);
      blocks_x            = prm.get_integer("Blocks x");
      blocks_y            = prm.get_integer("Blocks y");
      file                = prm.get("File");
      distributed         = prm.get("Distribution") == "distributed";
      partitioner         = prm.get("Partitioner");
      prm.leave_subsection();
      AssertThrow(partitioner != "blocks" || type == Type::criss_cross ||
                    type == Type::diagonal,
                  ExcMessage("Mesh/Partitioner = blocks needs Mesh/Type = "
                             "criss-cross or diagonal, got Mesh/Type = " +
                             t + "."));
      AssertThrow(!distributed || dim == 2,
                  ExcMessage("Mesh/Distribution = distributed needs "
                             "Geometry/Dimension = 2."));

      if constexpr (dim == 1)
        {
          // Gmsh meshes are read as triangles; a 1D mesh is always the
          // uniform subdivision of [0, Length].
          AssertThrow(type != Type::gmsh,
                      ExcMessage("Mesh/Type = gmsh is not available in 1D: "
                                 "the mesh is Mesh/Blocks x equal elements "
                                 "on [0, Geometry/Length]."));
          AssertThrow(length > 0,
                      ExcMessage("Geometry/Length must be positive, got " +
                                 std::to_string(length) + "."));
        }
      else
        {
          AssertThrow(type == Type::gmsh || (length > 0 && height > 0),
                      ExcMessage("Geometry/Length and Geometry/Height must be "
                                 "positive, got " +
                                 std::to_string(length) + " and " +
                                 std::to_string(height) + "."));

          if (type == Type::gmsh)
            {
              AssertThrow(!file.empty(),
                          ExcMessage("Mesh/File must name a .msh file when "
                                     "Mesh/Type = gmsh."));
              // Refused here, before anything opens it (a FIFO blocks),
              // on every rank if one rank cannot read it.
              check_msh_on_all_ranks(file, "Mesh/File = " + file, comm);
            }
        }
    }

    template <int dim>
    void
    MeshGenerator<dim>::check_block_shape() const
    {
      // Blocks far from square make slivers whose geometry is round-off
      // (non-finite results, or a refinement that never ends); coordinates
      // near the double range overflow in areas. Checked here, after the
      // run limits (a scene of millions of blocks is refused by those).
      if (dim == 2 && type != Type::gmsh)
        {
          const double       hx = length / blocks_x, hy = height / blocks_y;
          std::ostringstream s;
          s << "Geometry/Length = " << length
            << ", Geometry/Height = " << height
            << " with Mesh/Blocks x = " << blocks_x
            << ", Mesh/Blocks y = " << blocks_y;
          AssertThrow(length <= 1e12 && height <= 1e12,
                      ExcMessage(s.str() +
                                 ": the domain is larger than 1e12 m."));
          AssertThrow(
            std::max(hx / hy, hy / hx) <= 1e4,
            ExcMessage(s.str() + ": blocks with sides in a ratio above 1e4 (" +
                       std::to_string(hx) + " x " + std::to_string(hy) + ")."));
        }
    }

    template <int dim>
    void
    MeshGenerator<dim>::create(Triangulation<dim> &tria) const
    {
      check_block_shape();
      if constexpr (dim == 1)
        {
          const std::vector<unsigned int> repetitions{blocks_x};
          GridGenerator::subdivided_hyper_rectangle(tria,
                                                    repetitions,
                                                    Point<1>(0),
                                                    Point<1>(length),
                                                    true);
          names = {{"left", 0}, {"right", 1}};
        }
      else if (type == Type::gmsh)
        names = read_gmsh(tria, file);
      else
        {
          make_blocks(tria,
                      Point<2>(0, 0),
                      Point<2>(length, height),
                      blocks_x,
                      blocks_y,
                      type);
          names = {{"left", 0}, {"right", 1}, {"bottom", 2}, {"top", 3}};
        }
    }

    template <int dim>
    const std::map<std::string, types::boundary_id> &
    MeshGenerator<dim>::boundary_names() const
    {
      return names;
    }

    template <int dim>
    types::boundary_id
    MeshGenerator<dim>::boundary_id(const std::string &name) const
    {
      const auto it = names.find(name);
      if (it != names.end())
        return it->second;
      std::string known;
      for (const auto &n : names)
        known += " " + n.first;
      AssertThrow(false,
                  ExcMessage("Unknown boundary name '" + name +
                             "'; this mesh has:" + known + "."));
      return numbers::invalid_boundary_id;
    }

    template <int dim>
    void
    MeshGenerator<dim>::add_boundary_name(const std::string       &name,
                                          const types::boundary_id id) const
    {
      names[name] = id;
    }

    template <int dim>
    void
    MeshGenerator<dim>::make_blocks(Triangulation<2>  &tria,
                                    const Point<2>    &lower,
                                    const Point<2>    &upper,
                                    const unsigned int nx,
                                    const unsigned int ny,
                                    const Type         type)
    {
      Assert(type != Type::gmsh, ExcInternalError());
      if (type == Type::cartesian)
        {
          // Quadrilaterals, lexicographic (x fastest), colorized with the
          // same ids as the triangle blocks below.
          GridGenerator::subdivided_hyper_rectangle(
            tria,
            std::vector<unsigned int>{nx, ny},
            lower,
            upper,
            true);
          return;
        }
      const double hx = (upper[0] - lower[0]) / nx;
      const double hy = (upper[1] - lower[1]) / ny;

      std::vector<Point<2>> vertices;
      for (unsigned int j = 0; j <= ny; ++j)
        for (unsigned int i = 0; i <= nx; ++i)
          vertices.emplace_back(lower[0] + i * hx, lower[1] + j * hy);
      const auto corner = [nx](const unsigned int i, const unsigned int j) {
        return j * (nx + 1) + i;
      };

      std::vector<CellData<2>> cells;
      const auto               add = [&cells](const unsigned int a,
                                const unsigned int b,
                                const unsigned int c) {
        CellData<2> cell(3);
        cell.vertices = {a, b, c}; // counter-clockwise
        cells.push_back(cell);
      };
      for (unsigned int j = 0; j < ny; ++j)
        for (unsigned int i = 0; i < nx; ++i)
          {
            const unsigned int v00 = corner(i, j), v10 = corner(i + 1, j),
                               v01 = corner(i, j + 1),
                               v11 = corner(i + 1, j + 1);
            if (type == Type::criss_cross)
              {
                const unsigned int c = vertices.size();
                vertices.emplace_back(lower[0] + (i + 0.5) * hx,
                                      lower[1] + (j + 0.5) * hy);
                add(v00, v10, c);
                add(v10, v11, c);
                add(v11, v01, c);
                add(v01, v00, c);
              }
            else
              {
                add(v00, v10, v11);
                add(v00, v11, v01);
              }
          }

      tria.create_triangulation(vertices, cells, SubCellData());

      // Simplex grid generators do not colorize: name the sides ourselves.
      const double tol = 1e-10 * std::max(hx, hy);
      for (const auto &cell : tria.active_cell_iterators())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const Point<2>     c  = cell->face(f)->center();
              types::boundary_id id = 0;
              if (std::abs(c[0] - lower[0]) < tol)
                id = 0;
              else if (std::abs(c[0] - upper[0]) < tol)
                id = 1;
              else if (std::abs(c[1] - lower[1]) < tol)
                id = 2;
              else
                id = 3;
              cell->face(f)->set_boundary_id(id);
            }
    }

    namespace
    {
      /**
       * deal.II turns clockwise triangles around on reading, which is right
       * for a mesh that is clockwise throughout (a surface meshed with its
       * normal down) but hides a folded, tangled mesh. Reject meshes whose
       * triangles have both orientations (ASCII format 2; other formats
       * are left to deal.II's reader).
       */
      void
      check_orientation(std::istream &in, const std::string &filename)
      {
        std::string line;
        std::getline(in, line);
        if (line != "$MeshFormat")
          return;
        double version = 0;
        int    binary  = 1;
        in >> version >> binary;
        if (version >= 3 || binary != 0)
          return;
        std::map<long, Point<2>> nodes;
        while (std::getline(in, line) && line != "$Nodes")
          ;
        long n = 0;
        if (!(in >> n))
          return;
        for (long i = 0; i < n; ++i)
          {
            long   id;
            double x, y, z;
            if (!(in >> id >> x >> y >> z))
              return; // let the reader report the damage
            nodes[id] = Point<2>(x, y);
          }
        while (std::getline(in, line) && line != "$Elements")
          ;
        if (!(in >> n))
          return;
        long first_ccw = -1, first_cw = -1;
        for (long i = 0; i < n && std::getline(in >> std::ws, line); ++i)
          {
            std::istringstream e(line);
            long               id, type, n_tags;
            if (!(e >> id >> type >> n_tags))
              return;
            for (long t = 0, tag; t < n_tags; ++t)
              e >> tag;
            if (type != 2)
              continue;
            long a, b, c;
            if (!(e >> a >> b >> c) || !nodes.count(a) || !nodes.count(b) ||
                !nodes.count(c))
              return;
            const double area = signed_area({{nodes[a], nodes[b], nodes[c]}});
            if (area > 0 && first_ccw < 0)
              first_ccw = id;
            if (area < 0 && first_cw < 0)
              first_cw = id;
          }
        AssertThrow(first_ccw < 0 || first_cw < 0,
                    ExcMessage("Mesh/File = " + filename +
                               ": triangles of both orientations (element " +
                               std::to_string(first_ccw) +
                               " counter-clockwise, element " +
                               std::to_string(first_cw) +
                               " clockwise): the mesh is inverted or folded."));
      }



      /// The format line of the .msh stream @p in: psmpm reads ASCII
      /// files only.
      void
      check_ascii(std::istream &in, const std::string &filename)
      {
        std::string line;
        std::getline(in, line);
        if (line.rfind("$MeshFormat", 0) == 0)
          {
            std::string version;
            int         file_type = 0;
            in >> version >> file_type;
            AssertThrow(file_type == 0,
                        ExcMessage("Mesh/File = " + filename +
                                   ": a binary Gmsh file (format " + version +
                                   "); psmpm reads ASCII .msh files only "
                                   "(save it again without -bin, e.g. "
                                   "gmsh in.msh -save -format msh22 -o "
                                   "out.msh)."));
          }
      }



      /**
       * The boundaries named in the $PhysicalNames of @p in:
       * "$PhysicalNames / n / dim tag \"name\"". A name is one boundary:
       * defined once, with a tag other than 0 (deal.II gives every edge
       * without a physical tag boundary id 0).
       */
      std::map<std::string, types::boundary_id>
      read_boundary_names(std::istream &in, const std::string &filename)
      {
        std::map<std::string, types::boundary_id> physical_names;
        for (const auto &[entity_dim, tag, name] : read_physical_names(in))
          if (entity_dim == 1)
            {
              AssertThrow(physical_names.count(name) == 0,
                          ExcMessage("Mesh/File = " + filename +
                                     ": the physical name \"" + name +
                                     "\" is defined twice (tags " +
                                     std::to_string(physical_names[name]) +
                                     " and " + std::to_string(tag) + ")."));
              AssertThrow(tag > 0,
                          ExcMessage("Mesh/File = " + filename +
                                     ": the physical name \"" + name +
                                     "\" has tag " + std::to_string(tag) +
                                     "; boundary tags must be positive (0 is "
                                     "the boundary of edges without a "
                                     "physical group)."));
              physical_names[name] = tag;
            }
        return physical_names;
      }



      /// The cells read into @p tria: some, all triangles, none inverted.
      void
      check_cells(const Triangulation<2> &tria, const std::string &filename)
      {
        AssertThrow(tria.n_active_cells() > 0,
                    ExcMessage("Mesh/File = " + filename + ": no cells."));
        for (const auto &cell : tria.active_cell_iterators())
          {
            AssertThrow(cell->reference_cell() == ReferenceCells::Triangle,
                        ExcMessage("Mesh/File = " + filename +
                                   ": psmpm needs a mesh of triangles only."));
            AssertThrow(cell->measure() > 0,
                        ExcMessage("Mesh/File = " + filename + ": cell " +
                                   std::to_string(cell->active_cell_index()) +
                                   " is inverted (clockwise vertices)."));
          }
      }



      /**
       * Boundary edges of @p tria: every boundary of @p physical_names has
       * some, and no two boundary edges leave a vertex in the same
       * direction (that is a hanging node: a vertex inside an edge of the
       * neighbouring cell, whose edges then all count as boundary).
       */
      void
      check_boundary_edges(
        const Triangulation<2>                          &tria,
        const std::map<std::string, types::boundary_id> &physical_names,
        const std::string                               &filename)
      {
        std::map<types::boundary_id, unsigned int>        edges_of;
        std::map<unsigned int, std::vector<Tensor<1, 2>>> directions;
        for (const auto &cell : tria.active_cell_iterators())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              {
                const auto face = cell->face(f);
                ++edges_of[face->boundary_id()];
                for (unsigned int v = 0; v < 2; ++v)
                  {
                    const Tensor<1, 2> d =
                      face->vertex(1 - v) - face->vertex(v);
                    auto &list = directions[face->vertex_index(v)];
                    for (const auto &e : list)
                      {
                        const double cross = e[0] * d[1] - e[1] * d[0];
                        AssertThrow(
                          !(e * d > 0 &&
                            std::abs(cross) <= 1e-10 * e.norm() * d.norm()),
                          ExcMessage(
                            "Mesh/File = " + filename +
                            ": the mesh is not conforming at the vertex (" +
                            std::to_string(face->vertex(v)[0]) + ", " +
                            std::to_string(face->vertex(v)[1]) +
                            "): two edges leave it in the same direction (a "
                            "hanging node: a vertex inside the edge of a "
                            "neighbouring triangle). psmpm needs a "
                            "conforming mesh."));
                      }
                    list.push_back(d);
                  }
              }
        for (const auto &name : physical_names)
          AssertThrow(edges_of.count(name.second) > 0,
                      ExcMessage(
                        "Mesh/File = " + filename + ": the boundary \"" +
                        name.first + "\" (tag " + std::to_string(name.second) +
                        ") has no edges on the boundary of the mesh."));
      }
    } // namespace

    template <int dim>
    std::map<std::string, types::boundary_id>
    MeshGenerator<dim>::read_gmsh(Triangulation<2>  &tria,
                                  const std::string &filename)
    {
      check_msh(filename, "Mesh/File = " + filename);
      std::ifstream in(filename);
      AssertThrow(in.good(),
                  ExcMessage("Mesh/File = " + filename +
                             ": cannot open the mesh file."));
      // Each check reads the stream from its start.
      check_ascii(in, filename);
      in.clear();
      in.seekg(0);
      const std::map<std::string, types::boundary_id> physical_names =
        read_boundary_names(in, filename);
      in.clear();
      in.seekg(0);
      check_orientation(in, filename);
      in.clear();
      in.seekg(0);

      read_cells(in, tria, "Mesh/File = " + filename);
      check_cells(tria, filename);
      check_boundary_edges(tria, physical_names, filename);
      return physical_names;
    }



    template class MeshGenerator<1>;
    template class MeshGenerator<2>;
  } // namespace Mesh
} // namespace psmpm
