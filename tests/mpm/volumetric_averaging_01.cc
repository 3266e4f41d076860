// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Transfer/Volumetric strain = cell average (VolumetricAveraging):
//  * on the vertical cut of prm/vertical_cut.prm at 1.3 H_c (Tresca from
//    the geostatic stress, gravity), 40 steps: every particle of a cell
//    and body changes its volume by the same ratio in a step (the volume
//    ratio is 1 + the trace of the increment) with Powell-Sabin, where
//    the particles' own ratios in a cell differ; two bodies in one cell
//    keep their own means (the cut split into two bodies at x = 1.05,
//    inside a column of cells); with P1 (divergence constant on a cell)
//    the average is skipped: the same volumes to the bit;
//  * the forces take the cell-averaged mean stress (B-bar), so an elastic
//    Powell-Sabin block sagging under its weight from zero stress (MUSL,
//    no dissipation) keeps kinetic + strain + gravity energy as well as
//    without the average: within 1 % of the energy scale over two
//    periods.
#include "../mpm_tests.h"

namespace
{
  struct Before
  {
    unsigned int cell, body;
    double       volume;
  };

  std::map<std::uint64_t, Before>
  snapshot(const psmpm::Simulator::Simulator<2> &solver)
  {
    const auto                     &p = solver.get_particles();
    std::map<std::uint64_t, Before> s;
    for (std::size_t i = 0; i < p.size(); ++i)
      s[p.id[i]] = {p.cell[i], p.body_id[i], p.volume[i]};
    return s;
  }

  /// Largest spread (max - min) of the volume ratios of a step over the
  /// particles of one cell and body (of one cell, whatever the body, if
  /// not @p by_body), and the total volume after it.
  std::pair<double, double>
  step_spread(psmpm::Simulator::Simulator<2> &solver,
              const double                    dt,
              const bool                      by_body = true)
  {
    const auto before = snapshot(solver);
    solver.do_time_step(dt);
    const auto &p = solver.get_particles();
    std::map<std::pair<unsigned int, unsigned int>, std::pair<double, double>>
           range;
    double total = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      {
        total += p.volume[i];
        const auto b = before.find(p.id[i]);
        if (b == before.end())
          continue;
        const double r = p.volume[i] / b->second.volume;
        const auto   key =
          std::make_pair(b->second.cell, by_body ? b->second.body : 0u);
        auto it = range.find(key);
        if (it == range.end())
          range[key] = {r, r};
        else
          it->second = {std::min(it->second.first, r),
                        std::max(it->second.second, r)};
      }
    double spread = 0;
    for (const auto &r : range)
      spread = std::max(spread, r.second.second - r.second.first);
    return {spread, total};
  }

  std::unique_ptr<psmpm::Simulator::Simulator<2>>
  make_cut(const std::string &basis,
           const std::string &strain,
           const bool         two_bodies)
  {
    const double rho = 2000, g = 9.81, c_u = rho * g * 1 / (3.78 * 1.3);
    std::vector<std::string> set = {"Basis/Type=" + basis,
                                    "Mesh/Blocks x=14",
                                    "Mesh/Blocks y=5",
                                    "Material/Cohesion=" + std::to_string(c_u),
                                    "Material/Young's modulus=" +
                                      std::to_string(750 * c_u),
                                    "Transfer/Volumetric strain=" + strain,
                                    "Output/Interval=0"};
    if (two_bodies)
      set.insert(set.end(),
                 {"Bodies/Number of bodies=2",
                  "Bodies/Body 1/Corners=0, 0, 1.05, 1",
                  "Bodies/Body 2/Shape=rectangle",
                  "Bodies/Body 2/Corners=1.05, 0, 2, 1",
                  "Bodies/Body 2/Initial velocity=0; 0"});
    return make_scene_solver("vertical_cut.prm", set);
  }
} // namespace

namespace
{
  /// Largest |E(t) - E(0)| / the energy scale of an elastic Powell-Sabin
  /// block sagging under gravity from zero stress (MUSL).
  double
  energy_drift(const std::string &strain)
  {
    auto         solver = make_scene_solver("vertical_cut.prm",
                                    {"Basis/Type=powell-sabin",
                                             "Transfer/Scheme=musl",
                                             "Mesh/Blocks x=14",
                                             "Mesh/Blocks y=5",
                                             "Material/Cohesion=1e9",
                                             "Material/Young's modulus=3e6",
                                             "Initial conditions/Stress=none",
                                             "Transfer/Volumetric strain=" + strain,
                                             "Output/Interval=0"});
    const double e0     = solver->compute_energies().total();
    double       drift = 0, scale = 0;
    for (unsigned int n = 0; n < 400; ++n)
      {
        solver->do_time_step(5e-4);
        const auto e = solver->compute_energies();
        drift        = std::max(drift, std::abs(e.total() - e0));
        scale        = std::max(scale, e.scale());
      }
    return drift / scale;
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out = root_output();
  const double      dt  = 2e-3;
  for (const std::string basis : {"powell-sabin", "linear"})
    for (const bool two : {false, true})
      {
        auto   own        = make_cut(basis, "particle", two);
        auto   avg        = make_cut(basis, "cell average", two);
        double own_spread = 0, avg_spread = 0;
        for (unsigned int n = 0; n < 40; ++n)
          {
            // The first step by cell alone with two bodies.
            const bool by_body = !two || n != 0;
            const auto o       = step_spread(*own, dt);
            const auto a       = step_spread(*avg, dt, by_body);
            own_spread         = std::max(own_spread, o.first);
            if (by_body)
              avg_spread = std::max(avg_spread, a.first);
            else if (basis == "powell-sabin")
              // By cell alone: the bodies of a shared cell keep their own
              // means.
              PSMPM_CHECK(out, a.first > 1e-10);
          }
        double      volume_difference = 0;
        const auto &po                = own->get_particles();
        const auto &pa                = avg->get_particles();
        for (std::size_t i = 0; i < po.size() && i < pa.size(); ++i)
          volume_difference =
            std::max(volume_difference,
                     std::abs(po.volume[i] / pa.volume[i] - 1));
        // (Round-off spreads are not printed: they differ between
        // machines.)
        out << basis << (two ? ", two bodies" : ", one body")
            << ": largest spread of the volume ratios in a cell, particle "
            << std::setprecision(2) << (own_spread > 1e-8 ? own_spread : 0.)
            << std::endl;
        PSMPM_CHECK(out, avg_spread < 1e-14);
        if (basis == "powell-sabin")
          PSMPM_CHECK(out, own_spread > 1e-8);
        else
          PSMPM_CHECK(out, volume_difference == 0);
      }
  for (const std::string strain : {"particle", "cell average"})
    {
      const double drift = energy_drift(strain);
      out << "elastic block, " << strain << ": energy drift / scale "
          << std::setprecision(1) << drift << std::endl;
      PSMPM_CHECK(out, drift < 1e-2);
    }
}
