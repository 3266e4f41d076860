// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_basis_space_h
#define psmpm_basis_space_h

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>
#include <deal.II/lac/affine_constraints.h>

#include <memory>
#include <set>
#include <string>

namespace psmpm
{
  namespace Basis
  {
    using namespace dealii;

    /**
     * The one interface through which MPM code sees a discrete space on a
     * 2D simplex triangulation: "the non-zero functions of this cell, their
     * values and gradients at this point". The degrees of freedom are laid
     * out by the finite element returned by dof_layout(), so deal.II's
     * DoFHandler, sparsity patterns, AffineConstraints and parallel index
     * sets apply unchanged; the local order of the functions of a cell is
     * the order of cell->get_dof_indices().
     *
     * Cells are addressed by their active_cell_index(). reinit() must be
     * called after DoFHandler::distribute_dofs() and before evaluation.
     */
    class Space
    {
    public:
      virtual ~Space() = default;

      /// Name as used in the parameter file ("linear", "powell-sabin").
      virtual std::string
      name() const = 0;

      /// Finite element that defines the DoF layout for deal.II.
      virtual const FiniteElement<2> &
      dof_layout() const = 0;

      /// Number of functions that do not vanish on a cell.
      unsigned int
      dofs_per_cell() const
      {
        return dof_layout().n_dofs_per_cell();
      }

      /// Precompute per-cell data for the mesh of @p dof_handler.
      virtual void
      reinit(const DoFHandler<2> &dof_handler) = 0;

      /**
       * Values and gradients of the dofs_per_cell() functions of the cell
       * with active index @p cell at the point @p p (which must lie in the
       * closed cell). @p gradients may be nullptr.
       */
      virtual void
      evaluate(const unsigned int cell,
               const Point<2>    &p,
               double            *values,
               Tensor<1, 2>      *gradients) const = 0;

      /**
       * The same for @p n points at once: one virtual call per batch, so
       * that loops over particles do not dispatch per particle. Arrays are
       * row-major, dofs_per_cell() entries per point.
       */
      virtual void
      evaluate(const unsigned int  n,
               const unsigned int *cells,
               const Point<2>     *points,
               double             *values,
               Tensor<1, 2>       *gradients) const;

      /**
       * Add constraints that impose u = g on the boundaries with the given
       * ids to @p constraints (for P1 at the vertices; for Powell-Sabin on
       * value and tangential derivative at the vertices, exact for the
       * homogeneous case on the whole edge).
       */
      virtual void
      make_dirichlet_constraints(
        const DoFHandler<2>                &dof_handler,
        const std::set<types::boundary_id> &ids,
        const Function<2>                  &g,
        AffineConstraints<double>          &constraints) const = 0;
    };

    /// Create the space named @p name ("linear" or "powell-sabin").
    std::unique_ptr<Space>
    create_space(const std::string &name);
  } // namespace Basis
} // namespace psmpm

#endif
