// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Simulator::Contact::apply, the nodal algorithm over all nodes:
// (a) three bodies meeting at a node, each moving towards it: every pair
//     is corrected once, the node's momentum is unchanged to round-off,
//     its kinetic energy drops by exactly the normal and friction work
//     reported, and a fourth body with no mass at the node is untouched;
// (b) 2000 random nodes (seeded) of four bodies, some without mass at a
//     node, random gradients, velocities and a random coefficient per
//     pair (0, slip, no-slip), both normals: momentum conserved to 1e-14
//     of sum m |v| at every node, kinetic energy never increased (beyond
//     1e-14 relative), and the works reported sum to the change;
// (c) the average normal is antisymmetric: numbering the two bodies the
//     other way round gives the same velocities bit for bit;
// (d) pair friction: with Friction coefficient = no-slip and Pair
//     friction = 1-2: 0, a sliding approach of bodies 1 and 2 keeps its
//     tangential velocities while bodies 1 and 3 stick.
#include "../tests.h"
#include "contact_test_tools.h"

#include <random>

namespace
{
  /// Node 0 of @p f with the masses, gradients and velocities given.
  void
  set_body(ContactFields<2>  &f,
           const unsigned int b,
           const double       m,
           const Tensor<1, 2> g,
           const Tensor<1, 2> v)
  {
    f.mass[b]          = m;
    f.mass_gradient[b] = g;
    f.velocity[b]      = v;
  }

  void
  three_bodies(std::ostream &out)
  {
    out << "(a) three bodies at a node" << std::endl;
    const auto       contact = make_contact<2>({{"Type", "multi-velocity"},
                                                {"Friction coefficient", "0.2"},
                                                {"Separation criterion", "none"}},
                                         4);
    ContactFields<2> f;
    f.reinit(1, 4, false, false);
    // Body 1 below the node, 2 above on the left, 3 above on the right;
    // each mass gradient points out of its body, each body moves towards
    // the node.
    set_body(f, 0, 2.0, vec(0, 1), vec(0.1, 1.0));
    set_body(f, 1, 1.0, vec(0.8, -0.6), vec(0.7, -0.5));
    set_body(f, 2, 1.5, vec(-0.8, -0.6), vec(-0.6, -0.4));
    f.velocity[3]                            = vec(5, 5); // no mass here
    const Tensor<1, 2>                    p  = node_momentum(f, 0);
    const double                          e0 = node_kinetic_energy(f, 0);
    std::vector<ContactPairStatistics<2>> s;
    contact.apply(f, s);
    const double e1   = node_kinetic_energy(f, 0);
    double       work = 0;
    for (unsigned int a = 0; a < 4; ++a)
      for (unsigned int b = a + 1; b < 4; ++b)
        {
          const auto &t = s[Contact<2>::pair_index(a, b, 4)];
          out << "pair " << a + 1 << "-" << b + 1 << ": nodes "
              << t.n_contact_nodes << ", impulse (" << filter(t.impulse[0])
              << ", " << filter(t.impulse[1]) << "), friction work "
              << filter(t.friction_work) << std::endl;
          work += t.normal_work + t.friction_work;
        }
    for (unsigned int b = 0; b < 3; ++b)
      out << "v_" << b + 1 << " = (" << filter(f.velocity[b][0]) << ", "
          << filter(f.velocity[b][1]) << ")" << std::endl;
    out << "kinetic energy " << e0 << " -> " << e1 << std::endl;
    PSMPM_CHECK(out, (node_momentum(f, 0) - p).norm() <= 1e-15);
    PSMPM_CHECK(out, e1 < e0);
    PSMPM_CHECK(out, std::abs(e1 - e0 - work) <= 1e-14 * e0);
    PSMPM_CHECK(out, f.velocity[3] == vec(5, 5));
    PSMPM_CHECK(out, s[Contact<2>::pair_index(0, 3, 4)].n_contact_nodes == 0);
  }

  void
  random_nodes(std::ostream &out)
  {
    out << "(b) random nodes" << std::endl;
    const unsigned int                     n_nodes = 2000, n_bodies = 4;
    std::mt19937                           random(2024);
    std::uniform_real_distribution<double> u(-1, 1);
    for (const std::string normal : {"average", "larger gradient"})
      {
        const auto contact =
          make_contact<2>({{"Type", "multi-velocity"},
                           {"Friction coefficient", "0.3"},
                           {"Pair friction",
                            "1-2: 0, 1-3: no-slip, 2-4: 1.5, 3-4: 0.05"},
                           {"Normal", normal},
                           {"Separation criterion", "none"}},
                          n_bodies);
        ContactFields<2> f;
        f.reinit(n_nodes, n_bodies, false, false);
        for (unsigned int k = 0; k < n_nodes * n_bodies; ++k)
          {
            const double r     = u(random);
            f.mass[k]          = r < -0.3 ? 0. : std::pow(10., 2 * r);
            f.mass_gradient[k] = vec(u(random), u(random));
            f.velocity[k]      = vec(u(random), u(random));
          }
        std::vector<Tensor<1, 2>> p(n_nodes);
        std::vector<double>       e(n_nodes), scale(n_nodes);
        double                    e_total = 0;
        for (unsigned int i = 0; i < n_nodes; ++i)
          {
            p[i]     = node_momentum(f, i);
            e[i]     = node_kinetic_energy(f, i);
            scale[i] = node_momentum_scale(f, i);
            e_total += e[i];
          }
        std::vector<ContactPairStatistics<2>> s;
        contact.apply(f, s);
        double       momentum_error = 0, energy_rise = 0, change = 0;
        unsigned int corrected = 0;
        for (unsigned int i = 0; i < n_nodes; ++i)
          {
            if (scale[i] == 0)
              continue;
            momentum_error =
              std::max(momentum_error,
                       (node_momentum(f, i) - p[i]).norm() / scale[i]);
            const double e1 = node_kinetic_energy(f, i);
            energy_rise     = std::max(energy_rise, (e1 - e[i]) / e[i]);
            change += e1 - e[i];
          }
        double work = 0;
        for (const auto &t : s)
          {
            work += t.normal_work + t.friction_work;
            corrected += t.n_contact_nodes;
          }
        out << normal << ": corrected pairs " << corrected << std::endl;
        PSMPM_CHECK(out, corrected > 1000);
        PSMPM_CHECK(out, momentum_error <= 1e-14);
        PSMPM_CHECK(out, energy_rise <= 1e-14);
        PSMPM_CHECK(out, std::abs(change - work) <= 1e-13 * e_total);
        PSMPM_CHECK(out, change < -0.01 * e_total);
      }
  }

  void
  antisymmetric_normal(std::ostream &out)
  {
    out << "(c) average normal, bodies numbered the other way" << std::endl;
    const auto       contact = make_contact<2>({{"Type", "multi-velocity"},
                                                {"Friction coefficient", "0.4"},
                                                {"Separation criterion", "none"}},
                                         2);
    ContactFields<2> f, g;
    f.reinit(1, 2, false, false);
    g.reinit(1, 2, false, false);
    set_body(f, 0, 1.3, vec(0.2, -1.1), vec(0.3, -0.9));
    set_body(f, 1, 0.7, vec(-0.1, 0.8), vec(-0.2, -0.4));
    for (unsigned int b = 0; b < 2; ++b)
      set_body(g, 1 - b, f.mass[b], f.mass_gradient[b], f.velocity[b]);
    std::vector<ContactPairStatistics<2>> s, t;
    contact.apply(f, s);
    contact.apply(g, t);
    PSMPM_CHECK(out, s[0].n_contact_nodes == 1);
    PSMPM_CHECK(out,
                f.velocity[0] == g.velocity[1] &&
                  f.velocity[1] == g.velocity[0]);
    PSMPM_CHECK(out, s[0].impulse == -t[0].impulse);
  }

  void
  pair_friction(std::ostream &out)
  {
    out << "(d) pair friction" << std::endl;
    const auto contact = make_contact<2>({{"Type", "multi-velocity"},
                                          {"Friction coefficient", "no-slip"},
                                          {"Pair friction", "2-1: 0"},
                                          {"Separation criterion", "none"}},
                                         3);
    PSMPM_CHECK(out, contact.friction(0, 1) == 0);
    PSMPM_CHECK(out, contact.friction(1, 0) == 0);
    PSMPM_CHECK(out, std::isinf(contact.friction(0, 2)));
    PSMPM_CHECK(out, std::isinf(contact.friction(1, 2)));
    for (const unsigned int other : {1u, 2u})
      {
        ContactFields<2> f;
        f.reinit(1, 3, false, false);
        // Body 1 falls and slides onto the other body, at rest below.
        set_body(f, 0, 1., vec(0, -1), vec(1, -1));
        set_body(f, other, 1., vec(0, 1), vec(0, 0));
        std::vector<ContactPairStatistics<2>> s;
        contact.apply(f, s);
        out << "bodies 1 and " << other + 1 << ": v_1 = ("
            << filter(f.velocity[0][0]) << ", " << filter(f.velocity[0][1])
            << "), v_" << other + 1 << " = (" << filter(f.velocity[other][0])
            << ", " << filter(f.velocity[other][1]) << ")" << std::endl;
        if (other == 1)
          PSMPM_CHECK(out, f.velocity[0][0] == 1 && f.velocity[1][0] == 0);
        else
          PSMPM_CHECK(out, f.velocity[0] == f.velocity[2]);
      }
  }
} // namespace

int
main()
{
  return run_test([] {
    std::ofstream out("output");
    out << std::setprecision(10);
    three_bodies(out);
    random_nodes(out);
    antisymmetric_normal(out);
    pair_friction(out);
  });
}
