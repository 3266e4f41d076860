// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_mesh_gmsh_file_h
#define psmpm_mesh_gmsh_file_h

#include <deal.II/base/mpi.h>
#include <deal.II/grid/tria.h>

#include <istream>
#include <string>
#include <vector>

namespace psmpm
{
  namespace Mesh
  {
    /// One entry of a Gmsh file's $PhysicalNames section.
    struct PhysicalName
    {
      int         dimension = 0;
      int         tag       = 0;
      std::string name;
    };

    /**
     * The $PhysicalNames section of an ASCII .msh file (formats 2 and 4
     * write it the same way: "n", then "dim tag \"name\"" per line), read
     * from the current position of @p in to the section's end; empty if
     * there is none. deal.II's GridIn reads the tags but not the names,
     * which boundaries (Mesh/File) and bodies (Bodies/Body k/Physical
     * surfaces) are given by.
     */
    std::vector<PhysicalName>
    read_physical_names(std::istream &in);

    /**
     * Refuse a Gmsh file @p file that psmpm cannot read safely, before
     * anything else reads it: not a regular file (a FIFO or a device would
     * block or never end), no $MeshFormat of version 2.x or 4.x in ASCII
     * with 8-byte data, or a missing section end. Format 2 files are
     * checked through: node counts as given, finite coordinates, each
     * node id once (deal.II would let a later node of the same id win),
     * every element's nodes defined, element types with known node counts.
     * Throws ExcMessage "<where>: ..." (@p where: "Mesh/File = x.msh").
     */
    void
    check_msh(const std::string &file, const std::string &where);

    /**
     * check_msh() on every rank of @p comm (collective), which must agree:
     * a file that some rank cannot read ends every rank with ExcMessage
     * "on rank <r>: <where>: ..." (the first such rank), and so does a file
     * whose bytes differ between ranks, instead of one rank leaving while
     * the others wait in the next collective call. On one rank: check_msh().
     */
    void
    check_msh_on_all_ranks(const std::string &file,
                           const std::string &where,
                           const MPI_Comm     comm);

    /**
     * The cells of the .msh file @p in (from its start) into @p tria with
     * deal.II's GridIn (cell material ids: the physical tags). A file
     * GridIn cannot read throws ExcMessage "<where>: not a readable Gmsh
     * mesh (...)"; @p where names the entry and file ("Mesh/File = x.msh").
     */
    void
    read_cells(std::istream             &in,
               dealii::Triangulation<2> &tria,
               const std::string        &where);
  } // namespace Mesh
} // namespace psmpm

#endif
