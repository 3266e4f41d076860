// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_simulator_scene_text_h
#define psmpm_simulator_scene_text_h

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace psmpm
{
  namespace Simulator
  {
    using namespace dealii;

    /**
     * The scene of a run as ShortPRM text, and the content of the files it
     * reads, as checksums: what a checkpoint of the run stores and what a
     * resumed run compares it with (Checkpoint::parameter_differences(),
     * Checkpoint::file_differences()).
     */
    struct SceneText
    {
      /// The text of @p prm, of the declarations alone that @p declare
      /// makes (the defaults), and the checksums of the files it names.
      void
      record(const ParameterHandler &prm, void (*declare)(ParameterHandler &));

      /// The scene.
      std::string parameters;
      /// The declarations alone: entries added since a checkpoint was
      /// written are accepted on resume at their defaults.
      std::string defaults;
      /// Checkpoint::file_checksums() of the scene at the run's start: a
      /// mesh or geometry file edited in place between a run and its resume
      /// changes the results without changing the text of the scene.
      std::string files;
    };
  } // namespace Simulator
} // namespace psmpm

#endif
