// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_postprocess_rotation_statistics_h
#define psmpm_postprocess_rotation_statistics_h

#include <deal.II/base/point.h>

#include <psmpm/base/summary.h>
#include <psmpm/postprocess/state_view.h>
#include <psmpm/postprocess/statistics_table.h>

#include <vector>

namespace psmpm
{
  class Archive;

  namespace Postprocess
  {
    using namespace dealii;

    /**
     * Angular momentum and mean rotation of the body (2D; nothing in 1D),
     * about the centre of mass of the initial configuration:
     *
     * - angular momentum sum_p m_p (x_p - c) x v_p plus the particles'
     *   affine part sum_p m_p sum_i N_i(x_p) (X_i - x_p) x C_p (X_i - x_p)
     *   (X_i the space's control points). With C_p = 0 this is the usual
     *   particle sum; with the affine transfers it is the quantity they
     *   conserve: the angular momentum the grid receives.
     * - mean rotation angle atan2(sum m r0 x r, sum m r0 . r) with r0 =
     *   X_p - c0 and r = x_p - c(t), the mass-weighted best rotation of
     *   the body since the start (exact for a rigid rotation).
     *
     * - with affine transfers, the kinetic energy of the particles'
     *   affine parts, sum_p 1/2 m_p C_p : (C_p D_p), D_p = sum_i N_i(x_p)
     *   (X_i - x_p)(X_i - x_p)^T: what the affine fields carry beside
     *   1/2 m_p |v_p|^2 (for the control-point fit, the grid's lumped
     *   kinetic energy bounds the two together).
     *
     * Columns angular_momentum and rotation_angle (and
     * affine_kinetic_energy with affine transfers); summary.json gets the
     * initial and final angular momentum, its relative change and the
     * final angle.
     */
    template <int dim>
    class RotationStatistics
    {
    public:
      struct Values
      {
        double angular_momentum      = 0;
        double rotation_angle        = 0;
        double affine_kinetic_energy = 0;
      };

      /// The values of @p state; @p affine_part: whether the particles'
      /// affine matrices may be nonzero (false for schemes that do not
      /// carry them: they are then not read).
      Values
      compute(const StateView<dim> &state, const bool affine_part = true);

      /// This rank's sums, before the reduction.
      struct Sums
      {
        double h = 0, across = 0, along = 0, s = 0, mass = 0,
               affine_kinetic = 0;
        Tensor<1, dim> first, first_r0;
      };

      /// compute() in parts: prepare() (the initial centre and the
      /// control points, collective the first time), accumulate() the
      /// particles [@p first, @p last) in order, then finish() (the
      /// reduction; initial and last values). compute() is the three for
      /// all particles.
      void
      prepare(const StateView<dim> &state);
      void
      accumulate(const StateView<dim> &state,
                 const std::size_t     first,
                 const std::size_t     last,
                 const bool            affine_part,
                 Sums                 &sums) const;
      Values
      finish(const Sums &sums, MPI_Comm comm);

      /// Whether prepare() has nothing left to do (nothing collective).
      bool
      prepared() const
      {
        return initialized && have_control_points;
      }

      /// The columns of @p values; affine_kinetic_energy if
      /// @p affine_part (the transfer carries affine matrices).
      void
      add_columns(const Values    &values,
                  StatisticsTable &statistics,
                  const bool       affine_part);

      void
      fill_summary(Summary &summary) const;

      /// Centre, initial and last values and scale (checkpoints; the
      /// control points follow from the mesh).
      void
      save(Archive &archive) const;
      void
      load(const Archive &archive);

    private:
      bool                    initialized         = false;
      bool                    have_control_points = false;
      Point<dim>              centre;         ///< of the initial configuration
      std::vector<Point<dim>> control_points; ///< local relevant numbering
      Values                  initial, last;
      double                  scale = 0; ///< sum m |x - c| |v| at the start
    };
  } // namespace Postprocess
} // namespace psmpm

#endif
