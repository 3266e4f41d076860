// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_postprocess_state_view_h
#define psmpm_postprocess_state_view_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>
#include <deal.II/distributed/tria_base.h>
#include <deal.II/dofs/dof_handler.h>

#include <psmpm/basis/space.h>
#include <psmpm/material/material_set.h>
#include <psmpm/mesh/cell_locator.h>
#include <psmpm/particles/particle_set.h>
#include <psmpm/postprocess/reference.h>
#include <psmpm/solver/grid_system.h>

#include <string>
#include <vector>

namespace psmpm
{
  namespace Postprocess
  {
    using namespace dealii;

    /**
     * What a postprocessor may read of a run: the discrete state (the
     * members have the names and meaning of Simulator::State's, which
     * converts to a view of itself) and the run around it (reference,
     * transfer, output directory). Read-only: the postprocess layer sees
     * no simulator header, and a postprocessor cannot change the run it
     * measures. The references follow the state, so time, step and dt
     * are those of the moment a hook is called.
     */
    template <int dim>
    struct StateView
    {
      MPI_Comm                                comm;
      const parallel::TriangulationBase<dim> *triangulation;
      const DoFHandler<dim>                  &dof_handler;
      const Basis::Space<dim>                *space;
      const Mesh::CellLocator<dim>           &locator;
      const Solver::GridSystem<dim>          *grid;
      const Material::MaterialSet<dim>       &materials;
      const Particles::ParticleSet<dim>      &particles;
      const Tensor<1, dim>                   &gravity;
      /// Basis values at the particles, dofs_per_cell per particle.
      const std::vector<double> &shape_values;
      /// Grid fields in local relevant numbering.
      const std::vector<Tensor<1, dim>> &grid_velocity;
      const std::vector<Tensor<1, dim>> &grid_acceleration;
      const double                      &time;
      const unsigned int                &step;
      /// Length of the step just taken (0 before the first).
      const double &dt;

      /// The reference solution of the scene (nullptr: none). A
      /// reference computed alongside the run has been advanced to time.
      const Reference<dim> *reference = nullptr;
      /// Whether the transfer scheme carries affine velocity matrices
      /// (the particles' affine arrays may then be nonzero).
      bool carries_affine = true;
      /// Whether this is the last step of the run (Time/End time).
      bool last_step = false;
      /// Where the run writes its files ("" before run() or resume()).
      std::string output_directory;
    };
  } // namespace Postprocess
} // namespace psmpm

#endif
