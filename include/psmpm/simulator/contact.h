// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_simulator_contact_h
#define psmpm_simulator_contact_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <limits>
#include <string>
#include <vector>

namespace psmpm
{
  namespace Simulator
  {
    using namespace dealii;

    /**
     * The grid fields of every body at every node that contact reads and
     * corrects, as arrays indexed [node * n_bodies + body] (body 0 is
     * Bodies/Body 1). Built by the caller from a per-body particle-to-grid
     * pass; doc/contact.md.
     */
    template <int dim>
    struct ContactFields
    {
      /// Sizes every per-body array for @p n_nodes nodes (zero), and the
      /// optional arrays only if their criterion needs them.
      void
      reinit(const unsigned int n_nodes,
             const unsigned int n_bodies,
             const bool         with_volumes,
             const bool         with_centroids);

      unsigned int
      n_nodes() const
      {
        return n_bodies == 0 ? 0 : mass.size() / n_bodies;
      }

      unsigned int n_bodies = 0;
      /// m_bi = sum_p m_p N_i(x_p) over the particles of body b.
      std::vector<double> mass;
      /// v_bi, the body's own grid velocity after its grid update; the
      /// correction overwrites it.
      std::vector<Tensor<1, dim>> velocity;
      /// g_bi = sum_p m_p grad N_i(x_p). It approximates minus the
      /// gradient of the body's smoothed density, so it points out of the
      /// body where the body ends near the node. Volume gradients
      /// sum_p V_p grad N_i(x_p) may be given instead (the larger
      /// gradient then compares volumes, not densities times volumes).
      std::vector<Tensor<1, dim>> mass_gradient;
      /// Volume fraction criterion: V_bi = sum_p V_p N_i(x_p), and per
      /// node the integral of N_i over the domain (node_volume[i]).
      std::vector<double> volume;
      std::vector<double> node_volume;
      /// Distance criterion: the body's mass centre at the node,
      /// sum_p m_p N_i(x_p) x_p / m_bi.
      std::vector<Point<dim>> centroid;
      /// Optional output (sized by the caller, else left empty): 1 where
      /// the body stuck to another body at the node in apply() with
      /// friction (mu > 0 and the tangential relative velocity removed).
      std::vector<char> stuck;
      /// Optional (empty: none), [node * n_bodies + body], read for
      /// driven bodies only: 1 where the body's pairs take the normal
      /// correction alone at the node (frictionless), whatever the pair's
      /// friction coefficient. reinit() empties it.
      std::vector<char> normal_only;
    };

    /**
     * What the correction did between one pair of bodies, summed over the
     * nodes: the impulse on the body with the lower number (the other
     * gets its negative), its normal part (>= 0), the kinetic energy the
     * tangential (friction) part removed as a work (<= 0) and the one the
     * normal part removed (<= 0, the inelastic normal closure of the
     * method), and the number of nodes where they were in contact.
     */
    template <int dim>
    struct ContactPairStatistics
    {
      Tensor<1, dim> impulse;
      double         normal_impulse = 0;
      /// Sum over the nodes of |J_t|, the tangential impulse's magnitude:
      /// at most mu times normal_impulse, node by node.
      double       tangential_impulse = 0;
      double       friction_work      = 0;
      /// Coulomb's dissipation (<= 0): at a node where the pair slips,
      /// the friction impulse times the relative slip velocity after the
      /// correction, -m s (1 - s) |w_t|^2; zero where it sticks. The
      /// friction work also counts the kinetic energy of the relative
      /// tangential velocity that the correction removes, most of it the
      /// difference the projection left between the bodies' fields,
      /// which the particles do not lose.
      double       slip_work          = 0;
      double       normal_work        = 0;
      unsigned int n_contact_nodes    = 0;
    };

    /**
     * The correction of one pair (a, b) at one node, the two-body rule of
     * Bardenhagen et al. (2000): with the reduced mass
     * m = m_a m_b / (m_a + m_b), the relative velocity w = v_a - v_b and
     * the unit normal n from a towards b, the pair is approaching if
     * w.n > 0 (equivalently (v_a - v_cm).n > 0); then the impulse J on a
     * (-J on b) removes the normal relative velocity, J_n = -m (w.n) n,
     * and the tangential one, J_t = -m w_t, as far as Coulomb's bound
     * |J_t| <= mu |J_n| allows (mu = infinity: no-slip, v_a = v_b = v_cm;
     * mu = 0: frictionless). Returns whether the pair was corrected.
     * Momentum is conserved exactly (J and -J), and the kinetic energy
     * changes by -m/2 (w.n)^2 - m/2 (|w_t|^2 - |w_t'|^2) <= 0.
     *
     * A driven body (Bodies/Body k/Motion = prescribed) enters with an
     * infinite mass: then m is the other body's mass, the driven velocity
     * does not change (J / infinity = 0) and the other body alone takes
     * the correction (v_cm is the driven velocity); the energies are
     * those of the driven body's frame. Both infinite: no correction.
     */
    template <int dim>
    bool
    correct_pair(const double                m_a,
                 const double                m_b,
                 Tensor<1, dim>             &v_a,
                 Tensor<1, dim>             &v_b,
                 const Tensor<1, dim>       &normal,
                 const double                mu,
                 ContactPairStatistics<dim> &statistics);

    /**
     * Contact between bodies by multi-velocity fields (subsection
     * "Contact"; doc/contact.md): every body has its own grid velocity
     * where the supports of several bodies overlap, and at each such node
     * every pair of bodies that approaches and passes the separation
     * criterion is corrected by correct_pair() with the normal from the
     * two bodies' mass gradients and the pair's friction coefficient.
     *
     * The class holds the parameters and the nodal algorithm over arrays
     * (apply()); ContactCoupling builds the arrays in a run's step, and
     * the tests call it directly.
     */
    template <int dim>
    class Contact
    {
    public:
      /// How the normal of a pair is made from the two mass gradients.
      enum class NormalType
      {
        /// n_ab = (n_a - n_b)/|n_a - n_b| with n_a = g_a/|g_a| the
        /// outward normal of a: antisymmetric (n_ba = -n_ab exactly) and
        /// using both surfaces.
        average,
        /// The outward normal of the body whose gradient is larger
        /// (better where one body barely reaches the node).
        larger_gradient
      };

      /// When two approaching bodies at a node are in contact at all.
      enum class SeparationCriterion
      {
        /// Every approaching pair with mass at the node.
        none,
        /// (V_a + V_b) >= f_c * node_volume: the node's support is nearly
        /// filled by the two bodies.
        volume_fraction,
        /// (x_b - x_a).n_ab <= d_c, x the bodies' mass centres at the
        /// node: the bodies' material lies within d_c along the normal.
        distance
      };

      /// The bodies' numbers are 1-based in the parameters (Bodies/Body k)
      /// and at most this many.
      static constexpr unsigned int max_bodies = 8;

      /// Entries inside subsection "Contact" (entered by the caller).
      static void
      declare_parameters(ParameterHandler &prm);

      /// Inside subsection "Contact": syntax and values of every entry.
      void
      parse_parameters(ParameterHandler &prm);

      /// With the number of bodies of the scene (Bodies/Number of bodies):
      /// contact needs two bodies, and every pair named must exist. Also
      /// sizes the friction table.
      void
      check_bodies(const unsigned int n_bodies);

      bool
      enabled() const
      {
        return type_multi_velocity;
      }

      /// The friction coefficient of bodies @p a and @p b (0-based),
      /// infinity for no-slip.
      double
      friction(const unsigned int a, const unsigned int b) const;

      /// Index of the pair a < b (0-based bodies) among n (n - 1) / 2.
      static unsigned int
      pair_index(const unsigned int a,
                 const unsigned int b,
                 const unsigned int n_bodies)
      {
        return a * n_bodies - a * (a + 1) / 2 + (b - a - 1);
      }

      /**
       * The nodal algorithm at every node of @p fields: velocities
       * corrected in place, statistics (n (n - 1) / 2 pairs, resized)
       * summed over the nodes. Pairs are corrected one after the other in
       * the order (1,2), (1,3), ..., (2,3), ...; each step conserves the
       * node's momentum and does not increase its kinetic energy, so the
       * whole correction does neither. No allocation per node.
       */
      void
      apply(ContactFields<dim>                      &fields,
            std::vector<ContactPairStatistics<dim>> &statistics) const;

      /// The same, with only the nodes i where @p counted[i] != 0 in the
      /// statistics (nullptr: all; the DoFs a rank owns, every rank
      /// corrects its ghosts alike), and, unless @p with_friction, the
      /// normal correction alone (every pair frictionless).
      void
      apply(ContactFields<dim>                      &fields,
            std::vector<ContactPairStatistics<dim>> &statistics,
            const std::vector<char>                 *counted,
            const bool with_friction = true) const;

      /// Per body (0-based), 1 for a driven body (Bodies/Body k/Motion =
      /// prescribed): infinite mass in correct_pair(), pairs of two
      /// driven bodies skipped. Empty: none. The caller sets the driven
      /// velocity into the fields before apply().
      std::vector<char> driven;

      /// Contact/Driven body nodes = geometry: the caller marks the nodes
      /// outside a driven body's moved shape where it has mass
      /// (ContactFields::normal_only); false: friction wherever it has
      /// mass.
      bool driven_nodes_from_geometry = false;

      NormalType          normal_type = NormalType::average;
      SeparationCriterion criterion   = SeparationCriterion::volume_fraction;
      double              critical_volume_fraction = 0.8;
      double              contact_distance         = 0;

    private:
      /// The normal of pair (a, b) at one node from a towards b; zero if
      /// it is undefined (a zero gradient, or opposite unit normals that
      /// cancel).
      static Tensor<1, dim>
      pair_normal(const Tensor<1, dim> &g_a,
                  const Tensor<1, dim> &g_b,
                  const NormalType      type);

      /// Whether the pair passes the separation criterion at node @p i.
      bool
      close_enough(const ContactFields<dim> &fields,
                   const unsigned int        i,
                   const unsigned int        a,
                   const unsigned int        b,
                   const Tensor<1, dim>     &normal) const;

      /// Every pair of bodies with mass at node @p i.
      void
      correct_node(ContactFields<dim>                      &fields,
                   const unsigned int                       i,
                   std::vector<ContactPairStatistics<dim>> &statistics,
                   const bool with_friction) const;

      bool   type_multi_velocity = false;
      double default_friction    = 0;
      /// Per-pair overrides as parsed: 1-based body numbers and mu.
      struct PairFriction
      {
        unsigned int a, b;
        double       mu;
      };
      std::vector<PairFriction> pair_overrides;
      /// The text of Pair friction, for messages.
      std::string pair_text;
      /// mu of every pair (pair_index), after check_bodies().
      std::vector<double> pair_friction;
      unsigned int        n_bodies = 0;
    };
  } // namespace Simulator
} // namespace psmpm

#endif
