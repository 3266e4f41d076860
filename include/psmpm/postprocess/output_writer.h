// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_postprocess_output_writer_h
#define psmpm_postprocess_output_writer_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>

#include <psmpm/basis/space.h>
#include <psmpm/particles/particle_set.h>

#include <string>
#include <utility>
#include <vector>

namespace psmpm
{
  namespace Postprocess
  {
    using namespace dealii;

    /**
     * VTU output that ParaView opens: one piece per rank, a .pvtu per
     * step and a .pvd series each for particles and grid. Grid fields are
     * evaluated through the Space at the vertices of every cell, so the
     * same code serves P1 and Powell-Sabin (piecewise linear display).
     */
    class OutputWriter
    {
    public:
      OutputWriter(const std::string &directory, MPI_Comm comm);

      void
      write_particles(const unsigned int            step,
                      const double                  time,
                      const Particles::ParticleSet &particles);

      /// @p fields: name and coefficients (local relevant numbering, with
      /// @p cell_dofs mapping cell c's k-th function to a coefficient).
      void
      write_grid(
        const unsigned int               step,
        const double                     time,
        const DoFHandler<2>             &dof_handler,
        const Basis::Space              &space,
        const std::vector<unsigned int> &cell_dofs,
        const std::vector<
          std::pair<std::string, const std::vector<Tensor<1, 2>> *>>
          &vector_fields,
        const std::vector<std::pair<std::string, const std::vector<double> *>>
          &scalar_fields);

    private:
      void
      write_pvd(
        const std::string                                 &name,
        const std::vector<std::pair<double, std::string>> &records) const;

      std::string                                 directory;
      MPI_Comm                                    comm;
      std::vector<std::pair<double, std::string>> particle_records;
      std::vector<std::pair<double, std::string>> grid_records;
    };
  } // namespace Postprocess
} // namespace psmpm

#endif
