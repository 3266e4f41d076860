// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/simulator/output_files.h>

namespace psmpm
{
  namespace Simulator
  {
    template <int dim>
    void
    OutputFiles<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      prm.declare_entry("Interval",
                        "0",
                        Patterns::Integer(0),
                        "Write VTU output every this many steps (0: first and "
                        "last step only).");
      prm.leave_subsection();
    }

    template <int dim>
    void
    OutputFiles<dim>::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      interval        = prm.get_integer("Interval");
      subdivisions    = prm.get_integer("Subdivisions");
      particle_format = Postprocess::OutputWriter<dim>::parse_particle_format(
        prm.get("Particle format"));
      prm.leave_subsection();
    }

    template <int dim>
    void
    OutputFiles<dim>::check_particle_format() const
    {
      AssertThrow(particle_format == Postprocess::ParticleFormat::vtu ||
                    dim >= 2,
                  ExcMessage("Output/Particle format = hdf5 needs "
                             "Geometry/Dimension = 2; use vtu in 1D."));
    }

    template <int dim>
    unsigned int
    OutputFiles<dim>::grid_subdivisions(const unsigned int degree) const
    {
      return subdivisions > 0 ? subdivisions : (degree == 1 ? 1 : 4);
    }

    template <int dim>
    void
    OutputFiles<dim>::create_writer(const std::string &output_directory,
                                    MPI_Comm           comm,
                                    const unsigned int degree)
    {
      directory = output_directory;
      writer =
        std::make_unique<Postprocess::OutputWriter<dim>>(directory,
                                                         comm,
                                                         grid_subdivisions(
                                                           degree),
                                                         particle_format);
    }

    template <int dim>
    void
    OutputFiles<dim>::write_statistics(
      const std::vector<std::string> &scientific_columns)
    {
      std::vector<std::string> columns = {"time", "dt", "wall_time"};
      columns.insert(columns.end(),
                     scientific_columns.begin(),
                     scientific_columns.end());
      for (const auto &c : columns)
        {
          statistics.set_scientific(c, true);
          statistics.set_precision(c, 8);
        }
      const std::string file = directory + "/statistics.txt";
      if (!statistics_file || statistics_file->name() != file)
        statistics_file = std::make_unique<GrowingTextFile>(file);
      statistics_file->write(
        statistics.layout(),
        statistics.n_rows(),
        [this](std::ostream &out) { statistics.write_header(out); },
        [this](std::ostream      &out,
               const unsigned int begin,
               const unsigned int end) {
          statistics.write_rows(out, begin, end);
        });
    }

    template struct OutputFiles<1>;
    template struct OutputFiles<2>;
  } // namespace Simulator
} // namespace psmpm
