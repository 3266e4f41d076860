// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_in.h>

#include <psmpm/base/fnv1a.h>
#include <psmpm/base/root_errors.h>
#include <psmpm/mesh/gmsh_file.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace psmpm
{
  namespace Mesh
  {
    namespace
    {
      /// Nodes of a Gmsh element of @p type (format 2 numbering); 0 for
      /// a type psmpm does not know.
      unsigned int
      nodes_per_element(const int type)
      {
        switch (type)
          {
            case 15:
              return 1; // point
            case 1:
              return 2; // line
            case 2:
              return 3; // triangle
            case 3:
              return 4; // quadrilateral
            case 8:
              return 3; // second-order line
            case 9:
              return 6; // second-order triangle
            default:
              return 0;
          }
      }



      /// Refuse @p file unless it is a regular file: a FIFO or a device
      /// would block the readers or never end.
      void
      check_regular_file(const std::string &file, const std::string &where)
      {
        namespace fs = std::filesystem;
        std::error_code ec;
        const auto      status = fs::status(file, ec);
        AssertThrow(fs::exists(status),
                    dealii::ExcMessage(
                      where + ": cannot open the file (no such file)."));
        AssertThrow(fs::is_regular_file(status),
                    dealii::ExcMessage(
                      where + ": not a regular file (" +
                      (fs::is_directory(status) ? "a directory" :
                       fs::is_fifo(status)      ? "a FIFO" :
                       fs::is_character_file(status) ||
                           fs::is_block_file(status) ?
                                             "a device" :
                                             "a special file") +
                      "); give a Gmsh .msh file."));
      }



      /**
       * One pass over an opened .msh stream, section by section, throwing
       * "<where>: ..." at the first damage. Format 2 files are checked
       * entry by entry; format 4 files only by their section heads and
       * ends. All reads share one line buffer, so that a message quoting
       * the line after a failed read quotes the last line read.
       */
      class MshChecker
      {
      public:
        MshChecker(std::istream &in, const std::string &where)
          : in(in)
          , where(where)
        {
        }

        void
        run()
        {
          check_format();
          check_sections();
          if (v2)
            check_node_references();
        }

      private:
        void
        fail(const std::string &what) const
        {
          AssertThrow(false, dealii::ExcMessage(where + ": " + what));
        }

        /// The $MeshFormat section: version 2.x or 4.x, ASCII, 8 bytes.
        void
        check_format()
        {
          std::getline(in, line);
          if (line.rfind("$MeshFormat", 0) != 0)
            fail("not a Gmsh .msh file (it does not start with $MeshFormat).");
          std::getline(in, line);
          std::istringstream format(line);
          int                file_type = -1, data_size = -1;
          format >> version >> file_type >> data_size;
          v2 = version == "2" || version == "2.0" || version == "2.1" ||
               version == "2.2";
          v4 = version == "4" || version == "4.0" || version == "4.1";
          if (!v2 && !v4)
            fail("Gmsh format version '" + version +
                 "' in $MeshFormat; psmpm reads versions 2.x and 4.x (save "
                 "it again, e.g. gmsh in.msh -save -format msh22 -o out.msh).");
          if (file_type != 0)
            fail("a binary Gmsh file (format " + version +
                 "); psmpm reads ASCII .msh files only (save it again without "
                 "-bin, e.g. gmsh in.msh -save -format msh22 -o out.msh).");
          if (data_size != 8)
            fail("data size '" + std::to_string(data_size) +
                 "' in $MeshFormat (expected 8).");
        }

        /// Every section after $MeshFormat: closed, and $Nodes and
        /// $Elements present.
        void
        check_sections()
        {
          bool nodes = false, elements = false;
          while (std::getline(in, line))
            {
              if (!line.empty() && line.back() == '\r')
                line.pop_back();
              if (line.empty() || line[0] != '$')
                continue;
              const std::string name = line.substr(1);
              if (name.rfind("End", 0) == 0)
                continue;
              if (name == "Nodes")
                nodes = true;
              if (name == "Elements")
                elements = true;
              if (v2 && (name == "Nodes" || name == "Elements"))
                {
                  check_v2_section(name);
                  continue;
                }
              if (v4 && (name == "Nodes" || name == "Elements"))
                check_v4_section_head(name);
              // Other sections, and format 4: only their ends are checked.
              bool closed = false;
              while (!closed && std::getline(in, line))
                closed = line.rfind("$End" + name, 0) == 0;
              if (!closed)
                fail("$End" + name + " is missing (a truncated file?).");
            }
          if (!nodes || !elements)
            fail(std::string("no $") + (nodes ? "Elements" : "Nodes") +
                 " section (a truncated file?).");
        }

        /// A format 2 $Nodes or $Elements section @p name, after its head
        /// line: the announced count of entries, then its end.
        void
        check_v2_section(const std::string &name)
        {
          long long n = -1;
          if (!std::getline(in, line) || !(std::istringstream(line) >> n) ||
              n < 0)
            fail("the count of $" + name + " is not a number (" + line + ").");
          for (long long i = 0; i < n; ++i)
            {
              if (!std::getline(in, line) || line.rfind("$End", 0) == 0)
                fail("$" + name + " announces " + std::to_string(n) +
                     " entries and holds " + std::to_string(i) + ".");
              std::istringstream row(line);
              long long          id = 0;
              if (!(row >> id))
                fail("$" + name + ": entry " + std::to_string(i + 1) + " ('" +
                     line.substr(0, 60) + "') is not a number.");
              if (name == "Nodes")
                check_v2_node(row, id);
              else
                check_v2_element(row, id);
            }
          if (!std::getline(in, line) || line.rfind("$End" + name, 0) != 0)
            fail("$" + name +
                 " holds more entries than announced, or "
                 "$End" +
                 name + " is missing.");
        }

        /// The rest of the format 2 node line @p row of node @p id: three
        /// finite coordinates.
        void
        check_v2_node(std::istringstream &row, const long long id)
        {
          double x[3];
          if (!(row >> x[0] >> x[1] >> x[2]) || !std::isfinite(x[0]) ||
              !std::isfinite(x[1]) || !std::isfinite(x[2]) ||
              std::max({std::abs(x[0]), std::abs(x[1]), std::abs(x[2])}) >
                1e100)
            fail("node " + std::to_string(id) +
                 " has no three finite coordinates ('" + line.substr(0, 60) +
                 "').");
          ids.push_back(id);
        }

        /// The rest of the format 2 element line @p row of element @p id:
        /// a known type, its tags and its nodes.
        void
        check_v2_element(std::istringstream &row, const long long id)
        {
          int type = 0, n_tags = -1;
          if (!(row >> type >> n_tags) || n_tags < 0)
            fail("element " + std::to_string(id) +
                 ": no type and tag count ('" + line.substr(0, 60) + "').");
          const unsigned int n_nodes = nodes_per_element(type);
          if (n_nodes == 0)
            fail("element " + std::to_string(id) + " is of Gmsh type " +
                 std::to_string(type) +
                 ", which psmpm does not read (points, lines, "
                 "triangles, quadrilaterals).");
          long long tag = 0;
          for (int t = 0; t < n_tags; ++t)
            if (!(row >> tag))
              fail("element " + std::to_string(id) +
                   ": fewer tags than announced.");
          std::vector<long long> v(n_nodes);
          for (auto &node : v)
            if (!(row >> node))
              fail("element " + std::to_string(id) + " has " + "fewer than " +
                   std::to_string(n_nodes) + " nodes.");
          element_nodes.push_back(std::move(v));
        }

        /// The head line of a format 4 $Nodes or $Elements section @p name.
        void
        check_v4_section_head(const std::string &name)
        {
          // Format 4.1 starts these sections with four numbers (blocks,
          // entries, smallest and largest tag), 4.0 with two; a file of
          // another format made deal.II read forever.
          std::getline(in, line);
          std::istringstream head(line);
          long long          v = 0;
          unsigned int       n = 0;
          while (head >> v)
            ++n;
          if (n != (version == "4.1" ? 4u : 2u) || !head.eof())
            fail("$" + name + " does not start as in format " + version +
                 " ('" + line.substr(0, 60) + "').");
        }

        /// Format 2: each node id once, every element node defined.
        void
        check_node_references()
        {
          std::sort(ids.begin(), ids.end());
          const auto dup = std::adjacent_find(ids.begin(), ids.end());
          if (dup != ids.end())
            fail("node id " + std::to_string(*dup) +
                 " is defined twice in $Nodes.");
          for (const auto &v : element_nodes)
            for (const long long node : v)
              if (!std::binary_search(ids.begin(), ids.end(), node))
                fail("an element refers to node " + std::to_string(node) +
                     ", which $Nodes does not define.");
        }

        std::istream                       &in;
        const std::string                  &where;
        std::string                         line;
        std::string                         version;
        bool                                v2 = false, v4 = false;
        std::vector<long long>              ids;
        std::vector<std::vector<long long>> element_nodes;
      };

    } // namespace



    void
    check_msh(const std::string &file, const std::string &where)
    {
      check_regular_file(file, where);
      std::ifstream in(file);
      AssertThrow(in.good(),
                  dealii::ExcMessage(where + ": cannot open the file."));
      MshChecker(in, where).run();
    }



    void
    check_msh_on_all_ranks(const std::string &file,
                           const std::string &where,
                           const MPI_Comm     comm)
    {
      const unsigned int n_ranks =
        dealii::Utilities::MPI::n_mpi_processes(comm);
      if (n_ranks == 1)
        return check_msh(file, where);
      std::string error;
      try
        {
          check_msh(file, where);
        }
      catch (const std::exception &e)
        {
          error = error_text(e);
        }
      const auto errors = dealii::Utilities::MPI::all_gather(comm, error);
      for (unsigned int r = 0; r < n_ranks; ++r)
        AssertThrow(errors[r].empty(),
                    dealii::ExcMessage("on rank " + std::to_string(r) + ": " +
                                       errors[r]));
      // Every rank reads the file for itself: different bytes (another
      // file under the same name) would give the ranks different meshes.
      const auto sums =
        dealii::Utilities::MPI::all_gather(comm,
                                           fnv1a_of_file(file).value_or(0));
      for (unsigned int r = 1; r < n_ranks; ++r)
        AssertThrow(sums[r] == sums[0],
                    dealii::ExcMessage(
                      where + ": rank 0 and rank " + std::to_string(r) +
                      " read different content (another file under this "
                      "name, or the file changed while being read); every "
                      "rank must read the same mesh file."));
    }



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
