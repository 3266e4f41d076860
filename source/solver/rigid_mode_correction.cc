// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/lac/full_matrix.h>

#include <psmpm/solver/rigid_mode_correction.h>

#include <Epetra_Comm.h>

namespace psmpm
{
  namespace Solver
  {
    namespace
    {
      /// A mode as coefficients of the single-component columns
      /// 1, x, y of each component: mode_d = sum_m c[d][m] u_m.
      template <int dim>
      using Mode = std::array<std::array<double, dim + 1>, dim>;

      /// Translation of each free component; the rotation (-y, x) when
      /// a 2d field is free in every component.
      template <int dim>
      std::vector<Mode<dim>>
      rigid_modes(const std::array<bool, dim> &free)
      {
        std::vector<Mode<dim>> modes;
        bool                   all_free = true;
        for (unsigned int d = 0; d < dim; ++d)
          {
            all_free = all_free && free[d];
            if (free[d])
              {
                Mode<dim> t{};
                t[d][0] = 1;
                modes.push_back(t);
              }
          }
        if constexpr (dim == 2)
          if (all_free)
            {
              Mode<dim> r{};
              r[0][2] = -1;
              r[1][1] = 1;
              modes.push_back(r);
            }
        return modes;
      }
    } // namespace

    template <int dim>
    void
    RigidModeCorrection<dim>::reinit(std::vector<long long>  &&row_indices,
                                     std::vector<Point<dim>> &&row_points)
    {
      indices = std::move(row_indices);
      points  = std::move(row_points);
      modes.reset();
      modes_current = false;
    }

    template <int dim>
    void
    RigidModeCorrection<dim>::matrix_changed()
    {
      modes_current = false;
    }

    template <int dim>
    void
    RigidModeCorrection<dim>::set_modes(const Epetra_CrsMatrix &M)
    {
      const Epetra_Map &map = M.RowMap();
      if (!modes || !modes->Map().SameAs(map))
        {
          bool same =
            indices.size() == static_cast<std::size_t>(map.NumMyElements());
          for (int j = 0; same && j < map.NumMyElements(); ++j)
            same = map.GID64(j) == indices[j];
          AssertThrow(same,
                      ExcMessage("RigidModeCorrection: the matrix rows are "
                                 "not the DoFs of the control points"));
          modes    = std::make_unique<Epetra_MultiVector>(map, dim + 1);
          products = std::make_unique<Epetra_MultiVector>(map, dim + 1);
          residual = std::make_unique<Epetra_MultiVector>(map, dim);
        }
      int    *offsets, *columns;
      double *values;
      const_cast<Epetra_CrsMatrix &>(M).ExtractCrsDataPointers(offsets,
                                                               columns,
                                                               values);
      decoupled.clear();
      for (int j = 0; j < map.NumMyElements(); ++j)
        {
          // A row with one nonzero of a positive definite matrix: its
          // diagonal, coupled to no other row.
          int    nonzeros = 0;
          double value    = 0;
          for (int k = offsets[j]; k < offsets[j + 1]; ++k)
            if (values[k] != 0)
              {
                ++nonzeros;
                value = values[k];
              }
          const bool alone = nonzeros == 1;
          if (alone)
            decoupled.emplace_back(j, value);
          (*modes)[0][j] = alone ? 0. : 1.;
          for (unsigned int e = 0; e < dim; ++e)
            (*modes)[e + 1][j] = alone ? 0. : points[j][e];
        }
      M.Multiply(false, *modes, *products);
      modes_current = true;
    }

    template <int dim>
    void
    RigidModeCorrection<dim>::correct(const Epetra_CrsMatrix     &M,
                                      const std::array<bool, dim> free,
                                      const Epetra_MultiVector   &b,
                                      Epetra_MultiVector         &x)
    {
      const std::vector<Mode<dim>> rigid = rigid_modes<dim>(free);
      if (rigid.empty())
        return;
      if (!modes_current || !modes->Map().SameAs(M.RowMap()))
        set_modes(M);
      // A row coupled to no other: its exact solution, and no mode.
      for (const auto &[j, a_jj] : decoupled)
        for (unsigned int d = 0; d < dim; ++d)
          x[d][j] = b[d][j] / a_jj;
      M.Multiply(false, x, *residual);
      const int n = M.RowMap().NumMyElements();
      // S_mn = u_m . M u_n and h_dm = u_m . r_d, reduced together.
      constexpr unsigned int m_count = dim + 1;
      std::vector<double>    local(m_count * m_count + dim * m_count, 0.),
        global(local.size());
      for (unsigned int m = 0; m < m_count; ++m)
        {
          const double *u = (*modes)[m];
          for (unsigned int l = 0; l < m_count; ++l)
            {
              const double *w = (*products)[l];
              for (int j = 0; j < n; ++j)
                local[m * m_count + l] += u[j] * w[j];
            }
          for (unsigned int d = 0; d < dim; ++d)
            {
              const double *bd = b[d], *q = (*residual)[d];
              for (int j = 0; j < n; ++j)
                local[m_count * m_count + d * m_count + m] +=
                  u[j] * (bd[j] - q[j]);
            }
        }
      M.Comm().SumAll(local.data(), global.data(), local.size());

      const unsigned int  n_modes = rigid.size();
      FullMatrix<double>  G(n_modes, n_modes);
      std::vector<double> g(n_modes, 0.);
      for (unsigned int k = 0; k < n_modes; ++k)
        for (unsigned int d = 0; d < dim; ++d)
          for (unsigned int m = 0; m < m_count; ++m)
            {
              g[k] +=
                rigid[k][d][m] * global[m_count * m_count + d * m_count + m];
              for (unsigned int l = 0; l < n_modes; ++l)
                for (unsigned int o = 0; o < m_count; ++o)
                  G(k, l) +=
                    rigid[k][d][m] * rigid[l][d][o] * global[m * m_count + o];
            }
      // G is the mass matrix on the modes: positive definite wherever the
      // body's DoFs span them (an empty grid, or DoFs on a line for the
      // rotation, leave the CG's solution as it is).
      double diagonal_product = 1;
      for (unsigned int k = 0; k < n_modes; ++k)
        diagonal_product *= G(k, k);
      if (!(diagonal_product > 0) ||
          !(G.determinant() > 1e-12 * diagonal_product))
        return;
      G.gauss_jordan();
      for (unsigned int d = 0; d < dim; ++d)
        {
          std::array<double, m_count> c{};
          for (unsigned int k = 0; k < n_modes; ++k)
            {
              double a = 0;
              for (unsigned int l = 0; l < n_modes; ++l)
                a += G(k, l) * g[l];
              for (unsigned int m = 0; m < m_count; ++m)
                c[m] += a * rigid[k][d][m];
            }
          double *xd = x[d];
          for (unsigned int m = 0; m < m_count; ++m)
            if (c[m] != 0)
              {
                const double *u = (*modes)[m];
                for (int j = 0; j < n; ++j)
                  xd[j] += c[m] * u[j];
              }
        }
    }

    template class RigidModeCorrection<1>;
    template class RigidModeCorrection<2>;
  } // namespace Solver
} // namespace psmpm
