// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// A driven body (Bodies/Body k/Motion = prescribed) in the contact
// correction: infinite mass.
// (a) correct_pair with m_b = infinity: approaching head on, body a takes
//     b's normal velocity, b keeps its own bit for bit, the impulse is
//     m_a times the approach speed; separating: nothing changes; an
//     oblique approach with mu = 0.2 (slip: a's tangential velocity
//     relative to b drops by exactly mu times the normal one) and
//     no-slip (a moves with b); the driven body first (m_a = infinity)
//     gives the mirror image; two infinite masses: no correction.
// (b) Contact::apply at one node with bodies 1 (free), 2 (driven) and 3
//     (driven), no-slip: the free body takes body 2's velocity and then,
//     approaching body 3, body 3's;
//     the driven velocities stay; pair 2-3 is skipped although they
//     approach; the impulses reported are the free body's momentum
//     change.
#include "../tests.h"
#include "contact_test_tools.h"

#include <limits>

namespace
{
  constexpr double infinite = std::numeric_limits<double>::infinity();

  void
  print(std::ostream                   &out,
        const std::string              &name,
        const bool                      corrected,
        const Tensor<1, 2>             &v_a,
        const Tensor<1, 2>             &v_b,
        const ContactPairStatistics<2> &s)
  {
    out << name << ": corrected " << corrected << ", v_a = (" << filter(v_a[0])
        << ", " << filter(v_a[1]) << "), v_b = (" << filter(v_b[0]) << ", "
        << filter(v_b[1]) << "), impulse (" << filter(s.impulse[0]) << ", "
        << filter(s.impulse[1]) << "), normal " << filter(s.normal_impulse)
        << ", tangential " << filter(s.tangential_impulse) << std::endl;
  }

  void
  pairs(std::ostream &out)
  {
    out << "(a) correct_pair with a driven body" << std::endl;
    const Tensor<1, 2> n = vec(0, -1); // from a (above) down to b
    const double       m = 2;
    {
      // a falls at 1 onto b moving down at 0.25: a takes -0.25.
      Tensor<1, 2>             v_a = vec(0, -1), v_b = vec(0, -0.25);
      ContactPairStatistics<2> s;
      const bool c = correct_pair(m, infinite, v_a, v_b, n, 0.2, s);
      print(out, "head on", c, v_a, v_b, s);
      PSMPM_CHECK(out, c && v_a == vec(0, -0.25) && v_b == vec(0, -0.25));
      PSMPM_CHECK(out, s.impulse == m * vec(0, 0.75));
      PSMPM_CHECK(out, s.normal_impulse == m * 0.75);
      PSMPM_CHECK(out, s.n_contact_nodes == 1);
    }
    {
      Tensor<1, 2>             v_a = vec(0.3, 0.5), v_b = vec(0, -0.25);
      ContactPairStatistics<2> s;
      const bool c = correct_pair(m, infinite, v_a, v_b, n, 0.2, s);
      print(out, "separating", c, v_a, v_b, s);
      PSMPM_CHECK(out, !c && v_a == vec(0.3, 0.5) && v_b == vec(0, -0.25));
      PSMPM_CHECK(out, s.n_contact_nodes == 0 && s.impulse.norm() == 0);
    }
    {
      // Relative velocity (1, -1): normal 1, tangential 1; mu = 0.2
      // leaves 0.8 of the tangential one.
      Tensor<1, 2>             v_a = vec(1, -1.25), v_b = vec(0, -0.25);
      ContactPairStatistics<2> s;
      const bool c = correct_pair(m, infinite, v_a, v_b, n, 0.2, s);
      print(out, "oblique, mu = 0.2", c, v_a, v_b, s);
      PSMPM_CHECK(out, c && v_b == vec(0, -0.25));
      PSMPM_CHECK(out, (v_a - vec(0.8, -0.25)).norm() <= 1e-15);
      PSMPM_CHECK(out, std::abs(s.tangential_impulse - 0.2 * m) <= 1e-15);
    }
    {
      Tensor<1, 2>             v_a = vec(1, -1.25), v_b = vec(0, -0.25);
      ContactPairStatistics<2> s;
      const bool c = correct_pair(m, infinite, v_a, v_b, n, infinite, s);
      print(out, "oblique, no-slip", c, v_a, v_b, s);
      PSMPM_CHECK(out, c && v_a == v_b && v_b == vec(0, -0.25));
      PSMPM_CHECK(out, s.impulse == m * vec(-1, 1));
    }
    {
      // The driven body first: b (below, free) moves up into a.
      Tensor<1, 2>             v_a = vec(0, -0.25), v_b = vec(0, 1);
      ContactPairStatistics<2> s;
      const bool c = correct_pair(infinite, m, v_a, v_b, n, 0.2, s);
      print(out, "driven first", c, v_a, v_b, s);
      PSMPM_CHECK(out, c && v_a == vec(0, -0.25) && v_b == vec(0, -0.25));
      // The impulse on a; b took -J.
      PSMPM_CHECK(out, s.impulse == m * vec(0, 1.25));
    }
    {
      Tensor<1, 2>             v_a = vec(0, -1), v_b = vec(0, 1);
      ContactPairStatistics<2> s;
      const bool c = correct_pair(infinite, infinite, v_a, v_b, n, 0.2, s);
      print(out, "both driven", c, v_a, v_b, s);
      PSMPM_CHECK(out, !c && v_a == vec(0, -1) && v_b == vec(0, 1));
    }
  }

  void
  node(std::ostream &out)
  {
    out << "(b) Contact::apply with bodies 2 and 3 driven" << std::endl;
    auto contact   = make_contact<2>({{"Type", "multi-velocity"},
                                      {"Friction coefficient", "no-slip"},
                                      {"Normal", "larger gradient"},
                                      {"Separation criterion", "none"}},
                                   3);
    contact.driven = {0, 1, 1};
    ContactFields<2> f;
    f.reinit(1, 3, false, false);
    // Body 1 below the node moving up (barely there: the normals are
    // the driven bodies'); body 2 above pressing down; body 3 on the
    // right moving left.
    f.mass          = {2, 5, 4};
    f.mass_gradient = {vec(0, 0.1), vec(0, -1), vec(-1, 0)};
    f.velocity      = {vec(0.5, 1), vec(0, -0.5), vec(-0.2, 0)};
    std::vector<ContactPairStatistics<2>> s;
    contact.apply(f, s);
    for (unsigned int b = 0; b < 3; ++b)
      out << "v_" << b + 1 << " = (" << filter(f.velocity[b][0]) << ", "
          << filter(f.velocity[b][1]) << ")" << std::endl;
    for (const auto &[a, b] :
         {std::pair<unsigned, unsigned>{0, 1}, {0, 2}, {1, 2}})
      {
        const auto &t = s[Contact<2>::pair_index(a, b, 3)];
        out << "pair " << a + 1 << "-" << b + 1 << ": nodes "
            << t.n_contact_nodes << ", impulse (" << filter(t.impulse[0])
            << ", " << filter(t.impulse[1]) << ")" << std::endl;
      }
    // No-slip against 2 gives body 1 the velocity of 2; it then moves
    // right relative to 3 (w.n = 0.2 > 0 along n = (1, 0)) and takes 3's
    // velocity. Bodies 2 and 3 approach (w.n = 0.5 along (0, -1)) but
    // are both driven.
    PSMPM_CHECK(out, f.velocity[1] == vec(0, -0.5));
    PSMPM_CHECK(out, f.velocity[2] == vec(-0.2, 0));
    PSMPM_CHECK(out, f.velocity[0] == vec(-0.2, 0));
    PSMPM_CHECK(out, s[Contact<2>::pair_index(1, 2, 3)].n_contact_nodes == 0);
    const Tensor<1, 2> J = s[Contact<2>::pair_index(0, 1, 3)].impulse +
                           s[Contact<2>::pair_index(0, 2, 3)].impulse;
    PSMPM_CHECK(out, (J - 2 * (vec(-0.2, 0) - vec(0.5, 1))).norm() <= 1e-15);
  }
} // namespace

int
main()
{
  return run_test([] {
    std::ofstream out("output");
    out << std::setprecision(10);
    pairs(out);
    node(out);
  });
}
