// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_simulator_state_h
#define psmpm_simulator_state_h

#include <deal.II/distributed/tria_base.h>
#include <deal.II/dofs/dof_handler.h>

#include <psmpm/basis/space.h>
#include <psmpm/material/material_set.h>
#include <psmpm/mesh/cell_locator.h>
#include <psmpm/particles/particle_set.h>
#include <psmpm/postprocess/state_view.h>
#include <psmpm/simulator/cell_forces.h>
#include <psmpm/solver/grid_system.h>

#include <memory>
#include <vector>

namespace psmpm
{
  namespace Simulator
  {
    using namespace dealii;

    template <int dim>
    class Reconstruction;
    template <int dim>
    class BoundaryConditions;
    template <int dim>
    class ContactCoupling;

    /**
     * The discrete state of an MPM run that the components (transfer
     * scheme, time step control, monitors, postprocessors) read and
     * advance: mesh and space, grid system, material, particles, the
     * basis values at the particles, the grid fields and the time.
     */
    template <int dim>
    struct State
    {
      explicit State(MPI_Comm comm);
      ~State();

      /// Values and gradients of the basis at every particle (after the
      /// particles have moved or migrated).
      void
      evaluate_shape_functions();

      /// Size the basis arrays for the particles there are now (the
      /// values of those that stay keep their place) and, once, evaluate
      /// the cells' gradients where they are constant on cells.
      void
      prepare_shape_functions();

      /// Values and gradients of the basis at the particles
      /// [@p first, @p last) (after prepare_shape_functions()).
      void
      evaluate_shape_functions(const std::size_t first, const std::size_t last);

      /// The particle stresses the internal forces take: force_stress if
      /// a step prepared it, else the particles' own.
      const SymmetricTensor<2, dim> *
      stress_for_forces() const
      {
        return force_stress.empty() ? particles.stress.data() :
                                      force_stress.data();
      }

      /**
       * The dofs_per_cell() basis gradients at particle @p p, which lies
       * in cell @p cell (the loops have read it already): one set per cell
       * where the space's gradients are constant on cells (P1: 48 B per
       * particle that evaluate_shape_functions() does not write and the
       * particle loops do not read), one set per particle otherwise.
       */
      const Tensor<1, dim> *
      gradients(const std::size_t p, const unsigned int cell) const
      {
        return shape_gradients.data() +
               (gradients_per_cell ? std::size_t(cell) : p) *
                 functions_per_cell;
      }

      /// The rank's cell of index @p whole in the whole mesh (the identity
      /// on a replicated mesh), or numbers::invalid_unsigned_int.
      unsigned int
      local_cell(const unsigned int whole) const;

      /// What the postprocessors read: this state, without the run
      /// around it (no reference, an affine transfer assumed).
      operator Postprocess::StateView<dim>() const
      {
        return {comm,
                triangulation.get(),
                dof_handler,
                space.get(),
                locator,
                grid.get(),
                materials,
                particles,
                gravity,
                shape_values,
                grid_velocity,
                grid_acceleration,
                time,
                step,
                dt,
                nullptr,
                true,
                false,
                std::string()};
      }

      MPI_Comm comm;
      /// Replicated (parallel::shared) or, with Mesh/Distribution =
      /// distributed, parallel::fullydistributed.
      std::unique_ptr<parallel::TriangulationBase<dim>> triangulation;
      DoFHandler<dim>                                   dof_handler;
      std::unique_ptr<Basis::Space<dim>>                space;
      Mesh::CellLocator<dim>                            locator;
      std::unique_ptr<Solver::GridSystem<dim>>          grid;
      /// How particle data reach the grid integrals; nullptr: the
      /// particles themselves (Transfer/Reconstruction = particles).
      std::unique_ptr<Reconstruction<dim>> reconstruction;
      /// Reactions, friction and prescribed velocities of the walls,
      /// applied by the transfer schemes; nullptr when the scene uses
      /// none of them (the simulator owns the object).
      BoundaryConditions<dim> *boundary_conditions = nullptr;
      /// Multi-velocity contact between bodies, applied by the transfer
      /// schemes; nullptr with Contact/Type = none (the simulator owns the
      /// object).
      ContactCoupling<dim> *contact = nullptr;
      Material::MaterialSet<dim>           materials;
      Particles::ParticleSet<dim>          particles;
      Tensor<1, dim>                       gravity;
      std::vector<unsigned int>            cell_owner; ///< MPI rank
      /// A distributed mesh: the index in the whole mesh of each of the
      /// rank's cells (increasing), and the owner of every cell of the
      /// whole mesh (checkpoints name cells by it). Empty when replicated.
      std::vector<unsigned int> whole_index, whole_owner;
      /// Basis at the particles, dofs_per_cell per particle; the
      /// gradients per cell if gradients_per_cell (read them through
      /// gradients()).
      std::vector<double>         shape_values;
      std::vector<Tensor<1, dim>> shape_gradients;
      bool                        gradients_per_cell = false;
      unsigned int                functions_per_cell = 0;
      /// Grid fields in local relevant numbering.
      std::vector<Tensor<1, dim>> grid_velocity;
      std::vector<Tensor<1, dim>> grid_acceleration;
      double                      time = 0;
      unsigned int                step = 0;
      /// Length of the step under way (0 before the first).
      double dt = 0;
      /**
       * Whether the grid's cell arrays hold the particles' mass and forces
       * (momentum weight 0, force weight 1) of the state as it is now:
       * MUSL and USL accumulate them for the next step while each chunk of
       * moved particles is still in the cache
       * (TransferScheme::move_and_update_material()), and the next
       * particles_to_grid() takes them instead of a pass over all
       * particles. particles_to_grid() clears it; nothing else changes the
       * particles between two steps.
       */
      bool forces_in_cells = false;
      /**
       * With Transfer/Volumetric strain = cell average, from the start of
       * a step until its material update: each particle's stress with
       * its in-plane mean replaced by the mean of its cell and body, or
       * removed where the cell's pressure is integrated exactly
       * (cell_forces; VolumetricAveraging::prepare()), so that the
       * internal forces are work-conjugate to the averaged strain
       * increments (B-bar). Empty otherwise (stress_for_forces()).
       */
      std::vector<SymmetricTensor<2, dim>> force_stress;
      /// The forces of the cells whose pressure is integrated exactly,
      /// for the same steps as force_stress; every particle-to-grid pass
      /// adds them to the cell right-hand sides. Empty otherwise.
      CellForces<dim> cell_forces;

    private:
      /// Scratch of evaluate_shape_functions() (the values it discards
      /// when it evaluates the cells' gradients).
      std::vector<double> cell_values;
    };
  } // namespace Simulator
} // namespace psmpm

#endif
