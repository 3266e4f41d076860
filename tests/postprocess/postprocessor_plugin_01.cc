// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// A postprocessor defined outside psmpm's sources is one class and one
// registration (Postprocess::PostprocessorRegistry): the largest particle
// speed of every step becomes column max_speed of statistics.txt, after
// psmpm's own columns and before wall_time, its maximum over time an entry
// of summary.json and of the checkpoints. The short vibrating bar of
// prm/vibrating_bar_small.prm: the last row's value is the final state's
// largest speed, the summary's the column's largest value, and the final
// checkpoint holds it.
#include <deal.II/base/mpi.h>

#include <psmpm/base/archive.h>
#include <psmpm/postprocess/postprocessor.h>
#include <psmpm/base/summary.h>
#include <psmpm/simulator/checkpoint.h>

#include "../mpm_tests.h"

#include <algorithm>
#include <filesystem>

namespace
{
  using namespace psmpm;

  template <int dim>
  class MaxSpeed : public Postprocess::Postprocessor<dim>
  {
  public:
    void
    execute(const Postprocess::StateView<dim> &state,
            Postprocess::StatisticsTable      &statistics) override
    {
      double v2 = 0;
      for (const auto &v : state.particles.velocity)
        v2 = std::max(v2, v.norm_square());
      const double speed = Utilities::MPI::max(std::sqrt(v2), state.comm);
      largest            = std::max(largest, speed);
      statistics.add_value("max_speed", speed);
      statistics.set_scientific("max_speed", true);
      statistics.set_precision("max_speed", 8);
    }

    void
    save(Archive &archive) const override
    {
      archive.put("max_speed/largest", largest);
    }

    void
    load(const Archive &archive) override
    {
      largest = archive.get_number("max_speed/largest");
    }

    void
    fill_summary(const Postprocess::StateView<dim> &,
                 Summary &summary) const override
    {
      summary.set("max_speed_over_time", largest);
    }

  private:
    double largest = 0;
  };

  RegisterForDims<Postprocess::PostprocessorRegistry, MaxSpeed>
    register_max_speed("max speed", "the largest particle speed");
} // namespace


int
main(int argc, char **argv)
{
  using namespace psmpm;
  MPISession        mpi(argc, argv);
  std::ofstream     out("output");
  const std::string directory = "output-max-speed";
  std::filesystem::create_directories(directory);
  auto solver =
    make_scene_solver<2>("vibrating_bar_small.prm",
                         {"Time/End time=0.004", "Output/Interval=0"});
  const auto           status = solver->run(directory);
  Summary summary;
  solver->fill_summary(summary);

  const StatisticsTable table(directory);
  const auto           &names = table.names;
  out << "columns:";
  for (const auto &n : names)
    out << ' ' << n;
  out << std::endl;
  const auto column = table.column("max_speed");

  double v2 = 0;
  for (const auto &v : solver->get_particles().velocity)
    v2 = std::max(v2, v.norm_square());
  const double final_speed = std::sqrt(v2);
  const double largest     = summary.get_number("max_speed_over_time");
  const auto   archive     = Archive::read_hdf5(
    directory + "/" +
    Simulator::Checkpoint::file_name(solver->get_state().step));
  out << "rows " << column.size() << ", largest speed " << std::setprecision(6)
      << largest << std::endl;

  PSMPM_CHECK(out, status == Simulator::Status::completed);
  PSMPM_CHECK(out, names.size() > 3 && names[names.size() - 2] == "max_speed");
  PSMPM_CHECK(out, names.back() == "wall_time");
  PSMPM_CHECK(out, column.size() == solver->get_state().step + 1);
  PSMPM_CHECK(out, std::abs(column.back() / final_speed - 1) < 1e-7);
  PSMPM_CHECK(out,
              std::abs(
                *std::max_element(column.begin(), column.end()) / largest - 1) <
                1e-7);
  PSMPM_CHECK(out, largest > 0);
  PSMPM_CHECK(out, archive.get_number("max_speed/largest") == largest);
}
