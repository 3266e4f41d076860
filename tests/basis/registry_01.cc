// ---------------------------------------------------------------------
// psmpm: the spaces register themselves: SpaceRegistry<1> offers
// "bspline|linear", SpaceRegistry<2> "bspline|linear|powell-sabin" (2D
// bspline: the tensor-product B-splines of Mesh/Type = cartesian);
// create_space<dim> builds them by name, and an unknown name (or a 2D-only
// space asked for in 1D) throws an error
// naming the parameter Basis/Type and the known names. The bspline space
// is verified with lumped, consistent and ghost penalty mass (at its
// default degree 2) and MUSL/USL only, and refuses a Basis/Degree above 5.
// ---------------------------------------------------------------------
#include <deal.II/base/patterns.h>

#include <psmpm/basis/space.h>

#include "../tests.h"

namespace
{
  using namespace psmpm;

  /// The message of the exception, without deal.II's decoration, joined
  /// into one line; empty if nothing was thrown.
  template <int dim>
  std::string
  creation_error(const std::string &name)
  {
    try
      {
        Basis::create_space<dim>(name);
      }
    catch (const std::exception &e)
      {
        const std::string what  = e.what();
        const auto        begin = what.find("Basis/Type");
        if (begin == std::string::npos)
          return "(no Basis/Type in: " + what + ")";
        const auto  end = what.find("\n\n", begin);
        std::string message;
        for (const char c : what.substr(begin, end - begin))
          if (c == '\n' || c == ' ')
            {
              if (message.empty() || message.back() != ' ')
                message += ' ';
            }
          else
            message += c;
        return message;
      }
    return "";
  }
} // namespace

int
main()
{
  return run_test([]() {
    std::ofstream out("output");
    using namespace psmpm;

    const auto &registry_1d = Basis::SpaceRegistry<1>::instance();
    const auto &registry_2d = Basis::SpaceRegistry<2>::instance();
    out << "1D: " << registry_1d.selection() << std::endl
        << "  " << registry_1d.documentation() << std::endl
        << "2D: " << registry_2d.selection() << std::endl
        << "  " << registry_2d.documentation() << std::endl;
    PSMPM_CHECK(out, registry_1d.selection() == "bspline|linear");
    PSMPM_CHECK(out, registry_2d.selection() == "bspline|linear|powell-sabin");
    PSMPM_CHECK(out, !registry_1d.has("powell-sabin"));

    // What the parameter file accepts is what the registry holds.
    const Patterns::Selection pattern(registry_2d.selection());
    PSMPM_CHECK(out, pattern.match("powell-sabin") && pattern.match("linear"));
    PSMPM_CHECK(out, !pattern.match("quadratic"));

    for (const std::string name : {"linear", "powell-sabin"})
      {
        const auto space = Basis::create_space<2>(name);
        out << "2D " << space->name() << ": dofs per cell "
            << space->dofs_per_cell() << ", per vertex "
            << space->dofs_per_vertex() << ", stability factor lumped "
            << space->stability_factor(true) << ", consistent "
            << space->stability_factor(false) << std::endl;
        PSMPM_CHECK(out, space->name() == name);
      }
    for (const std::string name : {"linear", "bspline"})
      {
        const auto space = Basis::create_space<1>(name);
        out << "1D " << space->name() << ": dofs per cell "
            << space->dofs_per_cell() << ", per vertex "
            << space->dofs_per_vertex() << ", stability factor lumped "
            << space->stability_factor(true) << ", consistent "
            << space->stability_factor(false) << ", default mass "
            << space->default_mass_matrix() << std::endl;
        PSMPM_CHECK(out, space->name() == name);
        out << "  verified mass matrices:";
        for (const auto &m : space->verified_mass_matrices())
          out << ' ' << m;
        out << "; transfers:";
        for (const auto &t : space->verified_transfers())
          out << ' ' << t;
        out << std::endl;
      }
    {
      // Linear and Powell-Sabin accept every variant (empty lists), the
      // B-splines only what was verified with them.
      const auto linear  = Basis::create_space<1>("linear");
      const auto bspline = Basis::create_space<1>("bspline");
      PSMPM_CHECK(out, linear->verified_mass_matrices().empty());
      PSMPM_CHECK(out, bspline->verified_mass_matrices().size() == 3);
      PSMPM_CHECK(out, bspline->verified_transfers().size() == 2);
      PSMPM_CHECK(out, bspline->default_mass_matrix() == "consistent");
      bool refused = false;
      try
        {
          bspline->set_degree(6);
        }
      catch (const std::exception &e)
        {
          refused =
            std::string(e.what()).find("Basis/Degree = 6") != std::string::npos;
        }
      PSMPM_CHECK(out, refused);
      linear->set_degree(3); // fixed degree: ignored
      PSMPM_CHECK(out, linear->degree() == 1);
    }

    const std::string unknown_2d = creation_error<2>("quadratic");
    const std::string unknown_1d = creation_error<1>("powell-sabin");
    // 2D bspline: as in 1D, verified with lumped (p <= 2), consistent and
    // ghost penalty mass; lumped by default for p <= 2,
    // ghost penalty for p >= 3 (consistent on closed, filled meshes).
    const auto bspline_2d = Basis::create_space<2>("bspline");
    PSMPM_CHECK(out, bspline_2d->verified_mass_matrices().size() == 3);
    PSMPM_CHECK(out,
                bspline_2d->verified_mass_matrices()[2] == "ghost penalty");
    PSMPM_CHECK(out, bspline_2d->default_mass_matrix() == "lumped");
    PSMPM_CHECK(out, bspline_2d->closed_mass_matrix() == "consistent");
    bspline_2d->set_degree(3);
    PSMPM_CHECK(out, bspline_2d->verified_mass_matrices().size() == 2);
    PSMPM_CHECK(out, bspline_2d->default_mass_matrix() == "ghost penalty");
    out << "2D quadratic: " << unknown_2d << std::endl
        << "1D powell-sabin: " << unknown_1d << std::endl;
    PSMPM_CHECK(out, unknown_2d.find("Basis/Type = quadratic") == 0);
    PSMPM_CHECK(out,
                unknown_2d.find("bspline, linear, powell-sabin") !=
                  std::string::npos);
    PSMPM_CHECK(out, unknown_1d.find("Basis/Type = powell-sabin") == 0);
    PSMPM_CHECK(out, creation_error<2>("linear").empty());
  });
}
