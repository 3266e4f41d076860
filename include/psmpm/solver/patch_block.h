// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_solver_patch_block_h
#define psmpm_solver_patch_block_h

namespace psmpm
{
  namespace Solver
  {
    /// A dense block over a set of DoFs (local relevant numbering) that a
    /// strategy adds, times @p weight, to the matrix of every component
    /// (e.g. a ghost penalty over the union of two cells). The block
    /// only points to data the strategy keeps (a step adds tens of
    /// thousands of blocks: no allocation per block and step).
    struct PatchBlock
    {
      const unsigned int *dofs = nullptr;
      unsigned int        n    = 0;
      /// n x n, row-major.
      const double *values = nullptr;
      double        weight = 1;
      /// Value-array positions from GridSystem::patch_slots() for the
      /// current sparsity generation, or nullptr (searched in the row).
      const int *slots = nullptr;
    };
  } // namespace Solver
} // namespace psmpm

#endif
