// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/base/archive.h>
#include <psmpm/simulator/run_record.h>

namespace psmpm
{
  namespace Simulator
  {
    void
    RunRecord::save(Archive &archive) const
    {
      archive.put_integer("simulator/cg_iterations", total_iterations);
      archive.put_integer("simulator/time_outputs", time_outputs);
      archive.put("simulator/wall_time", wall_offset + wall.wall_time());
      archive.put("simulator/step_times", step_times);
    }

    void
    RunRecord::load(const Archive &archive)
    {
      total_iterations = archive.get_integer("simulator/cg_iterations");
      time_outputs     = archive.get_integer("simulator/time_outputs");
      wall_offset      = archive.get_number("simulator/wall_time");
      cell_crossings_offset =
        archive.has("simulator/cell_crossings") ?
          archive.get_integer("simulator/cell_crossings") :
          0;
    }
  } // namespace Simulator
} // namespace psmpm
