// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Material/Disconnected volume ratio of the granular column collapse
// (Mohr-Coulomb, phi 19.8 deg, psi 0, c 0, E 0.84 MPa, nu 0.3; three
// equal particles, plane strain, from a geostatic-like stress of -5 kPa,
// updated as a batch of two particles and one of one):
// (a) isotropic extension to J = V/V0 = 1.2: the stress goes to the apex
//     (zero) with or without the entry;
// (b) compression back from J = 1.2: without the entry the first step
//     already gives the dense material's stress (the dilated particle
//     resists as if its grains were in contact; its force J V0 sigma
//     grad(phi) then acts on J times the dense stiffness, what made the
//     toe of the collapses unstable); with 1.05, the stress stays exactly
//     zero while J > 1.05 and is compressive again below it;
// (c) a value <= 1 is refused by name (exit code 2, no output).
#include <psmpm/material/mohr_coulomb.h>

#include "../app_tests.h"

using namespace psmpm;

namespace
{
  void
  set_constants(Material::MohrCoulomb<2> &m, const double disconnected)
  {
    m.youngs_modulus            = 8.4e5;
    m.poisson_ratio             = 0.3;
    m.density                   = 2650;
    m.friction_angle            = 19.8;
    m.dilatancy_angle           = 0;
    m.cohesion                  = 0;
    m.residual_cohesion         = 0;
    m.residual_friction_angle   = 19.8;
    m.softening_strain          = 0;
    m.disconnected_volume_ratio = disconnected;
  }

  /// Three equal particles: the update takes a batch of two and one of one.
  struct Particle
  {
    std::vector<SymmetricTensor<2, 2>> stress =
      std::vector<SymmetricTensor<2, 2>>(3);
    std::vector<Tensor<2, 2>> dL = std::vector<Tensor<2, 2>>(3);
    std::vector<double>       state, ratio = std::vector<double>(3);
    double                    J = 1;

    explicit Particle(const Material::MohrCoulomb<2> &m)
      : state(3 * m.n_state())
    {
      m.initialize(3, state.data());
      for (auto &s : stress)
        s[0][0] = s[1][1] = -5e3;
      std::vector<double> szz(3, -5e3);
      m.set_initial_stress(3, stress.data(), szz.data(), state.data());
    }

    /// One isotropic step of volumetric strain 2 e of all three; the
    /// largest |stress|.
    double
    step(const Material::MohrCoulomb<2> &m, const double e)
    {
      for (auto &d : dL)
        {
          d       = 0;
          d[0][0] = d[1][1] = e;
        }
      m.update(3, dL.data(), stress.data(), state.data(), ratio.data());
      J *= ratio[0];
      double largest = 0;
      for (const auto &s : stress)
        largest = std::max(
          {largest, std::abs(s[0][0]), std::abs(s[1][1]), std::abs(s[0][1])});
      return largest;
    }
  };
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");
  out << std::setprecision(4);
  for (const double disconnected : {HUGE_VAL, 1.05})
    {
      Material::MohrCoulomb<2> m;
      set_constants(m, disconnected);
      Particle p(m);
      double   largest = 0;
      while (p.J < 1.2)
        largest = p.step(m, 1e-3);
      largest = p.step(m, 1e-3);
      out << "Disconnected volume ratio "
          << (disconnected == HUGE_VAL ? std::string("none") :
                                         std::to_string(disconnected))
          << ": extended to J = " << p.J << ", |stress| " << largest
          << std::endl;
      PSMPM_CHECK(out, largest == 0);

      double first = p.step(m, -1e-4), while_open = first;
      while (p.J > 1.05 + 1e-3)
        while_open = std::max(while_open, p.step(m, -1e-4));
      double closed = 0;
      while (p.J > 1.04)
        closed = p.step(m, -1e-4);
      out << "  compressed: first step |stress| " << first
          << " Pa, largest while J > 1.05 " << while_open
          << " Pa, at J = " << p.J << " " << closed << " Pa" << std::endl;
      if (disconnected == HUGE_VAL)
        PSMPM_CHECK(out, first > 10);
      else
        {
          PSMPM_CHECK(out, first == 0 && while_open == 0);
          PSMPM_CHECK(out, closed > 1e3);
        }
    }

  check_bad_input(out,
                  "Disconnected volume ratio = 1",
                  "set Output directory = bad_output\n"
                  "subsection Material\n"
                  "  set Model = mohr-coulomb\n"
                  "  set Disconnected volume ratio = 1\n"
                  "end\n",
                  {"Material/Disconnected volume ratio = 1", "> 1"});
}
