// Mohr-Coulomb and Drucker-Prager return maps, through the batched
// update() a particle loop calls:
// (a) consistency: over random strain paths with rotation, after every
//     update f(sigma) <= 1e-10 (|sigma| + c) (and sigma_1 <= t) for
//     associated and non-associated flow, Tresca, a tension cutoff,
//     softening, von Mises and each Drucker-Prager fit; the dissipation
//     never decreases;
// (b) the regions of the Mohr-Coulomb return: main plane (flow along the
//     potential's normal), both edges, the apex, the cutoff;
// (c) objectivity: a body on the yield surface in rigid rotation (a full
//     turn in 2000 steps) keeps its principal stresses to round-off and
//     dissipates nothing beyond round-off;
// (d) plane-strain biaxial compression under a confining pressure (one
//     particle, lateral stress held): the limit sigma_1/sigma_3 = (1 +
//     sin phi)/(1 - sin phi), the dilatancy ratio d(eps_v^p)/d(gamma^p) =
//     sin psi, and Drucker-Prager's plane-strain fit reaching the same
//     limit for associated flow;
// (e) bad input names the entry.
#include <deal.II/base/parameter_handler.h>

#include <psmpm/material/drucker_prager.h>
#include <psmpm/material/mohr_coulomb.h>

#include "../material_tests.h"

#include <random>

using namespace psmpm;

namespace
{
  constexpr double degree = numbers::PI / 180;

  /// Principal stresses of a 2D stress with its out-of-plane one.
  std::array<double, 3>
  principal(const SymmetricTensor<2, 2> &s, const double szz)
  {
    return sorted_principal(s[0][0], s[1][1], s[0][1], szz);
  }

  double
  mc_yield(const std::array<double, 3> &p,
           const double                 phi,
           const double                 c,
           const double                 t)
  {
    const double s = std::sin(phi * degree), co = std::cos(phi * degree);
    return std::max((1 + s) * p[0] - (1 - s) * p[2] - 2 * c * co, p[0] - t);
  }

  double
  dp_yield(const std::array<double, 3> &p, const double eta, const double xi_c)
  {
    const double m  = (p[0] + p[1] + p[2]) / 3;
    const double j2 = 0.5 * ((p[0] - m) * (p[0] - m) + (p[1] - m) * (p[1] - m) +
                             (p[2] - m) * (p[2] - m));
    return std::sqrt(j2) + eta * m - xi_c;
  }

  /// Random paths: compression, shear and rotation increments for a batch.
  template <typename Model, typename Yield>
  void
  random_paths(std::ostream      &out,
               const std::string &label,
               const Model       &model,
               const Yield       &yield)
  {
    const unsigned int                 n = 64, n_steps = 400;
    std::vector<SymmetricTensor<2, 2>> stress(n);
    std::vector<Tensor<2, 2>>          dL(n);
    std::vector<double> state(n * model.n_state()), ratio(n), work(n),
      old_work(n, 0.);
    model.initialize(n, state.data());
    std::mt19937                           rng(3);
    std::uniform_real_distribution<double> u(-1, 1);
    double                                 worst = 0, min_work_step = 0;
    unsigned int                           plastic = 0;
    const auto                             szz_column =
      Material::PlasticHypoelastic<2>::Column::out_of_plane;
    for (unsigned int step = 0; step < n_steps; ++step)
      {
        for (unsigned int p = 0; p < n; ++p)
          for (unsigned int i = 0; i < 2; ++i)
            for (unsigned int j = 0; j < 2; ++j)
              // Increments up to 5e-4 (several times the yield strain of
              // the weakest sets) with a drift towards compression or
              // extension by particle.
              dL[p][i][j] =
                5e-4 * u(rng) + (i == j ? (p % 3 == 0 ? -2e-4 : 1e-4) : 0);
        model.update(n, dL.data(), stress.data(), state.data(), ratio.data());
        model.dissipated_energy(n, state.data(), work.data());
        for (unsigned int p = 0; p < n; ++p)
          {
            const auto pr =
              principal(stress[p], state[p * model.n_state() + szz_column]);
            const double scale = std::abs(pr[0]) + std::abs(pr[1]) +
                                 std::abs(pr[2]) + model.cohesion;
            worst =
              std::max(worst, yield(pr, &state[p * model.n_state()]) / scale);
            min_work_step = std::min(min_work_step, work[p] - old_work[p]);
            plastic += work[p] > old_work[p] ? 1 : 0;
            old_work[p] = work[p];
          }
      }
    out << label << ": plastic updates "
        << (plastic > n * n_steps / 4 ? ">" : "<=") << " 1/4 of all"
        << std::endl;
    PSMPM_CHECK(out, plastic > 100);
    out << label << ": f <= 1e-10 (|sigma| + c): "
        << (worst <= 1e-10 ? "yes" : "no, " + std::to_string(worst))
        << std::endl;
    PSMPM_CHECK(out, worst <= 1e-10);
    PSMPM_CHECK(out, min_work_step >= -1e-12);
  }

  void
  check_consistency(std::ostream &out)
  {
    const double inf = HUGE_VAL;
    struct Case
    {
      const char *label;
      double      phi, psi, c, t, residual_c, residual_phi, softening;
    };
    for (const Case &k :
         {Case{"MC phi 30 psi 0 c 10 kPa", 30, 0, 1e4, inf, 1e4, 30, 0},
          Case{"MC phi 35 psi 35 c 0", 35, 35, 0, inf, 0, 35, 0},
          Case{"MC phi 20 psi 5 c 5 kPa t 2 kPa", 20, 5, 5e3, 2e3, 5e3, 20, 0},
          Case{"MC Tresca c 20 kPa", 0, 0, 2e4, inf, 2e4, 0, 0},
          Case{"MC softening c 20->2 kPa phi 35->25",
               35,
               5,
               2e4,
               inf,
               2e3,
               25,
               0.02}})
      {
        Material::MohrCoulomb<2> m;
        set_soil_constants(m, k.phi, k.psi, k.c, k.t);
        m.residual_cohesion       = k.residual_c;
        m.residual_friction_angle = k.residual_phi;
        m.softening_strain        = k.softening;
        // With softening, the surface of each particle's stored kappa.
        random_paths(out,
                     k.label,
                     m,
                     [&](const std::array<double, 3> &p, const double *block) {
                       const auto s = m.strength(block[m.kappa_column]);
                       return mc_yield(p,
                                       std::asin(s.sin_phi) / degree,
                                       s.cohesion,
                                       k.t);
                     });
      }
    using Fit = Material::DruckerPrager<2>::Fit;
    for (const auto &[label, fit, phi, psi, c] :
         {std::tuple<const char *, Fit, double, double, double>{
            "DP plane strain phi 30 psi 0 c 10 kPa",
            Fit::plane_strain,
            30,
            0,
            1e4},
          {"DP outer phi 35 psi 35 c 0", Fit::outer, 35, 35, 0},
          {"DP inner phi 25 psi 10 c 5 kPa", Fit::inner, 25, 10, 5e3},
          {"DP von Mises c 20 kPa", Fit::plane_strain, 0, 0, 2e4}})
      {
        Material::DruckerPrager<2> m;
        set_soil_constants(m, phi, psi, c);
        m.fit                                                = fit;
        typename Material::PlasticHypoelastic<2>::Strength s = m.strength(0);
        m.prepare(s);
        random_paths(out,
                     label,
                     m,
                     [&](const std::array<double, 3> &p, const double *) {
                       return dp_yield(p, s.derived[0], s.derived[1]);
                     });
      }
  }

  void
  check_regions(std::ostream &out)
  {
    Material::MohrCoulomb<2> m;
    const double             phi = 30, psi = 10, c = 1e4;
    set_soil_constants(m, phi, psi, c, 5e3);
    const auto   s  = m.strength(0);
    const double sp = std::sin(phi * degree), ss = std::sin(psi * degree);
    const double E = m.youngs_modulus, nu = m.poisson_ratio;
    const auto   plastic_strain = [&](const std::array<double, 3> &a,
                                    const std::array<double, 3> &b) {
      std::array<double, 3> d, e;
      for (unsigned int i = 0; i < 3; ++i)
        d[i] = a[i] - b[i];
      for (unsigned int i = 0; i < 3; ++i)
        e[i] = (d[i] - nu * (d[(i + 1) % 3] + d[(i + 2) % 3])) / E;
      return e;
    };
    // Main plane: a deviatoric trial state well inside the sextant.
    {
      const std::array<double, 3> trial = {{-1e4, -1.2e5, -3e5}};
      std::array<double, 3>       y     = trial;
      PSMPM_CHECK(out, m.return_stress(s, y));
      const auto e = plastic_strain(trial, y);
      // Along b = (1 + sin psi, 0, -(1 - sin psi)).
      const double b[3] = {1 + ss, 0, -(1 - ss)};
      const double dot  = e[0] * b[0] + e[1] * b[1] + e[2] * b[2];
      const double ne   = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
      const double nb   = std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
      out << "main plane: f = " << filter(mc_yield(y, phi, c, HUGE_VAL), 1e-6)
          << std::endl;
      PSMPM_CHECK(out, y[0] > y[1] && y[1] > y[2]);
      PSMPM_CHECK(out, std::abs(dot / (ne * nb) - 1) < 1e-12);
      PSMPM_CHECK(out, std::abs(e[0] + e[2] - ss * (e[0] - e[2])) < 1e-12 * ne);
    }
    // Edges: sigma_2 close to sigma_1 (triaxial extension) and to sigma_3
    // (triaxial compression).
    for (const auto &[label, trial] :
         {std::pair<const char *, std::array<double, 3>>{
            "edge sigma_1 = sigma_2",
            {{-1e4, -1.5e4, -4e5}}},
          {"edge sigma_2 = sigma_3", {{-1e4, -3.9e5, -4e5}}}})
      {
        std::array<double, 3> y = trial;
        PSMPM_CHECK(out, m.return_stress(s, y));
        const bool top    = std::abs(y[0] - y[1]) < 1e-9 * std::abs(y[2]);
        const bool bottom = std::abs(y[1] - y[2]) < 1e-9 * std::abs(y[2]);
        out << label << ": " << (top ? "sigma_1 = sigma_2" : "")
            << (bottom ? "sigma_2 = sigma_3" : "") << std::endl;
        PSMPM_CHECK(out, top != bottom);
        PSMPM_CHECK(out, std::abs(mc_yield(y, phi, c, HUGE_VAL)) < 1e-10 * 4e5);
      }
    // Apex and cutoff: a hydrostatic tension beyond t and beyond the apex.
    {
      Material::MohrCoulomb<2> no_cutoff;
      set_soil_constants(no_cutoff, phi, psi, c);
      const auto            s2   = no_cutoff.strength(0);
      const double          apex = c * std::cos(phi * degree) / sp;
      std::array<double, 3> y    = {{2 * apex, 1.9 * apex, 1.8 * apex}};
      PSMPM_CHECK(out, no_cutoff.return_stress(s2, y));
      PSMPM_CHECK(out,
                  std::abs(y[0] - apex) < 1e-12 * apex &&
                    std::abs(y[2] - apex) < 1e-12 * apex);
      std::array<double, 3> z = {{2e4, -1e3, -2e3}};
      PSMPM_CHECK(out, m.return_stress(s, z));
      out << "cutoff: sigma_1 = " << z[0] << std::endl;
      PSMPM_CHECK(out, z[0] <= 5e3 * (1 + 1e-12));
      PSMPM_CHECK(out, mc_yield(z, phi, c, 5e3) <= 1e-10 * 2e4);
    }
    // Inside: unchanged.
    {
      std::array<double, 3> y = {{-1e4, -2e4, -3e4}};
      PSMPM_CHECK(out, !m.return_stress(s, y));
    }
  }

  void
  check_objectivity(std::ostream &out)
  {
    for (const bool dp : {false, true})
      {
        Material::MohrCoulomb<2>   mc;
        Material::DruckerPrager<2> dpm;
        set_soil_constants(mc, 30, 0, 1e4);
        set_soil_constants(dpm, 30, 0, 1e4);
        const Material::Material<2> &m =
          dp ? static_cast<const Material::Material<2> &>(dpm) : mc;
        std::vector<SymmetricTensor<2, 2>> stress(1);
        std::vector<Tensor<2, 2>>          dL(1);
        std::vector<double>                state(m.n_state()), ratio(1), w(1);
        m.initialize(1, state.data());
        // Load in shear under compression until it flows.
        for (unsigned int k = 0; k < 200; ++k)
          {
            dL[0]       = 0;
            dL[0][0][0] = -1e-5;
            dL[0][1][1] = -2e-5;
            dL[0][0][1] = dL[0][1][0] = 1e-4;
            m.update(1, dL.data(), stress.data(), state.data(), ratio.data());
          }
        m.dissipated_energy(1, state.data(), w.data());
        const double w0 = w[0];
        const auto   p0 = principal(stress[0], state[0]);
        // A full turn in 2000 steps of rigid rotation: dL = W dt.
        const double dtheta = 2 * numbers::PI / 2000;
        double       drift  = 0;
        for (unsigned int k = 0; k < 2000; ++k)
          {
            dL[0]       = 0;
            dL[0][0][1] = -dtheta;
            dL[0][1][0] = dtheta;
            m.update(1, dL.data(), stress.data(), state.data(), ratio.data());
            const auto p = principal(stress[0], state[0]);
            for (unsigned int i = 0; i < 3; ++i)
              drift = std::max(drift, std::abs(p[i] - p0[i]) / std::abs(p0[2]));
          }
        m.dissipated_energy(1, state.data(), w.data());
        out << (dp ? "DP" : "MC") << " rigid rotation: yielded "
            << (w0 > 0 ? "yes" : "no") << std::endl;
        PSMPM_CHECK(out, w0 > 0);
        PSMPM_CHECK(out, drift < 1e-12);
        PSMPM_CHECK(out, std::abs(w[0] - w0) <= 1e-12 * w0);
      }
  }

  /// One particle in plane-strain biaxial compression: sigma_yy is
  /// compressed at a constant strain rate while sigma_xx is held at -p0
  /// (the lateral strain increment solved by a secant iteration per
  /// step). Returns sigma_yy / sigma_xx at the end and the plastic
  /// dilatancy ratio of the last steps.
  std::pair<double, double>
  biaxial(const Material::Material<2> &m, const double p0)
  {
    std::vector<SymmetricTensor<2, 2>> stress(1);
    std::vector<Tensor<2, 2>>          dL(1);
    std::vector<double>                state(m.n_state()), ratio(1);
    m.initialize(1, state.data());
    stress[0][0][0] = stress[0][1][1] = -p0;
    std::vector<double> szz           = {-p0};
    m.set_initial_stress(1, stress.data(), szz.data(), state.data());
    const unsigned int x = 1, y = 2, z = 4; // plastic strain columns
    double             ev0 = 0, g0 = 0, ev1 = 0, g1 = 0;
    for (unsigned int k = 0; k < 4000; ++k)
      {
        const SymmetricTensor<2, 2> s_old  = stress[0];
        const std::vector<double>   st_old = state;
        const double                dy     = -2e-5;
        double                      dx = 0, r0 = 0, dx0 = 0;
        for (unsigned int it = 0; it < 60; ++it)
          {
            stress[0]   = s_old;
            state       = st_old;
            dL[0]       = 0;
            dL[0][0][0] = dx;
            dL[0][1][1] = dy;
            m.update(1, dL.data(), stress.data(), state.data(), ratio.data());
            const double r = stress[0][0][0] + p0;
            if (std::abs(r) < 1e-9 * p0)
              break;
            const double slope =
              it == 0 ? m.p_wave_modulus() : (r - r0) / (dx - dx0);
            dx0 = dx;
            r0  = r;
            dx -= r / slope;
          }
        if (k == 3000)
          {
            ev0 = state[x] + state[y] + state[z];
            g0  = state[x] - state[y];
          }
      }
    ev1 = state[x] + state[y] + state[z];
    g1  = state[x] - state[y];
    return {stress[0][1][1] / stress[0][0][0], (ev1 - ev0) / (g1 - g0)};
  }

  void
  check_biaxial(std::ostream &out)
  {
    for (const double phi : {20., 35.})
      for (const double psi : {0., 0.5 * phi, phi})
        {
          Material::MohrCoulomb<2> m;
          set_soil_constants(m, phi, psi, 0);
          const auto [ratio, dilatancy] = biaxial(m, 1e5);
          const double sp               = std::sin(phi * degree);
          const double expected         = (1 + sp) / (1 - sp);
          out << "MC phi " << phi << " psi " << psi
              << ": sigma_1/sigma_3 / expected - 1 = " << std::setprecision(1)
              << filter(ratio / expected - 1, 1e-9)
              << ", dilatancy / sin psi - 1 = "
              << filter(psi > 0 ? dilatancy / std::sin(psi * degree) - 1 :
                                  dilatancy,
                        1e-9)
              << std::setprecision(6) << std::endl;
          PSMPM_CHECK(out, std::abs(ratio / expected - 1) < 1e-9);
          PSMPM_CHECK(out, std::abs(dilatancy - std::sin(psi * degree)) < 1e-9);
          if (psi == phi)
            {
              Material::DruckerPrager<2> d;
              set_soil_constants(d, phi, psi, 0);
              const auto [dp_ratio, dp_dilatancy] = biaxial(d, 1e5);
              (void)dp_dilatancy;
              out << "DP plane strain phi " << phi
                  << ": sigma_1/sigma_3 / MC's - 1 = " << std::setprecision(1)
                  << filter(dp_ratio / expected - 1, 1e-4)
                  << std::setprecision(6) << std::endl;
              PSMPM_CHECK(out, std::abs(dp_ratio / expected - 1) < 1e-4);
            }
        }
  }

  std::string
  message(const std::exception &e)
  {
    if (const auto *d = dynamic_cast<const ExceptionBase *>(&e))
      {
        std::ostringstream s;
        d->print_info(s);
        return s.str();
      }
    return e.what();
  }

  void
  check_bad_input(std::ostream &out)
  {
    for (const auto &[entry, value, mention] :
         {std::tuple<const char *, const char *, const char *>{
            "Friction angle",
            "90",
            "Material/Friction angle = 90"},
          {"Friction angle", "-1", "Material/Friction angle = -1"},
          {"Dilatancy angle", "40", "Material/Dilatancy angle = 40"},
          {"Cohesion", "-5", "Material/Cohesion = -5"},
          {"Tension cutoff", "abc", "Material/Tension cutoff = 'abc'"},
          {"Softening strain", "-0.1", "Material/Softening strain = -0.1"}})
      for (const char *model : {"mohr-coulomb", "drucker-prager"})
        {
          ParameterHandler prm;
          Material::Material<2>::declare_parameters(prm);
          prm.enter_subsection("Material");
          prm.set("Model", model);
          prm.set(entry, value);
          prm.leave_subsection();
          try
            {
              Material::Material<2>::create(prm);
              out << "FAIL " << model << " " << entry << " = " << value
                  << " accepted" << std::endl;
            }
          catch (const std::exception &e)
            {
              const bool named = message(e).find(mention) != std::string::npos;
              out << (named ? "OK   " : "FAIL ") << model << " " << entry
                  << " = " << value << " refused" << std::endl;
            }
        }
  }
} // namespace

int
main()
{
  return run_test([] {
    std::ofstream out("output");
    check_consistency(out);
    check_regions(out);
    check_objectivity(out);
    check_biaxial(out);
    check_bad_input(out);
  });
}
