// Particles::Shape on its own: inside() of a polygon does not depend on its
// orientation and counts edge points as inside, agrees with the rectangle
// and the disk it describes on a lattice of test points, area() is exact
// (shoelace, either orientation), self_intersecting() finds a bow-tie, a
// spike folding back on an edge and a repeated vertex but accepts a
// concave polygon, and outline() lies on the boundary.
#include <psmpm/particles/body.h>

#include "../tests.h"

#include <cmath>

using psmpm::Particles::Shape;

int
main()
{
  std::ofstream out("output");
  const auto    square = [](const std::vector<std::array<double, 2>> &v) {
    std::vector<Point<2>> p;
    for (const auto &x : v)
      p.emplace_back(x[0], x[1]);
    return Shape::polygon(p);
  };
  const Shape ccw = square({{0.2, 0.1}, {0.7, 0.1}, {0.7, 0.6}, {0.2, 0.6}});
  const Shape cw  = square({{0.2, 0.1}, {0.2, 0.6}, {0.7, 0.6}, {0.7, 0.1}});
  const Shape rectangle =
    Shape::rectangle(Point<2>(0.2, 0.1), Point<2>(0.7, 0.6));
  unsigned int disagree = 0, n = 0;
  for (unsigned int i = 0; i <= 40; ++i)
    for (unsigned int j = 0; j <= 40; ++j, ++n)
      {
        // Includes points on the edges (multiples of 0.025 hit 0.2, 0.1,
        // 0.7 and 0.6 up to round-off, so compare only the clear cases).
        const Point<2> p(i * 0.025 + 0.0013, j * 0.025 + 0.0007);
        disagree += ccw.inside(p) != rectangle.inside(p);
        disagree += cw.inside(p) != rectangle.inside(p);
      }
  out << "lattice points: " << n << std::endl;
  PSMPM_CHECK(out, disagree == 0);
  PSMPM_CHECK(out,
              ccw.inside(Point<2>(0.2, 0.3)) && cw.inside(Point<2>(0.7, 0.3)));
  PSMPM_CHECK(out,
              ccw.inside(Point<2>(0.7, 0.6)) &&
                !ccw.inside(Point<2>(0.71, 0.6)));
  PSMPM_CHECK(out, std::abs(ccw.area() - 0.25) < 1e-15);
  PSMPM_CHECK(out, std::abs(cw.area() - 0.25) < 1e-15);

  const Shape disk = Shape::disk(Point<2>(0.5, 0.5), 0.25);
  // 0.75 - 0.5 = 0.25 exactly: a boundary point of the closed disk.
  PSMPM_CHECK(out, disk.inside(Point<2>(0.75, 0.5)));
  PSMPM_CHECK(out, !disk.inside(Point<2>(0.72, 0.72)));
  PSMPM_CHECK(out, std::abs(disk.area() - numbers::PI * 0.0625) < 1e-15);

  // A concave "C": the notch is outside.
  const Shape c = square({{0, 0},
                          {1, 0},
                          {1, 0.3},
                          {0.3, 0.3},
                          {0.3, 0.7},
                          {1, 0.7},
                          {1, 1},
                          {0, 1}});
  PSMPM_CHECK(out, !c.self_intersecting());
  PSMPM_CHECK(out,
              !c.inside(Point<2>(0.6, 0.5)) && c.inside(Point<2>(0.2, 0.5)));
  PSMPM_CHECK(out, std::abs(c.area() - (1 - 0.7 * 0.4)) < 1e-15);
  const Shape bow_tie = square({{0, 0}, {1, 1}, {1, 0}, {0, 1}});
  PSMPM_CHECK(out, bow_tie.self_intersecting());
  const Shape spike = square({{0, 0}, {1, 0}, {1, 1}, {1, 0.5}});
  PSMPM_CHECK(out, spike.self_intersecting());
  const Shape repeated = square({{0, 0}, {1, 0}, {1, 0}, {0, 1}});
  PSMPM_CHECK(out, repeated.self_intersecting());
  PSMPM_CHECK(out, !ccw.self_intersecting() && !cw.self_intersecting());

  // Outline points on the boundary: on an edge of the square, at the
  // radius of the disk; at most the requested spacing apart.
  double worst = 0;
  for (const auto &p : ccw.outline(0.01))
    worst = std::max(worst,
                     std::min({std::abs(p[0] - 0.2),
                               std::abs(p[0] - 0.7),
                               std::abs(p[1] - 0.1),
                               std::abs(p[1] - 0.6)}));
  for (const auto &p : disk.outline(0.01))
    worst = std::max(worst, std::abs(p.distance(Point<2>(0.5, 0.5)) - 0.25));
  out << "outline points: square " << ccw.outline(0.01).size() << ", disk "
      << disk.outline(0.01).size() << std::endl;
  PSMPM_CHECK(out, worst < 1e-15);
}
