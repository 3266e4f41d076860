// Hypoelastic<dim>. 2D: the update and the energy density are bit for bit
// those of the old LinearElastic class (copied below as the reference)
// over random increments, for a batch of particles. 1D with nu = 0: bit
// for bit the bar sigma += E de - de sigma; with nu > 0 the uniaxial-strain
// moduli. Registry and Material/... parameters: both models exist for
// dims 1 and 2, an unknown model and bad constants are reported by name.
#include <deal.II/base/parameter_handler.h>

#include <psmpm/material/hypoelastic.h>

#include "../tests.h"

#include <random>

using namespace psmpm;

namespace
{
  // The linear elastic update written out independently (the model's
  // first implementation), as a reference for the hypoelastic class.
  class OldLinearElastic
  {
  public:
    double
    bulk_modulus() const
    {
      return youngs_modulus / (3 * (1 - 2 * poisson_ratio));
    }
    double
    shear_modulus() const
    {
      return youngs_modulus / (2 * (1 + poisson_ratio));
    }

    double
    update(const Tensor<2, 2>    &dL,
           SymmetricTensor<2, 2> &stress,
           double                &stress_zz,
           SymmetricTensor<2, 2> &strain) const
    {
      const SymmetricTensor<2, 2> de = symmetrize(dL);
      const double dw     = 0.5 * (dL[0][1] - dL[1][0]); // spin increment w_xy
      const double tr     = trace(de);
      const double lambda = bulk_modulus() - 2. / 3 * shear_modulus();
      const double two_g  = 2 * shear_modulus();

      SymmetricTensor<2, 2> ds;
      ds[0][0] = lambda * tr + two_g * de[0][0] - tr * stress[0][0] +
                 2 * dw * stress[0][1];
      ds[1][1] = lambda * tr + two_g * de[1][1] - tr * stress[1][1] -
                 2 * dw * stress[0][1];
      ds[0][1] = two_g * de[0][1] - tr * stress[0][1] +
                 dw * (stress[1][1] - stress[0][0]);
      stress_zz += lambda * tr - tr * stress_zz;
      stress += ds;
      strain += de;
      return tr;
    }

    double
    energy_density(const SymmetricTensor<2, 2> &s, const double szz) const
    {
      const double nu = poisson_ratio;
      return (s[0][0] * s[0][0] + s[1][1] * s[1][1] + szz * szz -
              2 * nu * (s[0][0] * s[1][1] + s[1][1] * szz + szz * s[0][0]) +
              2 * (1 + nu) * s[0][1] * s[0][1]) /
             (2 * youngs_modulus);
    }

    double density        = 1;
    double youngs_modulus = 100;
    double poisson_ratio  = 0;
  };

  /// A model registered for 2D only, to see that a 1D run rejects it.
  const Registration<Material::MaterialRegistry<2>>
    two_d_only({"two-d-only",
                "test model",
                [] { return std::make_unique<Material::Hypoelastic<2>>(); },
                {}});

  std::string
  message(const std::exception &e)
  {
    if (const auto *d = dynamic_cast<const ExceptionBase *>(&e))
      {
        std::ostringstream s;
        d->print_info(s);
        std::string m = s.str();
        while (!m.empty() && (m.back() == '\n' || m.back() == ' '))
          m.pop_back();
        return m.substr(m.find_first_not_of(' '));
      }
    return e.what();
  }

  /// Run @p f, expect an exception, print its message.
  template <typename F>
  void
  expect_error(std::ostream      &out,
               const std::string &what,
               const std::string &must_mention,
               F                &&f)
  {
    try
      {
        f();
        out << "FAIL " << what << ": no exception" << std::endl;
      }
    catch (const std::exception &e)
      {
        const std::string m = message(e);
        out << (m.find(must_mention) != std::string::npos ? "OK   " : "FAIL ")
            << what << ": " << m << std::endl;
      }
  }

  void
  compare_2d_with_old(std::ostream &out)
  {
    const unsigned int n = 5, n_steps = 2000;
    for (const double nu : {0., 0.3, -0.2, 0.49})
      {
        Material::Hypoelastic<2> model;
        model.youngs_modulus = 1.7e4;
        model.poisson_ratio  = nu;
        OldLinearElastic old;
        old.youngs_modulus = model.youngs_modulus;
        old.poisson_ratio  = nu;

        std::vector<SymmetricTensor<2, 2>> stress(n), old_stress(n),
          old_strain(n);
        std::vector<Tensor<2, 2>> dL(n);
        std::vector<double> state(n * model.n_state()), ratio(n), energy(n),
          volume(n, 1.), old_stress_zz(n, 0.), old_volume(n, 1.);
        model.initialize(n, state.data());

        std::mt19937                           rng(42);
        std::uniform_real_distribution<double> u(-1e-3, 1e-3);
        unsigned int                           mismatches = 0;
        double                                 max_stress = 0, max_energy = 0;
        for (unsigned int step = 0; step < n_steps; ++step)
          {
            for (unsigned int p = 0; p < n; ++p)
              for (unsigned int i = 0; i < 2; ++i)
                for (unsigned int j = 0; j < 2; ++j)
                  // A drift on particle p so that the stress grows.
                  dL[p][i][j] = u(rng) + (i == 0 && j == p % 2 ? 2e-4 : 0.);
            model.update(n,
                         dL.data(),
                         stress.data(),
                         state.data(),
                         ratio.data());
            model.energy_density(n, stress.data(), state.data(), energy.data());
            for (unsigned int p = 0; p < n; ++p)
              {
                const double dvol = old.update(dL[p],
                                               old_stress[p],
                                               old_stress_zz[p],
                                               old_strain[p]);
                old_volume[p] *= 1 + dvol;
                volume[p] *= ratio[p];
                const double old_energy =
                  old.energy_density(old_stress[p], old_stress_zz[p]);
                const double *block = &state[p * 4];
                const bool    same =
                  stress[p] == old_stress[p] && block[0] == old_stress_zz[p] &&
                  block[1] == old_strain[p][0][0] &&
                  block[2] == old_strain[p][1][1] &&
                  block[3] == old_strain[p][0][1] &&
                  volume[p] == old_volume[p] && energy[p] == old_energy;
                mismatches += same ? 0 : 1;
                max_stress = std::max(max_stress, stress[p].norm());
                max_energy = std::max(max_energy, energy[p]);
              }
          }
        out << "2D nu = " << nu << ": max |stress|/E = " << std::setprecision(2)
            << max_stress / model.youngs_modulus
            << ", max energy/E = " << max_energy / model.youngs_modulus
            << std::setprecision(6) << std::endl;
        PSMPM_CHECK(out, max_stress > 1e-2 * model.youngs_modulus);
        PSMPM_CHECK(out, mismatches == 0);
      }
  }

  void
  check_1d(std::ostream &out)
  {
    const unsigned int n = 3, n_steps = 2000;
    {
      Material::Hypoelastic<1> model;
      model.youngs_modulus                 = 3.3e3;
      model.poisson_ratio                  = 0;
      const double                       E = model.youngs_modulus;
      std::vector<SymmetricTensor<2, 1>> stress(n);
      std::vector<Tensor<2, 1>>          dL(n);
      std::vector<double> state(n * model.n_state()), ratio(n), energy(n),
        reference(n, 0.);
      model.initialize(n, state.data());
      std::mt19937                           rng(7);
      std::uniform_real_distribution<double> u(-2e-3, 3e-3);
      unsigned int                           mismatches = 0;
      for (unsigned int step = 0; step < n_steps; ++step)
        {
          for (unsigned int p = 0; p < n; ++p)
            dL[p][0][0] = u(rng);
          model.update(n, dL.data(), stress.data(), state.data(), ratio.data());
          model.energy_density(n, stress.data(), state.data(), energy.data());
          for (unsigned int p = 0; p < n; ++p)
            {
              const double de = dL[p][0][0];
              reference[p] += E * de - de * reference[p];
              const double s = reference[p];
              mismatches +=
                (stress[p][0][0] == s && state[2 * p] == 0 &&
                 ratio[p] == 1 + de &&
                 std::abs(energy[p] - s * s / (2 * E)) <= 1e-15 * s * s / E) ?
                  0 :
                  1;
            }
        }
      out << "1D nu = 0: final stress/E = " << std::setprecision(4)
          << stress[0][0][0] / E << std::setprecision(6) << std::endl;
      PSMPM_CHECK(out, std::abs(stress[0][0][0]) > 1e-2 * E);
      PSMPM_CHECK(out, mismatches == 0);
    }
    {
      // Uniaxial strain with nu > 0: sigma = (lambda + 2G) eps and
      // sigma_lateral = lambda eps to first order, energy (lambda + 2G)
      // eps^2 / 2.
      Material::Hypoelastic<1> model;
      model.youngs_modulus = 100;
      model.poisson_ratio  = 0.3;
      const double eps     = 1e-5;
      Tensor<2, 1> dL;
      dL[0][0] = eps;
      SymmetricTensor<2, 1> stress;
      double                state[2], ratio, energy;
      model.initialize(1, state);
      model.update(1, &dL, &stress, state, &ratio);
      model.energy_density(1, &stress, state, &energy);
      const double M = model.p_wave_modulus(), lambda = model.lame_lambda();
      out << "1D nu = 0.3: sigma/(M eps) = " << stress[0][0] / (M * eps)
          << ", lateral/(lambda eps) = " << state[0] / (lambda * eps)
          << ", energy/(M eps^2/2) = " << energy / (M * eps * eps / 2)
          << std::endl;
      PSMPM_CHECK(out, std::abs(stress[0][0] / (M * eps) - 1) < 1e-12);
      PSMPM_CHECK(out, std::abs(state[0] / (lambda * eps) - 1) < 1e-12);
      PSMPM_CHECK(out, std::abs(energy / (M * eps * eps / 2) - 1) < 1e-12);
      PSMPM_CHECK(out, state[1] == eps && ratio == 1 + eps);
      PSMPM_CHECK(out,
                  (model.state_names() ==
                   std::vector<std::string>{"stress_lateral", "strain_xx"}));
    }
  }

  void
  check_parameters(std::ostream &out)
  {
    for (const std::string name : {"hypoelastic", "neo-hookean"})
      {
        out << name << ": ";
        PSMPM_CHECK(out,
                    Material::MaterialRegistry<1>::instance().has(name) &&
                      Material::MaterialRegistry<2>::instance().has(name));
      }
    out << "2D models: " << Material::MaterialRegistry<2>::instance().names()
        << std::endl;
    out << "1D models: " << Material::MaterialRegistry<1>::instance().names()
        << std::endl;

    ParameterHandler prm;
    Material::Material<2>::declare_parameters(prm);
    // Declaring again (e.g. for the other dimension) must be harmless.
    Material::Material<1>::declare_parameters(prm);
    prm.enter_subsection("Material");
    out << "default Material/Model = " << prm.get("Model") << std::endl;
    prm.leave_subsection();

    {
      const auto m2 = Material::Material<2>::create(prm);
      const auto m1 = Material::Material<1>::create(prm);
      out << "created " << m2->name() << " (2D, state "
          << Utilities::to_string(m2->n_state()) << "), " << m1->name()
          << " (1D, state " << m1->n_state() << "), E = " << m2->youngs_modulus
          << ", nu = " << m2->poisson_ratio << ", rho = " << m2->density
          << ", wave speed = " << m2->wave_speed({}, nullptr) << std::endl;
      const std::vector<std::string> expected = {"stress_zz",
                                                 "strain_xx",
                                                 "strain_yy",
                                                 "strain_xy"};
      PSMPM_CHECK(out, m2->state_names() == expected);
      PSMPM_CHECK(out, m2->wave_speed({}, nullptr) == 10);
    }

    prm.enter_subsection("Material");
    prm.set("Model", "neo-hookean");
    prm.set("Young's modulus", "250");
    prm.set("Poisson's ratio", "0.25");
    prm.set("Density", "2");
    prm.leave_subsection();
    {
      const auto m1 = Material::Material<1>::create(prm);
      out << "created " << m1->name() << " (1D), E = " << m1->youngs_modulus
          << ", nu = " << m1->poisson_ratio << ", rho = " << m1->density
          << std::endl;
      PSMPM_CHECK(out, m1->name() == "neo-hookean" && m1->density == 2);
    }

    expect_error(out, "Model = nonsense", "nonsense", [&] {
      prm.enter_subsection("Material");
      try
        {
          prm.set("Model", "nonsense");
        }
      catch (...)
        {
          prm.leave_subsection();
          throw;
        }
      prm.leave_subsection();
    });

    // Known for 2D, not for 1D: create() must reject it, naming the entry.
    prm.enter_subsection("Material");
    prm.set("Model", "two-d-only");
    prm.leave_subsection();
    PSMPM_CHECK(out, Material::Material<2>::create(prm) != nullptr);
    expect_error(out, "1D two-d-only", "Material/Model", [&] {
      Material::Material<1>::create(prm);
    });

    const auto bad = [&](const std::string &entry, const std::string &value) {
      ParameterHandler p;
      Material::Material<2>::declare_parameters(p);
      p.enter_subsection("Material");
      p.set(entry, value);
      p.leave_subsection();
      expect_error(out, entry + " = " + value, "Material/" + entry, [&] {
        Material::Material<2>::create(p);
      });
      // create() left the subsection although it threw.
      PSMPM_CHECK(out, p.get({"Material"}, "Model") == "hypoelastic");
    };
    bad("Density", "-1");
    bad("Density", "0");
    bad("Young's modulus", "0");
    bad("Poisson's ratio", "0.5");
    bad("Poisson's ratio", "-1");
  }
} // namespace

int
main()
{
  std::ofstream out("output");
  return run_test([&] {
    compare_2d_with_old(out);
    check_1d(out);
    check_parameters(out);
  });
}
