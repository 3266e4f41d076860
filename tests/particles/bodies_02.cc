// Bodies from a Gmsh geometry file and a material per body.
//
// (a) prm/geometry/ring.msh (a 48-gon ring, radii 0.1 and 0.2, physical
// surfaces "outer" and "inner") as Body 1 and a disk inside its hole as
// Body 2: every particle of the ring lies between the two 48-gons (checked
// with the closed formula of a regular polygon, not with the shape's own
// test), the counts equal the candidate points inside, the covered area
// matches the ring's to the bound of bodies_01, and no particle of the disk
// is taken by the ring (the hole is a hole). Selecting "outer" alone, or
// the numeric tag 2 alone, gives the two halves, which add up to the ring.
//
// (b) Two bodies far apart with different models: Body 1 neo-Hookean
// (Materials/Material 1, its own density), Body 2 hypoelastic (subsection
// Material), one squeezed, one stretched, lumped mass with MUSL and a fixed
// step (5 x 4 particles per block: none on a cell edge). After 40 steps each body's stress, velocity and state columns equal
// those of a run with that body alone and its material as subsection
// Material: the per-body dispatch, the shared state array (8 columns: both
// models' names) and the densities are right. The automatic step of the
// pair is no larger than either body's alone.
#include "../mpm_tests.h"

#include <cmath>
#include <map>

namespace
{
  /// Inside the regular n-gon with vertices at radius R, angles 2 pi k / n,
  /// around c (closed).
  bool
  in_ngon(const Point<2> &x, const Point<2> &c, double R, unsigned int n)
  {
    const double r = x.distance(c);
    if (r == 0)
      return true;
    double phi = std::atan2(x[1] - c[1], x[0] - c[0]);
    if (phi < 0)
      phi += 2 * numbers::PI;
    const double sector = 2 * numbers::PI / n;
    const double mid    = (std::floor(phi / sector) + 0.5) * sector;
    return r * std::cos(phi - mid) <= R * std::cos(numbers::PI / n) + 1e-14;
  }

  struct Run
  {
    std::map<std::pair<double, double>, std::size_t> at; // initial x -> i
    std::unique_ptr<psmpm::Simulator::Simulator<2>>  solver;
  };

  Run
  run(const std::vector<std::string> &overrides, const unsigned int steps)
  {
    Run r;
    r.solver = std::make_unique<psmpm::Simulator::Simulator<2>>(MPI_COMM_WORLD);
    configure(*r.solver, overrides);
    for (unsigned int s = 0; s < steps; ++s)
      r.solver->do_time_step(1e-4);
    const auto &p = r.solver->get_particles();
    for (std::size_t i = 0; i < p.size(); ++i)
      r.at[{p.initial_position[i][0], p.initial_position[i][1]}] = i;
    return r;
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");
  const std::string                ring =
    std::string(PSMPM_SOURCE_DIR) + "/prm/geometry/ring.msh";
  const std::vector<std::string> common = {"Geometry/Length=1",
                                           "Geometry/Height=1",
                                           "Mesh/Type=criss-cross",
                                           "Mesh/Blocks x=20",
                                           "Mesh/Blocks y=20",
                                           "Particles/Per block x=5",
                                           "Particles/Per block y=5",
                                           "Boundary conditions/Fixed x=",
                                           "Boundary conditions/Fixed y=",
                                           "Body force/Gravity=0, 0",
                                           "Reference solution/Type=none"};
  const Point<2>                 c(0.5, 0.55);
  const double                   spacing   = 1. / 100;
  const unsigned int             n         = 48;
  const auto                     ngon_area = [n](double R) {
    return 0.5 * n * R * R * std::sin(2 * numbers::PI / n);
  };
  const auto ngon_perimeter = [n](double R) {
    return 2 * n * R * std::sin(numbers::PI / n);
  };

  out << "(a) a ring from a Gmsh file around a disk" << std::endl;
  std::map<std::string, unsigned int> ring_count;
  for (const std::string surfaces : {"outer, inner", "outer", "2"})
    {
      auto overrides = common;
      for (const std::string &o :
           std::vector<std::string>{"Bodies/Number of bodies=2",
                                    "Bodies/Body 1/Shape=gmsh",
                                    "Bodies/Body 1/File=" + ring,
                                    "Bodies/Body 1/Physical surfaces=" +
                                      surfaces,
                                    "Bodies/Body 2/Shape=disk",
                                    "Bodies/Body 2/Center=0.5, 0.55",
                                    "Bodies/Body 2/Radius=0.08"})
        overrides.push_back(o);
      psmpm::Simulator::Simulator<2> solver(MPI_COMM_WORLD);
      configure(solver, overrides);
      const auto  &p     = solver.get_particles();
      const double r_in  = surfaces == "outer" ? 0.15 : 0.1;
      const double r_out = surfaces == "2" ? 0.15 : 0.2;
      // The closed ring between the two polygons, by the n-gon formula.
      const auto in_ring = [&](const Point<2> &x) {
        if (!in_ngon(x, c, r_out, n))
          return false;
        // Closed ring: on the inner polygon's edge counts as inside.
        const double r   = x.distance(c);
        double       phi = std::atan2(x[1] - c[1], x[0] - c[0]);
        if (phi < 0)
          phi += 2 * numbers::PI;
        const double sector = 2 * numbers::PI / n;
        const double mid    = (std::floor(phi / sector) + 0.5) * sector;
        return r * std::cos(phi - mid) >=
               r_in * std::cos(numbers::PI / n) - 1e-14;
      };
      unsigned int expected = 0, in_disk = 0;
      for (unsigned int j = 0; j < 100; ++j)
        for (unsigned int i = 0; i < 100; ++i)
          {
            const Point<2> x((i + 0.5) * spacing, (j + 0.5) * spacing);
            expected += in_ring(x);
            in_disk += x.distance(c) <= 0.08;
          }
      unsigned int ring_n = 0, disk_n = 0, outside = 0;
      double       covered = 0;
      for (std::size_t i = 0; i < p.size(); ++i)
        if (p.body_id[i] == 1)
          {
            ++ring_n;
            covered += p.volume[i];
            outside += !in_ring(p.position[i]);
          }
        else
          {
            ++disk_n;
            outside += p.position[i].distance(c) > 0.08;
          }
      const double area  = ngon_area(r_out) - ngon_area(r_in);
      const double bound = std::sqrt(2.) *
                           (ngon_perimeter(r_out) + ngon_perimeter(r_in)) *
                           spacing;
      out << "Physical surfaces = " << surfaces << ": " << ring_n
          << " particles (expected " << expected << "), disk " << disk_n
          << " (expected " << in_disk << ")" << std::endl;
      PSMPM_CHECK(out, ring_n == expected);
      PSMPM_CHECK(out, disk_n == in_disk);
      PSMPM_CHECK(out, outside == 0);
      PSMPM_CHECK(out, std::abs(covered - area) <= bound);
      ring_count[surfaces] = ring_n;
    }
  PSMPM_CHECK(out,
              ring_count["outer"] + ring_count["2"] ==
                ring_count["outer, inner"]);

  out << "(b) a material per body" << std::endl;
  const std::vector<std::string> lumped      = {"Mass matrix/Type=lumped",
                                                "Transfer/Scheme=musl",
                                                "Basis/Type=linear",
                                                "Time/Time step=1e-4"};
  const std::vector<std::string> neo_hookean = {"Model=neo-hookean",
                                                "Density=3000",
                                                "Young's modulus=2e5",
                                                "Poisson's ratio=0.3"};
  const std::vector<std::string> hypoelastic = {"Model=hypoelastic",
                                                "Density=1000",
                                                "Young's modulus=1e5",
                                                "Poisson's ratio=0.25"};
  const std::string              squeezed[]  = {
                  "Shape=rectangle",
                  "Corners=0.1, 0.1, 0.3, 0.3",
                  "Initial velocity=-2*(x - 0.2); -2*(y - 0.2)"};
  const std::string stretched[] = {"Shape=rectangle",
                                   "Corners=0.6, 0.6, 0.9, 0.9",
                                   "Initial velocity=3*(x - 0.75); 0"};
  // 5 x 4 particles per block: none on the diagonals of a criss-cross
  // block, where the P1 gradient (and so the first strain increment)
  // depends on which of the two triangles the search returns first.
  auto base = common;
  base.insert(base.end(), lumped.begin(), lumped.end());
  base.push_back("Particles/Per block y=4");

  auto both = base;
  both.push_back("Bodies/Number of bodies=2");
  for (const auto &e : squeezed)
    both.push_back("Bodies/Body 1/" + e);
  both.push_back("Bodies/Body 1/Material=1");
  for (const auto &e : stretched)
    both.push_back("Bodies/Body 2/" + e);
  for (const auto &e : neo_hookean)
    both.push_back("Materials/Material 1/" + e);
  for (const auto &e : hypoelastic)
    both.push_back("Material/" + e);

  std::vector<std::vector<std::string>> alone(2, base);
  for (unsigned int b = 0; b < 2; ++b)
    {
      alone[b].push_back("Bodies/Number of bodies=1");
      for (const auto &e : (b == 0 ? squeezed : stretched))
        alone[b].push_back("Bodies/Body 1/" + e);
      for (const auto &e : (b == 0 ? neo_hookean : hypoelastic))
        alone[b].push_back("Material/" + e);
    }

  const Run   pair      = run(both, 40);
  const Run   single[2] = {run(alone[0], 40), run(alone[1], 40)};
  const auto &p         = pair.solver->get_particles();
  out << "state columns:";
  for (const auto &name : p.get_state_names())
    out << " " << name;
  out << std::endl;
  PSMPM_CHECK(out, p.n_state() == 8);
  PSMPM_CHECK(out, (p.body_material == std::vector<unsigned int>{0, 1, 0}));

  for (unsigned int b = 0; b < 2; ++b)
    {
      const auto  &q    = single[b].solver->get_particles();
      const double rho  = b == 0 ? 3000 : 1000;
      double       diff = 0, scale = 0;
      unsigned int matched = 0, wrong_density = 0;
      for (const auto &[x, i] : pair.at)
        if (p.body_id[i] == b + 1)
          {
            const auto found = single[b].at.find(x);
            if (found == single[b].at.end())
              continue;
            const std::size_t k = found->second;
            ++matched;
            diff  = std::max({diff,
                              (p.stress[i] - q.stress[k]).norm(),
                              (p.velocity[i] - q.velocity[k]).norm()});
            scale = std::max({scale, q.stress[k].norm(), q.velocity[k].norm()});
            // The body's own columns, at the offset of its model.
            const unsigned int offset = b == 0 ? 4 : 0;
            for (unsigned int s = 0; s < 4; ++s)
              for (unsigned int s = 0; s < 4; ++s)
                diff = std::max(diff,
                                std::abs(p.state_of(i)[offset + s] -
                                         q.state_of(k)[s]));
            wrong_density +=
              std::abs(p.mass[i] / (p.density[i] * p.volume[i]) - 1) > 1e-12 ||
              std::abs(p.mass[i] / p.volume[i] / rho - 1) > 0.05;
          }
      unsigned int in_body = 0;
      for (const auto id : p.body_id)
        in_body += id == b + 1;
      out << "body " << b + 1 << ": " << matched << " of " << in_body
          << " particles matched, stress and velocity scale > 0: "
          << (scale > 0) << std::endl;
      PSMPM_CHECK(out, matched == in_body && matched == q.size());
      PSMPM_CHECK(out, scale > 0);
      if (diff > 1e-12 * scale)
        out << "  diff " << diff << ", scale " << scale << std::endl;
      PSMPM_CHECK(out, diff <= 1e-12 * scale);
      PSMPM_CHECK(out, wrong_density == 0);
    }

  // The automatic step of the pair: the stiffer, lighter and faster body
  // decides, so it is at most either body's own.
  auto automatic = [&](std::vector<std::string> o) {
    o.push_back("Time/Time step=0");
    psmpm::Simulator::Simulator<2> solver(MPI_COMM_WORLD);
    configure(solver, o);
    return solver.next_time_step();
  };
  const double dt_pair = automatic(both);
  const double dt_1 = automatic(alone[0]), dt_2 = automatic(alone[1]);
  out << "automatic step: pair / min(alone) = "
      << (std::abs(dt_pair / std::min(dt_1, dt_2) - 1) < 1e-12 ? "1" : "not 1")
      << std::endl;
  PSMPM_CHECK(out, dt_pair <= std::min(dt_1, dt_2) * (1 + 1e-12));
}
