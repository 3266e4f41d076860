// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_simulator_output_files_h
#define psmpm_simulator_output_files_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <psmpm/base/growing_text_file.h>
#include <psmpm/postprocess/output_writer.h>
#include <psmpm/postprocess/statistics_table.h>

#include <memory>
#include <string>
#include <vector>

namespace psmpm
{
  namespace Simulator
  {
    using namespace dealii;

    /**
     * What a run writes and where: the VTU/PVD output (OutputWriter,
     * every Output/Interval steps), the statistics rows and
     * statistics.txt, in the output directory.
     */
    template <int dim>
    struct OutputFiles
    {
      /// Output/Interval (OutputWriter declares Subdivisions and Particle
      /// format).
      static void
      declare_parameters(ParameterHandler &prm);

      /// Output/Interval, Subdivisions and Particle format.
      void
      parse_parameters(ParameterHandler &prm);

      /// Throw ExcMessage if the particle format needs another dimension
      /// (HDF5 and XDMF store points in 2 or 3 coordinates only).
      void
      check_particle_format() const;

      /// Output/Subdivisions, or for 0 what a space of @p degree needs:
      /// linear fields are exact at the corners; sub-cells cost output
      /// volume (16x for 4) that only higher degrees need.
      unsigned int
      grid_subdivisions(const unsigned int degree) const;

      /// Write into @p output_directory from now on.
      void
      create_writer(const std::string &output_directory,
                    MPI_Comm           comm,
                    const unsigned int degree);

      /// Bring statistics.txt up to date with the rows (on one rank);
      /// the columns time, dt, wall_time and @p scientific_columns in
      /// scientific notation (the postprocessors format their own).
      void
      write_statistics(const std::vector<std::string> &scientific_columns);

      std::string directory;
      /// Output/Interval.
      unsigned int interval = 0;
      /// Output/Subdivisions (0: by degree).
      unsigned int subdivisions = 0;
      /// Output/Particle format.
      Postprocess::ParticleFormat particle_format =
        Postprocess::ParticleFormat::vtu;
      Postprocess::StatisticsTable statistics;
      /// statistics.txt, appended to at every output.
      std::unique_ptr<GrowingTextFile>                statistics_file;
      std::unique_ptr<Postprocess::OutputWriter<dim>> writer;
    };
  } // namespace Simulator
} // namespace psmpm

#endif
