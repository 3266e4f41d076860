// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <psmpm/postprocess/updated_lagrangian_1d.h>

#include <algorithm>
#include <cmath>

namespace psmpm
{
  namespace Postprocess
  {
    UpdatedLagrangian1D::UpdatedLagrangian1D(const Parameters &p)
      : prm(p)
    {
      const unsigned int n = prm.n_elements;
      AssertThrow(n >= 2, dealii::ExcMessage("need at least two elements"));
      const double h = prm.length / n;
      X.resize(n + 1);
      for (unsigned int i = 0; i <= n; ++i)
        X[i] = i * h;
      x = X;
      v.assign(n + 1, 0.);
      if (prm.initial_velocity)
        for (unsigned int i = 0; i <= n; ++i)
          v[i] = prm.initial_velocity(X[i]);
      v[0] = 0;
      if (prm.fix_end)
        v[n] = 0;
      mass.assign(n + 1, 0.);
      for (unsigned int e = 0; e < n; ++e)
        {
          mass[e] += 0.5 * prm.density * h;
          mass[e + 1] += 0.5 * prm.density * h;
        }
      sigma.assign(n, 0.);
      // Elements shrink under compression, so keep a margin on the step.
      max_step = prm.courant * h / std::sqrt(prm.youngs_modulus / prm.density);
    }

    void
    UpdatedLagrangian1D::step(const double dt)
    {
      // Runs every step of the MPM run beside it (2,000 elements for the
      // large bar): two passes, no allocation. Node i's force m_i g -
      // sigma_{i-1} + sigma_i is summed in the order of the element loop
      // that used to scatter it, so the results are the same bits.
      const unsigned int n = prm.n_elements;
      for (unsigned int i = 1; i <= n; ++i)
        {
          double force = mass[i] * prm.gravity;
          force -= sigma[i - 1];
          if (i < n)
            force += sigma[i];
          v[i] += dt * force / mass[i];
        }
      if (prm.fix_end)
        v[n] = 0;
      // Element e reads x[e] and x[e + 1] before x[e] moves.
      for (unsigned int e = 0; e < n; ++e)
        {
          const double length = x[e + 1] - x[e];
          const double deps   = dt * (v[e + 1] - v[e]) / length;
          sigma[e] += prm.youngs_modulus * deps - deps * sigma[e];
          x[e] += dt * v[e];
        }
      x[n] += dt * v[n];
      ++steps;
    }

    void
    UpdatedLagrangian1D::advance_to(const double t)
    {
      const double span = t - current_time;
      if (span <= 0)
        return;
      const unsigned int n_sub =
        std::max(1., std::ceil(span / max_step - 1e-9));
      const double dt = span / n_sub;
      for (unsigned int i = 0; i < n_sub; ++i)
        step(dt);
      current_time = t;
    }

    UpdatedLagrangian1D::State
    UpdatedLagrangian1D::evaluate(const double Xp) const
    {
      const unsigned int n = prm.n_elements;
      const double       h = prm.length / n;
      const double       s = std::clamp(Xp / h, 0., double(n));
      const unsigned int e = std::min(n - 1, static_cast<unsigned int>(s));
      const double       w = s - e;
      State              r;
      r.displacement = (1 - w) * (x[e] - X[e]) + w * (x[e + 1] - X[e + 1]);
      r.velocity     = (1 - w) * v[e] + w * v[e + 1];
      // Stress is element-wise constant; interpolate between element
      // centres for a second-order accurate value.
      const double c = s - 0.5;
      const int e0 = std::clamp(static_cast<int>(std::floor(c)), 0, int(n) - 1);
      const int e1 = std::min(e0 + 1, int(n) - 1);
      const double wc = std::clamp(c - e0, 0., 1.);
      r.stress        = (1 - wc) * sigma[e0] + wc * sigma[e1];
      return r;
    }
  } // namespace Postprocess
} // namespace psmpm
