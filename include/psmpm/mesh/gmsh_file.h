// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_mesh_gmsh_file_h
#define psmpm_mesh_gmsh_file_h

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
