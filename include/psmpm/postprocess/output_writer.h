// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_postprocess_output_writer_h
#define psmpm_postprocess_output_writer_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>

#include <psmpm/basis/space.h>
#include <psmpm/particles/particle_set.h>
#include <psmpm/postprocess/particle_hdf5_writer.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace psmpm
{
  class Archive;

  namespace Postprocess
  {
    using namespace dealii;

    /// How particles are written (`Output/Particle format`).
    enum class ParticleFormat
    {
      /// One VTU piece per rank, a .pvtu per output, particles.pvd.
      vtu,
      /// One HDF5 file per output for all ranks, particles.xdmf
      /// (ParticleHdf5Writer; 2D only).
      hdf5
    };

    /**
     * VTU output that ParaView opens: one piece per rank, a .pvtu per
     * step and a .pvd series each for particles ("particles.pvd") and grid
     * ("grid.pvd") in the output directory. With ParticleFormat::hdf5 the
     * particles go into one HDF5 file per output and the series
     * "particles.xdmf" instead (ParticleHdf5Writer); the grid stays VTU.
     *
     * Grid fields are evaluated through the Space on a lattice of
     * `subdivisions` sub-cells per cell edge, so the same code serves P1
     * and Powell-Sabin, and the quadratic Powell-Sabin fields look smooth
     * instead of being shown as their linear interpolant at the corners.
     * deal.II 9.4 does not subdivide simplex patches (only hypercube
     * ones), so in 2D every sub-triangle is a patch of its own; in 1D a
     * cell is one line patch with n_subdivisions = subdivisions.
     *
     * Collective: every rank of @p comm calls the write functions; rank 0
     * writes the .pvtu and .pvd records. The directory must exist.
     */
    template <int dim>
    class OutputWriter
    {
    public:
      /// @p subdivisions: sub-cells per cell edge of the grid output (>= 1).
      OutputWriter(const std::string   &directory,
                   MPI_Comm             comm,
                   const unsigned int   subdivisions,
                   const ParticleFormat particle_format = ParticleFormat::vtu);

      /// Declare "Subdivisions" and "Particle format" in subsection
      /// "Output".
      static void
      declare_parameters(ParameterHandler &prm);

      /// The format named by @p name ("vtu" or "hdf5"; "Particle format").
      static ParticleFormat
      parse_particle_format(const std::string &name);

      /**
       * One point per particle with the fields id, cell, rank, mass,
       * volume, density, the vectors displacement and velocity, the
       * Cauchy stress as a (symmetric) tensor and every material state
       * scalar under its name (particles.get_state_names()).
       *
       * The VTU piece is the file deal.II's DataOutBase::write_vtu() writes
       * for one patch per particle, but written array by array from the
       * particle arrays with memory independent of the number of particles
       * (the patches cost about 336 B per particle and set a run's peak
       * memory).
       */
      void
      write_particles(const unsigned int                 step,
                      const double                       time,
                      const Particles::ParticleSet<dim> &particles);

      /**
       * The locally owned cells of @p dof_handler with the given fields:
       * name and coefficients (locally relevant numbering, with
       * @p cell_dofs mapping cell c's k-th function of @p space to
       * a coefficient: cell_dofs[c * space.dofs_per_cell() + k]). A
       * "rank" field holds the MPI rank that owns each cell.
       *
       * @p moved_vertices: for a grid that moves with the material (OTM),
       * the current vertex positions in the numbering of @p cell_dofs (P1
       * only, one function per vertex); the cells are then drawn there,
       * with a "grid_displacement" field (moved minus initial position).
       * nullptr: the triangulation's vertices.
       */
      void
      write_grid(
        const unsigned int               step,
        const double                     time,
        const DoFHandler<dim>           &dof_handler,
        const Basis::Space<dim>         &space,
        const std::vector<unsigned int> &cell_dofs,
        const std::vector<
          std::pair<std::string, const std::vector<Tensor<1, dim>> *>>
          &vector_fields,
        const std::vector<std::pair<std::string, const std::vector<double> *>>
                                      &scalar_fields,
        const std::vector<Point<dim>> *moved_vertices = nullptr);

      unsigned int
      n_subdivisions() const
      {
        return subdivisions;
      }

      /// The .pvd records so far and, for hdf5, the .xdmf records
      /// (checkpoints).
      void
      save(Archive &archive) const;
      void
      load(const Archive &archive);

      /**
       * After load(): rewrite particles.pvd (particles.xdmf for hdf5) and
       * grid.pvd from the records and remove the VTU/PVTU (and particle
       * HDF5) files of steps after @p step, which a run that went on after
       * its checkpoint wrote (rank 0; collective in that every rank must
       * call it). Throws ExcWriteFailed.
       */
      void
      restore_files(const unsigned int step) const;

    private:
      void
      write_pvd(
        const std::string                                 &name,
        const std::vector<std::pair<double, std::string>> &records) const;

      std::string                                 directory;
      MPI_Comm                                    comm;
      unsigned int                                subdivisions;
      std::vector<std::pair<double, std::string>> particle_records;
      std::vector<std::pair<double, std::string>> grid_records;
      /// The particle writer of ParticleFormat::hdf5 (then the VTU
      /// particle_records stay empty); nullptr for vtu.
      std::unique_ptr<ParticleHdf5Writer> hdf5;
    };
  } // namespace Postprocess
} // namespace psmpm

#endif
