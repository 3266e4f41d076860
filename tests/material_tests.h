// ---------------------------------------------------------------------
// psmpm: helpers for the tests of the soil models (Mohr-Coulomb,
// Drucker-Prager) in plane strain.
// ---------------------------------------------------------------------
#ifndef psmpm_tests_material_tests_h
#define psmpm_tests_material_tests_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include "tests.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <functional>
#include <vector>

/// A soil of E = 20 MPa, nu = 0.3, rho = 2000 kg/m^3 with friction angle
/// @p phi, dilatancy angle @p psi (degrees), cohesion @p c and tension
/// cutoff @p t (Pa), without softening (the residual values are the
/// initial ones).
template <typename Model>
void
set_soil_constants(Model       &m,
                   const double phi,
                   const double psi,
                   const double c,
                   const double t = HUGE_VAL)
{
  m.youngs_modulus          = 2e7;
  m.poisson_ratio           = 0.3;
  m.density                 = 2000;
  m.friction_angle          = phi;
  m.dilatancy_angle         = psi;
  m.cohesion                = c;
  m.tension_cutoff          = t;
  m.residual_cohesion       = c;
  m.residual_friction_angle = phi;
  m.softening_strain        = 0;
}

/// The principal stresses, largest first, of the plane stress (@p xx,
/// @p yy, @p xy) with the out-of-plane stress @p zz.
inline std::array<double, 3>
sorted_principal(const double xx,
                 const double yy,
                 const double xy,
                 const double zz)
{
  const double          c = 0.5 * (xx + yy), h = 0.5 * (xx - yy);
  const double          r = std::sqrt(h * h + xy * xy);
  std::array<double, 3> p = {{c + r, c - r, zz}};
  std::sort(p.begin(), p.end(), std::greater<double>());
  return p;
}

/// A soil and the drift of its random strain paths (added to the normal
/// strain increments): compression, dilation or none.
struct SoilCase
{
  const char *label;
  double      phi, psi, c, t, drift;
};

/// Mohr-Coulomb soils whose random paths reach the main plane, the edges
/// (Tresca with c = 1e-6 Pa), the apex (c = 0) and the tension cutoff.
inline std::vector<SoilCase>
mohr_coulomb_paths()
{
  const double inf = HUGE_VAL;
  return {SoilCase{"MC phi 30 psi 0 c 1 kPa", 30, 0, 1e3, inf, 0},
          SoilCase{"MC phi 35 psi 35 c 0", 35, 35, 0, inf, 1e-4},
          SoilCase{"MC phi 20 psi 5 c 5 kPa t 2 kPa", 20, 5, 5e3, 2e3, 2e-4},
          SoilCase{"MC Tresca c 1e-6 Pa", 0, 0, 1e-6, inf, -2e-4}};
}

/// Drucker-Prager soils whose random paths reach the cone, its apex
/// (c = 0) and von Mises' cylinder (phi = 0, c = 1e-6 Pa).
inline std::vector<SoilCase>
drucker_prager_paths()
{
  const double inf = HUGE_VAL;
  return {SoilCase{"DP phi 30 psi 0 c 1 kPa", 30, 0, 1e3, inf, 0},
          SoilCase{"DP phi 35 psi 35 c 0", 35, 35, 0, inf, 1e-4},
          SoilCase{"DP von Mises c 1e-6 Pa", 0, 0, 1e-6, inf, -2e-4}};
}

/// The soil of @p k, its constants those of set_soil_constants().
template <typename Model>
Model
make_soil(const SoilCase &k)
{
  Model m;
  set_soil_constants(m, k.phi, k.psi, k.c, k.t);
  return m;
}

/// The stresses, states and volume ratios of @p n particles of a model
/// updated as one batch (update(n, ...)) and, from the same stresses and
/// states, one particle at a time (update(1, ...): the one-particle loop),
/// for the tests that the two agree bit for bit.
template <typename Model>
struct BatchAndSingleUpdates
{
  BatchAndSingleUpdates(const Model &m, const unsigned int n)
    : model(m)
    , n(n)
    , ns(m.n_state())
    , stress(n)
    , single_stress(n)
    , state(n * ns)
    , single_state(n * ns)
    , ratio(n)
    , single_ratio(n)
  {
    model.initialize(n, state.data());
  }

  /// Both updates with the velocity gradient increments @p dL; before
  /// keeps the states they start from.
  void
  update(const std::vector<dealii::Tensor<2, 2>> &dL)
  {
    single_stress = stress;
    single_state  = state;
    before        = state;
    model.update(n, dL.data(), stress.data(), state.data(), ratio.data());
    for (unsigned int p = 0; p < n; ++p)
      model.update(1,
                   &dL[p],
                   &single_stress[p],
                   &single_state[p * ns],
                   &single_ratio[p]);
  }

  /// Whether particle @p p's stress, state columns or volume ratio differ
  /// in any bit between the two updates.
  bool
  differs(const unsigned int p) const
  {
    return std::memcmp(&stress[p], &single_stress[p], sizeof(stress[p])) != 0 ||
           std::memcmp(&state[p * ns],
                       &single_state[p * ns],
                       ns * sizeof(double)) != 0 ||
           std::memcmp(&ratio[p], &single_ratio[p], sizeof(double)) != 0;
  }

  const Model                               &model;
  const unsigned int                         n, ns;
  std::vector<dealii::SymmetricTensor<2, 2>> stress, single_stress;
  std::vector<double> state, single_state, ratio, single_ratio, before;
};

#endif
