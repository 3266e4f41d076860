// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_basis_extrapolation_h
#define psmpm_basis_extrapolation_h

#include <deal.II/grid/tria.h>
#include <deal.II/lac/full_matrix.h>

#include <psmpm/basis/space.h>

namespace psmpm
{
  namespace Basis
  {
    /**
     * The extended B-spline idea on a vertex basis: the coefficients of a
     * poorly supported vertex @p to are taken from the local linear part
     * of a well supported vertex @p from, c_to = W c_from.
     *
     * Powell-Sabin coefficients are values of the vertex's linear part at
     * its control points, so W(q, r) is the r-th barycentric coordinate of
     * control point Q_{to,q} in the control triangle of @p from: linear
     * fields are extrapolated exactly. For P1 the linear part at a vertex
     * is its value (W = 1).
     */
    FullMatrix<double>
    extrapolation_weights(const Space            &space,
                          const Triangulation<2> &tria,
                          const unsigned int      from,
                          const unsigned int      to);
  } // namespace Basis
} // namespace psmpm

#endif
