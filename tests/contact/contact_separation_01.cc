// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// The separation criteria of Simulator::Contact on the fields of two 1D
// bodies of particles (200 per cell) on a grid of linear hat functions,
// h = 1, body 1 moving right at speed 1 up to x = s, body 2 moving left
// from x = s + gap:
// (a) touching at a node (s = 5, gap 0) and inside a cell (s = 5.5, gap
//     0): the volume fraction criterion (f_c = 0.8) and the distance
//     criterion (d_c = 0.9 h) find contact at the nodes where both
//     bodies have mass, and the bodies' velocities there become 0;
// (b) one cell apart (gap = h, centred on a cell and off the centre) and
//     half a cell apart at a node: both bodies have mass at a node
//     between them, the approach test alone (Separation criterion =
//     none) would correct them, the two criteria leave them apart;
// (c) the measured volume fractions and mass-centre gaps at the shared
//     nodes, against the closed forms of the hat function (touching at a
//     node: fraction 1, gap 2h/3; one cell apart: fraction 1/4, gap 4h/3).
#include "../tests.h"
#include "contact_test_tools.h"

namespace
{
  constexpr unsigned int n_nodes = 12;
  constexpr double       h       = 1;

  /// Fields of body 1 on [0, s] and body 2 on [s + gap, 11], 200
  /// particles per cell of unit density, at their cell-fraction centres.
  ContactFields<1>
  make_fields(const double s, const double gap)
  {
    ContactFields<1> f;
    f.reinit(n_nodes, 2, true, true);
    for (unsigned int i = 0; i < n_nodes; ++i)
      f.node_volume[i] = (i == 0 || i + 1 == n_nodes) ? h / 2 : h;
    const unsigned int per_cell = 200;
    const double       dx       = h / per_cell;
    for (unsigned int k = 0; k < (n_nodes - 1) * per_cell; ++k)
      {
        const double x = (k + 0.5) * dx;
        if (x > s && x < s + gap)
          continue;
        const unsigned int b = x < s ? 0 : 1;
        for (unsigned int i = 0; i < n_nodes; ++i)
          {
            const double r = x - i * h;
            if (std::abs(r) >= h)
              continue;
            const double       N = 1 - std::abs(r) / h;
            const unsigned int j = i * 2 + b;
            f.mass[j] += dx * N;
            f.volume[j] += dx * N;
            f.mass_gradient[j][0] += dx * (r > 0 ? -1 : 1) / h;
            f.centroid[j][0] += dx * N * x;
          }
      }
    for (unsigned int j = 0; j < n_nodes * 2; ++j)
      {
        if (f.mass[j] > 0)
          f.centroid[j][0] /= f.mass[j];
        f.velocity[j][0] = j % 2 == 0 ? 1 : -1;
      }
    return f;
  }

  /// Nodes where both bodies have mass: their volume fraction and gap.
  void
  print_shared_nodes(std::ostream &out, const ContactFields<1> &f)
  {
    for (unsigned int i = 0; i < n_nodes; ++i)
      if (f.mass[2 * i] > 0 && f.mass[2 * i + 1] > 0)
        out << "  node " << i << ": volume fraction "
            << (f.volume[2 * i] + f.volume[2 * i + 1]) / f.node_volume[i]
            << ", gap " << f.centroid[2 * i + 1][0] - f.centroid[2 * i][0]
            << std::endl;
  }

  /// The number of nodes corrected with @p criterion.
  unsigned int
  contact_nodes(const ContactFields<1> &fields, const std::string &criterion)
  {
    const auto       contact = make_contact<1>({{"Type", "multi-velocity"},
                                                {"Separation criterion", criterion},
                                                {"Contact distance", "0.9"}},
                                         2);
    ContactFields<1> f       = fields;
    std::vector<ContactPairStatistics<1>> s;
    contact.apply(f, s);
    // Corrected nodes stop (equal masses, no tangent), the others keep
    // their speeds.
    for (unsigned int i = 0; i < n_nodes; ++i)
      if (f.mass[2 * i] > 0 && f.mass[2 * i + 1] > 0 &&
          f.velocity[2 * i][0] != 1)
        AssertThrow(std::abs(f.velocity[2 * i][0] - f.velocity[2 * i + 1][0]) <
                      1e-14,
                    ExcInternalError());
    return s[0].n_contact_nodes;
  }
} // namespace

int
main()
{
  return run_test([] {
    std::ofstream out("output");
    out << std::setprecision(4);
    for (const auto &[s, gap, touching] :
         {std::tuple<double, double, bool>{5., 0., true},
          {5.5, 0., true},
          {5.5, 1., false},
          {4.75, 1., false},
          {5., 0.5, false}})
      {
        const ContactFields<1> f = make_fields(s, gap);
        out << "body 1 up to " << s << ", gap " << gap << std::endl;
        print_shared_nodes(out, f);
        const unsigned int none     = contact_nodes(f, "none");
        const unsigned int fraction = contact_nodes(f, "volume fraction");
        const unsigned int distance = contact_nodes(f, "distance");
        out << "  contact nodes: none " << none << ", volume fraction "
            << fraction << ", distance " << distance << std::endl;
        PSMPM_CHECK(out, none > 0);
        if (touching)
          PSMPM_CHECK(out, fraction == none && distance == none);
        else
          PSMPM_CHECK(out, fraction == 0 && distance == 0);
      }
  });
}
