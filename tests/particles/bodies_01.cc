// Particles of Bodies: a rectangle, a disk and an L-shaped polygon on a
// criss-cross mesh. Every particle of a body lies in its shape (checked
// here with independent formulas), no candidate point is lost or counted
// twice, and the covered area (particles x volume) matches the shape's
// area to within sqrt(2) x perimeter x particle spacing: only the spacing
// x spacing squares around the particle positions that the boundary cuts
// differ, and they lie within spacing/sqrt(2) of it. Each body gets its
// density (0: Material/Density), its initial velocity and its id; without
// Bodies every particle is in body 0.
#include "../mpm_tests.h"

#include <cmath>

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");
  const std::vector<std::string>   common = {"Geometry/Length=2",
                                             "Geometry/Height=1",
                                             "Mesh/Blocks x=20",
                                             "Mesh/Blocks y=10",
                                             "Particles/Per block x=5",
                                             "Particles/Per block y=5",
                                             "Boundary conditions/Fixed x=",
                                             "Boundary conditions/Fixed y=",
                                             "Reference solution/Type=none"};
  {
    psmpm::Simulator::Simulator<2> solver(MPI_COMM_WORLD);
    configure(solver, common);
    const auto &p    = solver.get_particles();
    bool        zero = true;
    for (const auto b : p.body_id)
      zero = zero && b == 0;
    out << "no bodies: " << p.size() << " particles" << std::endl;
    PSMPM_CHECK(out, p.n_bodies == 0);
    PSMPM_CHECK(out, zero);
    PSMPM_CHECK(out, p.size() == 20 * 10 * 25);
  }

  auto overrides = common;
  for (const std::string o :
       {"Bodies/Number of bodies=3",
        "Bodies/Body 1/Shape=rectangle",
        "Bodies/Body 1/Corners=0.125, 0.165, 0.605, 0.825",
        "Bodies/Body 2/Shape=disk",
        "Bodies/Body 2/Center=1, 0.5",
        "Bodies/Body 2/Radius=0.3",
        "Bodies/Body 2/Density=2000",
        "Bodies/Body 2/Initial velocity=1; x",
        "Bodies/Body 3/Shape=polygon",
        "Bodies/Body 3/Vertices=1.4, 0.1, 1.9, 0.1, 1.9, 0.3, 1.6, 0.3, "
        "1.6, 0.9, 1.4, 0.9"})
    overrides.push_back(o);
  psmpm::Simulator::Simulator<2> solver(MPI_COMM_WORLD);
  configure(solver, overrides);
  const auto &p = solver.get_particles();

  const auto in_rectangle =
    [](const Point<2> &x, double x0, double y0, double x1, double y1) {
      return x[0] >= x0 && x[0] <= x1 && x[1] >= y0 && x[1] <= y1;
    };
  const std::vector<std::function<bool(const Point<2> &)>> inside = {
    [&](const Point<2> &x) {
      return in_rectangle(x, 0.125, 0.165, 0.605, 0.825);
    },
    [](const Point<2> &x) { return std::hypot(x[0] - 1, x[1] - 0.5) <= 0.3; },
    [&](const Point<2> &x) {
      return in_rectangle(x, 1.4, 0.1, 1.9, 0.3) ||
             in_rectangle(x, 1.4, 0.1, 1.6, 0.9);
    }};
  const double area[]      = {0.48 * 0.66, numbers::PI * 0.09, 0.22};
  const double perimeter[] = {2 * (0.48 + 0.66), 2 * numbers::PI * 0.3, 2.6};
  const double spacing     = 0.1 / 5;

  // The candidate points inside some body, counted independently.
  unsigned int expected[3] = {0, 0, 0};
  for (unsigned int j = 0; j < 10 * 5; ++j)
    for (unsigned int i = 0; i < 20 * 5; ++i)
      {
        const Point<2> x((i + 0.5) * spacing, (j + 0.5) * spacing);
        for (unsigned int b = 0; b < 3; ++b)
          expected[b] += inside[b](x);
      }

  out << "particles: " << p.size() << ", bodies: " << p.n_bodies << std::endl;
  PSMPM_CHECK(out, p.n_bodies == 3);
  for (unsigned int b = 0; b < 3; ++b)
    {
      unsigned int n = 0, outside = 0, wrong_density = 0, wrong_velocity = 0;
      double       covered = 0;
      for (std::size_t i = 0; i < p.size(); ++i)
        if (p.body_id[i] == b + 1)
          {
            ++n;
            covered += p.volume[i];
            outside += !inside[b](p.position[i]);
            const double rho = (b == 1 ? 2000. : 1.);
            wrong_density +=
              std::abs(p.density[i] - rho) > 0 ||
              std::abs(p.mass[i] - rho * p.volume[i]) > 1e-12 * p.mass[i];
            const Tensor<1, 2> v =
              b == 1 ? Tensor<1, 2>({1., p.position[i][0]}) : Tensor<1, 2>();
            wrong_velocity += (p.velocity[i] - v).norm() > 1e-12;
          }
      const double error = std::abs(covered - area[b]);
      const double bound = std::sqrt(2.) * perimeter[b] * spacing;
      out << "body " << b + 1 << ": " << n << " particles (expected "
          << expected[b]
          << "), area error / bound < 0.5: " << (error < 0.5 * bound)
          << std::endl;
      PSMPM_CHECK(out, n == expected[b]);
      PSMPM_CHECK(out, outside == 0);
      PSMPM_CHECK(out, error <= bound);
      PSMPM_CHECK(out, wrong_density == 0);
      PSMPM_CHECK(out, wrong_velocity == 0);
    }
  unsigned int stray = 0;
  for (const auto b : p.body_id)
    stray += (b < 1 || b > 3);
  PSMPM_CHECK(out, stray == 0);
  PSMPM_CHECK(out, p.size() == expected[0] + expected[1] + expected[2]);
}
