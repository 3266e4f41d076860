// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/utilities.h>

#include <psmpm/base/format.h>
#include <psmpm/simulator/contact.h>

#include <algorithm>
#include <cmath>

namespace psmpm
{
  namespace Simulator
  {
    namespace
    {
      constexpr double no_slip = std::numeric_limits<double>::infinity();

      /// @p text as a friction coefficient: a finite number >= 0 or
      /// "no-slip" (infinity); false if it is neither.
      bool
      to_friction(const std::string &text, double &mu)
      {
        const std::string s = Utilities::trim(text);
        if (s == "no-slip")
          {
            mu = no_slip;
            return true;
          }
        try
          {
            std::size_t end = 0;
            mu              = std::stod(s, &end);
            return Utilities::trim(s.substr(end)).empty() &&
                   std::isfinite(mu) && mu >= 0;
          }
        catch (...)
          {
            return false;
          }
      }

      /// @p text as a body number 1 ... Contact::max_bodies.
      bool
      to_body(const std::string &text, unsigned int &body)
      {
        const std::string s = Utilities::trim(text);
        if (s.empty() || s.size() > 2 ||
            !std::all_of(s.begin(), s.end(), [](const char c) {
              return c >= '0' && c <= '9';
            }))
          return false;
        body = std::stoi(s);
        return body >= 1 && body <= Contact<2>::max_bodies;
      }
    } // namespace

    template <int dim>
    void
    ContactFields<dim>::reinit(const unsigned int n_nodes,
                               const unsigned int bodies,
                               const bool         with_volumes,
                               const bool         with_centroids)
    {
      n_bodies             = bodies;
      const unsigned int n = n_nodes * bodies;
      mass.assign(n, 0.);
      velocity.assign(n, Tensor<1, dim>());
      mass_gradient.assign(n, Tensor<1, dim>());
      volume.assign(with_volumes ? n : 0, 0.);
      node_volume.assign(with_volumes ? n_nodes : 0, 0.);
      centroid.assign(with_centroids ? n : 0, Point<dim>());
      normal_only.clear();
    }

    template <int dim>
    bool
    correct_pair(const double                m_a,
                 const double                m_b,
                 Tensor<1, dim>             &v_a,
                 Tensor<1, dim>             &v_b,
                 const Tensor<1, dim>       &normal,
                 const double                mu,
                 ContactPairStatistics<dim> &statistics)
    {
      const Tensor<1, dim> w   = v_a - v_b;
      const double         w_n = w * normal;
      if (!(w_n > 0) || (std::isinf(m_a) && std::isinf(m_b)))
        return false;
      // A driven body's infinite mass: the other's is the reduced one.
      const double         m        = std::isinf(m_a) ? m_b :
                                      std::isinf(m_b) ? m_a :
                                                        m_a * m_b / (m_a + m_b);
      const Tensor<1, dim> w_t      = w - w_n * normal;
      const double         w_t_norm = w_t.norm();
      // The tangential relative velocity keeps the fraction 1 - s of
      // itself: s = 1 sticks, s < 1 slips at the Coulomb bound.
      double s = 1;
      if (w_t_norm > mu * w_n)
        s = mu * w_n / w_t_norm;
      const Tensor<1, dim> J = -m * (w_n * normal + s * w_t);
      v_a += J / m_a;
      v_b -= J / m_b;

      statistics.impulse += J;
      statistics.normal_impulse += m * w_n;
      statistics.tangential_impulse += m * s * w_t_norm;
      statistics.normal_work -= 0.5 * m * w_n * w_n;
      statistics.friction_work -=
        0.5 * m * (1 - (1 - s) * (1 - s)) * w_t_norm * w_t_norm;
      // Coulomb's dissipation: the friction impulse m s |w_t| times the
      // slip velocity left, (1 - s) |w_t| (zero where the pair sticks).
      statistics.slip_work -= m * s * (1 - s) * w_t_norm * w_t_norm;
      ++statistics.n_contact_nodes;
      return true;
    }

    template <int dim>
    void
    Contact<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Type",
        "none",
        Patterns::Selection("none|multi-velocity"),
        "Contact between the bodies of subsection Bodies. 'none': the "
        "bodies share one grid velocity and stick where their supports "
        "overlap. 'multi-velocity': every body has its own grid velocity, "
        "and approaching bodies at a node are corrected against their "
        "centre of mass with Coulomb friction (doc/contact.md): with "
        "Transfer/Scheme musl and Mass matrix/Type lumped, which "
        "automatic then selects.");
      prm.declare_entry(
        "Friction coefficient",
        "0",
        Patterns::Anything(),
        "Coulomb coefficient of every pair of bodies without an entry in "
        "Pair friction: a number >= 0 (0: frictionless) or 'no-slip'.");
      prm.declare_entry(
        "Pair friction",
        "",
        Patterns::Anything(),
        "Coefficients of particular pairs of bodies, overriding Friction "
        "coefficient: '1-2: 0.3, 1-3: no-slip' (body numbers of Bodies/"
        "Body k; each pair once).");
      prm.declare_entry(
        "Normal",
        "average",
        Patterns::Selection("average|larger gradient"),
        "The contact normal of a pair from the two bodies' mass gradients: "
        "'average' of the one body's outward unit normal and the other's "
        "inward one (antisymmetric in the pair, both surfaces count); "
        "'larger gradient': the outward normal of the body whose gradient "
        "is larger (where the other barely reaches the node).");
      prm.declare_entry(
        "Separation criterion",
        "volume fraction",
        Patterns::Selection("none|volume fraction|distance"),
        "When two approaching bodies at a node are in contact: 'none' "
        "always; 'volume fraction' when their particle volumes at the node "
        "fill at least Critical volume fraction of the node's support; "
        "'distance' when their mass centres at the node are at most "
        "Contact distance apart along the normal.");
      prm.declare_entry(
        "Driven body nodes",
        "particle mass",
        Patterns::Selection("particle mass|geometry"),
        "Where a driven body (Bodies/Body k/Motion = prescribed) holds "
        "the other bodies by friction: 'particle mass' at every node where "
        "its particles have mass (up to a cell beyond its outline); "
        "'geometry' only at the nodes (Powell-Sabin: the DoFs of the "
        "vertices) inside or on the outline of its shape moved by its "
        "displacement, with the normal correction alone at the other "
        "nodes where it has mass (doc/contact.md, \"Driven bodies\").");
      prm.declare_entry(
        "Critical volume fraction",
        "0.8",
        Patterns::Double(0, 1),
        "f_c of the volume fraction criterion: (V_a + V_b) >= f_c V_i, "
        "V_b = sum_p V_p N_i(x_p) over body b, V_i the integral of N_i.");
      prm.declare_entry("Contact distance",
                        "0",
                        Patterns::Double(0),
                        "d_c of the distance criterion (a length, > 0 with "
                        "Separation criterion = distance).");
    }

    template <int dim>
    void
    Contact<dim>::parse_parameters(ParameterHandler &prm)
    {
      type_multi_velocity = prm.get("Type") == "multi-velocity";

      const std::string coefficient = prm.get("Friction coefficient");
      AssertThrow(to_friction(coefficient, default_friction),
                  ExcMessage("Contact/Friction coefficient = " + coefficient +
                             ": must be a number >= 0 or 'no-slip'."));

      pair_text = prm.get("Pair friction");
      pair_overrides.clear();
      for (const auto &item : Utilities::split_string_list(pair_text, ','))
        {
          const std::string prefix =
            "Contact/Pair friction = " + pair_text + ": '" + item + "' ";
          const auto   colon = item.find(':');
          const auto   dash  = item.find('-');
          PairFriction p;
          AssertThrow(colon != std::string::npos && dash < colon &&
                        to_body(item.substr(0, dash), p.a) &&
                        to_body(item.substr(dash + 1, colon - dash - 1), p.b),
                      ExcMessage(prefix +
                                 "is not 'a-b: mu' with body "
                                 "numbers a, b from 1 to " +
                                 std::to_string(max_bodies) + "."));
          AssertThrow(p.a != p.b,
                      ExcMessage(prefix + "pairs a body with itself."));
          const std::string value = item.substr(colon + 1);
          AssertThrow(to_friction(value, p.mu),
                      ExcMessage(prefix + "has the coefficient '" +
                                 Utilities::trim(value) +
                                 "': must be a number >= 0 or 'no-slip'."));
          if (p.a > p.b)
            std::swap(p.a, p.b);
          for (const auto &q : pair_overrides)
            AssertThrow(q.a != p.a || q.b != p.b,
                        ExcMessage(prefix + "names a pair given before."));
          pair_overrides.push_back(p);
        }

      const std::string normal = prm.get("Normal");
      normal_type =
        normal == "average" ? NormalType::average : NormalType::larger_gradient;
      const std::string separation = prm.get("Separation criterion");
      criterion = separation == "none" ? SeparationCriterion::none :
                  separation == "distance" ?
                                         SeparationCriterion::distance :
                                         SeparationCriterion::volume_fraction;
      critical_volume_fraction = prm.get_double("Critical volume fraction");
      contact_distance         = prm.get_double("Contact distance");
      driven_nodes_from_geometry = prm.get("Driven body nodes") == "geometry";
      AssertThrow(
        criterion != SeparationCriterion::distance || contact_distance > 0,
        ExcMessage("Contact/Contact distance = " + prm_value(contact_distance) +
                   ": must be > 0 with Separation criterion = "
                   "distance."));
    }

    template <int dim>
    void
    Contact<dim>::check_bodies(const unsigned int bodies)
    {
      n_bodies = bodies;
      AssertThrow(!type_multi_velocity || n_bodies >= 2,
                  ExcMessage("Contact/Type = multi-velocity: needs at least "
                             "two bodies (Bodies/Number of bodies = " +
                             std::to_string(n_bodies) + ")."));
      for (const auto &p : pair_overrides)
        AssertThrow(p.b <= n_bodies,
                    ExcMessage("Contact/Pair friction = " + pair_text +
                               ": the pair " + std::to_string(p.a) + "-" +
                               std::to_string(p.b) + " names Body " +
                               std::to_string(p.b) +
                               ", but Bodies/Number of bodies = " +
                               std::to_string(n_bodies) + "."));
      pair_friction.assign(n_bodies * (n_bodies - (n_bodies > 0)) / 2,
                           default_friction);
      for (const auto &p : pair_overrides)
        pair_friction[pair_index(p.a - 1, p.b - 1, n_bodies)] = p.mu;
    }

    template <int dim>
    double
    Contact<dim>::friction(const unsigned int a, const unsigned int b) const
    {
      AssertIndexRange(std::max(a, b), n_bodies);
      Assert(a != b, ExcMessage("A body has no friction with itself."));
      return pair_friction[pair_index(std::min(a, b),
                                      std::max(a, b),
                                      n_bodies)];
    }

    template <int dim>
    Tensor<1, dim>
    Contact<dim>::pair_normal(const Tensor<1, dim> &g_a,
                              const Tensor<1, dim> &g_b,
                              const NormalType      type)
    {
      const double   a = g_a.norm(), b = g_b.norm();
      Tensor<1, dim> n;
      if (type == NormalType::larger_gradient)
        {
          // The outward normal of a is g_a/|g_a|; b's outward normal
          // points towards a, so its negative is the normal from a to b.
          if (a >= b && a > 0)
            n = g_a / a;
          else if (b > 0)
            n = -g_b / b;
          return n;
        }
      if (a == 0 || b == 0)
        return n;
      n               = g_a / a - g_b / b;
      const double nn = n.norm();
      // Two gradients pointing the same way leave no direction between
      // the bodies (round-off of a full overlap): no normal, no contact.
      if (nn < 1e-12)
        return Tensor<1, dim>();
      return n / nn;
    }

    template <int dim>
    bool
    Contact<dim>::close_enough(const ContactFields<dim> &fields,
                               const unsigned int        i,
                               const unsigned int        a,
                               const unsigned int        b,
                               const Tensor<1, dim>     &normal) const
    {
      const unsigned int n  = fields.n_bodies;
      const unsigned int ia = i * n + a, ib = i * n + b;
      switch (criterion)
        {
          case SeparationCriterion::volume_fraction:
            return fields.volume[ia] + fields.volume[ib] >=
                   critical_volume_fraction * fields.node_volume[i];
          case SeparationCriterion::distance:
            return (fields.centroid[ib] - fields.centroid[ia]) * normal <=
                   contact_distance;
          default:
            return true;
        }
    }

    template <int dim>
    void
    Contact<dim>::correct_node(
      ContactFields<dim>                      &fields,
      const unsigned int                       i,
      std::vector<ContactPairStatistics<dim>> &statistics,
      const bool                               with_friction) const
    {
      const unsigned int n           = fields.n_bodies;
      constexpr double   infinite    = std::numeric_limits<double>::infinity();
      const bool         with_driven = !driven.empty();
      const bool with_normal_only = with_driven && !fields.normal_only.empty();
      for (unsigned int a = 0; a < n; ++a)
        {
          const unsigned int ia = i * n + a;
          if (!(fields.mass[ia] > 0))
            continue;
          for (unsigned int b = a + 1; b < n; ++b)
            {
              const unsigned int ib = i * n + b;
              if (!(fields.mass[ib] > 0) ||
                  (with_driven && driven[a] && driven[b]))
                continue;
              const Tensor<1, dim> normal =
                pair_normal(fields.mass_gradient[ia],
                            fields.mass_gradient[ib],
                            normal_type);
              if (normal.norm_square() == 0 ||
                  (fields.velocity[ia] - fields.velocity[ib]) * normal <= 0 ||
                  !close_enough(fields, i, a, b, normal))
                continue;
              const unsigned int pair = pair_index(a, b, n);
              const double       mu =
                with_friction &&
                    !(with_normal_only &&
                      (fields.normal_only[ia] || fields.normal_only[ib])) ?
                        pair_friction[pair] :
                        0.;
              if (!fields.stuck.empty() && mu > 0)
                {
                  const Tensor<1, dim> w =
                    fields.velocity[ia] - fields.velocity[ib];
                  const double w_n = w * normal;
                  if ((w - w_n * normal).norm() <= mu * w_n)
                    fields.stuck[ia] = fields.stuck[ib] = 1;
                }
              correct_pair(with_driven && driven[a] ? infinite :
                                                      fields.mass[ia],
                           with_driven && driven[b] ? infinite :
                                                      fields.mass[ib],
                           fields.velocity[ia],
                           fields.velocity[ib],
                           normal,
                           mu,
                           statistics[pair]);
            }
        }
    }

    template <int dim>
    void
    Contact<dim>::apply(
      ContactFields<dim>                      &fields,
      std::vector<ContactPairStatistics<dim>> &statistics) const
    {
      AssertThrow(fields.n_bodies == n_bodies,
                  ExcMessage("The contact fields have " +
                             std::to_string(fields.n_bodies) +
                             " bodies, the scene " + std::to_string(n_bodies) +
                             "."));
      const unsigned int n_nodes = fields.n_nodes();
      AssertThrow(driven.empty() || driven.size() == n_bodies,
                  ExcMessage(
                    "Contact::driven names " + std::to_string(driven.size()) +
                    " bodies, the scene " + std::to_string(n_bodies) + "."));
      Assert(criterion != SeparationCriterion::volume_fraction ||
               (fields.volume.size() == fields.mass.size() &&
                fields.node_volume.size() == n_nodes),
             ExcMessage("The volume fraction criterion needs the volumes."));
      Assert(criterion != SeparationCriterion::distance ||
               fields.centroid.size() == fields.mass.size(),
             ExcMessage("The distance criterion needs the mass centres."));
      statistics.assign(pair_friction.size(), ContactPairStatistics<dim>());
      for (unsigned int i = 0; i < n_nodes; ++i)
        correct_node(fields, i, statistics, true);
    }

    template <int dim>
    void
    Contact<dim>::apply(ContactFields<dim>                      &fields,
                        std::vector<ContactPairStatistics<dim>> &statistics,
                        const std::vector<char>                 *counted,
                        const bool with_friction) const
    {
      if (counted == nullptr && with_friction)
        {
          apply(fields, statistics);
          return;
        }
      std::vector<char> all;
      if (counted == nullptr)
        {
          all.assign(fields.n_nodes(), 1);
          counted = &all;
        }
      AssertDimension(counted->size(), fields.n_nodes());
      AssertThrow(fields.n_bodies == n_bodies,
                  ExcMessage("The contact fields have " +
                             std::to_string(fields.n_bodies) +
                             " bodies, the scene " + std::to_string(n_bodies) +
                             "."));
      statistics.assign(pair_friction.size(), ContactPairStatistics<dim>());
      std::vector<ContactPairStatistics<dim>> uncounted(statistics);
      for (unsigned int i = 0; i < fields.n_nodes(); ++i)
        correct_node(fields,
                     i,
                     (*counted)[i] ? statistics : uncounted,
                     with_friction);
    }

    template struct ContactFields<1>;
    template struct ContactFields<2>;
    template bool
    correct_pair<1>(double,
                    double,
                    Tensor<1, 1> &,
                    Tensor<1, 1> &,
                    const Tensor<1, 1> &,
                    double,
                    ContactPairStatistics<1> &);
    template bool
    correct_pair<2>(double,
                    double,
                    Tensor<1, 2> &,
                    Tensor<1, 2> &,
                    const Tensor<1, 2> &,
                    double,
                    ContactPairStatistics<2> &);
    template class Contact<1>;
    template class Contact<2>;
  } // namespace Simulator
} // namespace psmpm
