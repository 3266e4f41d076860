// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi.h>

#include <psmpm/base/archive.h>
#include <psmpm/base/cross.h>
#include <psmpm/base/prefetch.h>
#include <psmpm/postprocess/rotation_statistics.h>

#include <cmath>

namespace psmpm
{
  namespace Postprocess
  {
    namespace
    {
      /// A particle's affine angular momentum sum_k phi_k d_k x C d_k
      /// and kinetic energy 1/2 C : (C D) per unit mass, d_k = X_k - x
      /// (X the control points of the particle's cell's functions
      /// @p dofs), D = sum_k phi_k d_k d_k^T: the momentum as C_yx D_xx
      /// + (C_yy - C_xx) D_xy - C_xy D_yy, three independent sums instead
      /// of one chain of additions.
      std::pair<double, double>
      affine_momentum_and_energy(const double                *phi,
                                 const unsigned int          *dofs,
                                 const unsigned int           n,
                                 const std::vector<Point<2>> &X,
                                 const Point<2>              &x,
                                 const Tensor<2, 2>          &C)
      {
        double Dxx = 0, Dxy = 0, Dyy = 0;
        for (unsigned int k = 0; k < n; ++k)
          {
            const Tensor<1, 2> d = X[dofs[k]] - x;
            Dxx += phi[k] * d[0] * d[0];
            Dxy += phi[k] * d[0] * d[1];
            Dyy += phi[k] * d[1] * d[1];
          }
        const double energy = 0.5 * (C[0][0] * (C[0][0] * Dxx + C[0][1] * Dxy) +
                                     C[0][1] * (C[0][0] * Dxy + C[0][1] * Dyy) +
                                     C[1][0] * (C[1][0] * Dxx + C[1][1] * Dxy) +
                                     C[1][1] * (C[1][0] * Dxy + C[1][1] * Dyy));
        return {C[1][0] * Dxx + (C[1][1] - C[0][0]) * Dxy - C[0][1] * Dyy,
                energy};
      }
    } // namespace

    template <int dim>
    typename RotationStatistics<dim>::Values
    RotationStatistics<dim>::compute(const StateView<dim> &state,
                                     const bool            affine_part)
    {
      prepare(state);
      Sums sums;
      accumulate(state, 0, state.particles.size(), affine_part, sums);
      return finish(sums, state.comm);
    }

    template <int dim>
    void
    RotationStatistics<dim>::prepare(const StateView<dim> &state)
    {
      if constexpr (dim == 2)
        {
          const auto &particles = state.particles;
          if (!initialized)
            {
              double       mass = 0;
              Tensor<1, 2> first;
              for (std::size_t p = 0; p < particles.size(); ++p)
                {
                  mass += particles.mass[p];
                  first += particles.mass[p] * particles.initial_position[p];
                }
              mass   = Utilities::MPI::sum(mass, state.comm);
              first  = Utilities::MPI::sum(first, state.comm);
              centre = Point<2>(first / mass);
            }
          if (!have_control_points)
            {
              const auto &global = state.grid->relevant_global_indices();
              const std::vector<Point<2>> all =
                state.space->control_points(state.dof_handler);
              control_points.resize(global.size());
              for (std::size_t l = 0; l < global.size(); ++l)
                control_points[l] = all[global[l]];
              have_control_points = true;
            }
        }
    }

    template <int dim>
    void
    RotationStatistics<dim>::accumulate(const StateView<dim> &state,
                                        const std::size_t     first_p,
                                        const std::size_t     last_p,
                                        const bool            affine_part,
                                        Sums                 &sums) const
    {
      if constexpr (dim == 2)
        {
          // One pass over the particles and one reduction (these
          // statistics run every step; on large scenes they cost as much
          // as a particle loop). The angle's sums are about the current
          // centre of mass c(t), known only after the pass; with r = x - c
          // about the initial centre c,
          //   sum m r0 x (r - s) = sum m r0 x r - (sum m r0) x s,
          // s = c(t) - c,
          // and the same for the dot product (sum m r0 is zero up to
          // round-off: the second terms are round-off corrections).
          const auto         &particles = state.particles;
          const unsigned int  n         = state.grid->dofs_per_cell;
          const unsigned int *dofs      = state.grid->cell_dofs().data();
          const bool          affine =
            affine_part && control_points.size() ==
                             state.grid->relevant_global_indices().size();
          // The sums in registers: through the reference, every addition
          // would wait for the store of the previous particle's (the
          // compiler cannot tell them from the particle arrays). Same
          // operations in the same order.
          Sums local = sums;
          for (std::size_t p = first_p; p < last_p; ++p)
            {
              // In the update's chunks (prefetch.h) only this loop reads
              // the initial positions; with the affine part (APIC, one
              // pass over all particles) also the affine matrices and the
              // basis values.
              if (p + prefetch_distance < particles.size())
                {
                  const std::size_t ahead = p + prefetch_distance;
                  prefetch_lines(&particles.initial_position[ahead]);
                  if (affine)
                    {
                      prefetch_lines<sizeof(Tensor<2, 2>)>(
                        &particles.affine[ahead]);
                      prefetch_lines(&particles.cell[ahead]);
                      // n values: 24 B for P1, 72 B (two lines) for
                      // Powell-Sabin.
                      prefetch_lines(&state.shape_values[ahead * n]);
                      if (n > 8)
                        prefetch_lines(&state.shape_values[ahead * n + 8]);
                    }
                }
              const double        m  = particles.mass[p];
              const Point<2>     &x  = particles.position[p];
              const Tensor<1, 2>  r  = x - centre;
              const Tensor<1, 2>  r0 = particles.initial_position[p] - centre;
              const Tensor<1, 2> &v  = particles.velocity[p];
              local.h += m * cross(r, v);
              // The scale is only needed once (two square roots).
              if (!initialized)
                local.s += m * r.norm() * v.norm();
              // C is read only where affine (binding the reference reads
              // nothing).
              const Tensor<2, 2> &C = particles.affine[p];
              if (affine && (C[0][0] != 0 || C[0][1] != 0 || C[1][0] != 0 ||
                             C[1][1] != 0))
                {
                  const auto [h, energy] =
                    affine_momentum_and_energy(&state.shape_values[p * n],
                                               &dofs[particles.cell[p] * n],
                                               n,
                                               control_points,
                                               x,
                                               C);
                  local.h += m * h;
                  local.affine_kinetic += m * energy;
                }
              local.mass += m;
              local.first += m * x;
              local.first_r0 += m * r0;
              local.across += m * cross(r0, r);
              local.along += m * (r0 * r);
            }
          sums = local;
        }
      else
        {
          (void)state;
          (void)first_p;
          (void)last_p;
          (void)affine_part;
          (void)sums;
        }
    }

    template <int dim>
    typename RotationStatistics<dim>::Values
    RotationStatistics<dim>::finish(const Sums &local, MPI_Comm comm)
    {
      if constexpr (dim == 1)
        {
          (void)local;
          (void)comm;
          return {};
        }
      else
        {
          double sums[10] = {local.h,
                             local.across,
                             local.along,
                             local.s,
                             local.mass,
                             local.first[0],
                             local.first[1],
                             local.first_r0[0],
                             local.first_r0[1],
                             local.affine_kinetic};
          Utilities::MPI::sum(ArrayView<const double>(sums, 10),
                              comm,
                              ArrayView<double>(sums, 10));
          // Times the inverse, as Tensor / double computes it.
          const double       inverse_mass = 1. / sums[4];
          const Tensor<1, 2> shift({sums[5] * inverse_mass - centre[0],
                                    sums[6] * inverse_mass - centre[1]});
          const Tensor<1, 2> sum_r0({sums[7], sums[8]});
          sums[1] -= cross(sum_r0, shift);
          sums[2] -= sum_r0 * shift;
          Values v;
          v.angular_momentum      = sums[0];
          v.rotation_angle        = std::atan2(sums[1], sums[2]);
          v.affine_kinetic_energy = sums[9];
          if (!initialized)
            {
              initial     = v;
              scale       = sums[3];
              initialized = true;
            }
          last = v;
          return v;
        }
    }

    template <int dim>
    void
    RotationStatistics<dim>::add_columns(const Values    &values,
                                         StatisticsTable &statistics,
                                         const bool       affine_part)
    {
      if (dim == 1)
        return;
      statistics.add_value("angular_momentum", values.angular_momentum);
      statistics.add_value("rotation_angle", values.rotation_angle);
      statistics.set_scientific("angular_momentum", true);
      statistics.set_precision("angular_momentum", 8);
      statistics.set_scientific("rotation_angle", true);
      statistics.set_precision("rotation_angle", 8);
      if (!affine_part)
        return;
      statistics.add_value("affine_kinetic_energy",
                           values.affine_kinetic_energy);
      statistics.set_scientific("affine_kinetic_energy", true);
      statistics.set_precision("affine_kinetic_energy", 8);
    }

    template <int dim>
    void
    RotationStatistics<dim>::fill_summary(Summary &summary) const
    {
      if (dim == 1 || !initialized)
        return;
      summary.set("angular_momentum_initial", initial.angular_momentum);
      summary.set("angular_momentum_final", last.angular_momentum);
      // Relative to the initial value if the body spins, else to the
      // scale sum m |x - c| |v| (a body that should not spin).
      const double reference =
        std::abs(initial.angular_momentum) > 1e-2 * scale ?
          std::abs(initial.angular_momentum) :
          scale;
      if (reference > 0)
        summary.set("angular_momentum_relative_change",
                    (last.angular_momentum - initial.angular_momentum) /
                      reference);
      summary.set("rotation_angle_final", last.rotation_angle);
    }

    template <int dim>
    void
    RotationStatistics<dim>::save(Archive &archive) const
    {
      archive.put_integer("rotation_statistics/initialized", initialized);
      std::vector<double> c(dim);
      for (unsigned int d = 0; d < dim; ++d)
        c[d] = centre[d];
      archive.put("rotation_statistics/centre", c);
      archive.put("rotation_statistics/initial",
                  std::vector<double>{initial.angular_momentum,
                                      initial.rotation_angle});
      archive.put("rotation_statistics/last",
                  std::vector<double>{last.angular_momentum,
                                      last.rotation_angle});
      archive.put("rotation_statistics/scale", scale);
    }

    template <int dim>
    void
    RotationStatistics<dim>::load(const Archive &archive)
    {
      initialized = archive.get_integer("rotation_statistics/initialized") != 0;
      const auto &c = archive.get("rotation_statistics/centre", dim);
      for (unsigned int d = 0; d < dim; ++d)
        centre[d] = c[d];
      const auto &i = archive.get("rotation_statistics/initial", 2);
      initial       = {i[0], i[1]};
      const auto &l = archive.get("rotation_statistics/last", 2);
      last          = {l[0], l[1]};
      scale         = archive.get_number("rotation_statistics/scale");
    }

    template class RotationStatistics<1>;
    template class RotationStatistics<2>;
  } // namespace Postprocess
} // namespace psmpm
