// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Subsection Contact (Simulator::Contact::parse_parameters and
// check_bodies):
// (a) the defaults: contact off, frictionless pairs, average normal,
//     volume fraction criterion with f_c = 0.8;
// (b) a default coefficient with per-pair overrides in either order of
//     the bodies, no-slip among them: the friction table of three bodies;
// (c) bad input is refused with a message naming the entry and the
//     value (the text the application reports with exit code 2): a
//     negative or non-numeric coefficient, a malformed pair, a body
//     paired with itself, a body number above 8, a pair given twice, a
//     pair naming a body the scene does not have, contact with one body,
//     the distance criterion without a distance.
#include <deal.II/base/exceptions.h>

#include "../tests.h"
#include "contact_test_tools.h"

#include <sstream>

namespace
{
  std::string
  message(const std::exception &e)
  {
    if (const auto *d = dynamic_cast<const ExceptionBase *>(&e))
      {
        std::ostringstream s;
        d->print_info(s);
        return Utilities::trim(s.str());
      }
    return e.what();
  }

  void
  check_refused(
    std::ostream                                           &out,
    const std::vector<std::pair<std::string, std::string>> &settings,
    const unsigned int                                      n_bodies,
    const std::string                                      &mention)
  {
    try
      {
        make_contact<2>(settings, n_bodies);
        out << "FAIL accepted: " << mention << std::endl;
      }
    catch (const std::exception &e)
      {
        const std::string text = message(e);
        out << (text.find(mention) != std::string::npos ? "OK   " : "FAIL ")
            << text << std::endl;
      }
  }
} // namespace

int
main()
{
  return run_test([] {
    std::ofstream out("output");

    out << "(a) defaults" << std::endl;
    {
      const auto contact = make_contact<2>({}, 2);
      PSMPM_CHECK(out, !contact.enabled());
      PSMPM_CHECK(out, contact.friction(0, 1) == 0);
      PSMPM_CHECK(out, contact.normal_type == Contact<2>::NormalType::average);
      PSMPM_CHECK(out,
                  contact.criterion ==
                    Contact<2>::SeparationCriterion::volume_fraction);
      PSMPM_CHECK(out, contact.critical_volume_fraction == 0.8);
    }

    out << "(b) pair friction" << std::endl;
    {
      const auto contact =
        make_contact<2>({{"Type", "multi-velocity"},
                         {"Friction coefficient", "0.25"},
                         {"Pair friction", "3-1: 0.5, 2-3: no-slip"},
                         {"Normal", "larger gradient"},
                         {"Separation criterion", "distance"},
                         {"Contact distance", "0.01"}},
                        3);
      PSMPM_CHECK(out, contact.enabled());
      for (unsigned int a = 0; a < 3; ++a)
        for (unsigned int b = a + 1; b < 3; ++b)
          out << "mu(" << a + 1 << ", " << b + 1
              << ") = " << contact.friction(a, b) << std::endl;
      PSMPM_CHECK(out, contact.friction(2, 0) == 0.5);
      PSMPM_CHECK(out,
                  contact.normal_type ==
                    Contact<2>::NormalType::larger_gradient);
      PSMPM_CHECK(out, contact.contact_distance == 0.01);
    }

    out << "(c) bad input" << std::endl;
    const std::string on = "multi-velocity";
    check_refused(out,
                  {{"Type", on}, {"Friction coefficient", "-0.3"}},
                  2,
                  "Contact/Friction coefficient = -0.3");
    check_refused(out,
                  {{"Friction coefficient", "rough"}},
                  2,
                  "Contact/Friction coefficient = rough");
    check_refused(out,
                  {{"Pair friction", "1-2: -0.1"}},
                  2,
                  "Contact/Pair friction = 1-2: -0.1");
    check_refused(out,
                  {{"Pair friction", "1-2: 0.1, 12: 0.3"}},
                  2,
                  "Contact/Pair friction = 1-2: 0.1, 12: 0.3");
    check_refused(out,
                  {{"Pair friction", "2-2: 0.1"}},
                  2,
                  "Contact/Pair friction = 2-2: 0.1");
    check_refused(out,
                  {{"Pair friction", "1-9: 0.1"}},
                  2,
                  "Contact/Pair friction = 1-9: 0.1");
    check_refused(out,
                  {{"Pair friction", "1-2: 0.1, 2-1: 0.2"}},
                  2,
                  "Contact/Pair friction = 1-2: 0.1, 2-1: 0.2");
    check_refused(out,
                  {{"Type", on}, {"Pair friction", "1-3: 0.2"}},
                  2,
                  "Contact/Pair friction = 1-3: 0.2");
    check_refused(out, {{"Type", on}}, 1, "Contact/Type = multi-velocity");
    check_refused(out,
                  {{"Type", on}, {"Separation criterion", "distance"}},
                  2,
                  "Contact/Contact distance = 0");
  });
}
