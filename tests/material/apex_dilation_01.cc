// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Apex dilation = recoverable of Mohr-Coulomb and Drucker-Prager (phi
// 19.8 deg, psi 0, c 0, E 0.84 MPa, nu 0.3: the granular column
// collapse), plane strain, from an isotropic stress of -5 kPa:
// (a) isotropic in-plane extension to J = 1.2: the stress goes to zero
//     and the gap e_a is the volumetric strain beyond the elastic release,
//     sum tr(de) + p0 / K;
// (b) compression back to J = 1.04: the stress stays exactly zero, e_a
//     falls by the volumetric strain, the plastic work does not change;
// (c) compression past the closing point: the stress is, bit for bit,
//     that of a particle at zero stress compressed by the remainder of the
//     closing step and the same increments after it; the yield function
//     holds after every update;
// (d) random paths that dilate and compact: the batch and the
//     one-particle updates agree bit for bit, particles separate and
//     close again, separated particles carry no stress;
// (e) uniaxial strain (1D): the same gap under extension and compression;
// (f) bad input: an unknown value and a cohesive material are refused by
//     name (exit code 2, no output).
#include <psmpm/material/drucker_prager.h>
#include <psmpm/material/mohr_coulomb.h>

#include "../app_tests.h"
#include "../material_tests.h"

#include <random>

using namespace psmpm;

namespace
{
  template <typename Model>
  void
  set_constants(Model &m)
  {
    set_soil_constants(m, 19.8, 0, 0);
    m.youngs_modulus            = 8.4e5;
    m.density                   = 2650;
    m.recoverable_apex_dilation = true;
  }

  /// f of Mohr-Coulomb with c = 0 (the Drucker-Prager cone lies inside
  /// the outer Mohr-Coulomb surface of its plane-strain fit only near the
  /// plane-strain states; for it the test is the cone's own).
  double
  yield(const Material::MohrCoulomb<2> &m,
        const SymmetricTensor<2, 2>    &s,
        const double                    zz)
  {
    const auto   p  = sorted_principal(s[0][0], s[1][1], s[0][1], zz);
    const double sp = std::sin(m.friction_angle * dealii::numbers::PI / 180);
    return (1 + sp) * p[0] - (1 - sp) * p[2];
  }

  double
  yield(const Material::DruckerPrager<2> &m,
        const SymmetricTensor<2, 2>      &s,
        const double                      zz)
  {
    const double t   = std::tan(m.friction_angle * dealii::numbers::PI / 180);
    const double eta = 3 * t / std::sqrt(9 + 12 * t * t);
    const double p   = (s[0][0] + s[1][1] + zz) / 3;
    const double dx = s[0][0] - p, dy = s[1][1] - p, dz = zz - p;
    return std::sqrt(0.5 * (dx * dx + dy * dy + dz * dz) + s[0][1] * s[0][1]) +
           eta * p;
  }

  /// One particle in plane strain.
  template <typename Model>
  struct Particle
  {
    const Model          &m;
    SymmetricTensor<2, 2> stress;
    std::vector<double>   state;
    double                J = 1, ratio = 1;

    explicit Particle(const Model &m, const double p0)
      : m(m)
      , state(m.n_state())
    {
      m.initialize(1, state.data());
      stress[0][0] = stress[1][1] = p0;
      m.set_initial_stress(1, &stress, &p0, state.data());
    }

    void
    step(const Tensor<2, 2> &dL)
    {
      m.update(1, &dL, &stress, state.data(), &ratio);
      J *= ratio;
    }

    double
    gap() const
    {
      return state[Model::apex_column];
    }
  };

  Tensor<2, 2>
  isotropic(const double e)
  {
    Tensor<2, 2> d;
    d[0][0] = d[1][1] = e;
    return d;
  }

  template <typename Model>
  void
  check_path(std::ostream &out, const std::string &label)
  {
    Model m;
    set_constants(m);
    const double    p0 = -5e3, K = m.bulk_modulus();
    Particle<Model> p(m, p0);
    double          sum_tr = 0;
    while (p.J < 1.2)
      {
        p.step(isotropic(1e-3));
        sum_tr += 2e-3;
      }
    const double opened = p.gap();
    out << label << ": extended to J = " << p.J << ", |stress| "
        << p.stress.norm() << ", gap " << opened
        << " (sum tr(de) + p0 / K = " << sum_tr + p0 / K << ")" << std::endl;
    PSMPM_CHECK(out, p.stress.norm() == 0 && p.state[0] == 0);
    PSMPM_CHECK(out, std::abs(opened - (sum_tr + p0 / K)) < 1e-12);

    // (b) Back to J = 1.04: open all the way, no stress, no work.
    const double work      = p.state[Model::work_column];
    double       closed_by = 0, largest = 0;
    while (p.J > 1.04)
      {
        p.step(isotropic(-1e-4));
        closed_by += 2e-4;
        largest = std::max(largest, p.stress.norm() + std::abs(p.state[0]));
      }
    out << "  compressed to J = " << p.J << ": largest |stress| " << largest
        << ", gap " << p.gap() << " (" << opened << " - " << closed_by << ")"
        << std::endl;
    PSMPM_CHECK(out, largest == 0 && p.gap() > 0);
    PSMPM_CHECK(out, std::abs(p.gap() - (opened - closed_by)) < 1e-12);
    PSMPM_CHECK(out, p.state[Model::work_column] == work);

    // (c) Past the closing point: the remainder of the closing step and
    // the increments after it load the particle as one from zero stress.
    const Tensor<2, 2> dL   = isotropic(-1e-4);
    const double       tr   = -2e-4;
    unsigned int       open = 0;
    while (p.gap() + tr > 0)
      {
        p.step(dL);
        ++open;
      }
    const double    left = 1 - (-p.gap() / tr);
    Particle<Model> fresh(m, 0);
    p.step(dL);
    fresh.step(left * dL);
    double worst = 0, difference = 0;
    for (unsigned int s = 0; s < 200; ++s)
      {
        Tensor<2, 2> d = dL;
        d[0][1]        = 2e-3 * std::sin(0.1 * s); // and shear
        p.step(d);
        fresh.step(d);
        difference = std::max(difference, (p.stress - fresh.stress).norm());
        worst      = std::max(worst, yield(m, p.stress, p.state[0]));
      }
    out << "  closed after " << open << " more steps; 200 steps after: "
        << "stress " << p.stress.norm() << " Pa, against the particle from "
        << "zero stress " << difference << " Pa, largest f / |stress| "
        << (worst <= 1e-10 * p.stress.norm() ? "<= 1e-10" : "> 1e-10")
        << ", equivalent plastic strain " << p.state[Model::kappa_column]
        << std::endl;
    PSMPM_CHECK(out, p.gap() == 0 && p.stress.norm() > 1e4);
    PSMPM_CHECK(out, p.state[Model::kappa_column] > 0); // it yielded
    PSMPM_CHECK(out, difference == 0);
    PSMPM_CHECK(out, worst <= 1e-10 * p.stress.norm());
  }

  /// (d) Random paths: batch and one-particle updates, separation and
  /// closure.
  template <typename Model>
  void
  check_random(std::ostream &out, const std::string &label)
  {
    Model m;
    set_constants(m);
    const unsigned int        n = 65, n_steps = 300, ns = m.n_state();
    BatchAndSingleUpdates     u2(m, n);
    std::vector<Tensor<2, 2>> dL(n);
    std::mt19937              rng(5);
    std::uniform_real_distribution<double> u(-1, 1);
    unsigned int differing = 0, separated = 0, closing = 0, loaded = 0;
    for (unsigned int step = 0; step < n_steps; ++step)
      {
        const double drift = step < n_steps / 3 ? 2e-4 : -2e-4;
        for (unsigned int p = 0; p < n; ++p)
          for (unsigned int i = 0; i < 2; ++i)
            for (unsigned int j = 0; j < 2; ++j)
              dL[p][i][j] = 5e-4 * u(rng) + (i == j ? drift : 0);
        u2.update(dL);
        for (unsigned int p = 0; p < n; ++p)
          {
            const double gap = u2.state[p * ns + Model::apex_column];
            const double was = u2.before[p * ns + Model::apex_column];
            if (gap > 0)
              {
                ++separated;
                loaded +=
                  u2.stress[p].norm() + std::abs(u2.state[p * ns]) > 0 ? 1 : 0;
              }
            closing += was > 0 && gap == 0 ? 1 : 0;
            differing += u2.differs(p) ? 1 : 0;
          }
      }
    out << label << " random paths: separated particle-steps "
        << (separated > 1000 ? "> 1000" : "few") << ", closures "
        << (closing > 50 ? "> 50" : "few") << ", separated with stress "
        << loaded << ", differing from the one-particle update " << differing
        << std::endl;
    PSMPM_CHECK(out, separated > 1000 && closing > 50);
    PSMPM_CHECK(out, loaded == 0 && differing == 0);
  }

  /// (e) Uniaxial strain: opened by 0.1, closed by 0.1 and compressed by
  /// 0.05 more, against a particle compressed by 0.05 from zero stress.
  void
  check_uniaxial(std::ostream &out)
  {
    Material::MohrCoulomb<1> m;
    set_constants(m);
    const unsigned int    col = Material::MohrCoulomb<1>::apex_column;
    std::vector<double>   state(m.n_state()), fresh_state(m.n_state());
    SymmetricTensor<2, 1> stress, fresh;
    Tensor<2, 1>          dL;
    double                ratio, sum = 0, largest = 0;
    m.initialize(1, state.data());
    m.initialize(1, fresh_state.data());
    dL[0][0] = 1e-3;
    for (unsigned int s = 0; s < 100; ++s, sum += 1e-3)
      m.update(1, &dL, &stress, state.data(), &ratio);
    const double opened = state[col];
    dL[0][0]            = -1e-3;
    for (unsigned int s = 0; s < 150; ++s)
      {
        m.update(1, &dL, &stress, state.data(), &ratio);
        largest = s < 99 ? std::max(largest, std::abs(stress[0][0])) : largest;
        if (s >= 100)
          m.update(1, &dL, &fresh, fresh_state.data(), &ratio);
      }
    out << "1D: opened by " << opened << " (strain " << sum
        << "), |stress| while open " << largest << "; closed and compressed "
        << "by 0.05: " << stress[0][0] << " Pa, from zero stress "
        << fresh[0][0] << " Pa, gap " << state[col] << std::endl;
    PSMPM_CHECK(out, std::abs(opened - sum) < 1e-12 && largest == 0);
    PSMPM_CHECK(out, state[col] == 0 && fresh[0][0] < -1e3);
    PSMPM_CHECK(out,
                std::abs(stress[0][0] - fresh[0][0]) <=
                  1e-9 * std::abs(fresh[0][0]));
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");
  out << std::setprecision(4);
  check_path<Material::MohrCoulomb<2>>(out, "MC");
  check_path<Material::DruckerPrager<2>>(out, "DP");
  check_random<Material::MohrCoulomb<2>>(out, "MC");
  check_random<Material::DruckerPrager<2>>(out, "DP");
  check_uniaxial(out);

  check_bad_input(out,
                  "Apex dilation = sometimes",
                  "set Output directory = bad_output\n"
                  "subsection Material\n"
                  "  set Model = mohr-coulomb\n"
                  "  set Apex dilation = sometimes\n"
                  "end\n",
                  {"Apex dilation", "sometimes"});
  check_bad_input(out,
                  "Apex dilation = recoverable with Cohesion = 1000",
                  "set Output directory = bad_output\n"
                  "subsection Material\n"
                  "  set Model = drucker-prager\n"
                  "  set Cohesion = 1000\n"
                  "  set Apex dilation = recoverable\n"
                  "end\n",
                  {"Material/Apex dilation = recoverable",
                   "Material/Cohesion = 1000"});
}
