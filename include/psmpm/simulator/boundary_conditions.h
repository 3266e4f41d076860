// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_simulator_boundary_conditions_h
#define psmpm_simulator_boundary_conditions_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/tria.h>

#include <psmpm/base/archive.h>
#include <psmpm/mesh/mesh_generator.h>
#include <psmpm/postprocess/statistics_table.h>

#include <array>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace psmpm
{
  namespace Simulator
  {
    using namespace dealii;

    template <int dim>
    struct State;

    /**
     * What the walls of a scene do beyond fixing velocity components to
     * zero (subsection "Boundary conditions"; doc/geomechanics.md):
     *
     * - the reaction force of every named boundary with a constrained
     *   component, R_i = (M a)_i - b_i summed over its constrained DoFs
     *   (the force the wall exerts on the body), as statistics columns
     *   reaction_<name>_<x|y> (Report reactions, or automatically with the
     *   two entries below);
     * - Coulomb friction on walls whose normal component is fixed
     *   (Friction coefficient): the tangential acceleration of a DoF in
     *   contact is reduced so that its tangential velocity changes by at
     *   most mu |R_n| dt / m_i towards zero, never reversing it; "no-slip"
     *   fixes the tangential component too;
     * - prescribed velocities, functions of t, on named boundaries
     *   (Prescribed velocity, lumped mass only), and named parts of a
     *   boundary (Boundary parts).
     *
     * The simulator creates the object; the State points to it only when
     * one of these is used (nullptr otherwise, so a scene without them
     * runs the same operations as before). The transfer schemes call
     * after_acceleration() right after the acceleration solve and
     * impose_velocity() after every grid velocity of the step that
     * particles are moved with.
     */
    template <int dim>
    class BoundaryConditions
    {
    public:
      /// Entries inside subsection "Boundary conditions" (entered by the
      /// caller).
      static void
      declare_parameters(ParameterHandler &prm);
      /// Inside subsection "Boundary conditions"; checks the syntax and
      /// values (names are checked against the mesh later).
      void
      parse_parameters(ParameterHandler &prm);

      /// Whether any of the features is used (the State then points to
      /// this object).
      bool
      active() const
      {
        return report_reactions || !friction.empty() || !prescribed.empty() ||
               local_damping > 0 || stop_at_walls;
      }

      /// Throws ExcMessage naming Boundary conditions/Stop particles at
      /// walls if it is on and the transfer @p scheme (Transfer/Scheme)
      /// is not musl.
      void
      check_transfer(const std::string &scheme) const;

      /// Boundary parts: relabel the faces of each part with a new
      /// boundary id and give it its name in @p mesh. Right after the mesh
      /// is created (every rank, on the cells it holds).
      void
      mark_boundary_parts(Triangulation<dim>             &tria,
                          const Mesh::MeshGenerator<dim> &mesh) const;

      /// Add the prescribed boundaries (every component) and the no-slip
      /// walls (their tangential component) to @p fixed, the sets the
      /// grid constrains to zero; checks the names.
      void
      add_constrained(std::array<std::set<types::boundary_id>, dim> &fixed,
                      const Mesh::MeshGenerator<dim> &mesh) const;

      /**
       * The DoFs of every reported boundary, the frictional and
       * prescribed DoFs, after the grid's reinit(). @p fixed_names are
       * the Fixed x/y entries in their order: a DoF on two boundaries
       * with the same constrained component is reported with the first
       * (prescribed boundaries first, then Fixed x/y in their order,
       * then no-slip walls). @p grid_moves: the transfer's grid moves
       * with the material (refused).
       */
      void
      reinit(const State<dim>                                &state,
             const std::array<std::vector<std::string>, dim> &fixed_names,
             const Mesh::MeshGenerator<dim>                  &mesh,
             const bool                                       grid_moves);

      /**
       * Prescribed accelerations, reactions and friction, on
       * state.grid_acceleration (after its solve). The tangential
       * velocity v_t of a frictional DoF is state.grid_velocity's: this
       * step's with APIC (solved first), the last step's final one with
       * MUSL and USL, which the hold of impose_velocity() and the
       * particles share. A DoF that sticks keeps the rest of its Coulomb
       * bound for that hold.
       */
      void
      after_acceleration(State<dim> &state);

      /// The prescribed velocities at the end of the step into
      /// state.grid_velocity, and the hold of the walls that stick.
      void
      impose_velocity(State<dim> &state);

      /**
       * Stop particles at walls (MUSL, after impose_velocity()): the
       * velocity change with which the constraints of the fixed and
       * prescribed DoFs set the re-projected grid velocity (lumped: the
       * momentum over the mass of the DoF's cells) to its constrained
       * value goes to the particles too, v_p += sum_i N_i(x_p) dv_i, as
       * the hold of a sticking wall does; the particles' kinetic energy
       * change is the work wall_stop_work. Nothing when the entry is off.
       */
      void
      stop_particles(State<dim> &state);

    private:
      /// The hold's change of the wall DoFs to the particles' velocities;
      /// returns the particles' kinetic energy change (this rank's).
      double
      hold_particles(State<dim> &state) const;

      /// The constraints' change dv_i of the fixed and prescribed DoFs
      /// into stop_momentum (from the cell right-hand sides of a momentum
      /// projection and state.grid_velocity after its solve); whether any
      /// rank has one.
      bool
      stop_change(const State<dim> &state);

    public:
      /// Reaction columns (the last step's) and the accumulated work.
      void
      add_columns(Postprocess::StatisticsTable &table) const;

      /// The names of the columns add_columns() writes.
      std::vector<std::string>
      statistics_columns() const;

      /// Reaction of column @p column (see column_names()) of the last
      /// step.
      double
      reaction(const unsigned int column) const
      {
        return reactions[column];
      }
      /// reaction_<name>_<x|y>, in column order.
      std::vector<std::string>
      column_names() const;
      /// Work of the friction forces on the body so far (<= 0): sum of
      /// F_t v_t dt, v_t the mean tangential velocity of the step.
      double
      friction_work() const
      {
        return accumulated_friction_work;
      }
      /// Work of the local damping forces on the body so far (<= 0).
      double
      damping_work() const
      {
        return accumulated_damping_work;
      }
      /// Work of the prescribed boundaries' reactions on the body so far.
      double
      prescribed_work() const
      {
        return accumulated_prescribed_work;
      }

      /**
       * The energy the stability monitor checks, from the total
       * (kinetic + strain + gravity) energy @p total after step @p step:
       * minus the works of friction, damping and the prescribed
       * boundaries, and with prescribed boundaries minus the part of the
       * first step's change that their work misses. A step's reaction is
       * that of the stress at its start, which is zero in the first step
       * of a body loaded by a plate: the strain energy that step builds is
       * not in its work (22 % of the energy after one step of the strip
       * footing of doc/geomechanics.md), and the monitor would take it for
       * growth without work. The balance is counted from the end of that
       * step instead.
       */
      double
      monitored_energy(const double total, const unsigned int step);

      /// The entry of the first prescribed velocity that is not finite at
      /// @p t (the end of the step that imposes it), with that time;
      /// empty if none.
      std::string
      non_finite_velocity(const double t) const;

      /// The accumulated work (checkpoints).
      void
      save(Archive &archive) const;
      void
      load(const Archive &archive);

    private:
      struct Friction
      {
        std::string name;
        double      mu      = 0;
        bool        no_slip = false;
      };
      struct Prescribed
      {
        std::string                        name;
        std::string                        expression;
        std::unique_ptr<FunctionParser<1>> velocity;
        /// The velocity of the step's start (the one imposed at the end
        /// of the last step; 0 before the first: the body starts at
        /// rest there) and of its end, v(t + dt).
        std::array<double, dim> old_value{}, new_value{};
        std::array<double, dim> imposed{};
        /// Components given as 'free': not constrained (e.g. the
        /// tangential velocity of a smooth loading plate).
        std::array<bool, dim> free{};
      };
      struct Part
      {
        std::string name, parent;
        double      from = 0, to = 0;
      };
      /// One reported (boundary, component).
      struct Column
      {
        std::string  name;
        unsigned int component;
      };
      /// A constrained DoF k of an owned cell c (index c * dofs_per_cell
      /// + k of the cell arrays), its column and, for the normal of a
      /// frictional wall, its wall DoF (else invalid).
      struct Entry
      {
        unsigned int index, column, wall;
      };
      /// A DoF of a frictional wall: local relevant index, normal and
      /// tangential component, outward sign of the normal, mu and the
      /// tangential reaction column.
      struct WallDof
      {
        unsigned int dof, normal, tangential;
        double       outward, mu;
        unsigned int column;
      };
      struct PrescribedDof
      {
        unsigned int dof, component, boundary;
      };

      /// The entries Friction coefficient, Prescribed velocity and
      /// Boundary parts (their text as given, for the messages).
      void
      parse_friction(const std::string &text);
      void
      parse_prescribed(const std::string &text);
      void
      parse_parts(const std::string &text);

      /// The boundaries per component in the order of attribution:
      /// prescribed, fixed, then no-slip.
      std::array<std::vector<std::string>, dim>
      attribution_order(
        const std::array<std::vector<std::string>, dim> &fixed_names) const;
      /// A column per boundary and component of @p order, and the column
      /// of each DoF fixed to zero by the grid (the first one's).
      void
      assign_columns(const State<dim>                                &state,
                     const std::array<std::vector<std::string>, dim> &order,
                     const Mesh::MeshGenerator<dim>                  &mesh);
      /// A frictional wall: its normal DoFs whose tangential component is
      /// free, with the outward sign of the normal from the faces, and
      /// the column of its tangential reaction.
      void
      add_friction_wall(
        const State<dim>                                &state,
        const Friction                                  &f,
        const std::array<std::vector<std::string>, dim> &fixed_names,
        const Mesh::MeshGenerator<dim>                  &mesh);
      /// The constrained DoFs of the owned cells (cell array index,
      /// column, wall).
      void
      collect_entries(const State<dim> &state);
      void
      collect_prescribed_dofs();
      /// Reactions, wall forces and the buffers of the sum over ranks.
      void
      allocate_results(const State<dim> &state);

      /// The steps of after_acceleration().
      void
      apply_local_damping(State<dim> &state);
      void
      prescribe_acceleration(State<dim> &state);
      void
      compute_reactions(State<dim> &state);
      void
      sum_wall_normals(const State<dim> &state);
      void
      apply_friction(State<dim> &state);
      void
      add_prescribed_work(const double dt);

      bool                    report_reactions = false;
      std::vector<Friction>   friction;
      std::vector<Prescribed> prescribed;
      std::vector<Part>       parts;
      std::vector<Column>     columns;
      /// Per component, the DoFs' columns (local relevant numbering).
      std::array<std::vector<unsigned int>, dim> dof_column;
      std::array<std::vector<Entry>, dim>        entries;
      std::vector<WallDof>                       walls;
      /// Per local relevant DoF its wall DoF (or invalid).
      std::vector<unsigned int>  wall_of;
      std::vector<PrescribedDof> prescribed_dofs;
      /// Per column, whether it belongs to a prescribed boundary.
      std::vector<bool>   column_prescribed;
      std::vector<double> reactions, wall_normal;
      /// Per wall DoF, the tangential velocity change that the step's
      /// Coulomb bound mu |R_n| dt / m still allows after the friction of
      /// after_acceleration() (0 when it slides or is not in contact).
      std::vector<double> hold_capacity;
      /// Per wall DoF, the tangential velocity change of the hold in the
      /// last impose_velocity().
      std::vector<double> hold_change;
      /// Per wall DoF, whether this rank owns it (its friction force and
      /// work are counted there); buffers of the normal force's sum over
      /// ranks.
      std::vector<bool>   wall_owned;
      std::vector<double> relevant_buffer, owned_buffer;
      bool                sum_over_ranks = false;
      /// Stop particles at walls: the entry; per component and local
      /// relevant DoF the momentum and mass sums of the constrained DoFs
      /// (then the velocity change); the accumulated work (<= 0 at fixed
      /// walls).
      bool                                 stop_at_walls = false;
      std::array<std::vector<double>, dim> stop_momentum, stop_mass;
      /// Per cell: whether it has a constrained DoF (its particles are
      /// the ones stop_particles() changes).
      std::vector<char> stop_cell;
      double            accumulated_stop_work = 0;
      /// The last step's reactions (the prescribed work's extrapolation;
      /// empty before the first step).
      std::vector<double> previous_reactions;
      bool                lumped_acceleration         = true;
      double              accumulated_friction_work   = 0;
      double              accumulated_prescribed_work = 0;
      double              accumulated_damping_work    = 0;
      /// monitored_energy(): the balance at step 0 and the first step's
      /// change that the prescribed work missed.
      double initial_balance = 0, first_step_offset = 0;
      /// Local damping alpha (0: off).
      double local_damping = 0;
    };
  } // namespace Simulator
} // namespace psmpm

#endif
