// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_solver_l2_projection_h
#define psmpm_solver_l2_projection_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <psmpm/basis/space.h>
#include <psmpm/mesh/mesh_generator.h>
#include <psmpm/base/summary.h>

#include <memory>
#include <string>

namespace psmpm
{
  namespace Solver
  {
    using namespace dealii;

    /**
     * The "l2 projection" scene (thesis section 3.6): project a given
     * function onto a basis (linear or powell-sabin) with the consistent
     * mass matrix, or its lumped diagonal, and report the L2 error.
     *
     * Mass matrix and right-hand side are integrated with the 7-point
     * degree-5 Gauss rule on each of the six Powell-Sabin sub-triangles of
     * every cell, for both spaces, so that the spline pieces are integrated
     * exactly and P1 is treated the same way. The error is integrated on
     * the sub-triangles split once more into four (168 points per cell),
     * so that quadrature does not pollute the convergence study.
     *
     * The scene is computed redundantly on every rank of @p comm; only rank
     * 0 writes files.
     */
    class L2Projection
    {
    public:
      /// Subsection "Projection": "Function", "Lumped"; subsection
      /// "Output": "Basis function".
      static void
      declare_parameters(ParameterHandler &prm);

      /// Throws ExcMessage naming the entry on bad values.
      void
      parse_parameters(ParameterHandler &prm);

      /**
       * Create the mesh and the space, check Output/Basis function against
       * them and Projection/Function at every quadrature point, project
       * and integrate the error: everything the input can make fail, so
       * that bad input is reported as such (exit 2) before the output
       * directory is touched. Throws ExcMessage naming the entry if the
       * function is not finite at a quadrature point or its projection
       * exceeds the range of double numbers; a CG solve that does not
       * converge is no error here but failure() of the run.
       *
       * Values beyond 2^-256 .. 2^256 in magnitude are projected divided
       * by a power of two near their largest magnitude (exact in binary
       * arithmetic), so that the squares in CG's norms neither overflow
       * nor vanish; the coefficients and the error are scaled back.
       */
      void
      prepare(const Mesh::MeshGenerator<2> &mesh,
              const std::string            &basis_name);

      /**
       * Fill @p summary (errors.L2, n_dofs, n_cells, h = the largest cell
       * diameter) and write projection.vtu (projection, exact function,
       * error and, if requested, one basis function on a refined patch
       * mesh), mesh.vtu and ps_refinement.vtu into @p output_directory;
       * prepare() first unless it was called since the last run(), whose
       * @p mesh and @p basis_name it then uses. If failure() is not
       * empty, only n_dofs and n_cells are filled and nothing is written.
       */
      void
      run(const Mesh::MeshGenerator<2> &mesh,
          const std::string            &basis_name,
          const std::string            &output_directory,
          Summary                      &summary,
          MPI_Comm                      comm);

      /// Why the last projection failed (CG did not converge), or "".
      std::string
      failure() const;

      /// Throws ExcMessage naming Output/Basis function if it is not a
      /// function of @p space on @p tria.
      void
      check_basis_function(const Triangulation<2> &tria,
                           const Basis::Space<2>  &space,
                           const std::string      &basis_name) const;

      /// "sin(pi*x)*sin(pi*y)" by default; variables x, y; constant pi.
      std::string function_expression = "sin(pi*x)*sin(pi*y)";
      /// Lumped (row-sum) mass matrix instead of the consistent one.
      bool lumped = false;
      /// Basis function to output: vertex index and function number q, or
      /// none when output_basis_vertex is invalid.
      unsigned int output_basis_vertex   = numbers::invalid_unsigned_int;
      unsigned int output_basis_function = 0;
      /// Each sub-triangle is split into this many squared triangles for
      /// output (the pieces are quadratic: 4 shows their shape).
      unsigned int output_subdivisions = 4;
      /// Write the VTU files (off for timing runs).
      bool write_output = true;

    private:
      struct Projected;
      /// What prepare() computed for the next run(); null before prepare()
      /// and after run().
      std::shared_ptr<const Projected> projected;
      /// Projected::failure of the last prepare().
      std::string failure_reason;
    };
  } // namespace Solver
} // namespace psmpm

#endif
