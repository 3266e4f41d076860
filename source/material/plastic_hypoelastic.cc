// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/numbers.h>

#include <psmpm/base/format.h>
#include <psmpm/material/plastic_hypoelastic.h>

#include <algorithm>

namespace psmpm
{
  namespace Material
  {
    namespace
    {
      constexpr double degree = numbers::PI / 180;

      /// "none" or a number, for the entries whose default is "none".
      double
      parse_optional(const std::string &text,
                     const std::string &entry,
                     const double       none_value)
      {
        if (text == "none")
          return none_value;
        try
          {
            std::size_t  used  = 0;
            const double value = std::stod(text, &used);
            if (text.find_first_not_of(" \t", used) == std::string::npos &&
                std::isfinite(value))
              return value;
          }
        catch (const std::exception &)
          {
          }
        AssertThrow(false,
                    ExcMessage(entry + " = '" + text +
                               "': expected a number or 'none'."));
        return none_value;
      }
    } // namespace



    template <int dim>
    void
    PlasticHypoelastic<dim>::declare_entries(ParameterHandler &prm)
    {
      prm.declare_entry("Friction angle",
                        "30",
                        Patterns::Double(),
                        "mohr-coulomb, drucker-prager: friction angle phi "
                        "[degrees], 0 <= phi < 90 (0: Tresca, von Mises).");
      prm.declare_entry("Dilatancy angle",
                        "0",
                        Patterns::Double(),
                        "mohr-coulomb, drucker-prager: dilatancy angle psi "
                        "[degrees] of the plastic potential, 0 <= psi <= "
                        "phi (psi = phi: associated flow).");
      prm.declare_entry("Cohesion",
                        "0",
                        Patterns::Double(),
                        "mohr-coulomb, drucker-prager: cohesion c [Pa], >= 0 "
                        "(> 0 if Friction angle = 0).");
      prm.declare_entry("Tension cutoff",
                        "none",
                        Patterns::Anything(),
                        "mohr-coulomb: largest principal stress t [Pa] "
                        "(tension positive), >= 0, or 'none'; only a value "
                        "below the apex c cot(phi) changes the surface.");
      prm.declare_entry("Residual cohesion",
                        "none",
                        Patterns::Anything(),
                        "mohr-coulomb, drucker-prager: cohesion reached at "
                        "Softening strain [Pa] ('none': Cohesion).");
      prm.declare_entry("Residual friction angle",
                        "none",
                        Patterns::Anything(),
                        "mohr-coulomb, drucker-prager: friction angle "
                        "reached at Softening strain [degrees] ('none': "
                        "Friction angle).");
      prm.declare_entry("Softening strain",
                        "0",
                        Patterns::Double(),
                        "mohr-coulomb, drucker-prager: equivalent plastic "
                        "strain at which cohesion and friction angle reach "
                        "their residual values, linearly from 0 (0: no "
                        "softening).");
      prm.declare_entry("Disconnected volume ratio",
                        "none",
                        Patterns::Anything(),
                        "mohr-coulomb, drucker-prager: a granular material "
                        "whose volume ratio J = V/V0 exceeds this (> 1) is "
                        "taken as grains out of contact: the particle "
                        "carries no stress until compacted below it again "
                        "(the disconnected state of Dunatunga and Kamrin, "
                        "J. Fluid Mech. 779, 2015). 'none': never "
                        "(doc/geomechanics.md, granular column collapse).");
      prm.declare_entry(
        "Apex dilation",
        "permanent",
        Patterns::Selection("permanent|recoverable"),
        "mohr-coulomb, drucker-prager with Cohesion = 0: what becomes of the "
        "volume a return to the apex (zero stress) adds. permanent: plastic "
        "for good; compressed again, the particle takes the dense "
        "material's stress at once. recoverable: it is a gap between grains "
        "out of contact (Dunatunga and Kamrin, J. Fluid Mech. 779, 2015), "
        "kept per particle (state column apex_dilation): while it is open "
        "the particle carries no stress and its strain is plastic; "
        "compression closes it first, and only the strain after that "
        "loads the particle (doc/geomechanics.md, granular column "
        "collapse).");
    }



    template <int dim>
    void
    PlasticHypoelastic<dim>::parse_parameters(ParameterHandler &prm)
    {
      Material<dim>::parse_parameters(prm);
      const std::string &p = this->path;
      friction_angle       = prm.get_double("Friction angle");
      dilatancy_angle      = prm.get_double("Dilatancy angle");
      cohesion             = prm.get_double("Cohesion");
      tension_cutoff       = parse_optional(prm.get("Tension cutoff"),
                                      p + "/Tension cutoff",
                                      HUGE_VAL);
      residual_cohesion    = parse_optional(prm.get("Residual cohesion"),
                                         p + "/Residual cohesion",
                                         cohesion);
      residual_friction_angle =
        parse_optional(prm.get("Residual friction angle"),
                       p + "/Residual friction angle",
                       friction_angle);
      softening_strain = prm.get_double("Softening strain");
      disconnected_volume_ratio =
        parse_optional(prm.get("Disconnected volume ratio"),
                       p + "/Disconnected volume ratio",
                       HUGE_VAL);
      recoverable_apex_dilation = prm.get("Apex dilation") == "recoverable";
      AssertThrow(
        !recoverable_apex_dilation || (cohesion == 0 && residual_cohesion == 0),
        ExcMessage(p + "/Apex dilation = recoverable with " + p +
                   "/Cohesion = " + prm_value(cohesion) +
                   " (Residual cohesion = " + prm_value(residual_cohesion) +
                   "): a gap between grains needs a cohesionless "
                   "material, whose apex is at zero stress "
                   "(Cohesion = 0, Residual cohesion = 0)."));
      AssertThrow(!recoverable_apex_dilation ||
                    disconnected_volume_ratio == HUGE_VAL,
                  ExcMessage(p + "/Apex dilation = recoverable with " + p +
                             "/Disconnected volume ratio = " +
                             prm_value(disconnected_volume_ratio) +
                             ": the gap replaces the fixed volume ratio; "
                             "set Disconnected volume ratio = none."));
      AssertThrow(disconnected_volume_ratio > 1,
                  ExcMessage(p + "/Disconnected volume ratio = " +
                             prm_value(disconnected_volume_ratio) +
                             ": must be a number > 1 (a volume ratio above "
                             "the initial one) or 'none'."));

      const auto check_angle = [&](const double v, const std::string &e) {
        AssertThrow(std::isfinite(v) && v >= 0 && v < 90,
                    ExcMessage(p + "/" + e + " = " + prm_value(v) +
                               ": must satisfy 0 <= angle < 90 degrees."));
      };
      check_angle(friction_angle, "Friction angle");
      check_angle(residual_friction_angle, "Residual friction angle");
      AssertThrow(std::isfinite(dilatancy_angle) && dilatancy_angle >= 0 &&
                    dilatancy_angle <= friction_angle &&
                    dilatancy_angle <= residual_friction_angle,
                  ExcMessage(
                    p + "/Dilatancy angle = " + prm_value(dilatancy_angle) +
                    ": must satisfy 0 <= psi <= phi (Friction angle "
                    "= " +
                    prm_value(friction_angle) +
                    ", and the residual one): a larger psi "
                    "creates energy."));
      for (const auto &[v, e] :
           {std::pair<double, const char *>{cohesion, "Cohesion"},
            {residual_cohesion, "Residual cohesion"},
            {tension_cutoff, "Tension cutoff"},
            {softening_strain, "Softening strain"}})
        AssertThrow(v >= 0 && !std::isnan(v) &&
                      (std::isfinite(v) || v == tension_cutoff),
                    ExcMessage(p + "/" + e + " = " + prm_value(v) +
                               ": must be a finite number >= 0."));
      AssertThrow(friction_angle > 0 || cohesion > 0,
                  ExcMessage(p + "/Cohesion = 0 with Friction angle = 0: the "
                                 "material would have no strength at all."));
      AssertThrow(residual_friction_angle > 0 || residual_cohesion > 0,
                  ExcMessage(p + "/Residual cohesion = 0 with Residual "
                                 "friction angle = 0: the softened material "
                                 "would have no strength at all."));
    }



    template <int dim>
    typename PlasticHypoelastic<dim>::Strength
    PlasticHypoelastic<dim>::strength(const double kappa) const
    {
      double phi = friction_angle, c = cohesion;
      if (softening_strain > 0)
        {
          const double x = std::min(kappa / softening_strain, 1.);
          phi += x * (residual_friction_angle - friction_angle);
          c += x * (residual_cohesion - cohesion);
        }
      Strength s;
      s.cohesion       = c;
      s.sin_phi        = std::sin(phi * degree);
      s.cos_phi        = std::cos(phi * degree);
      s.sin_psi        = std::sin(std::min(dilatancy_angle, phi) * degree);
      s.tension_cutoff = tension_cutoff;
      return s;
    }



    template <int dim>
    std::vector<std::string>
    PlasticHypoelastic<dim>::state_names() const
    {
      std::vector<std::string> names;
      if constexpr (dim == 1)
        names = {"stress_lateral",
                 "plastic_strain_xx",
                 "plastic_strain_lateral",
                 "equivalent_plastic_strain",
                 "plastic_work",
                 "volume_ratio"};
      else
        names = {"stress_zz",
                 "plastic_strain_xx",
                 "plastic_strain_yy",
                 "plastic_strain_xy",
                 "plastic_strain_zz",
                 "equivalent_plastic_strain",
                 "plastic_work",
                 "volume_ratio"};
      // Only with the option, so that the outputs without it keep their
      // columns.
      if (recoverable_apex_dilation)
        names.emplace_back("apex_dilation");
      return names;
    }



    template <int dim>
    void
    PlasticHypoelastic<dim>::initialize(const unsigned int n,
                                        double            *state) const
    {
      Material<dim>::initialize(n, state);
      const unsigned int s = this->state_stride();
      for (unsigned int i = 0; i < n; ++i)
        state[i * s + ratio_column] = 1;
    }



    template <int dim>
    void
    PlasticHypoelastic<dim>::set_initial_stress(
      const unsigned int n,
      const SymmetricTensor<2, dim> *,
      const double *out_of_plane_stress,
      double       *state) const
    {
      const unsigned int s = this->state_stride();
      for (unsigned int i = 0; i < n; ++i)
        state[i * s + out_of_plane] = out_of_plane_stress[i];
    }



    template <int dim>
    void
    PlasticHypoelastic<dim>::energy_density(
      const unsigned int             n,
      const SymmetricTensor<2, dim> *stress,
      const double                  *state,
      double                        *energy) const
    {
      // The elastic (complementary) energy of all three normal stresses:
      // the strain energy stored; what plastic flow took is in
      // dissipated_energy().
      const double       nu = this->poisson_ratio;
      const double       E  = this->youngs_modulus;
      const unsigned int st = this->state_stride();
      for (unsigned int i = 0; i < n; ++i)
        {
          const SymmetricTensor<2, dim> &s   = stress[i];
          const double                   szz = state[st * i + out_of_plane];
          const double                   sxx = s[0][0];
          const double syy = dim == 1 ? szz : s[1 % dim][1 % dim];
          const double sxy = dim == 1 ? 0 : s[0][1 % dim];
          energy[i]        = (sxx * sxx + syy * syy + szz * szz -
                       2 * nu * (sxx * syy + syy * szz + szz * sxx) +
                       2 * (1 + nu) * sxy * sxy) /
                      (2 * E);
        }
    }



    template <int dim>
    void
    PlasticHypoelastic<dim>::dissipated_energy(const unsigned int n,
                                               const double      *state,
                                               double *per_unit_mass) const
    {
      const unsigned int s = this->state_stride();
      for (unsigned int i = 0; i < n; ++i)
        per_unit_mass[i] = state[i * s + work_column];
    }



    template class PlasticHypoelastic<1>;
    template class PlasticHypoelastic<2>;
  } // namespace Material
} // namespace psmpm
