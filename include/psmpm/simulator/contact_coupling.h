// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_simulator_contact_coupling_h
#define psmpm_simulator_contact_coupling_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <psmpm/base/archive.h>
#include <psmpm/postprocess/statistics_table.h>
#include <psmpm/simulator/contact.h>
#include <psmpm/simulator/driven_bodies.h>
#include <psmpm/simulator/state.h>

#include <string>
#include <vector>

namespace psmpm
{
  namespace Simulator
  {
    /**
     * Multi-velocity contact in the time step (subsection "Contact",
     * doc/contact.md): the nodal algorithm of Contact applied to per-body
     * grid fields at the contact DoFs, the DoFs whose support holds
     * particles of two bodies or more, and its result handed to the
     * particles of each body as velocity increments on top of the shared
     * grid solution, whatever mass strategy solved it.
     *
     * Per step (MUSL): correct_momentum() after the shared grid
     * acceleration (per-body mass, momentum, force, mass gradient and
     * volume at the contact DoFs, the per-body lumped update, the
     * correction); add_velocity_increments() after the particle velocity
     * update; correct_moving_velocity() after the shared grid velocity
     * the particles move with, and move() per chunk of moved particles
     * (positions and strain increments of each body with its own
     * velocity). With MPI the per-body sums of DoFs on rank boundaries are
     * added up over the ranks.
     *
     * Per node and body the increments keep what the shared solution
     * gives the node's centre of mass: body b's field is the shared one
     * plus its deviation from the lumped mass average,
     * a_bi = a_i + f_bi / m_bi - F_i / M_i (F_i, M_i the sums over the
     * bodies), so that sum_b m_bi (a_bi - a_i) = 0; one body at a node
     * gets exactly the shared field.
     */
    template <int dim>
    class ContactCoupling
    {
    public:
      /// Subsection "Contact" (entered here).
      static void
      declare_parameters(ParameterHandler &prm);

      /// Subsection "Contact", checked against the scene's number of
      /// bodies (Bodies/Number of bodies).
      void
      parse_parameters(ParameterHandler &prm, const unsigned int n_bodies);

      /// The driven bodies of the scene (Bodies/Body k/Motion =
      /// prescribed), after parse_parameters(); errors name the entry.
      void
      parse_driven(const std::vector<Particles::Body> &bodies);

      bool
      enabled() const
      {
        return contact.enabled();
      }

      /// With contact: Mass matrix/Type = automatic becomes lumped (a mass
      /// matrix with couplings mixes the bodies next to the contact DoFs),
      /// and Transfer/Scheme = automatic then takes the space's transfer
      /// for lumped mass (musl for P1, apic for Powell-Sabin); the note()
      /// says so.
      void
      choose_automatic(ParameterHandler &prm, std::string &mass_type);

      /// What choose_automatic() changed, for the run's log (empty: none).
      const std::string &
      note() const
      {
        return automatic_note;
      }

      /// Throws ExcMessage naming Contact/Type unless the transfer
      /// @p scheme (Transfer/Scheme), @p reconstruction and @p mass_type
      /// (Mass matrix/Type) are supported.
      void
      check_transfer(const std::string &scheme,
                     const std::string &reconstruction,
                     const std::string &mass_type) const;

      /// Once the grid exists: the node volumes, vertex groups and table
      /// sizes.
      void
      initialize(const State<dim> &state);

      /**
       * After the shared grid acceleration state.grid_acceleration (its
       * boundary conditions applied), before the particles' velocities
       * change: the contact DoFs of this step, the per-body fields there,
       * the per-body velocities v_bi* = v_bi + dt a_bi, the correction and
       * the increments v_bi' - v_bi - dt a_i each particle of body b gets
       * on top of the shared update (add_velocity_increments()).
       */
      void
      correct_momentum(State<dim> &state);

      /**
       * The apic form of correct_momentum(), after the shared grid
       * velocity v_i^{n+1} = v_i^n + dt a_i (state.grid_velocity): the
       * per-body momenta are those of the particles' affine fields, and
       * the increments are v_bi' - v_i^{n+1}, which
       * add_affine_increments() gives the particles' new velocities and
       * affine matrices. @p control_points: the space's control points in
       * local relevant numbering (apic's X_i).
       */
      void
      correct_affine_momentum(State<dim> &state, const Point<dim> *control_points);

      /**
       * After apic's grid-to-particle update (v_p = sum N_i v_i, C_p =
       * B_p D_p^{-1}, lumped mass, the momentum of the new affine fields in
       * the cell right-hand sides): the particles near contact DoFs get
       * their own body's field, v_p += sum N_i dv_bi and, with @p fit,
       * C_p += (sum N_i dv_bi (X_i - x_p)^T) D_p^{-1}, and the momentum of
       * that change goes into the cell right-hand sides.
       */
      void
      add_affine_increments(State<dim> &state, const bool fit);

      /// v_p += sum_i dv_bi N_i(x_p) for the particles near contact DoFs;
      /// with @p momentum_to_grid their momentum change goes into the
      /// cell right-hand sides too (MUSL's second projection). Driven
      /// bodies' particles then take their velocity
      /// (DrivenBodies::set_velocities; so does add_affine_increments()).
      void
      add_velocity_increments(State<dim> &state, const bool momentum_to_grid);

      /// After the shared grid velocity state.grid_velocity the particles
      /// move with: the per-body velocities from the particles' momenta,
      /// corrected again, and their deviation from the shared one, which
      /// move() adds.
      void
      correct_moving_velocity(const State<dim> &state);

      /// For the moved particles [@p first, @p last) of a chunk (after
      /// ParticleLoops::move_particles): positions, displacements and
      /// strain increments (increments[p - first]) of each body's
      /// particles with the body's own moving velocity.
      void
      move(State<dim>       &state,
           const std::size_t first,
           const std::size_t last,
           Tensor<2, dim>   *increments) const;

      /// move() for apic: positions only if @p positions (apic moves with
      /// v_p, which carries the body's field already), and the affine
      /// matrices of apic's velocity-gradient (@p gradient) or rotation
      /// (@p rotation) mode from the body's velocity gradient. Then, with
      /// driven bodies, their particles' own motion (DrivenBodies::move),
      /// for both schemes.
      void
      move_affine(State<dim>       &state,
                  const std::size_t first,
                  const std::size_t last,
                  Tensor<2, dim>   *increments,
                  const bool        positions,
                  const bool        gradient,
                  const bool        rotation) const;

      /// Per pair a-b: contact_force_a_b_x (, _y), the force on body a
      /// over the last step; normal_force_a_b and friction_force_a_b, the
      /// sums over the nodes of the normal and tangential impulses'
      /// magnitudes over dt (friction <= mu normal, node by node); and
      /// friction_work_a_b, normal_work_a_b, the kinetic energy removed
      /// since the start (<= 0), and slip_work_a_b, the part of
      /// friction_work_a_b at slipping nodes.
      std::vector<std::string>
      statistics_columns() const;

      /// The friction work of slipping nodes since the start, summed over
      /// the pairs (<= 0): energy dissipated by sliding, which the
      /// stability monitor's balance counts.
      double
      sliding_work() const;

      /// The work the driven bodies did on the others since the start
      /// (the contact force on them times the driven velocity, summed
      /// over the steps) plus the change of their own kinetic energy: the
      /// external work in the stability monitor's balance (0 without
      /// driven bodies).
      double
      driven_work() const
      {
        return accumulated_driven_work;
      }

      /// The columns above, summed over the ranks (collective).
      void
      add_columns(Postprocess::StatisticsTable &table) const;

      /// The accumulated works (contact/ in a checkpoint).
      void
      save(Archive &archive) const;
      void
      load(const Archive &archive);

      /// The parameters and the nodal algorithm.
      Contact<dim> contact;

      /// The bodies moved with a prescribed velocity (none by default).
      DrivenBodies<dim> driven_bodies;

    private:
      /// The driven bodies' velocities v(t^{n+1}) into their fields at
      /// the contact DoFs.
      void
      set_driven_fields();

      /// Contact/Driven body nodes = geometry: marks the contact DoFs
      /// whose vertex lies outside a driven body's moved shape, where the
      /// body has mass, as normal-only for it (fields.normal_only).
      void
      mark_normal_only();

      /// move_affine() of the particles near contact DoFs.
      void
      move_near_contact(State<dim>       &state,
                        const std::size_t first,
                        const std::size_t last,
                        Tensor<2, dim>   *increments,
                        const bool        positions,
                        const bool        gradient,
                        const bool        rotation) const;

      /// Per step: the contact DoFs (contact_dofs, dof_index), the cells
      /// touching them and the particles in those cells. Returns the
      /// number of contact DoFs over all ranks.
      unsigned int
      find_contact_dofs(const State<dim> &state);

      /// Per-body sums at the contact DoFs, width values per (DoF, body),
      /// added up over the ranks (collective; nothing on one rank).
      void
      sum_over_ranks(const State<dim>    &state,
                     std::vector<double> &values,
                     const unsigned int   width) const;

      /// Per-body mass, volume, momentum, force and mass gradient of the
      /// listed particles at the contact DoFs into sums.
      void
      particles_to_contact_dofs(const State<dim> &state);

      /// Contact::apply on fields; the statistics of the DoFs each rank
      /// owns, summed over the ranks, into step_statistics.
      void
      apply_correction();

      /// The mass gradients of the DoFs of one vertex summed, for each of
      /// them (Powell-Sabin; nothing changes for P1).
      void
      vertex_gradients();

      /// correct_momentum(), the per-body momenta of the particles'
      /// velocities (affine_points nullptr) or of their affine fields.
      void
      correct(State<dim> &state);

      /// Zero the increments of components fixed at a wall.
      void
      clear_fixed(const State<dim>            &state,
                  std::vector<Tensor<1, dim>> &dv) const;

      unsigned int n_bodies = 0;
      /// Per local relevant DoF: its contact index or invalid; whether
      /// this rank owns it; its volume (the integral of N_i).
      std::vector<unsigned int> dof_index;
      std::vector<char>         owned;
      std::vector<double>       dof_volume;
      /// Per local relevant DoF: the first DoF of its vertex.
      std::vector<unsigned int> vertex_dof;
      /// Per local relevant DoF: its vertex's position (only with
      /// Contact/Driven body nodes = geometry and a driven body).
      std::vector<Point<dim>> vertex_point;
      /// Scratch of vertex_gradients().
      std::vector<unsigned int>   vertex_slot;
      std::vector<Tensor<1, dim>> grouped;
      /// Scratch of find_contact_dofs(): body bit masks per cell and DoF.
      std::vector<unsigned int> cell_mask, dof_mask;
      /// The contact DoFs (local relevant indices), the cells touching
      /// them (1) and the particles in those cells.
      std::vector<unsigned int> contact_dofs;
      std::vector<char>         node_owned, contact_cell;
      std::vector<std::size_t>  near_particles;
      /// [(i * n_bodies + b) * width + j]: the per-body sums.
      std::vector<double> sums;
      ContactFields<dim>  fields;
      /// dv_bi of correct_momentum(), then the moving velocity's.
      std::vector<Tensor<1, dim>> velocity_increment, moving_increment;
      /// Per (DoF, body): p_bi / m_bi of the projection, and the unit
      /// direction in which the correction changed v_bi (zero where it
      /// did not); per near particle its velocity at the projection.
      std::vector<Tensor<1, dim>> projected_velocity, correction_direction,
        old_velocity;
      std::vector<ContactPairStatistics<dim>> step_statistics, scratch;
      /// Per pair (all ranks): force of the last step and the works
      /// accumulated since the start.
      std::vector<Tensor<1, dim>> pair_force;
      /// Per pair, the step's sums over the nodes of the normal and the
      /// tangential impulse magnitudes over dt.
      std::vector<double> normal_force, friction_force;
      std::vector<double> friction_work, normal_work, slip_work;
      /// apic's control points (local relevant numbering) for the per-body
      /// momenta of affine fields; nullptr: MUSL's m_p v_p.
      const Point<dim> *affine_points = nullptr;
      std::string       automatic_note;
      /// driven_work(), and its part of the step (add_driven_work()).
      double accumulated_driven_work = 0;

      /// The step's work of the driven bodies into
      /// accumulated_driven_work (collective).
      void
      add_driven_work();

      /// Whether any rank has contact DoFs in this step.
      bool         any_contact = false;
      MPI_Comm     comm        = MPI_COMM_SELF;
      unsigned int n_ranks     = 1;
    };
  } // namespace Simulator
} // namespace psmpm

#endif
