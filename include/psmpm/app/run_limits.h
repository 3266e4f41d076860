// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_app_run_limits_h
#define psmpm_app_run_limits_h

#include <deal.II/base/parameter_handler.h>

#include <psmpm/simulator/simulator.h>

namespace psmpm
{
  namespace App
  {
    /**
     * Sane limits on the work of a run (subsection Limits), checked before
     * anything is built or written: a scene that asks for more (an end
     * time of 1e12 s at a fixed step, an automatic step of 1e-14 s,
     * millions of blocks or reference elements, an output volume above
     * the disk) is bad input with a message naming the entries, unless
     * Limits/Allow large runs is set.
     */
    class RunLimits
    {
    public:
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /// Before the scene is parsed (which builds the reference): the
      /// reference's elements.
      void
      check_entries(dealii::ParameterHandler &prm) const;

      /// From the entries, before the mesh is built: mesh cells,
      /// particles and reference elements against the memory limit.
      void
      check_scene(dealii::ParameterHandler &prm) const;

      /// After setup: steps and output volume.
      void
      check_run(const Simulator::RunSize &size) const;

      bool   allow_large_runs = false;
      double max_steps        = 1e7;
      double max_memory_gb    = 0; ///< 0: the physical memory
      double max_output_gb    = 100;
    };
  } // namespace App
} // namespace psmpm

#endif
