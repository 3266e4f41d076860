// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_basis_space_h
#define psmpm_basis_space_h

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>

#include <psmpm/base/registry.h>

#include <memory>
#include <set>
#include <string>
#include <vector>

namespace psmpm
{
  namespace Basis
  {
    using namespace dealii;

    /**
     * The one interface through which MPM code sees a discrete space on a
     * simplex triangulation (lines in 1D, triangles in 2D): "the non-zero
     * functions of this cell, their values and gradients at this point",
     * plus what the mass strategies and transfers need to know about the
     * space. The degrees of freedom are laid out by the finite element
     * returned by dof_layout(), so deal.II's DoFHandler, sparsity
     * patterns, AffineConstraints and parallel index sets apply unchanged;
     * the local order of the functions of a cell is the order of
     * cell->get_dof_indices(). For the vertex-wise mass strategies every
     * DoF belongs to a vertex (dofs_per_vertex() of them each); a space
     * with cell DoFs (bspline) restricts verified_mass_matrices().
     *
     * Cells are addressed by their active_cell_index(). reinit() must be
     * called after DoFHandler::distribute_dofs() and before evaluation.
     *
     * Spaces register in SpaceRegistry<dim>; Basis/Type lists them.
     */
    template <int dim>
    class Space
    {
    public:
      virtual ~Space() = default;

      /// Name as used in the parameter file ("linear", "powell-sabin").
      virtual std::string
      name() const = 0;

      /// Finite element that defines the DoF layout for deal.II.
      virtual const FiniteElement<dim> &
      dof_layout() const = 0;

      /// Largest polynomial degree of the functions on a cell (what the
      /// output needs to show the field faithfully).
      virtual unsigned int
      degree() const = 0;

      /// Number of functions that do not vanish on a cell.
      unsigned int
      dofs_per_cell() const
      {
        return dof_layout().n_dofs_per_cell();
      }

      /// Number of functions attached to each vertex.
      unsigned int
      dofs_per_vertex() const
      {
        return dof_layout().n_dofs_per_vertex();
      }

      /**
       * Basis/Degree. Spaces of one fixed degree (linear, powell-sabin)
       * ignore it; a space that implements some degrees only throws an
       * error naming the entry for the others.
       */
      virtual void
      set_degree(const unsigned int degree)
      {
        (void)degree;
      }

      /// Precompute per-cell data for the mesh of @p dof_handler.
      virtual void
      reinit(const DoFHandler<dim> &dof_handler) = 0;

      /**
       * Values and gradients of the dofs_per_cell() functions of the cell
       * with active index @p cell at the point @p p (which must lie in the
       * closed cell). @p gradients may be nullptr.
       */
      virtual void
      evaluate(const unsigned int cell,
               const Point<dim>  &p,
               double            *values,
               Tensor<1, dim>    *gradients) const = 0;

      /**
       * The same for @p n points at once: one virtual call per batch, so
       * that loops over particles do not dispatch per particle. Arrays are
       * row-major, dofs_per_cell() entries per point.
       */
      virtual void
      evaluate(const unsigned int  n,
               const unsigned int *cells,
               const Point<dim>   *points,
               double             *values,
               Tensor<1, dim>     *gradients) const;

      /**
       * Whether the gradients of every function are constant on each
       * cell (P1). The particle loops then read them once per cell
       * instead of once per particle (State::gradients()), which saves
       * the per-particle gradient array and its traffic in every step.
       */
      virtual bool
      gradients_constant_on_cells() const
      {
        return false;
      }

      /**
       * Constraints that belong to the space itself, not to boundary
       * conditions: the ties that make the DoF layout's functions span the
       * space (bspline: C1 at the interior vertices of a C0 quadratic
       * layout). GridSystem adds them to the constraints of every
       * component, for the consistent and the lumped mass alike. Default:
       * none, so the spaces without ties keep their unconstrained paths.
       */
      virtual void
      make_space_constraints(const DoFHandler<dim>     &dof_handler,
                             AffineConstraints<double> &constraints) const
      {
        (void)dof_handler;
        (void)constraints;
      }

      /**
       * Add constraints that impose u = g on the boundaries with the given
       * ids to @p constraints (for P1 at the vertices; for Powell-Sabin on
       * value and tangential derivative at the vertices, exact for the
       * homogeneous case on the whole edge).
       */
      virtual void
      make_dirichlet_constraints(
        const DoFHandler<dim>              &dof_handler,
        const std::set<types::boundary_id> &ids,
        const Function<dim>                &g,
        AffineConstraints<double>          &constraints) const = 0;

      /**
       * The control point of every DoF, indexed by global DoF index: the
       * points X_i with sum_i X_i N_i(x) = x, so that the coefficients
       * f(X_i) of an affine f reproduce f exactly (P1: the vertices;
       * Powell-Sabin: the corners of the control triangles). Transfers
       * that carry affine velocity fields (APIC, TPIC) use them.
       */
      virtual std::vector<Point<dim>>
      control_points(const DoFHandler<dim> &dof_handler) const = 0;

      /**
       * Extended-B-spline extrapolation: the dofs_per_vertex() x
       * dofs_per_vertex() weights W with c_to = W c_from that continue the
       * local linear part of vertex @p from's functions to vertex @p to.
       */
      virtual FullMatrix<double>
      extrapolation_weights(const unsigned int from,
                            const unsigned int to) const = 0;

      /**
       * Quadrature on cell @p cell (active index) that integrates products
       * of two functions of the space exactly on the cell, in real
       * coordinates (L2 projection, reference mass matrices).
       */
      virtual Quadrature<dim>
      cell_quadrature(const DoFHandler<dim> &dof_handler,
                      const unsigned int     cell) const = 0;

      /**
       * Largest stable time step over h_min / c_p of the explicit scheme
       * with this space, with a lumped (@p lumped = true) or a consistent
       * mass matrix (measured, see doc/stability.md; h_min is the smallest
       * triangle height, in 1D the smallest element length).
       */
      virtual double
      stability_factor(const bool lumped) const = 0;

      /**
       * What `Mass matrix/Type = automatic` and `Transfer/Scheme =
       * automatic` select for this space: the combination that the suite
       * of doc/transfers.md measured as stable and accurate on free,
       * emptying and filling bodies (the transfer for the mass matrix in
       * use). P1: the ghost-penalty stabilised mass matrix with MUSL, the
       * only P1 combination measured to keep a free body's rigid rotation
       * (angular momentum and angle to 1e-4) and to complete every scene of
       * the suite; partially lumped mass lost 47 % of the angular momentum,
       * lumped mass with APIC keeps it but its PIC update damps a vibrating
       * bar 40x. The ghost penalty is computed on the initial cells, so a
       * transfer whose grid moves with the material (@p grid_moves, OTM)
       * gets partially lumped mass instead.
       */
      virtual std::string
      default_mass_matrix(const bool grid_moves = false) const
      {
        return grid_moves ? "partially lumped" : "ghost penalty";
      }
      virtual std::string
      default_transfer(const std::string &mass_matrix) const
      {
        (void)mass_matrix;
        return "musl";
      }

      /**
       * What `Mass matrix/Type = automatic` selects instead of
       * default_mass_matrix() when the material fills a mesh whose
       * boundaries are all closed in their normal direction, so that no
       * cell empties for good (P1, Powell-Sabin: partially lumped, see
       * Simulator::setup_space_and_grid()). Used only if verified with the
       * space.
       */
      virtual std::string
      closed_mass_matrix() const
      {
        return "partially lumped";
      }

      /**
       * The Mass matrix/Type and Transfer/Scheme names verified with this
       * space; the simulator refuses the others as bad input. Empty: all
       * (linear and powell-sabin, for which every variant was written).
       */
      virtual std::vector<std::string>
      verified_mass_matrices() const
      {
        return {};
      }
      virtual std::vector<std::string>
      verified_transfers() const
      {
        return {};
      }
    };

    template <int dim>
    using SpaceRegistry = Registry<Space<dim>>;

    /// Create the space named @p name (Basis/Type).
    template <int dim>
    std::unique_ptr<Space<dim>>
    create_space(const std::string &name);
  } // namespace Basis
} // namespace psmpm

#endif
