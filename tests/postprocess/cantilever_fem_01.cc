// The "cantilever fem" reference: a 4 m x 0.5 m plane-strain beam
// (E = 1e9, nu = 0.3, rho = 1000) clamped at x = 0 and released from rest
// under gravity.
//
// * Static tip deflection against beam theory with the plane-strain
//   modulus E' = E / (1 - nu^2), load q = rho g H per unit width:
//   Euler-Bernoulli q L^4 / (8 E' I) is stiffer than the 2D solid (no
//   shear deformation, FE larger by 1.2 %: within 2 %), Timoshenko
//   (shear factor 5/6) is softer here (FE smaller by 0.5 %: within 1 %).
// * First period against Euler-Bernoulli 2 pi / (1.8751^2 sqrt(E' I /
//   (rho A L^4))): shear and rotary inertia make the solid slower, by
//   1.0 % (within 2 %).
// * Convergence: tip deflection and period on 2, 4, 8, 16 elements across
//   the height; the changes shrink by more than 2 per halving, and the
//   automatic choice is within 1e-4 of the finest mesh.
// * Dynamics: at rest at t = 0 with u = 0; the clamped edge stays fixed;
//   the tip oscillates about the static deflection (mean within 1e-3)
//   with the first period (within 1e-3) and overshoots to about twice it.
// * Oscillation::measure recovers the mean and period of a noisy cosine.
// * The scene must clamp the mesh's left boundary where the beam starts.
#include <deal.II/base/numbers.h>
#include <deal.II/base/parameter_handler.h>

#include <psmpm/material/material.h>
#include <psmpm/postprocess/oscillation.h>
#include <psmpm/postprocess/reference.h>
#include <psmpm/postprocess/references/cantilever_fem.h>

#include "../tests.h"

using namespace psmpm;
using Postprocess::CantileverFEM;

const double L = 4, H = 0.5, Y0 = 0.25, E = 1e9, nu = 0.3, rho = 1000, g = 9.81;

std::unique_ptr<Postprocess::Reference<2>>
make_reference(const std::vector<double>                     &region,
               const std::array<std::vector<std::string>, 2> &fixed)
{
  ParameterHandler prm;
  Material::Material<2>::declare_parameters(prm);
  Postprocess::Reference<2>::declare_parameters(prm);
  prm.enter_subsection("Reference solution");
  prm.set("Type", "cantilever fem");
  prm.leave_subsection();
  prm.enter_subsection("Material");
  prm.set("Model", "hypoelastic");
  prm.set("Density", std::to_string(rho));
  prm.set("Young's modulus", std::to_string(E));
  prm.set("Poisson's ratio", std::to_string(nu));
  prm.leave_subsection();
  const auto material = Material::Material<2>::create(prm);
  return Postprocess::Reference<2>::create(prm,
                                           *material,
                                           4.5,
                                           1,
                                           Tensor<1, 2>({0, -g}),
                                           region,
                                           fixed);
}

int
main()
{
  std::ofstream  out("output");
  const Point<2> tip(L, Y0 + H / 2);

  // Through the registry, as a scene creates it.
  auto reference =
    make_reference({0, Y0, L, Y0 + H}, {{{"left", "bottom"}, {"left"}}});
  auto &beam = dynamic_cast<CantileverFEM &>(*reference);
  PSMPM_CHECK(out, beam.axis() == 1);
  PSMPM_CHECK(out, !beam.one_dimensional());
  const double w = -beam.static_displacement(tip)[1];
  const double T = beam.first_period();
  out << "automatic mesh: " << beam.elements_y()
      << " elements across the height" << std::endl;

  // Beam theory.
  const double Ep = E / (1 - nu * nu), I = H * H * H / 12, q = rho * g * H;
  const double G            = E / (2 * (1 + nu));
  const double w_eb         = q * std::pow(L, 4) / (8 * Ep * I);
  const double w_timoshenko = w_eb + q * L * L / (2 * 5. / 6 * G * H);
  const double T_eb         = 2 * numbers::PI /
                      (1.875104069 * 1.875104069 *
                       std::sqrt(Ep * I / (rho * H * std::pow(L, 4))));
  out << std::setprecision(3)
      << "tip deflection / Euler-Bernoulli = " << w / w_eb
      << ", / Timoshenko = " << w / w_timoshenko << std::endl;
  out << "first period / Euler-Bernoulli = " << T / T_eb << std::endl;
  PSMPM_CHECK(out, w > w_eb && w < 1.02 * w_eb);
  PSMPM_CHECK(out, w < w_timoshenko && w > 0.99 * w_timoshenko);
  PSMPM_CHECK(out, T > T_eb && T < 1.02 * T_eb);

  // Convergence under refinement.
  {
    CantileverFEM::Parameters p;
    p.lower          = Point<2>(0, Y0);
    p.upper          = Point<2>(L, Y0 + H);
    p.youngs_modulus = E;
    p.poisson_ratio  = nu;
    p.density        = rho;
    p.gravity[1]     = -g;
    std::vector<double> tips, periods;
    for (const unsigned int n : {2, 4, 8, 16})
      {
        p.elements_y = n;
        const CantileverFEM c(p);
        tips.push_back(-c.static_displacement(tip)[1]);
        periods.push_back(c.first_period());
        if (n == beam.elements_y())
          PSMPM_CHECK(out, tips.back() == w && periods.back() == T);
      }
    bool shrinking = true;
    for (unsigned int i = 2; i < tips.size(); ++i)
      {
        const double dw0 = std::abs(tips[i - 1] - tips[i - 2]),
                     dw1 = std::abs(tips[i] - tips[i - 1]),
                     dT0 = std::abs(periods[i - 1] - periods[i - 2]),
                     dT1 = std::abs(periods[i] - periods[i - 1]);
        out << "changes shrink by " << dw0 / dw1 << " (tip), " << dT0 / dT1
            << " (period)" << std::endl;
        shrinking = shrinking && dw0 > 2 * dw1 && dT0 > 2 * dT1;
      }
    PSMPM_CHECK(out, shrinking);
    PSMPM_CHECK(out, std::abs(w - tips.back()) < 1e-4 * w);
    PSMPM_CHECK(out, std::abs(T - periods.back()) < 1e-4 * T);
  }

  // Dynamics over 2.25 periods, sampled as a run would.
  {
    const auto s0 = beam.evaluate(tip, 0);
    PSMPM_CHECK(out,
                s0.displacement.norm() < 1e-15 && s0.velocity.norm() < 1e-15);
    std::vector<double> t, x;
    double              clamp = 0, lowest = 0;
    const double        dt = T / 1000;
    for (unsigned int i = 0; i <= 2250; ++i)
      {
        beam.advance_to(i * dt);
        t.push_back(i * dt);
        x.push_back(beam.evaluate(tip, i * dt).displacement[1]);
        lowest = std::min(lowest, x.back());
        for (const double y : {Y0, Y0 + H / 3, Y0 + H})
          clamp =
            std::max(clamp,
                     beam.evaluate(Point<2>(0, y), i * dt).displacement.norm());
      }
    const auto r = Postprocess::Oscillation::measure(t, x);
    out << "tip: mean / static - 1 = " << std::setprecision(1)
        << -r.mean / w - 1
        << ", period / first period - 1 = " << r.period / T - 1
        << ", lowest / static = " << std::setprecision(3) << -lowest / w
        << std::endl;
    PSMPM_CHECK(out, r.valid && r.crossings == 4);
    PSMPM_CHECK(out, std::abs(-r.mean / w - 1) < 1e-3);
    PSMPM_CHECK(out, std::abs(r.period / T - 1) < 1e-3);
    PSMPM_CHECK(out, -lowest > 1.9 * w && -lowest < 2.1 * w);
    PSMPM_CHECK(out, clamp < 1e-15);
  }

  // The oscillation measure: x = -1 + 0.5 cos(2 pi t / 0.7) with noise of
  // 2 % of the amplitude, sampled unevenly over 3.3 periods.
  {
    std::vector<double> t, x;
    for (double s = 0; s < 3.3 * 0.7; s += 1e-3 * (1 + 0.5 * std::sin(7 * s)))
      {
        t.push_back(s);
        x.push_back(-1 + 0.5 * std::cos(2 * numbers::PI * s / 0.7) +
                    0.01 * std::sin(2 * numbers::PI * s / 0.013));
      }
    const auto r = Postprocess::Oscillation::measure(t, x);
    PSMPM_CHECK(out, r.valid && r.crossings == 7);
    PSMPM_CHECK(out, std::abs(r.mean + 1) < 1e-3);
    PSMPM_CHECK(out, std::abs(r.period - 0.7) < 1e-3);
    // Less than a period: nothing to measure.
    t.resize(t.size() / 4);
    x.resize(t.size());
    PSMPM_CHECK(out, !Postprocess::Oscillation::measure(t, x).valid);
  }

  // Scenes that do not fit.
  for (unsigned int c = 0; c < 2; ++c)
    try
      {
        if (c == 0)
          make_reference({0.5, Y0, L, Y0 + H}, {{{"left"}, {"left"}}});
        else
          make_reference({0, Y0, L, Y0 + H}, {{{"left"}, {"bottom"}}});
        out << "FAIL: no exception" << std::endl;
      }
    catch (const std::exception &e)
      {
        const std::string m = e.what();
        PSMPM_CHECK(out,
                    m.find(c == 0 ? "must start at the mesh's left boundary" :
                                    "Fixed y must both name 'left'") !=
                      std::string::npos);
      }
}
