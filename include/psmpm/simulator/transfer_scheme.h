// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_simulator_transfer_scheme_h
#define psmpm_simulator_transfer_scheme_h

#include <deal.II/base/parameter_handler.h>

#include <psmpm/base/archive.h>
#include <psmpm/base/phase_timer.h>
#include <psmpm/base/registry.h>
#include <psmpm/simulator/particle_loops.h>
#include <psmpm/simulator/particle_relocation.h>
#include <psmpm/simulator/stability_monitor.h>
#include <psmpm/simulator/state.h>
#include <psmpm/simulator/volumetric_averaging.h>

#include <array>
#include <memory>

namespace psmpm
{
  namespace Simulator
  {
    /**
     * Told of every chunk of particles whose update a scheme has finished
     * in a step (positions, velocities, stresses and volumes final), in
     * particle order from the first particle, while the chunk is still in
     * the cache: the per-step statistics sum over the particles there
     * instead of in a pass of their own (Postprocess::StepSums).
     */
    template <int dim>
    class UpdatedChunkObserver
    {
    public:
      virtual ~UpdatedChunkObserver() = default;

      virtual void
      updated(const State<dim> &state,
              const std::size_t first,
              const std::size_t last) = 0;
    };

    /**
     * One MPM time step between particles and grid (subsection
     * "Transfer", entry "Scheme"): from the particles' mass, momentum and
     * stress to grid accelerations and velocities and back to particle
     * velocities, stresses (through the material), volumes and positions.
     * The simulator locates the moved particles, or hands that to the
     * scheme (relocate_with()). Failures go to the monitor; kernels never
     * throw for an unstable state.
     *
     * Schemes register in TransferSchemeRegistry<dim>; the factory gets
     * the parameters inside subsection "Transfer".
     */
    template <int dim>
    class TransferScheme
    {
    public:
      virtual ~TransferScheme() = default;

      static void
      declare_parameters(ParameterHandler &prm);

      /// Called once by Simulator::setup() when the state is complete
      /// (mesh, space, grid, particles and their basis values): a scheme
      /// checks that it can work with this state (throws ExcMessage naming
      /// the entry otherwise) and copies what it keeps.
      virtual void
      initialize(const State<dim> &state)
      {
        (void)state;
      }

      /// What the scheme keeps from step to step beyond the particles
      /// (OTM: the moved grid), into a checkpoint (collective; every rank
      /// writes the same entries) ...
      virtual void
      save(Archive &archive, const State<dim> &state) const
      {
        (void)archive;
        (void)state;
      }

      /// ... and back, after the particles have been restored.
      virtual void
      load(const Archive &archive, State<dim> &state)
      {
        (void)archive;
        (void)state;
      }

      /// Whether the grid moves with the material (OTM): particles then
      /// keep their cells, the simulator does not locate them, and the
      /// scheme itself keeps state.shape_values and shape_gradients
      /// current (on its moved grid) after every step.
      virtual bool
      moves_grid() const
      {
        return false;
      }

      /// Whether the scheme transfers and updates the particles' affine
      /// matrices C_p (APIC). The initial conditions set C_p = grad v for
      /// such schemes; for the others the simulator clears it, since they
      /// never update it and the angular momentum statistic would
      /// otherwise report a stale affine part.
      virtual bool
      carries_affine() const
      {
        return false;
      }

      /// Smallest cell height (triangle height, line length in 1D) of the
      /// grid the scheme computes on now: the length of the time step
      /// bound. The fixed mesh's by default; a scheme whose grid moves
      /// (OTM) returns that of its moved cells, which shrink as the
      /// material compresses. Collective: every rank calls it between
      /// steps.
      virtual double
      minimum_height(const State<dim> &state) const
      {
        return state.locator.minimum_height();
      }

      /// The current positions of the grid's vertices in local relevant
      /// DoF numbering (P1: one DoF per vertex) if the grid moves, so that
      /// the grid output shows the moved cells; nullptr if the grid is the
      /// triangulation.
      virtual const std::vector<Point<dim>> *
      moved_vertices() const
      {
        return nullptr;
      }

      /// Advance @p state by state.dt. Returns false if the step had to
      /// be abandoned (a failure is reported, positions are not advanced).
      virtual bool
      step(State<dim> &state, StabilityMonitor &monitor, PhaseTimer &timer) = 0;

      /// Tell @p observer (nullptr: nobody) of the chunks that
      /// move_and_update_material() finishes; schemes that update their
      /// particles otherwise tell nobody, and the observer sees an
      /// incomplete step.
      void
      observe_updated_chunks(UpdatedChunkObserver<dim> *observer)
      {
        chunk_observer = observer;
      }

      /// Let move_and_update_material() locate the moved particles with
      /// @p relocation (nullptr: it does not), chunk by chunk while they
      /// are in the cache. Set before every step.
      void
      relocate_with(ParticleRelocation<dim> *relocation)
      {
        this->relocation = relocation;
        relocated_now    = false;
      }

      /// Whether move_and_update_material() gives each particle the mean
      /// volumetric strain of its cell and body (Transfer/Volumetric
      /// strain = cell average; VolumetricAveraging), with the cells one
      /// body fills integrated exactly if @p exact_cells (a fixed grid).
      void
      average_volumetric_strain(const bool average, const bool exact_cells)
      {
        averaging.reset(average ? new VolumetricAveraging<dim>(exact_cells) :
                                  nullptr);
      }

      /// Before step(): with the volumetric average, the stresses and cell
      /// forces of the step's internal forces (State::force_stress,
      /// State::cell_forces), on the cells the particles are in now.
      void
      prepare_step(State<dim> &state)
      {
        if (averages(state))
          averaging->prepare(state);
      }

      /// Whether the last step located its particles (relocate_with());
      /// schemes that move them otherwise leave it to the simulator.
      bool
      relocated() const
      {
        return relocated_now;
      }

    protected:
      /// Whether the volumetric average applies: asked for, and gradients
      /// not constant on cells (P1's strain is the mean of its cell
      /// already).
      bool
      averages(const State<dim> &state) const
      {
        return averaging && !state.gradients_per_cell;
      }

      /// state.grid->solve(@p solution), a CG failure reported to the
      /// monitor (returns false) instead of thrown.
      static bool
      solve(State<dim>                  &state,
            std::vector<Tensor<1, dim>> &solution,
            StabilityMonitor            &monitor,
            PhaseTimer                  &timer);

      /// The grid acceleration M^{-1} f: as solve(), with the lumped mass
      /// if the reconstruction asks for it
      /// (Reconstruction::lumped_acceleration()).
      static bool
      solve_acceleration(State<dim>       &state,
                         StabilityMonitor &monitor,
                         PhaseTimer       &timer);

      /// Particle mass into the cell matrices (lumped and, for matrix
      /// strategies, consistent; then the strategy: assemble_mass) and the
      /// cell right-hand sides momentum_weight sum_p m_p v_p N_i +
      /// force_weight f_i, f_i = sum_p (m_p g N_i - V_p sigma_p grad N_i).
      /// MUSL and USL take the forces alone (0, 1); OTM's combined update
      /// both (1, its mean step).
      static void
      particles_to_grid(State<dim>  &state,
                        PhaseTimer  &timer,
                        const double momentum_weight,
                        const double force_weight);

      /// Cell right-hand sides sum_p m_p v_p N_i (the mass matrix of the
      /// step already assembled).
      static void
      momentum_to_grid(State<dim> &state, PhaseTimer &timer);

      /// The material update of all particles from their increments
      /// dt grad v, then volumes and densities; a non-positive volume is
      /// reported. @p volume_ratio is scratch of any size.
      static void
      update_material(State<dim>                        &state,
                      const std::vector<Tensor<2, dim>> &increments,
                      std::vector<double>               &volume_ratio,
                      StabilityMonitor                  &monitor);

      /// The same for the particles [@p first, @p last), whose increments
      /// and volume ratios (scratch) start at @p increments[0] and
      /// @p volume_ratio[0].
      static void
      update_material(State<dim>           &state,
                      const std::size_t     first,
                      const std::size_t     last,
                      const Tensor<2, dim> *increments,
                      double               *volume_ratio,
                      StabilityMonitor     &monitor);

      /**
       * ParticleLoops::move_particles() and update_material() for every
       * particle, a chunk of particles at a time: a chunk's strain
       * increments and volume ratios stay in the L1 cache between the two
       * loops instead of going through memory in arrays over all
       * particles (80 B per particle and step; the same operations on
       * every particle, so the same results). The observer sums the
       * chunk's statistics.
       *
       * With a relocation (relocate_with()), the chunk's particles are
       * then located and the basis evaluated at their new positions, and
       * (without a reconstruction) their mass and forces added to the
       * cell arrays of the next step (State::forces_in_cells), while
       * their data are in the cache: one pass over the particles instead
       * of three. The next particles_to_grid(state, timer, 0, 1) uses
       * those sums; they are the same bits as its own pass, since the
       * particles are summed in the same order.
       */
      template <ParticleLoops::VelocityUpdate velocity_update>
      void
      move_and_update_material(State<dim>       &state,
                               StabilityMonitor &monitor,
                               PhaseTimer       &timer);

      /**
       * The chunked pass of move_and_update_material() with a scheme's
       * own particle loops (APIC: its velocities, affine matrices and
       * momentum), @p kernels providing, for particles [first, last):
       *  - move(state, first, last, increments): positions, velocities
       *    and the strain increments (increments[p - first]);
       *  - accumulates(state): whether the located particles go to the
       *    cell arrays of the next step (State::forces_in_cells);
       *  - start_cells(state), add_to_cells(state, first, last) and
       *    finish_cells(state): zero those sums, add the located
       *    particles [first, last) in particle order, complete them.
       * A template (transfer_scheme.templates.h): the kernels are called
       * per chunk, never per particle through a virtual function.
       */
      template <typename Kernels>
      void
      update_in_chunks(State<dim>       &state,
                       StabilityMonitor &monitor,
                       PhaseTimer       &timer,
                       Kernels          &kernels);

    private:
      /// 16 kB of increments in 2D: a chunk fits the L1 cache.
      static constexpr std::size_t      chunk = 512;
      std::array<Tensor<2, dim>, chunk> chunk_increments;
      std::array<double, chunk>         chunk_volume_ratio;
      UpdatedChunkObserver<dim>        *chunk_observer = nullptr;
      ParticleRelocation<dim>          *relocation     = nullptr;
      bool                              relocated_now  = false;
      /// Cell-averaged volumetric strain (nullptr: off), which needs the
      /// increments of all particles before the first update.
      std::unique_ptr<VolumetricAveraging<dim>> averaging;
      std::vector<Tensor<2, dim>>               all_increments;

      /// The located particles [first, last) of update_in_chunks() into
      /// the cell arrays (@p kernels), without those that left this rank.
      template <typename Kernels>
      void
      add_located_to_cells(State<dim>       &state,
                           const std::size_t first,
                           const std::size_t last,
                           const bool        some_left,
                           Kernels          &kernels) const;
    };

    template <int dim>
    using TransferSchemeRegistry =
      Registry<TransferScheme<dim>, ParameterHandler &>;
  } // namespace Simulator
} // namespace psmpm

#endif
