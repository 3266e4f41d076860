// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <psmpm/base/cross.h>
#include <psmpm/base/format.h>
#include <psmpm/particles/body.h>

#include <algorithm>
#include <cmath>

namespace psmpm
{
  namespace Particles
  {
    namespace
    {
      /// Closed segments [a, b] and [c, d] share a point.
      bool
      segments_meet(const Point<2> &a,
                    const Point<2> &b,
                    const Point<2> &c,
                    const Point<2> &d)
      {
        const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
        const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
        if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) &&
            ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
          return true;
        // Collinear touching.
        const auto on =
          [](const Point<2> &p, const Point<2> &q, const Point<2> &r) {
            return std::min(p[0], q[0]) <= r[0] &&
                   r[0] <= std::max(p[0], q[0]) &&
                   std::min(p[1], q[1]) <= r[1] && r[1] <= std::max(p[1], q[1]);
          };
        return (d1 == 0 && on(a, b, c)) || (d2 == 0 && on(a, b, d)) ||
               (d3 == 0 && on(c, d, a)) || (d4 == 0 && on(c, d, b));
      }

      /**
       * Crossing test (W. R. Franklin's pnpoly) over the edges edge(0),
       * ..., edge(n - 1), each a pair of points: a ray to +x crosses the
       * boundary an odd number of times from inside. Points on an edge are
       * counted explicitly (closed shapes), as the crossing test gives
       * either answer there.
       */
      template <typename Edge>
      bool
      crossing_test(const Point<2> &p, const std::size_t n, const Edge &edge)
      {
        bool in = false;
        for (std::size_t i = 0; i < n; ++i)
          {
            const auto [a, b] = edge(i);
            if (cross(b - a, p - a) == 0 && std::min(a[0], b[0]) <= p[0] &&
                p[0] <= std::max(a[0], b[0]) && std::min(a[1], b[1]) <= p[1] &&
                p[1] <= std::max(a[1], b[1]))
              return true;
            if ((a[1] > p[1]) != (b[1] > p[1]) &&
                p[0] < (b[0] - a[0]) * (p[1] - a[1]) / (b[1] - a[1]) + a[0])
              in = !in;
          }
        return in;
      }

      std::string
      list(const std::vector<double> &v)
      {
        std::string s;
        for (std::size_t i = 0; i < v.size(); ++i)
          s += (i ? ", " : "") + prm_value(v[i]);
        return s;
      }
    } // namespace



    Shape
    Shape::rectangle(const Point<2> &lower, const Point<2> &upper)
    {
      Shape s;
      s.type     = Type::rectangle;
      s.vertices = {lower, upper};
      return s;
    }



    Shape
    Shape::disk(const Point<2> &center, const double radius)
    {
      Shape s;
      s.type   = Type::disk;
      s.center = center;
      s.radius = radius;
      return s;
    }



    Shape
    Shape::polygon(const std::vector<Point<2>> &vertices)
    {
      Shape s;
      s.type     = Type::polygon;
      s.vertices = vertices;
      return s;
    }



    bool
    Shape::inside(const Point<2> &p) const
    {
      switch (type)
        {
          case Type::rectangle:
            return p[0] >= vertices[0][0] && p[0] <= vertices[1][0] &&
                   p[1] >= vertices[0][1] && p[1] <= vertices[1][1];
          case Type::disk:
            return (p - center).norm_square() <= radius * radius;
          case Type::polygon:
            {
              const std::size_t n = vertices.size();
              return crossing_test(p, n, [&](const std::size_t i) {
                return std::make_pair(vertices[i], vertices[(i + n - 1) % n]);
              });
            }
          case Type::gmsh:
            // The outline's edges need not form one loop (holes, several
            // pieces): the crossing test does not care.
            if (p[0] < box_lower[0] || p[0] > box_upper[0] ||
                p[1] < box_lower[1] || p[1] > box_upper[1])
              return false;
            return crossing_test(p, edges.size(), [&](const std::size_t i) {
              return std::make_pair(edges[i][0], edges[i][1]);
            });
        }
      return false;
    }



    double
    Shape::area() const
    {
      switch (type)
        {
          case Type::rectangle:
            return (vertices[1][0] - vertices[0][0]) *
                   (vertices[1][1] - vertices[0][1]);
          case Type::disk:
            return numbers::PI * radius * radius;
          case Type::polygon:
            {
              double            a = 0;
              const std::size_t n = vertices.size();
              for (std::size_t i = 0; i < n; ++i)
                a += cross(vertices[i], vertices[(i + 1) % n]);
              return std::abs(a) / 2;
            }
          case Type::gmsh:
            return gmsh_area;
        }
      return 0;
    }



    std::vector<Point<2>>
    Shape::outline(const double spacing) const
    {
      std::vector<Point<2>> corners;
      if (type == Type::gmsh)
        {
          std::vector<Point<2>> points;
          for (const auto &[a, b] : edges)
            {
              const unsigned int n =
                std::max(1u,
                         static_cast<unsigned int>(
                           std::ceil(a.distance(b) / spacing)));
              for (unsigned int k = 0; k < n; ++k)
                points.push_back(a + (double(k) / n) * (b - a));
            }
          return points;
        }
      if (type == Type::disk)
        {
          const unsigned int n =
            std::max(16u,
                     static_cast<unsigned int>(
                       std::ceil(2 * numbers::PI * radius / spacing)));
          std::vector<Point<2>> points;
          for (unsigned int k = 0; k < n; ++k)
            {
              const double phi = 2 * numbers::PI * k / n;
              points.emplace_back(center[0] + radius * std::cos(phi),
                                  center[1] + radius * std::sin(phi));
            }
          return points;
        }
      if (type == Type::rectangle)
        corners = {vertices[0],
                   Point<2>(vertices[1][0], vertices[0][1]),
                   vertices[1],
                   Point<2>(vertices[0][0], vertices[1][1])};
      else
        corners = vertices;
      std::vector<Point<2>> points;
      for (std::size_t i = 0; i < corners.size(); ++i)
        {
          const Point<2>    &a = corners[i];
          const Point<2>    &b = corners[(i + 1) % corners.size()];
          const unsigned int n = std::max(1u,
                                          static_cast<unsigned int>(std::ceil(
                                            a.distance(b) / spacing)));
          for (unsigned int k = 0; k < n; ++k)
            points.push_back(a + (double(k) / n) * (b - a));
        }
      return points;
    }



    bool
    Shape::self_intersecting() const
    {
      if (type != Type::polygon)
        return false;
      const std::size_t n = vertices.size();
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j)
          {
            // Adjacent edges share a vertex by construction; they only
            // count if they fold back onto each other.
            const bool      adjacent = (j == i + 1) || (i == 0 && j == n - 1);
            const Point<2> &a = vertices[i], &b = vertices[(i + 1) % n];
            const Point<2> &c = vertices[j], &d = vertices[(j + 1) % n];
            if (!adjacent)
              {
                if (segments_meet(a, b, c, d))
                  return true;
              }
            else
              {
                // Shared vertex s; the other ends must not lie on the
                // other edge (a spike back along itself).
                const Point<2> &s = (j == i + 1) ? b : a;
                const Point<2> &p = (j == i + 1) ? a : b;
                const Point<2> &q = (j == i + 1) ? d : c;
                if (cross(p - s, q - s) == 0 && (p - s) * (q - s) > 0)
                  return true;
              }
          }
      // Repeated vertices make a zero-length edge.
      for (std::size_t i = 0; i < n; ++i)
        if (vertices[i] == vertices[(i + 1) % n])
          return true;
      return false;
    }



    std::string
    Shape::description() const
    {
      switch (type)
        {
          case Type::rectangle:
            return "Shape = rectangle, Corners = " + list({vertices[0][0],
                                                           vertices[0][1],
                                                           vertices[1][0],
                                                           vertices[1][1]});
          case Type::disk:
            return "Shape = disk, Center = " + list({center[0], center[1]}) +
                   ", Radius = " + prm_value(radius);
          case Type::polygon:
            {
              std::vector<double> v;
              for (const auto &p : vertices)
                v.insert(v.end(), {p[0], p[1]});
              return "Shape = polygon, Vertices = " + list(v);
            }
          case Type::gmsh:
            return "Shape = gmsh, File = " + file +
                   ", Physical surfaces = " + surfaces;
        }
      return "";
    }



    void
    Bodies::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Bodies");
      prm.declare_entry("Number of bodies",
                        "0",
                        Patterns::Integer(0, max_bodies),
                        "Bodies 1 to this number hold the material (2D); 0: "
                        "the material fills the blocks or Particles/Region.");
      for (unsigned int b = 1; b <= max_bodies; ++b)
        {
          prm.enter_subsection("Body " + std::to_string(b));
          prm.declare_entry("Shape",
                            "rectangle",
                            Patterns::Selection("rectangle|disk|polygon|gmsh"),
                            "rectangle (Corners), disk (Center, Radius), "
                            "polygon (Vertices) or gmsh (File, Physical "
                            "surfaces).");
          prm.declare_entry("Corners",
                            "",
                            Patterns::List(Patterns::Double(), 0, 4, ","),
                            "Rectangle: x0, y0, x1, y1 (lower left, upper "
                            "right).");
          prm.declare_entry("Center",
                            "",
                            Patterns::List(Patterns::Double(), 0, 2, ","),
                            "Disk: x, y of the centre.");
          prm.declare_entry("Radius",
                            "0",
                            Patterns::Double(),
                            "Disk: radius (> 0).");
          prm.declare_entry("Vertices",
                            "",
                            Patterns::List(Patterns::Double(), 0, 2000, ","),
                            "Polygon: x0, y0, x1, y1, ... in order, at least "
                            "3 vertices, no edges crossing (a simple "
                            "polygon); the last is joined to the first.");
          prm.declare_entry("File",
                            "",
                            Patterns::Anything(),
                            "Gmsh: an ASCII .msh file (format 2 or 4) whose "
                            "cells make the body; relative paths are taken "
                            "relative to the parameter file. Its mesh is "
                            "only a geometry: particles are placed as for "
                            "the other shapes, in the cells of Mesh.");
          prm.declare_entry("Physical surfaces",
                            "",
                            Patterns::Anything(),
                            "Gmsh: names or tags of the physical surfaces "
                            "that form the body, separated by commas; empty: "
                            "every cell of the file.");
          prm.declare_entry("Material",
                            "0",
                            Patterns::Integer(0, max_materials),
                            "The body's material (model and constants): 0 "
                            "for subsection Material, j for subsection "
                            "Materials/Material j.");
          // Unbounded, so that a negative value is reported with the
          // body's name rather than by the parser.
          prm.declare_entry("Density",
                            "0",
                            Patterns::Double(),
                            "Density of this body; 0: the density of its "
                            "material.");
          prm.declare_entry("Initial velocity",
                            "0; 0",
                            Patterns::Anything(),
                            "Initial velocity as a function of x, y, one "
                            "component per dimension separated by ';', with "
                            "Initial conditions/Function constants.");
          prm.declare_entry(
            "Motion",
            "free",
            Patterns::Selection("free|prescribed"),
            "'free': the body moves as the equations of motion say. "
            "'prescribed': a driven rigid body, every particle moves with "
            "Velocity, a function of the time (no strain, its stress stays "
            "the initial one); it acts on the other bodies through "
            "Contact/Type = multi-velocity as a body of infinite mass "
            "(doc/contact.md, \"Driven bodies\").");
          prm.declare_entry(
            "Velocity",
            "0; 0",
            Patterns::Anything(),
            "Motion = prescribed: the body's velocity as a function of the "
            "time t, one expression per component separated by ';' (as "
            "Boundary conditions/Prescribed velocity): e.g. '0; "
            "-0.1*min(t/0.1, 1)'. Start it smoothly from Initial velocity.");
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }



    namespace
    {
      /// The entries of subsection Bodies/Body k beside its shape.
      void
      read_material_and_motion(ParameterHandler &prm, Body &body)
      {
        body.material = prm.get_integer("Material");
        body.density  = prm.get_double("Density");
        AssertThrow(body.density >= 0 && std::isfinite(body.density),
                    ExcMessage(body.name() +
                               "/Density = " + prm_value(body.density) +
                               ": must be positive (0: the density of its "
                               "material)."));
        body.velocity          = prm.get("Initial velocity");
        body.prescribed_motion = prm.get("Motion") == "prescribed";
        body.motion_velocity   = prm.get("Velocity");
      }
    } // namespace

    void
    Bodies::parse_parameters(ParameterHandler &prm)
    {
      bodies.clear();
      prm.enter_subsection("Bodies");
      const unsigned int n = prm.get_integer("Number of bodies");
      for (unsigned int b = 1; b <= n; ++b)
        {
          Body body;
          body.number            = b;
          const std::string name = body.name();
          prm.enter_subsection("Body " + std::to_string(b));
          const std::string shape   = prm.get("Shape");
          const auto        numbers = [&prm, &name](const std::string &entry) {
            // The pattern takes numbers string_to_double refuses
            // (subnormals such as 4.9e-324).
            try
              {
                return Utilities::string_to_double(
                  Utilities::split_string_list(prm.get(entry)));
              }
            catch (const std::exception &)
              {
                AssertThrow(false,
                            ExcMessage(name + "/" + entry + " = '" +
                                       prm.get(entry) +
                                       "': not a list of numbers."));
              }
            return std::vector<double>();
          };
          if (shape == "rectangle")
            {
              const auto c = numbers("Corners");
              AssertThrow(c.size() == 4,
                          ExcMessage(name + "/Corners = '" + list(c) +
                                     "': a rectangle needs x0, y0, x1, y1."));
              AssertThrow(c[0] < c[2] && c[1] < c[3],
                          ExcMessage(name + "/Corners = " + list(c) +
                                     ": need x0 < x1 and y0 < y1."));
              body.shape =
                Shape::rectangle(Point<2>(c[0], c[1]), Point<2>(c[2], c[3]));
            }
          else if (shape == "disk")
            {
              const auto   c = numbers("Center");
              const double r = prm.get_double("Radius");
              AssertThrow(c.size() == 2,
                          ExcMessage(name + "/Center = '" + list(c) +
                                     "': a disk needs x, y."));
              AssertThrow(r > 0 && std::isfinite(r),
                          ExcMessage(name + "/Radius = " + prm_value(r) +
                                     ": must be positive."));
              body.shape = Shape::disk(Point<2>(c[0], c[1]), r);
            }
          else if (shape == "gmsh")
            {
              const std::string file = prm.get("File");
              AssertThrow(!file.empty(),
                          ExcMessage(name + "/File: a gmsh body needs the "
                                            "name of a .msh file."));
              body.shape = Shape::from_gmsh(file,
                                            Utilities::split_string_list(
                                              prm.get("Physical surfaces")),
                                            name);
            }
          else
            {
              const auto v = numbers("Vertices");
              AssertThrow(v.size() % 2 == 0,
                          ExcMessage(name + "/Vertices = " + list(v) +
                                     ": an odd number of coordinates."));
              AssertThrow(v.size() >= 6,
                          ExcMessage(name + "/Vertices = '" + list(v) +
                                     "': a polygon needs at least 3 vertices, "
                                     "got " +
                                     std::to_string(v.size() / 2) + "."));
              std::vector<Point<2>> points;
              for (std::size_t i = 0; i < v.size(); i += 2)
                points.emplace_back(v[i], v[i + 1]);
              body.shape = Shape::polygon(points);
              AssertThrow(!body.shape.self_intersecting(),
                          ExcMessage(name + "/Vertices = " + list(v) +
                                     ": the polygon intersects itself (edges "
                                     "cross or touch, or a vertex repeats)."));
              AssertThrow(body.shape.area() > 0,
                          ExcMessage(name + "/Vertices = " + list(v) +
                                     ": the polygon has no area."));
            }
          read_material_and_motion(prm, body);
          prm.leave_subsection();
          bodies.push_back(body);
        }
      prm.leave_subsection();
    }
  } // namespace Particles
} // namespace psmpm
