// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Multi-velocity contact in a run (Contact/Type = multi-velocity, the
// scenes prm/contact_sliding_block.prm and prm/contact_two_disks.prm,
// shortened), with the linear and the Powell-Sabin basis:
// (a) a block on a slab under gravity tilted by 30 degrees, mu = 0.3
//     (tan 30 > mu): the block's centre accelerates at
//     g (sin 30 - mu cos 30) = 2.356 m/s^2 (a quadratic fit of its x over
//     0.15 s) within 1 %; the friction force on it (the sum of the
//     nodes' tangential impulses) is at most mu times the normal force,
//     the mean contact force gives the block (20 kg/m) the fitted
//     acceleration within 1 %, the friction work is negative, and the
//     energy balance closes with the slipping nodes' Coulomb dissipation
//     (slip_work_1_2): total energy - slip work stays within 1 % of the
//     energy scale (kinetic + strain + |gravity|) of its initial value
//     (linear);
// (b) mu = 0.7 (> tan 30), musl: the block moves less than 6 % (linear)
//     and 3 % (Powell-Sabin) of the sliding block's distance (it creeps
//     at a few mm/s; doc/contact.md);
// (c) two elastic disks meeting head-on, frictionless, with musl (apic,
//     Powell-Sabin's default with contact, keeps the momentum but damps
//     the elastic disks' energy like its PIC update does without contact,
//     doc/contact.md "With the defaults"): the momentum stays
//     zero to round-off, the total energy never exceeds the initial by
//     2 % and ends within 2 % of it (during the impact it dips by about
//     5 %, as without contact), and
//     the disks separate: their centres end more than two cells beyond
//     touching distance, the contact force is zero at the end.
#include "../contact_tests.h"

#include <cmath>
#include <map>

namespace
{
  /// The columns of @p table by name.
  std::map<std::string, std::vector<double>>
  by_name(const StatisticsTable &table)
  {
    std::map<std::string, std::vector<double>> columns;
    for (const auto &n : table.names)
      columns[n] = table.column(n);
    return columns;
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");
  const double      g = 9.81, theta = M_PI / 6;
  for (const std::string basis : {"linear", "powell-sabin"})
    {
      out << basis << std::endl;
      const bool linear = basis == "linear";
      // (a)
      auto s =
        by_name(run_scene(out,
                          "contact_sliding_block.prm",
                          "slide",
                          {"Basis/Type=" + basis, "Time/End time=0.15"}));
      const double a        = fitted_acceleration(s["time"], s["body1_x"]);
      const double expected = g * (std::sin(theta) - 0.3 * std::cos(theta));
      std::cout << basis << ": a " << a << " (closed form " << expected << ")"
                << std::endl;
      PSMPM_CHECK(out, std::abs(a / expected - 1) < 0.01);
      // Coulomb's bound holds node by node, so for the sums of the
      // impulses' magnitudes; the force's components (the normal of the
      // slab's mass gradient tilts by a fraction of a milliradian) and
      // the centre's acceleration agree with it on average.
      // (statistics.txt has 9 digits: 1e-7 of the ratio is its round-off)
      double max_ratio = 0, impulse_x = 0, time = 0;
      for (std::size_t i = 1; i < s["time"].size(); ++i)
        {
          if (s["normal_force_1_2"][i] > 0)
            max_ratio =
              std::max(max_ratio,
                       s["friction_force_1_2"][i] / s["normal_force_1_2"][i]);
          impulse_x += s["contact_force_1_2_x"][i] * s["dt"][i];
          time += s["dt"][i];
        }
      const double a_force = g * std::sin(theta) + impulse_x / time / 20.;
      std::cout << basis << ": friction / normal force at most " << max_ratio
                << ", a from the mean contact force " << a_force << std::endl;
      PSMPM_CHECK(out, max_ratio > 0.2 && max_ratio <= 0.3 * (1 + 1e-7));
      PSMPM_CHECK(out, std::abs(a_force / a - 1) < 0.01);
      PSMPM_CHECK(out, s["friction_work_1_2"].back() < 0);
      double balance = 0, energy_scale = 0;
      for (std::size_t i = 0; i < s["time"].size(); ++i)
        {
          balance = std::max(balance,
                             std::abs(s["total_energy"][i] -
                                      s["slip_work_1_2"][i] -
                                      s["total_energy"][0]));
          energy_scale = std::max(energy_scale,
                                  s["kinetic_energy"][i] +
                                    s["strain_energy"][i] +
                                    std::abs(s["gravity_energy"][i]));
        }
      std::cout << basis << ": energy balance with the slip work off by "
                << balance << " of scale " << energy_scale
                << ", slip work " << s["slip_work_1_2"].back() << std::endl;
      PSMPM_CHECK(out, s["slip_work_1_2"].back() < 0);
      // Powell-Sabin's balance is off by 1.4 % of the scale over 0.15 s
      // (0.45 % over 0.3 s; doc/contact.md): asserted for linear only.
      if (linear)
        PSMPM_CHECK(out, balance < 0.01 * energy_scale);
      const double slid = s["body1_x"].back() - s["body1_x"].front();

      // (b)
      s = by_name(run_scene(out,
                            "contact_sliding_block.prm",
                            "stick",
                            {"Basis/Type=" + basis,
                             "Transfer/Scheme=musl",
                             "Time/End time=0.15",
                             "Contact/Friction coefficient=0.7"}));
      const double crept = s["body1_x"].back() - s["body1_x"].front();
      std::cout << basis << ": slid " << slid << ", crept " << crept
                << std::endl;
      PSMPM_CHECK(out, std::abs(crept) < slid * (linear ? 0.06 : 0.03));

      // (c)
      s = by_name(run_scene(out,
                            "contact_two_disks.prm",
                            "disks",
                            {"Basis/Type=" + basis, "Transfer/Scheme=musl"}));
      const auto  &E = s["total_energy"];
      const double scale =
        s["mass"].front() / 2 * 0.1 * std::sqrt(2.); // one disk's |p|
      double p_max = 0, e_max = 0;
      for (std::size_t i = 0; i < E.size(); ++i)
        {
          p_max =
            std::max(p_max, std::hypot(s["momentum_x"][i], s["momentum_y"][i]));
          e_max = std::max(e_max, E[i] / E.front());
        }
      const double e_end = E.back() / E.front();
      const double d     = std::hypot(s["body2_x"].back() - s["body1_x"].back(),
                                  s["body2_y"].back() - s["body1_y"].back());
      std::cout << basis << ": |p|max/scale " << p_max / scale << ", E_max/E0 "
                << e_max << ", E_end/E0 " << e_end << ", d_end " << d
                << std::endl;
      PSMPM_CHECK(out, p_max < 1e-12 * scale);
      PSMPM_CHECK(out, e_max < 1.02 && std::abs(e_end - 1) < 0.02);
      PSMPM_CHECK(out, d > 0.4 + 2 * 0.05);
      PSMPM_CHECK(out,
                  s["contact_force_1_2_x"].back() == 0 &&
                    s["contact_force_1_2_y"].back() == 0);
    }
}
