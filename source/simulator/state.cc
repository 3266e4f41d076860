// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/simulator/reconstruction.h>
#include <psmpm/simulator/state.h>

namespace psmpm
{
  namespace Simulator
  {
    template <int dim>
    State<dim>::State(MPI_Comm comm)
      : comm(comm)
      , triangulation(comm,
                      Triangulation<dim>::none,
                      false,
                      parallel::shared::Triangulation<dim>::partition_metis)
    {
    }

    template <int dim>
    State<dim>::~State()
    {
      // The grid system refers to the DoF handler.
      reconstruction.reset();
      grid.reset();
      dof_handler.clear();
    }

    template <int dim>
    void
    State<dim>::evaluate_shape_functions()
    {
      const unsigned int n = space->dofs_per_cell();
      Particles::resize_per_particle(shape_values, particles, n);
      Particles::resize_per_particle(shape_gradients, particles, n);
      space->evaluate(particles.size(),
                      particles.cell.data(),
                      particles.position.data(),
                      shape_values.data(),
                      shape_gradients.data());
    }

    template struct State<1>;
    template struct State<2>;
  } // namespace Simulator
} // namespace psmpm
