// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_postprocess_particle_hdf5_writer_h
#define psmpm_postprocess_particle_hdf5_writer_h

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>
#include <deal.II/numerics/data_component_interpretation.h>

#include <cstdint>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace psmpm
{
  class Archive;

  namespace Postprocess
  {
    using namespace dealii;

    /// deal.II's description of vector and tensor fields among the data
    /// components: first and last component, name, interpretation.
    using DataRanges = std::vector<
      std::tuple<unsigned int,
                 unsigned int,
                 std::string,
                 DataComponentInterpretation::DataComponentInterpretation>>;

    /**
     * Particle output for large runs (`Output/Particle format = hdf5`):
     * every output is ONE HDF5 file `particles-<step>.h5` for all MPI
     * ranks, written collectively by deal.II (DataOutBase::
     * write_filtered_data and write_hdf5_parallel), and rank 0 keeps the
     * time series `particles.xdmf`, which ParaView opens with its XDMF
     * reader. One file per output instead of one VTU piece per rank plus
     * a .pvtu keeps the number of files small, and raw binary datasets
     * need no zlib/base64 encoding.
     *
     * The file holds the datasets "nodes" (n x 2 positions), "cells"
     * (n x 1, a polyvertex per particle) and one dataset per field of the
     * VTU output under the same name: vectors as n x 3 (deal.II pads the
     * third component with zeros), every other component as an n x 1
     * scalar. Tensors (stress, tensor-valued material state) are written
     * as their scalar components (stress_xx, stress_xy, ...): deal.II
     * 9.4's DataOutFilter forces every non-scalar field to 3 components,
     * which would cut a 2D tensor's four to three and drop the yy one.
     * Datasets are doubles, but the field values pass through the
     * patches' Float32 table (DataOutBase::Patch::data), so they carry
     * the precision of the VTU output; positions are exact.
     *
     * HDF5 stores positions in 2 or 3 space dimensions only: 2D runs.
     */
    class ParticleHdf5Writer
    {
    public:
      /// Writes into @p directory (which must exist); collective on
      /// @p comm.
      ParticleHdf5Writer(const std::string &directory, MPI_Comm comm);

      /// The file of the output of step @p step: "particles-00012.h5".
      static std::string
      file_name(const unsigned int step);

      /**
       * Write this output's file (collective) and, on rank 0, rewrite
       * particles.xdmf with it. @p names and @p ranges: the data
       * components of the patches as for DataOutBase::write_vtu. The file
       * is written as "<file>.tmp" and renamed when every rank has
       * written its part, so a reader never sees half a file; a failed
       * write removes it and throws ExcWriteFailed naming the file on
       * every rank.
       */
      template <int spacedim>
      void
      write(const unsigned int                                  step,
            const double                                        time,
            const std::vector<std::string>                     &names,
            const DataRanges                                   &ranges,
            const std::vector<DataOutBase::Patch<0, spacedim>> &patches);

      /// Rank 0: write particles.xdmf from the records (atomically).
      /// Throws ExcWriteFailed.
      void
      write_index() const;

      /// The XDMF records (checkpoints).
      void
      save(Archive &archive) const;
      /// The records of @p archive; none if it has none (a checkpoint of
      /// a VTU run).
      void
      load(const Archive &archive);

    private:
      /// One output in particles.xdmf.
      struct Record
      {
        double        time;
        std::string   file;
        std::uint64_t n_points;
        /// Field name and number of components (1 or 3).
        std::vector<std::pair<std::string, unsigned int>> fields;
      };

      std::string         directory;
      MPI_Comm            comm;
      std::vector<Record> records;
    };
  } // namespace Postprocess
} // namespace psmpm

#endif
