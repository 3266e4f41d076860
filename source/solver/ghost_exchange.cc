// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/solver/ghost_exchange.h>

namespace psmpm
{
  namespace Solver
  {
    void
    GhostExchange::reinit(const IndexSet &owned,
                          const IndexSet &relevant,
                          MPI_Comm        comm)
    {
      partitioner =
        std::make_shared<const Utilities::MPI::Partitioner>(owned,
                                                            relevant,
                                                            comm);
      work.reinit(partitioner);
      position.resize(relevant.n_elements());
      for (unsigned int l = 0; l < position.size(); ++l)
        position[l] =
          partitioner->global_to_local(relevant.nth_index_in_set(l));
    }

    void
    GhostExchange::sum_to_owned(const std::vector<double> &relevant_values,
                                double                    *owned) const
    {
      AssertDimension(relevant_values.size(), position.size());
      work = 0.; // the ghost entries too
      for (unsigned int l = 0; l < position.size(); ++l)
        work.local_element(position[l]) += relevant_values[l];
      work.compress(VectorOperation::add);
      const unsigned int n_owned = partitioner->locally_owned_size();
      for (unsigned int j = 0; j < n_owned; ++j)
        owned[j] = work.local_element(j);
    }

    void
    GhostExchange::owned_to_relevant(const double        *owned,
                                     std::vector<double> &relevant_values) const
    {
      const unsigned int n_owned = partitioner->locally_owned_size();
      for (unsigned int j = 0; j < n_owned; ++j)
        work.local_element(j) = owned[j];
      work.update_ghost_values();
      relevant_values.resize(position.size());
      for (unsigned int l = 0; l < position.size(); ++l)
        relevant_values[l] = work.local_element(position[l]);
      work.zero_out_ghost_values();
    }
  } // namespace Solver
} // namespace psmpm
