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
      prepare_shape_functions();
      evaluate_shape_functions(0, particles.size());
    }

    template <int dim>
    void
    State<dim>::prepare_shape_functions()
    {
      const unsigned int n = space->dofs_per_cell();
      functions_per_cell   = n;
      gradients_per_cell   = space->gradients_constant_on_cells();
      Particles::resize_per_particle(shape_values, particles, n);
      const unsigned int n_cells = triangulation->n_active_cells();
      if (!gradients_per_cell)
        Particles::resize_per_particle(shape_gradients, particles, n);
      else if (shape_gradients.size() != std::size_t(n_cells) * n)
        {
          // Every cell's gradients, evaluated anywhere (they are constant
          // there), once: they depend on the mesh alone, which does not
          // change during a run (OTM keeps those of its moved grid here).
          shape_gradients.resize(std::size_t(n_cells) * n);
          cell_values.resize(n);
          for (unsigned int c = 0; c < n_cells; ++c)
            space->evaluate(c,
                            Point<dim>(),
                            cell_values.data(),
                            shape_gradients.data() + std::size_t(c) * n);
        }
    }

    template <int dim>
    void
    State<dim>::evaluate_shape_functions(const std::size_t first,
                                         const std::size_t last)
    {
      const unsigned int n = functions_per_cell;
      space->evaluate(last - first,
                      particles.cell.data() + first,
                      particles.position.data() + first,
                      shape_values.data() + first * n,
                      gradients_per_cell ? nullptr :
                                           shape_gradients.data() + first * n);
    }

    template struct State<1>;
    template struct State<2>;
  } // namespace Simulator
} // namespace psmpm
