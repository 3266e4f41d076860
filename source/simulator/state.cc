// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/distributed/shared_tria.h>

#include <psmpm/simulator/reconstruction.h>
#include <psmpm/simulator/state.h>

#include <algorithm>

namespace psmpm
{
  namespace Simulator
  {
    template <int dim>
    State<dim>::State(MPI_Comm comm)
      : comm(comm)
      , triangulation(std::make_unique<parallel::shared::Triangulation<dim>>(
          comm,
          Triangulation<dim>::none,
          false,
          parallel::shared::Triangulation<dim>::partition_metis))
    {
    }

    template <int dim>
    unsigned int
    State<dim>::local_cell(const unsigned int whole) const
    {
      if (whole_index.empty())
        return whole;
      const auto it =
        std::lower_bound(whole_index.begin(), whole_index.end(), whole);
      return it != whole_index.end() && *it == whole ?
               static_cast<unsigned int>(it - whole_index.begin()) :
               numbers::invalid_unsigned_int;
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
