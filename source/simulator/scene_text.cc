// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/simulator/checkpoint.h>
#include <psmpm/simulator/scene_text.h>

#include <sstream>

namespace psmpm
{
  namespace Simulator
  {
    void
    SceneText::record(const ParameterHandler &prm,
                      void (*declare)(ParameterHandler &))
    {
      std::ostringstream text;
      prm.print_parameters(text, ParameterHandler::ShortPRM);
      parameters = text.str();
      ParameterHandler declared;
      declare(declared);
      std::ostringstream defaults_text;
      declared.print_parameters(defaults_text, ParameterHandler::ShortPRM);
      defaults = defaults_text.str();
      files    = Checkpoint::file_checksums(parameters);
    }
  } // namespace Simulator
} // namespace psmpm
