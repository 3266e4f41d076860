// NeoHookean<dim>. (a) A rigid rotation (a quarter turn in 1000 steps)
// leaves an unstressed body unstressed and J = 1 to round-off, and rotates
// a prestressed one without changing its stress invariants. (b) Along a
// smooth deformation path the work sum of sigma : dL_sym V equals the
// change of the stored energy W/J V to second order in dt. (c) A small
// strain increment gives the hypoelastic stress to first order. (d) 1D
// stretches give the closed-form stress and energy. (e) A step that
// inverts the material gives NaN, not an exception; wave speed.
#include <psmpm/material/hypoelastic.h>
#include <psmpm/material/neo_hookean.h>

#include "../tests.h"

#include <random>

using namespace psmpm;

namespace
{
  template <int dim>
  Material::NeoHookean<dim>
  make(const double E, const double nu)
  {
    Material::NeoHookean<dim> m;
    m.youngs_modulus = E;
    m.poisson_ratio  = nu;
    m.density        = 2;
    return m;
  }

  double
  max_abs(const SymmetricTensor<2, 2> &s)
  {
    return std::max({std::abs(s[0][0]), std::abs(s[1][1]), std::abs(s[0][1])});
  }

  void
  rigid_rotation(std::ostream &out)
  {
    const double       E = 100, pi = 3.14159265358979323846;
    const unsigned int n_steps = 1000;
    const double       dt      = 0.5 * pi / n_steps;
    const auto         m       = make<2>(E, 0.3);
    Tensor<2, 2>       dL;
    dL[0][1] = -dt; // W = [[0, -1], [1, 0]], 1 rad/s
    dL[1][0] = dt;

    // Particle 0 starts undeformed, particle 1 prestretched.
    const Tensor<2, 2>    dLs[2] = {dL, dL};
    SymmetricTensor<2, 2> stress[2];
    double                state[8], ratio[2], energy[2];
    m.initialize(2, state);
    state[4] = 1.1;
    state[5] = 0.05;
    state[7] = 0.9;
    {
      // Stress of the prestretched state: a zero increment.
      const Tensor<2, 2> zero[2];
      m.update(2, zero, stress, state, ratio);
    }
    m.energy_density(2, stress, state, energy);
    const double tr0 = trace(stress[1]), det0 = determinant(stress[1]),
                 energy0 = energy[1];

    double max_stress = 0, max_J = 0, volume = 1;
    for (unsigned int step = 0; step < n_steps; ++step)
      {
        m.update(2, dLs, stress, state, ratio);
        volume *= ratio[0];
        max_stress = std::max(max_stress, max_abs(stress[0]));
        max_J =
          std::max(max_J,
                   std::abs(state[0] * state[3] - state[1] * state[2] - 1));
      }
    m.energy_density(2, stress, state, energy);
    out << "rotation: F = [" << filter(state[0], 1e-5) << " "
        << filter(state[1], 1e-5) << "; " << filter(state[2], 1e-5) << " "
        << filter(state[3], 1e-5) << "]" << std::endl;
    PSMPM_CHECK(out, max_stress < 1e-10 * E);
    // Round-off of 1000 products F <- dF F accumulates (~2e-13 here).
    PSMPM_CHECK(out, max_J < 1e-12 && std::abs(volume - 1) < 1e-12);
    PSMPM_CHECK(out, std::abs(energy[0]) < 1e-13 * E);
    // Cayley rotation angle: 1000 * 2 atan(dt / 2) ~ pi/2 - 3e-7.
    PSMPM_CHECK(out,
                std::abs(state[0]) < 1e-6 && std::abs(state[1] + 1) < 1e-12 &&
                  std::abs(state[2] - 1) < 1e-12 && std::abs(state[3]) < 1e-6);
    // The prestressed particle: the stress is rotated, not changed.
    out << "prestressed: tr sigma/E = " << std::setprecision(8) << tr0 / E
        << std::setprecision(6) << std::endl;
    PSMPM_CHECK(out, std::abs(trace(stress[1]) - tr0) < 1e-12 * E);
    PSMPM_CHECK(out, std::abs(determinant(stress[1]) - det0) < 1e-12 * E * E);
    PSMPM_CHECK(out, std::abs(energy[1] - energy0) < 1e-12 * E);
    PSMPM_CHECK(out, std::abs(stress[1][0][1]) > 1e-2 * E);
  }

  /// Velocity gradient of a smooth path with stretch, shear and rotation.
  template <int dim>
  Tensor<2, dim>
  velocity_gradient(const double t)
  {
    Tensor<2, dim> L;
    L[0][0] = 0.4 * std::cos(2 * t) - 0.1;
    if constexpr (dim == 2)
      {
        L[0][1] = 0.3 * std::sin(3 * t) + 0.2;
        L[1][0] = -0.25 * std::cos(t);
        L[1][1] = -0.35 * std::sin(2.5 * t) + 0.05;
      }
    return L;
  }

  /// |work - change of stored energy| / energy scale for @p n_steps on
  /// [0, 1].
  template <int dim>
  double
  energy_mismatch(const Material::NeoHookean<dim> &m,
                  const unsigned int               n_steps,
                  double                          &energy_change)
  {
    const double            dt = 1. / n_steps;
    SymmetricTensor<2, dim> stress;
    double                  state[dim * dim], ratio, energy;
    m.initialize(1, state);
    m.energy_density(1, &stress, state, &energy);
    double       volume = 0.7, work = 0;
    const double stored0 = energy * volume;
    for (unsigned int step = 0; step < n_steps; ++step)
      {
        const Tensor<2, dim> dL =
          dt * velocity_gradient<dim>((step + 0.5) * dt);
        const SymmetricTensor<2, dim> de     = symmetrize(dL);
        const double                  before = stress * de * volume;
        m.update(1, &dL, &stress, state, &ratio);
        volume *= ratio;
        // Trapezoidal work: second order, like the midpoint update of F.
        work += 0.5 * (before + stress * de * volume);
      }
    m.energy_density(1, &stress, state, &energy);
    energy_change = energy * volume - stored0;
    return std::abs(work - energy_change);
  }

  template <int dim>
  void
  energy_consistency(std::ostream &out)
  {
    const auto m      = make<dim>(100, dim == 2 ? 0.3 : 0.2);
    double     change = 0, previous = 0;
    for (const unsigned int n : {100u, 200u, 400u, 800u})
      {
        const double mismatch = energy_mismatch(m, n, change);
        out << dim << "D energy: steps " << n
            << ", mismatch/change = " << std::setprecision(2)
            << mismatch / change;
        if (previous > 0)
          out << ", ratio " << std::setprecision(3) << previous / mismatch;
        out << std::setprecision(6) << std::endl;
        PSMPM_CHECK(out, mismatch < 1e-3 * change);
        if (previous > 0)
          PSMPM_CHECK(out,
                      previous / mismatch > 3.6 && previous / mismatch < 4.4);
        previous = mismatch;
      }
    out << dim << "D energy: stored energy change " << std::setprecision(3)
        << change << std::setprecision(6) << std::endl;
    PSMPM_CHECK(out, change > 0.1);
  }

  void
  small_strain(std::ostream &out)
  {
    std::mt19937                           rng(3);
    std::uniform_real_distribution<double> u(-1, 1);
    for (const double nu : {0., 0.3, 0.45})
      {
        const auto               neo = make<2>(100, nu);
        Material::Hypoelastic<2> hypo;
        hypo.youngs_modulus = neo.youngs_modulus;
        hypo.poisson_ratio  = nu;
        double worst        = 0;
        // Uniaxial strain, simple shear, random.
        for (unsigned int c = 0; c < 3; ++c)
          for (const double eps : {1e-4, 1e-5})
            {
              Tensor<2, 2> dL;
              if (c == 0)
                dL[0][0] = eps;
              else if (c == 1)
                dL[0][1] = eps;
              else
                for (unsigned int i = 0; i < 2; ++i)
                  for (unsigned int j = 0; j < 2; ++j)
                    dL[i][j] = eps * u(rng);
              SymmetricTensor<2, 2> s_neo, s_hypo;
              double state_neo[4], state_hypo[4], ratio_neo, ratio_hypo;
              neo.initialize(1, state_neo);
              hypo.initialize(1, state_hypo);
              neo.update(1, &dL, &s_neo, state_neo, &ratio_neo);
              hypo.update(1, &dL, &s_hypo, state_hypo, &ratio_hypo);
              // First order: the difference is O(eps^2) relative to E.
              const double diff = max_abs(s_neo - s_hypo) / 100;
              worst             = std::max(worst, diff / (eps * eps));
              if (c == 0)
                PSMPM_CHECK(out,
                            std::abs(s_hypo[0][0] -
                                     neo.p_wave_modulus() * eps) <
                              1e-10 * neo.p_wave_modulus() * eps);
              PSMPM_CHECK(out, max_abs(s_hypo) > 0.1 * eps * 100);
              PSMPM_CHECK(out,
                          std::abs(ratio_neo - ratio_hypo) < 10 * eps * eps);
            }
        out << "small strain nu = " << nu
            << ": |sigma_neo - sigma_hypo| / (E eps^2) <= "
            << std::setprecision(2) << worst << std::setprecision(6)
            << std::endl;
        PSMPM_CHECK(out, worst < 10);
      }
  }

  void
  stretch_1d(std::ostream &out)
  {
    const auto   m      = make<1>(100, 0.25);
    const double mu     = m.shear_modulus();
    const double lambda = m.lame_lambda();
    for (const double stretch : {1.5, 0.6, 1.})
      {
        // Ten equal Cayley steps: dF = (1 + d/2) / (1 - d/2) = r.
        const double          r = std::pow(stretch, 0.1);
        Tensor<2, 1>          dL;
        SymmetricTensor<2, 1> stress;
        double                F, ratio, energy, volume = 1;
        dL[0][0] = 2 * (r - 1) / (r + 1);
        m.initialize(1, &F);
        for (unsigned int step = 0; step < 10; ++step)
          {
            m.update(1, &dL, &stress, &F, &ratio);
            volume *= ratio;
          }
        m.energy_density(1, &stress, &F, &energy);
        const double ln_J = std::log(stretch);
        const double sigma =
          (mu * (stretch * stretch - 1) + lambda * ln_J) / stretch;
        const double W = 0.5 * mu * (stretch * stretch - 1 - 2 * ln_J) +
                         0.5 * lambda * ln_J * ln_J;
        out << "1D stretch " << stretch << ": sigma = " << std::setprecision(10)
            << filter(stress[0][0], 1e-10)
            << ", W/J = " << filter(energy, 1e-10) << std::setprecision(6)
            << std::endl;
        PSMPM_CHECK(out, std::abs(F - stretch) < 1e-14);
        PSMPM_CHECK(out, std::abs(volume - stretch) < 1e-14);
        PSMPM_CHECK(out, std::abs(stress[0][0] - sigma) < 1e-12 * 100);
        PSMPM_CHECK(out, std::abs(energy - W / stretch) < 1e-12 * 100);
      }
  }

  void
  guards_and_wave_speed(std::ostream &out)
  {
    const auto m2 = make<2>(100, 0.3);
    const auto m1 = make<1>(100, 0.3);
    {
      // (I - dL/2) singular, then an inverting step.
      Tensor<2, 2> dL[2];
      dL[0][0][0] = 2;
      dL[1][1][1] = -3;
      SymmetricTensor<2, 2> stress[2];
      double                state[8], ratio[2];
      m2.initialize(2, state);
      m2.update(2, dL, stress, state, ratio);
      for (unsigned int p = 0; p < 2; ++p)
        PSMPM_CHECK(out,
                    std::isnan(stress[p][0][0]) &&
                      std::isnan(stress[p][1][1]) &&
                      std::isnan(stress[p][0][1]) && state[4 * p] == 1 &&
                      state[4 * p + 3] == 1);
      PSMPM_CHECK(out, std::isnan(ratio[0]) && ratio[1] < 0);
    }
    {
      Tensor<2, 1> dL;
      dL[0][0] = -2.5;
      SymmetricTensor<2, 1> stress;
      double                F, ratio;
      m1.initialize(1, &F);
      m1.update(1, &dL, &stress, &F, &ratio);
      PSMPM_CHECK(out, std::isnan(stress[0][0]) && F == 1 && !(ratio > 0));
    }
    {
      double       F[4] = {1, 0, 0, 1}, F1 = 1;
      const double c0 = m2.wave_speed({}, F);
      out << "wave speed at F = I: " << c0 << " (p-wave " << m2.p_wave_speed()
          << ")" << std::endl;
      PSMPM_CHECK(out, std::abs(c0 - m2.p_wave_speed()) < 1e-12 * c0);
      PSMPM_CHECK(out, std::abs(m1.wave_speed({}, &F1) - c0) < 1e-12 * c0);
      // Compression stiffens the law: the estimate must grow.
      F[0] = F[3] = 0.8;
      F1          = 0.7;
      PSMPM_CHECK(out,
                  m2.wave_speed({}, F) > c0 && m1.wave_speed({}, &F1) > c0);
      // 1D: the estimate is the exact longitudinal speed,
      // sqrt((lambda (1 - ln J) + mu (1 + F^2)) / rho0).
      const double exact = std::sqrt((m1.lame_lambda() * (1 - std::log(F1)) +
                                      m1.shear_modulus() * (1 + F1 * F1)) /
                                     m1.density);
      PSMPM_CHECK(out,
                  std::abs(m1.wave_speed({}, &F1) - exact) < 1e-12 * exact);
    }
    {
      const std::vector<std::string> names2 = {"F_xx", "F_xy", "F_yx", "F_yy"};
      const std::vector<std::string> names1 = {"F_xx"};
      PSMPM_CHECK(out,
                  m2.state_names() == names2 && m1.state_names() == names1);
      PSMPM_CHECK(out,
                  m2.name() == "neo-hookean" && m1.name() == "neo-hookean");
    }
  }
} // namespace

int
main()
{
  std::ofstream out("output");
  return run_test([&] {
    rigid_rotation(out);
    energy_consistency<2>(out);
    energy_consistency<1>(out);
    small_strain(out);
    stretch_1d(out);
    guards_and_wave_speed(out);
  });
}
