// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <psmpm/app/run_limits.h>
#include <psmpm/base/format.h>

#include <unistd.h>

namespace psmpm
{
  namespace App
  {
    using namespace dealii;

    namespace
    {
      const char *override_hint =
        " Set Limits/Allow large runs = true to run it anyway.";

      double
      physical_memory_gb()
      {
        const long pages = sysconf(_SC_PHYS_PAGES);
        const long size  = sysconf(_SC_PAGE_SIZE);
        return pages > 0 && size > 0 ? double(pages) * size / 1073741824. : 64.;
      }

      std::string
      gb(const double bytes)
      {
        return prm_value(bytes / 1073741824.) + " GiB";
      }
    } // namespace

    void
    RunLimits::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Limits");
      prm.declare_entry("Allow large runs",
                        "false",
                        Patterns::Bool(),
                        "Run a scene even if its estimated steps, memory or "
                        "output volume exceed the limits below.");
      prm.declare_entry("Maximum steps",
                        "1e7",
                        Patterns::Double(1),
                        "Largest number of time steps (End time / time step) "
                        "a run may take.");
      prm.declare_entry("Maximum memory",
                        "0",
                        Patterns::Double(0),
                        "Largest estimated memory of the mesh, particles and "
                        "reference solution in GiB (0: the physical memory "
                        "of this machine).");
      prm.declare_entry("Maximum output",
                        "100",
                        Patterns::Double(0),
                        "Largest estimated output volume (VTU series and "
                        "statistics) in GiB.");
      prm.leave_subsection();
    }

    void
    RunLimits::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Limits");
      allow_large_runs = prm.get_bool("Allow large runs");
      max_steps        = prm.get_double("Maximum steps");
      max_memory_gb    = prm.get_double("Maximum memory");
      max_output_gb    = prm.get_double("Maximum output");
      prm.leave_subsection();
    }

    void
    RunLimits::check_entries(ParameterHandler &prm) const
    {
      if (allow_large_runs)
        return;
      prm.enter_subsection("Reference solution");
      const std::string reference = prm.get("Type");
      const double      elements  = prm.get_integer("ULFEM elements");
      prm.leave_subsection();
      // The reference advances with its own stable step: its work grows
      // with the square of the elements (and it is built with the scene).
      AssertThrow(reference.find("ulfem") == std::string::npos ||
                    elements <= 1e6,
                  ExcMessage("Reference solution/ULFEM elements = " +
                             prm_value(elements) +
                             " is above 1e6 (the reference's memory grows "
                             "with its elements, its work with their "
                             "square)." +
                             override_hint));
    }

    void
    RunLimits::check_scene(ParameterHandler &prm) const
    {
      if (allow_large_runs)
        return;
      prm.enter_subsection("Geometry");
      const long dimension = prm.get_integer("Dimension");
      prm.leave_subsection();
      prm.enter_subsection("Mesh");
      const std::string type     = prm.get("Type");
      const double      blocks_x = prm.get_integer("Blocks x");
      const double      blocks_y = prm.get_integer("Blocks y");
      prm.leave_subsection();
      prm.enter_subsection("Particles");
      const double per_x = prm.get_integer("Per block x");
      const double per_y = prm.get_integer("Per block y");
      prm.leave_subsection();
      prm.enter_subsection("Reference solution");
      const std::string reference = prm.get("Type");
      const double      elements  = prm.get_integer("ULFEM elements");
      prm.leave_subsection();

      // About 1 KiB per cell (triangulation, DoFs, grid arrays, locator),
      // 0.5 KiB per particle, 0.2 KiB per reference element.
      double cells = 0, particles = 0;
      if (dimension == 1)
        {
          cells     = blocks_x;
          particles = blocks_x * per_x;
        }
      else if (type != "gmsh") // a Gmsh mesh is bounded by its file
        {
          cells     = (type == "criss-cross" ? 4 : 2) * blocks_x * blocks_y;
          particles = blocks_x * blocks_y * per_x * per_y;
        }
      const bool   ulfem = reference.find("ulfem") != std::string::npos;
      const double bytes =
        1024. * cells + 512. * particles + (ulfem ? 200. * elements : 0.);
      const double limit =
        (max_memory_gb > 0 ? max_memory_gb : physical_memory_gb()) *
        1073741824.;
      AssertThrow(bytes <= limit,
                  ExcMessage(
                    "the scene needs about " + gb(bytes) +
                    " of memory (Mesh/Blocks x = " + prm_value(blocks_x) +
                    ", Blocks y = " + prm_value(blocks_y) + ": " +
                    prm_value(cells) + " cells; Particles/Per block x, y: " +
                    prm_value(particles) + " particles" +
                    (ulfem ? "; Reference solution/ULFEM elements = " +
                               prm_value(elements) :
                             std::string()) +
                    "), more than Limits/Maximum memory = " + gb(limit) + "." +
                    override_hint));
    }

    void
    RunLimits::check_run(const Simulator::RunSize &size) const
    {
      if (allow_large_runs)
        return;
      // The message names what sets the step: the entry of a fixed step,
      // else the material whose wave speed makes it small.
      AssertThrow(
        size.steps <= max_steps,
        ExcMessage("Time/End time = " + prm_value(size.end_time) + " and " +
                   (size.time_step.empty() ? "the time step" : size.time_step) +
                   " ask for " + prm_value(size.steps) +
                   " steps, more than Limits/Maximum steps = " +
                   prm_value(max_steps) + "." + override_hint));
      AssertThrow(size.output_bytes <= max_output_gb * 1073741824.,
                  ExcMessage(
                    "the run would write about " + gb(size.output_bytes) +
                    " (" + prm_value(size.n_outputs) +
                    " outputs of Output/Interval and Output/Time "
                    "interval, " +
                    prm_value(size.n_particles) + " particles, " +
                    prm_value(size.n_cells) +
                    " cells), more than Limits/Maximum output = " +
                    prm_value(max_output_gb) + " GiB." + override_hint));
    }
  } // namespace App
} // namespace psmpm
