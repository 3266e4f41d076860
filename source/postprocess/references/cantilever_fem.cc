// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/function.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <psmpm/postprocess/reference.h>
#include <psmpm/postprocess/references/cantilever_fem.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace psmpm
{
  namespace Postprocess
  {
    class CantileverFEM::Implementation
    {
    public:
      static constexpr unsigned int n_local = 18; // 9 nodes x 2 components

      /// A point's cell DoFs and shape functions (component, value,
      /// gradient) there.
      struct PointData
      {
        std::array<types::global_dof_index, n_local> dofs;
        std::array<unsigned int, n_local>            component;
        std::array<double, n_local>                  value;
        std::array<Tensor<1, 2>, n_local>            gradient;
      };

      explicit Implementation(const Parameters &p)
        : prm(p)
        , fe(FE_Q<2>(2), 2)
        , lambda(p.youngs_modulus * p.poisson_ratio /
                 ((1 + p.poisson_ratio) * (1 - 2 * p.poisson_ratio)))
        , mu(p.youngs_modulus / (2 * (1 + p.poisson_ratio)))
      {
        const double L = p.upper[0] - p.lower[0], H = p.upper[1] - p.lower[1];
        AssertThrow(L > 0 && H > 0,
                    ExcMessage("cantilever fem: the beam box is empty."));
        AssertThrow(p.youngs_modulus > 0 && p.density > 0 &&
                      p.poisson_ratio > -1 && p.poisson_ratio < 0.5,
                    ExcMessage("cantilever fem: needs E > 0, density > 0 "
                               "and -1 < Poisson's ratio < 0.5."));
        AssertThrow(p.gravity.norm() > 0,
                    ExcMessage("cantilever fem: needs Body force/Gravity "
                               "(the beam is loaded by its weight)."));
        if (p.elements_y > 0)
          setup_level(p.elements_y);
        else
          {
            // Double n_y until tip deflection and first period settle.
            double tip_old = 0, period_old = 0;
            for (unsigned int ny = 1;; ny *= 2)
              {
                setup_level(ny);
                const double tip = std::abs(tip_deflection());
                const double T   = 2 * numbers::PI / omega1;
                const bool   converged =
                  ny > 1 &&
                  std::abs(tip - tip_old) <= p.convergence_tolerance * tip &&
                  std::abs(T - period_old) <= p.convergence_tolerance * T;
                if (converged || 2 * ny > p.max_elements_y)
                  break;
                tip_old    = tip;
                period_old = T;
              }
          }
        setup_newmark();
      }

      /// Mesh, matrices, static solution and first eigenvalue of the mesh
      /// with @p ny elements across the height.
      void
      setup_level(const unsigned int ny)
      {
        make_mesh(ny);
        make_constraints_and_sparsity();
        assemble();
        K_inverse.initialize(K);
        u_static.reinit(dof_handler.n_dofs());
        K_inverse.vmult(u_static, force);
        constraints.distribute(u_static);
        omega1 = std::sqrt(first_eigenvalue());
        points.clear();
        index.clear();
      }

      /// The n_x x @p ny mesh of the beam, refined around the clamped
      /// corners, its DoFs, and its coarse cells by position (cells).
      void
      make_mesh(const unsigned int ny)
      {
        const double L = prm.upper[0] - prm.lower[0],
                     H = prm.upper[1] - prm.lower[1];
        n_y            = ny;
        n_x = static_cast<unsigned int>(std::ceil(ny * L / H - 1e-9));
        h_x = L / n_x;
        h_y = H / n_y;
        dof_handler.clear();
        tria.clear();
        GridGenerator::subdivided_hyper_rectangle(tria,
                                                  {n_x, n_y},
                                                  prm.lower,
                                                  prm.upper,
                                                  true);
        // The clamped corners are singular: refine around them.
        const Point<2> corners[] = {prm.lower,
                                    Point<2>(prm.lower[0], prm.upper[1])};
        for (unsigned int r = 0; r < prm.corner_refinements; ++r)
          {
            for (const auto &cell : tria.active_cell_iterators())
              for (const Point<2> &c : corners)
                for (const unsigned int v : cell->vertex_indices())
                  if (cell->vertex(v).distance(c) < 1e-9 * h_y)
                    cell->set_refine_flag();
            tria.execute_coarsening_and_refinement();
          }
        dof_handler.reinit(tria);
        dof_handler.distribute_dofs(fe);
        cells.assign(n_x * n_y, {});
        for (const auto &cell : dof_handler.cell_iterators_on_level(0))
          {
            const Point<2> c = cell->center();
            const auto     i =
              static_cast<unsigned int>((c[0] - prm.lower[0]) / h_x);
            const auto j =
              static_cast<unsigned int>((c[1] - prm.lower[1]) / h_y);
            cells[j * n_x + i] = cell;
          }
      }

      /// Hanging nodes and the clamped end x = lower[0]; the matrices
      /// and the load vector sized.
      void
      make_constraints_and_sparsity()
      {
        constraints.clear();
        DoFTools::make_hanging_node_constraints(dof_handler, constraints);
        VectorTools::interpolate_boundary_values(dof_handler,
                                                 0, // x = lower[0]
                                                 Functions::ZeroFunction<2>(2),
                                                 constraints);
        constraints.close();

        DynamicSparsityPattern dsp(dof_handler.n_dofs());
        DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
        K.clear();
        M.clear();
        K_eff.clear();
        sparsity.copy_from(dsp);
        K.reinit(sparsity);
        M.reinit(sparsity);
        force.reinit(dof_handler.n_dofs());
      }

      /// Stiffness K, consistent mass M and the weight (force) of plane-
      /// strain linear elasticity.
      void
      assemble()
      {
        const QGauss<2>                  quadrature(3);
        FEValues<2>                      fv(fe,
                       quadrature,
                       update_values | update_gradients | update_JxW_values);
        const FEValuesExtractors::Vector u(0);
        FullMatrix<double> k(n_local, n_local), m(n_local, n_local);
        Vector<double>     b(n_local);
        std::vector<types::global_dof_index> dofs(n_local);
        for (const auto &cell : dof_handler.active_cell_iterators())
          {
            fv.reinit(cell);
            k = 0;
            m = 0;
            b = 0;
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              {
                const double JxW = fv.JxW(q);
                for (unsigned int i = 0; i < n_local; ++i)
                  {
                    const auto   ei   = fv[u].symmetric_gradient(i, q);
                    const double divi = trace(ei);
                    const auto   vi   = fv[u].value(i, q);
                    for (unsigned int j = 0; j < n_local; ++j)
                      {
                        const auto ej = fv[u].symmetric_gradient(j, q);
                        k(i, j) +=
                          (lambda * divi * trace(ej) + 2 * mu * (ei * ej)) *
                          JxW;
                        m(i, j) += prm.density * (vi * fv[u].value(j, q)) * JxW;
                      }
                    b(i) += prm.density * (prm.gravity * vi) * JxW;
                  }
              }
            cell->get_dof_indices(dofs);
            constraints.distribute_local_to_global(k, b, dofs, K, force);
            constraints.distribute_local_to_global(m, dofs, M);
          }
      }

      /// Inverse iteration for the first eigenvalue of K x = lambda M x,
      /// from the static deflection (nearly the first mode).
      double
      first_eigenvalue() const
      {
        Vector<double> x(u_static), y(x.size()), z(x.size());
        double         eigenvalue = 0;
        for (unsigned int it = 0; it < 100; ++it)
          {
            M.vmult(y, x);
            K_inverse.vmult(z, y);
            K.vmult(y, z);
            const double zKz = z * y;
            M.vmult(y, z);
            const double zMz = z * y;
            const double ev  = zKz / zMz;
            x                = z;
            x /= std::sqrt(zMz);
            const bool done = std::abs(ev - eigenvalue) <= 1e-14 * ev;
            eigenvalue      = ev;
            if (done)
              break;
          }
        return eigenvalue;
      }

      void
      setup_newmark()
      {
        dt = 2 * numbers::PI / omega1 / prm.steps_per_period;
        K_eff.reinit(sparsity);
        K_eff.copy_from(K);
        K_eff.add(4 / (dt * dt), M);
        K_eff_inverse.initialize(K_eff);
        const unsigned int n = dof_handler.n_dofs();
        for (auto *v : {&u0, &v0, &a0, &u1, &v1, &a1})
          v->reinit(n);
        // Released from rest: u = v = 0, M a = f.
        SparseDirectUMFPACK M_inverse;
        M_inverse.initialize(M);
        M_inverse.vmult(a1, force);
        constraints.distribute(a1);
        n_steps = 0;
        step();
      }

      /// Level 1 becomes level 0; Newmark (beta = 1/4, gamma = 1/2) to
      /// the next level 1.
      void
      step()
      {
        u0 = u1;
        v0 = v1;
        a0 = a1;
        Vector<double> rhs(u0.size()), tmp(u0);
        tmp *= 4 / (dt * dt);
        tmp.add(4 / dt, v0);
        tmp += a0;
        M.vmult(rhs, tmp);
        rhs += force;
        K_eff_inverse.vmult(u1, rhs);
        constraints.distribute(u1);
        // a1 = 4/dt^2 (u1 - u0) - 4/dt v0 - a0
        a1 = u1;
        a1 -= u0;
        a1 *= 4 / (dt * dt);
        a1.add(-4 / dt, v0);
        a1 -= a0;
        v1 = v0;
        v1.add(dt / 2, a0);
        v1.add(dt / 2, a1);
        t0 = n_steps * dt;
        ++n_steps;
        t1 = n_steps * dt;
      }

      PointData
      make_point_data(const Point<2> &X) const
      {
        const auto locate = [](const double       x,
                               const double       x0,
                               const double       h,
                               const unsigned int n) {
          return static_cast<unsigned int>(
            std::clamp(std::floor((x - x0) / h), 0., n - 1.));
        };
        auto cell = cells[locate(X[1], prm.lower[1], h_y, n_y) * n_x +
                          locate(X[0], prm.lower[0], h_x, n_x)];
        while (cell->has_children())
          {
            const Point<2> c = cell->center();
            cell = cell->child((X[0] > c[0] ? 1 : 0) + (X[1] > c[1] ? 2 : 0));
          }
        // Children are numbered lexicographically: vertex 0 is the lower
        // left corner, vertex 3 the upper right one.
        const Tensor<1, 2> size = cell->vertex(3) - cell->vertex(0);
        Point<2>           xi;
        for (unsigned int d = 0; d < 2; ++d)
          xi[d] = std::clamp((X[d] - cell->vertex(0)[d]) / size[d], 0., 1.);
        PointData                            d;
        std::vector<types::global_dof_index> dofs(n_local);
        cell->get_dof_indices(dofs);
        for (unsigned int k = 0; k < n_local; ++k)
          {
            d.dofs[k]        = dofs[k];
            d.component[k]   = fe.system_to_component_index(k).first;
            d.value[k]       = fe.shape_value(k, xi);
            const auto g     = fe.shape_grad(k, xi);
            d.gradient[k][0] = g[0] / size[0];
            d.gradient[k][1] = g[1] / size[1];
          }
        return d;
      }

      const PointData &
      point_data(const Point<2> &X) const
      {
        const auto key = std::make_pair(X[0], X[1]);
        const auto it  = index.find(key);
        if (it != index.end())
          return points[it->second];
        index.emplace(key, points.size());
        points.push_back(make_point_data(X));
        return points.back();
      }

      Tensor<1, 2>
      value(const PointData &d, const Vector<double> &v) const
      {
        Tensor<1, 2> r;
        for (unsigned int k = 0; k < n_local; ++k)
          r[d.component[k]] += d.value[k] * v[d.dofs[k]];
        return r;
      }

      double
      tip_deflection() const
      {
        const Point<2> tip(prm.upper[0], 0.5 * (prm.lower[1] + prm.upper[1]));
        return value(make_point_data(tip), u_static)[1];
      }

      State
      evaluate(const Point<2> &X, const double t) const
      {
        AssertThrow(
          t >= t0 - 1e-9 * dt && t <= t1 + 1e-9 * dt,
          ExcMessage("cantilever fem: evaluated at t = " + std::to_string(t) +
                     " outside the current step [" + std::to_string(t0) + ", " +
                     std::to_string(t1) + "]; call advance_to(t) first."));
        const double s = std::clamp((t - t0) / dt, 0., 1.);
        // Cubic Hermite weights.
        const double h00 = (2 * s - 3) * s * s + 1, h10 = ((s - 2) * s + 1) * s,
                     h01 = (3 - 2 * s) * s * s, h11 = (s - 1) * s * s;
        const PointData &d = point_data(X);
        State            r;
        Tensor<2, 2>     grad_u;
        for (unsigned int k = 0; k < n_local; ++k)
          {
            const auto   i = d.dofs[k];
            const auto   c = d.component[k];
            const double cu =
              h00 * u0[i] + h10 * dt * v0[i] + h01 * u1[i] + h11 * dt * v1[i];
            const double cv =
              h00 * v0[i] + h10 * dt * a0[i] + h01 * v1[i] + h11 * dt * a1[i];
            r.displacement[c] += d.value[k] * cu;
            r.velocity[c] += d.value[k] * cv;
            grad_u[c] += cu * d.gradient[k];
          }
        const SymmetricTensor<2, 2> strain = symmetrize(grad_u);
        r.stress =
          lambda * trace(strain) * unit_symmetric_tensor<2>() + 2 * mu * strain;
        return r;
      }

      const Parameters prm;
      FESystem<2>      fe;
      const double     lambda, mu;

      unsigned int                              n_x = 0, n_y = 0;
      double                                    h_x = 0, h_y = 0;
      Triangulation<2>                          tria;
      DoFHandler<2>                             dof_handler;
      std::vector<DoFHandler<2>::cell_iterator> cells;
      AffineConstraints<double>                 constraints;
      SparsityPattern                           sparsity;
      SparseMatrix<double>                      K, M, K_eff;
      Vector<double>                            force, u_static;
      SparseDirectUMFPACK                       K_inverse, K_eff_inverse;
      double                                    omega1 = 0, dt = 0;

      Vector<double> u0, v0, a0, u1, v1, a1;
      double         t0 = 0, t1 = 0;
      unsigned long  n_steps = 0;

      mutable std::map<std::pair<double, double>, unsigned int> index;
      mutable std::vector<PointData>                            points;
    };


    CantileverFEM::CantileverFEM(const Parameters &parameters)
      : impl(std::make_unique<Implementation>(parameters))
    {
    }

    CantileverFEM::~CantileverFEM() = default;

    void
    CantileverFEM::advance_to(const double t)
    {
      while (t > impl->t1 + 1e-9 * impl->dt)
        impl->step();
    }

    Reference<2>::State
    CantileverFEM::evaluate(const Point<2> &X, const double t) const
    {
      return impl->evaluate(X, t);
    }

    Tensor<1, 2>
    CantileverFEM::static_displacement(const Point<2> &X) const
    {
      return impl->value(impl->make_point_data(X), impl->u_static);
    }

    double
    CantileverFEM::first_period() const
    {
      return 2 * numbers::PI / impl->omega1;
    }

    unsigned int
    CantileverFEM::elements_y() const
    {
      return impl->n_y;
    }

    unsigned int
    CantileverFEM::n_dofs() const
    {
      return impl->dof_handler.n_dofs();
    }

    double
    CantileverFEM::time_step() const
    {
      return impl->dt;
    }

    namespace
    {
      Registration<ReferenceRegistry<2>> registration(
        {"cantilever fem",
         "plane-strain linear elastic beam in Particles/Region (the whole "
         "mesh if empty) clamped at its left end, which must be the mesh's "
         "left boundary, fixed in x and y; loaded by Body force/Gravity and "
         "released from rest; Q2 finite elements (mesh converged "
         "automatically), Newmark average acceleration",
         [](const ReferenceContext<2> &c) {
           AssertThrow(c.region.size() == 4,
                       ExcMessage("cantilever fem: needs the beam box."));
           AssertThrow(std::abs(c.region[0]) <= 1e-12 * c.length,
                       ExcMessage("Reference solution/Type = cantilever fem: "
                                  "the beam (Particles/Region) must start at "
                                  "the mesh's left boundary x = 0, where it "
                                  "is clamped."));
           AssertThrow(c.clamped("left"),
                       ExcMessage("Reference solution/Type = cantilever fem: "
                                  "the beam is clamped at x = 0; Boundary "
                                  "conditions/Fixed x and Fixed y must both "
                                  "name 'left'."));
           CantileverFEM::Parameters p;
           p.lower          = Point<2>(c.region[0], c.region[1]);
           p.upper          = Point<2>(c.region[2], c.region[3]);
           p.youngs_modulus = c.material.youngs_modulus;
           p.poisson_ratio  = c.material.poisson_ratio;
           p.density        = c.material.density;
           p.gravity        = c.gravity;
           return std::make_unique<CantileverFEM>(p);
         },
         nullptr});
    } // namespace
  }   // namespace Postprocess
} // namespace psmpm
