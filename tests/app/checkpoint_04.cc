// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Checkpoint::parameter_differences with entries added since a checkpoint
// was written: an entry missing from the checkpoint is accepted on resume
// if its current value is its default (so a checkpoint of an older psmpm
// resumes in a newer one), refused if it was set to something else, and
// refused as before when no defaults are given; changed values and
// entries no longer declared are still reported, and entries that may
// change (Time/End time) are not.
#include <deal.II/base/parameter_handler.h>

#include <psmpm/simulator/checkpoint.h>

#include "../tests.h"

#include <fstream>
#include <sstream>

namespace
{
  /// ShortPRM text of a handler with entries "Time/End time", "Material/
  /// Density" and, if @p with_new, "Material/Model" (the "new" entry),
  /// with the given values set.
  std::string
  text(const bool                                              with_new,
       const std::vector<std::pair<std::string, std::string>> &values)
  {
    ParameterHandler prm;
    prm.enter_subsection("Time");
    prm.declare_entry("End time", "1", Patterns::Double());
    prm.leave_subsection();
    prm.enter_subsection("Material");
    prm.declare_entry("Density", "1", Patterns::Double());
    if (with_new)
      prm.declare_entry("Model", "hypoelastic", Patterns::Anything());
    prm.leave_subsection();
    for (const auto &[path, value] : values)
      {
        const auto slash = path.find('/');
        prm.enter_subsection(path.substr(0, slash));
        prm.set(path.substr(slash + 1), value);
        prm.leave_subsection();
      }
    std::ostringstream out;
    prm.print_parameters(out, ParameterHandler::ShortPRM);
    return out.str();
  }

  void
  print(std::ostream &out, const std::vector<std::string> &differences)
  {
    out << differences.size() << " difference(s)";
    for (const auto &d : differences)
      out << "; " << d;
    out << std::endl;
  }
} // namespace

int
main()
{
  std::ofstream out("output");
  using psmpm::Simulator::Checkpoint;
  const std::string old_checkpoint = text(false, {{"Material/Density", "2"}});
  const std::string defaults       = text(true, {});

  const auto at_default =
    Checkpoint::parameter_differences(old_checkpoint,
                                      text(true, {{"Material/Density", "2"}}),
                                      defaults);
  out << "new entry at its default: ";
  print(out, at_default);
  PSMPM_CHECK(out, at_default.empty());

  const auto set = Checkpoint::parameter_differences(
    old_checkpoint,
    text(true, {{"Material/Density", "2"}, {"Material/Model", "neo-hookean"}}),
    defaults);
  out << "new entry set: ";
  print(out, set);
  PSMPM_CHECK(out, set.size() == 1 && set[0].find("Material/Model") == 0);

  const auto no_defaults =
    Checkpoint::parameter_differences(old_checkpoint,
                                      text(true, {{"Material/Density", "2"}}));
  out << "no defaults given: ";
  print(out, no_defaults);
  PSMPM_CHECK(out, no_defaults.size() == 1);

  const auto changed = Checkpoint::parameter_differences(
    old_checkpoint,
    text(true, {{"Material/Density", "3"}, {"Time/End time", "5"}}),
    defaults);
  out << "changed value, longer end time: ";
  print(out, changed);
  PSMPM_CHECK(out,
              changed.size() == 1 && changed[0].find("Material/Density") == 0);

  const auto removed =
    Checkpoint::parameter_differences(text(true,
                                           {{"Material/Model", "neo-hookean"}}),
                                      text(false, {}),
                                      defaults);
  out << "entry no longer declared: ";
  print(out, removed);
  PSMPM_CHECK(out, removed.size() == 1);
}
