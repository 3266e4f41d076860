// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_solver_ghost_exchange_h
#define psmpm_solver_ghost_exchange_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/partitioner.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <memory>
#include <vector>

namespace psmpm
{
  namespace Solver
  {
    using namespace dealii;

    /**
     * The two halo exchanges of a grid vector between MPI ranks, for
     * arrays in GridSystem's local relevant numbering (entry l is the
     * l-th index of the relevant set) and owned arrays in the order of
     * the owned set (the value arrays of the Trilinos vectors):
     *  - sum_to_owned(): every rank's partial sums of relevant entries,
     *    added up on the owning rank (the assembled right-hand side or
     *    lumped mass);
     *  - owned_to_relevant(): the owners' values copied to every rank
     *    that has the entry as a ghost (the solution the particles read).
     *
     * Both go through deal.II's Utilities::MPI::Partitioner, whose
     * point-to-point pattern is computed once in reinit(). The Trilinos
     * route (Epetra_FEVector::GlobalAssemble, which builds an Epetra_Export
     * and its communication plan in every call, then an import into a
     * ghosted vector read through global-index lookups) cost 4.4 ms per
     * step of the 2-rank P1 lumped throughput bar (10,271 DoFs), a
     * tenth of a rank's whole step (doc/performance.md).
     */
    class GhostExchange
    {
    public:
      /// Pattern for the ranks' @p owned and @p relevant sets (relevant
      /// contains owned).
      void
      reinit(const IndexSet &owned, const IndexSet &relevant, MPI_Comm comm);

      /// owned[j] = the sum over ranks of @p relevant_values at the j-th
      /// owned index (collective).
      void
      sum_to_owned(const std::vector<double> &relevant_values,
                   double                    *owned) const;

      /// relevant_values[l] = the owner's value of the l-th relevant
      /// index, from this rank's @p owned values (collective).
      void
      owned_to_relevant(const double        *owned,
                        std::vector<double> &relevant_values) const;

    private:
      std::shared_ptr<const Utilities::MPI::Partitioner> partitioner;
      /// Owned entries, then ghosts: the Partitioner's local storage.
      mutable LinearAlgebra::distributed::Vector<double> work;
      /// Position in work's local storage of each relevant entry.
      std::vector<unsigned int> position;
    };
  } // namespace Solver
} // namespace psmpm

#endif
