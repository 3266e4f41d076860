// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Contact/Driven body nodes = geometry, its two parts.
// (a) DrivenBodies::inside(): the footing's rectangle [0, 0.5] x
//     [2.5, 2.75] moved by its displacement (0, -0.1) (restored as from a
//     checkpoint): points inside, on the moved outline (bottom edge,
//     corner: closed) and just outside it (below the bottom, beyond the
//     side, above the moved top, at the old bottom's level outside) are
//     told apart; a free body's shape does not move.
// (b) Contact::apply with normal-only nodes of the driven body
//     (ContactFields::normal_only, the nodes outside its shape where it
//     has mass), no-slip: at an ordinary node the free body takes the
//     driven velocity (normal and tangential), at a normal-only node only
//     its normal relative velocity goes (no friction), at a separating
//     node nothing; the driven velocity never changes.
#include "../tests.h"
#include "contact_test_tools.h"

namespace
{
  void
  shape(std::ostream &out)
  {
    out << "(a) the driven body's moved shape" << std::endl;
    std::vector<psmpm::Particles::Body> bodies(2);
    bodies[0].number = 1;
    bodies[0].shape =
      psmpm::Particles::Shape::rectangle(Point<2>(0, 0), Point<2>(5, 2.5));
    bodies[1].number = 2;
    bodies[1].shape =
      psmpm::Particles::Shape::rectangle(Point<2>(0, 2.5), Point<2>(0.5, 2.75));
    bodies[1].prescribed_motion = true;
    bodies[1].motion_velocity   = "0; -0.1";
    psmpm::Simulator::DrivenBodies<2> driven;
    driven.parse(bodies, true);
    driven.set_displacements({0, 0, 0, -0.1});
    const auto show = [&](const unsigned int b, const Point<2> &x) {
      const bool in = driven.inside(b, x);
      out << "body " << b + 1 << " (" << x[0] << ", " << x[1]
          << "): " << (in ? "inside" : "outside") << std::endl;
      return in;
    };
    PSMPM_CHECK(out, show(1, Point<2>(0.25, 2.5)));
    PSMPM_CHECK(out, show(1, Point<2>(0.25, 2.4)));
    PSMPM_CHECK(out, show(1, Point<2>(0.5, 2.4)));
    PSMPM_CHECK(out, show(1, Point<2>(0.5, 2.65)));
    PSMPM_CHECK(out, !show(1, Point<2>(0.25, 2.39)));
    PSMPM_CHECK(out, !show(1, Point<2>(0.51, 2.5)));
    PSMPM_CHECK(out, !show(1, Point<2>(0.25, 2.7)));
    PSMPM_CHECK(out, !show(1, Point<2>(0.625, 2.5)));
    PSMPM_CHECK(out, show(0, Point<2>(5, 2.5)));
    const auto u = driven.displacements();
    PSMPM_CHECK(out, u.size() == 4 && u[3] == -0.1);
  }

  void
  normal_only(std::ostream &out)
  {
    out << "(b) Contact::apply with normal-only nodes of the driven body"
        << std::endl;
    auto contact   = make_contact<2>({{"Type", "multi-velocity"},
                                      {"Friction coefficient", "no-slip"},
                                      {"Separation criterion", "none"},
                                      {"Driven body nodes", "geometry"}},
                                   2);
    contact.driven = {0, 1};
    PSMPM_CHECK(out, contact.driven_nodes_from_geometry);
    ContactFields<2> f;
    f.reinit(3, 2, false, false);
    // At every node: the soil (body 1, mass 2) below, the footing (body
    // 2) above, pressing down at 0.1; the soil moves up and right at
    // nodes 0 and 1, down faster than the footing at node 2.
    for (unsigned int i = 0; i < 3; ++i)
      {
        f.mass[2 * i]              = 2;
        f.mass[2 * i + 1]          = 5;
        f.mass_gradient[2 * i]     = vec(0, 1);
        f.mass_gradient[2 * i + 1] = vec(0, -1);
        f.velocity[2 * i]          = i < 2 ? vec(0.3, 0.2) : vec(0.3, -0.5);
        f.velocity[2 * i + 1]      = vec(0, -0.1);
      }
    f.normal_only = {0, 0, 0, 1, 0, 1};
    std::vector<ContactPairStatistics<2>> s;
    contact.apply(f, s);
    for (unsigned int i = 0; i < 3; ++i)
      out << "node " << i << ", normal only " << int(f.normal_only[2 * i + 1])
          << ": soil (" << filter(f.velocity[2 * i][0]) << ", "
          << filter(f.velocity[2 * i][1]) << "), footing ("
          << filter(f.velocity[2 * i + 1][0]) << ", "
          << filter(f.velocity[2 * i + 1][1]) << ")" << std::endl;
    out << "nodes in contact " << s[0].n_contact_nodes << ", impulse ("
        << filter(s[0].impulse[0]) << ", " << filter(s[0].impulse[1])
        << "), tangential " << filter(s[0].tangential_impulse) << std::endl;
    PSMPM_CHECK(out, (f.velocity[0] - vec(0, -0.1)).norm() <= 1e-15);
    PSMPM_CHECK(out, (f.velocity[2] - vec(0.3, -0.1)).norm() <= 1e-15);
    PSMPM_CHECK(out, f.velocity[4] == vec(0.3, -0.5));
    for (unsigned int i = 0; i < 3; ++i)
      PSMPM_CHECK(out, f.velocity[2 * i + 1] == vec(0, -0.1));
    PSMPM_CHECK(out, s[0].n_contact_nodes == 2);
    // Node 0: 2 (-0.3, -0.3); node 1: 2 (0, -0.3), no tangential part.
    PSMPM_CHECK(out, (s[0].impulse - vec(-0.6, -1.2)).norm() <= 1e-15);
    PSMPM_CHECK(out, std::abs(s[0].tangential_impulse - 0.6) <= 1e-15);
  }
} // namespace

int
main()
{
  return run_test([] {
    std::ofstream out("output");
    out << std::setprecision(10);
    shape(out);
    normal_only(out);
  });
}
