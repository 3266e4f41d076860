// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include <psmpm/simulator/dof_body_masks.h>

namespace psmpm
{
  namespace Simulator
  {
    template <int dim>
    void
    dof_body_masks(const State<dim>          &state,
                   std::vector<unsigned int> &cell_mask,
                   std::vector<unsigned int> &dof_mask,
                   const std::vector<char>   *owned_cells)
    {
      const auto         &grid      = *state.grid;
      const auto         &particles = state.particles;
      const unsigned int  n         = grid.dofs_per_cell;
      const unsigned int *dofs      = grid.cell_dofs().data();
      const unsigned int  n_cells   = grid.cell_dofs().size() / n;
      cell_mask.assign(n_cells, 0);
      const bool by_body = particles.body_id.size() == particles.size();
      for (std::size_t p = 0; p < particles.size(); ++p)
        cell_mask[particles.cell[p]] |=
          1u << (by_body ? particles.body_id[p] - 1 : 0u);
      if (owned_cells != nullptr)
        for (unsigned int c = 0; c < n_cells; ++c)
          if ((*owned_cells)[c] && cell_mask[c] == 0)
            cell_mask[c] = empty_bit(state);
      dof_mask.assign(grid.relevant_dofs().n_elements(), 0);
      for (unsigned int c = 0; c < n_cells; ++c)
        if (cell_mask[c] != 0)
          for (unsigned int k = 0; k < n; ++k)
            dof_mask[dofs[c * n + k]] |= cell_mask[c];
      if (Utilities::MPI::n_mpi_processes(state.comm) == 1)
        return;
      // Bit b of a DoF on a rank boundary: body b on any rank.
      std::vector<double> has(dof_mask.size()),
        sum(grid.locally_owned_dofs().n_elements());
      const unsigned int n_bits =
        std::max(particles.n_bodies, 1u) + (owned_cells != nullptr ? 1 : 0);
      for (unsigned int b = 0; b < n_bits; ++b)
        {
          for (unsigned int l = 0; l < has.size(); ++l)
            has[l] = (dof_mask[l] >> b) & 1u;
          grid.ghost_exchange().sum_to_owned(has, sum.data());
          grid.ghost_exchange().owned_to_relevant(sum.data(), has);
          for (unsigned int l = 0; l < has.size(); ++l)
            if (has[l] > 0)
              dof_mask[l] |= 1u << b;
        }
    }

    template void
    dof_body_masks(const State<1> &,
                   std::vector<unsigned int> &,
                   std::vector<unsigned int> &,
                   const std::vector<char> *);
    template void
    dof_body_masks(const State<2> &,
                   std::vector<unsigned int> &,
                   std::vector<unsigned int> &,
                   const std::vector<char> *);
  } // namespace Simulator
} // namespace psmpm
