// The plane-strain returns of Mohr-Coulomb and Drucker-Prager done in the
// stress' own x-y frame (the batched update() without softening: no
// principal stresses for Drucker-Prager, closed-form plastic strain and
// equivalent plastic strain), checked against an independent computation
// from each update's trial stress (the Hughes-Winget rotation plus the
// elastic increment, recomputed here):
// (a) the principal stresses after the update are those of the model's
//     principal-space return_stress() of the trial stress, to 1e-10;
// (b) the plastic strain increment is C^-1 (trial - sigma), to 1e-10 of
//     |trial| / E;
// (c) the equivalent plastic strain increment is sqrt(2/3 |dev de_p|^2)
//     and the plastic work increment J sigma : de_p / rho0, to 1e-9;
// over random paths that reach the main plane, the edges (Tresca with c =
// 1e-6 Pa), the apex (c = 0, Drucker-Prager's apex) and the cutoff.
#include <psmpm/material/drucker_prager.h>
#include <psmpm/material/mohr_coulomb.h>

#include "../material_tests.h"

#include <random>

using namespace psmpm;

namespace
{
  /// Random paths of @p n particles; every update is checked against the
  /// trial stress recomputed here. @p principal_return(strength, sigma)
  /// is the model's return in principal space.
  template <typename Model, typename PrincipalReturn>
  void
  check(std::ostream          &out,
        const std::string     &label,
        const Model           &m,
        const double           drift,
        const PrincipalReturn &principal_return)
  {
    const unsigned int n = 64, n_steps = 300, ns = m.n_state();
    const double       E = m.youngs_modulus, nu = m.poisson_ratio;
    const double       lambda = m.lame_lambda(), two_g = 2 * m.shear_modulus();
    std::vector<SymmetricTensor<2, 2>> stress(n);
    std::vector<Tensor<2, 2>>          dL(n);
    std::vector<double> state(n * ns), old_state(n * ns), ratio(n);
    m.initialize(n, state.data());
    std::mt19937                           rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    double       stress_error = 0, strain_error = 0, other_error = 0;
    unsigned int plastic = 0, hydrostatic = 0;
    for (unsigned int step = 0; step < n_steps; ++step)
      {
        for (unsigned int p = 0; p < n; ++p)
          for (unsigned int i = 0; i < 2; ++i)
            for (unsigned int j = 0; j < 2; ++j)
              dL[p][i][j] = 5e-4 * u(rng) + (i == j ? drift : 0);
        const std::vector<SymmetricTensor<2, 2>> old_stress = stress;
        old_state                                           = state;
        m.update(n, dL.data(), stress.data(), state.data(), ratio.data());
        for (unsigned int p = 0; p < n; ++p)
          {
            const double *b0 = &old_state[p * ns], *b1 = &state[p * ns];
            // The trial stress.
            const double w  = 0.5 * (dL[p][0][1] - dL[p][1][0]);
            const double q  = 1 / (1 + 0.25 * w * w);
            const double cr = (1 - 0.25 * w * w) * q, sn = w * q;
            const double sxx = old_stress[p][0][0], syy = old_stress[p][1][1],
                         sxy = old_stress[p][0][1];
            const double exx = dL[p][0][0], eyy = dL[p][1][1],
                         exy               = 0.5 * (dL[p][0][1] + dL[p][1][0]);
            const double                tr = exx + eyy;
            const std::array<double, 4> t  = {
               {cr * cr * sxx + 2 * cr * sn * sxy + sn * sn * syy + lambda * tr +
                  two_g * exx,
                sn * sn * sxx - 2 * cr * sn * sxy + cr * cr * syy + lambda * tr +
                  two_g * eyy,
                -cr * sn * sxx + (cr * cr - sn * sn) * sxy + cr * sn * syy +
                  two_g * exy,
                b0[0] + lambda * tr}};
            const std::array<double, 4> s = {
              {stress[p][0][0], stress[p][1][1], stress[p][0][1], b1[0]}};
            const double scale = std::abs(t[0]) + std::abs(t[1]) +
                                 std::abs(t[2]) + std::abs(t[3]) + m.cohesion;
            // (a) against the principal-space return.
            std::array<double, 3> r = sorted_principal(t[0], t[1], t[2], t[3]);
            const bool            yielded = principal_return(r);
            std::sort(r.begin(), r.end(), std::greater<double>());
            const std::array<double, 3> got =
              sorted_principal(s[0], s[1], s[2], s[3]);
            for (unsigned int d = 0; d < 3; ++d)
              stress_error =
                std::max(stress_error, std::abs(got[d] - r[d]) / scale);
            if (!yielded)
              continue;
            ++plastic;
            hydrostatic += got[0] - got[2] <= 1e-9 * scale ? 1 : 0;
            // (b) de_p = C^-1 (trial - sigma), tensor shear.
            const std::array<double, 4> d = {
              {t[0] - s[0], t[1] - s[1], t[2] - s[2], t[3] - s[3]}};
            const double                dtr      = d[0] + d[1] + d[3];
            const std::array<double, 4> expected = {
              {((1 + nu) * d[0] - nu * dtr) / E,
               ((1 + nu) * d[1] - nu * dtr) / E,
               (1 + nu) * d[2] / E,
               ((1 + nu) * d[3] - nu * dtr) / E}};
            std::array<double, 4> ep;
            for (unsigned int c = 0; c < 4; ++c)
              {
                ep[c] = b1[1 + c] - b0[1 + c];
                strain_error =
                  std::max(strain_error,
                           std::abs(ep[c] - expected[c]) / (scale / E));
              }
            // (c) the equivalent plastic strain and the work.
            const double m3         = (ep[0] + ep[1] + ep[3]) / 3;
            const double equivalent = std::sqrt(
              2. / 3 *
              ((ep[0] - m3) * (ep[0] - m3) + (ep[1] - m3) * (ep[1] - m3) +
               (ep[3] - m3) * (ep[3] - m3) + 2 * ep[2] * ep[2]));
            const double work =
              b1[7] *
              (s[0] * ep[0] + s[1] * ep[1] + 2 * s[2] * ep[2] + s[3] * ep[3]) /
              m.density;
            const double strain_scale = std::abs(ep[0]) + std::abs(ep[1]) +
                                        std::abs(ep[2]) + std::abs(ep[3]) +
                                        1e-9 * scale / E;
            other_error =
              std::max({other_error,
                        std::abs(b1[5] - b0[5] - equivalent) / strain_scale,
                        std::abs(b1[6] - b0[6] - work) /
                          (scale * strain_scale / m.density)});
          }
      }
    out << label << ": plastic updates " << (plastic > 1000 ? "> 1000" : "few")
        << ", hydrostatic after the return "
        << (hydrostatic > 0 ? "some" : "none") << std::endl;
    PSMPM_CHECK(out, plastic > 1000);
    out << label << ": stresses as the principal return: "
        << (stress_error <= 1e-10 ? "yes" :
                                    "no " + std::to_string(stress_error))
        << "; plastic strain C^-1 (trial - sigma): "
        << (strain_error <= 1e-10 ? "yes" :
                                    "no " + std::to_string(strain_error))
        << "; equivalent and work: "
        << (other_error <= 1e-9 ? "yes" : "no " + std::to_string(other_error))
        << std::endl;
    PSMPM_CHECK(out, stress_error <= 1e-10);
    PSMPM_CHECK(out, strain_error <= 1e-10);
    PSMPM_CHECK(out, other_error <= 1e-9);
  }
} // namespace

int
main()
{
  return run_test([] {
    std::ofstream out("output");
    for (const SoilCase &k : mohr_coulomb_paths())
      {
        const auto m = make_soil<Material::MohrCoulomb<2>>(k);
        const auto s = m.strength(0);
        check(out, k.label, m, k.drift, [&](std::array<double, 3> &sigma) {
          return m.return_stress(s, sigma);
        });
      }
    using Fit = Material::DruckerPrager<2>::Fit;
    for (const SoilCase &k : drucker_prager_paths())
      {
        auto m = make_soil<Material::DruckerPrager<2>>(k);
        m.fit  = Fit::outer;
        auto s = m.strength(0);
        m.prepare(s);
        check(out, k.label, m, k.drift, [&](std::array<double, 3> &sigma) {
          return m.return_stress(s, sigma);
        });
      }
  });
}
