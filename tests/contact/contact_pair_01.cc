// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Simulator::correct_pair, the two-body rule of multi-velocity contact:
// (a) two bodies approaching head on (1D and 2D): the normal velocities
//     both become the centre of mass velocity, the impulse is the reduced
//     mass times the approach speed, the normal work its kinetic energy;
// (b) the same bodies separating, or sliding without approach, are left
//     bit for bit as they were;
// (c) an oblique approach in 2D with mu = 0 (frictionless: the tangential
//     velocities stay), a small mu (slip: the tangential relative
//     velocity drops by exactly mu times the normal one, the friction
//     work is what the closed form says), a large mu and no-slip (stick:
//     both bodies move with the centre of mass);
// (d) in every case the momentum m_a v_a + m_b v_b is unchanged to
//     round-off and the kinetic energy drops by the normal plus friction
//     work reported.
#include <psmpm/simulator/contact.h>

#include "../tests.h"

#include <limits>

using psmpm::Simulator::ContactPairStatistics;
using psmpm::Simulator::correct_pair;

namespace
{
  template <int dim>
  double
  kinetic_energy(const double          m_a,
                 const double          m_b,
                 const Tensor<1, dim> &v_a,
                 const Tensor<1, dim> &v_b)
  {
    return 0.5 * (m_a * v_a.norm_square() + m_b * v_b.norm_square());
  }

  /// Corrects (v_a, v_b), prints the result and checks (d).
  template <int dim>
  ContactPairStatistics<dim>
  run_pair(std::ostream         &out,
           const std::string    &name,
           const double          m_a,
           const double          m_b,
           Tensor<1, dim>       &v_a,
           Tensor<1, dim>       &v_b,
           const Tensor<1, dim> &normal,
           const double          mu)
  {
    const Tensor<1, dim>       p  = m_a * v_a + m_b * v_b;
    const double               e0 = kinetic_energy(m_a, m_b, v_a, v_b);
    ContactPairStatistics<dim> s;
    const bool   corrected = correct_pair(m_a, m_b, v_a, v_b, normal, mu, s);
    const double e1        = kinetic_energy(m_a, m_b, v_a, v_b);
    out << name << ": corrected " << corrected << ", v_a = (";
    for (unsigned int d = 0; d < dim; ++d)
      out << (d ? ", " : "") << filter(v_a[d]);
    out << "), v_b = (";
    for (unsigned int d = 0; d < dim; ++d)
      out << (d ? ", " : "") << filter(v_b[d]);
    out << "), normal impulse " << filter(s.normal_impulse) << ", normal work "
        << filter(s.normal_work) << ", friction work "
        << filter(s.friction_work) << std::endl;
    PSMPM_CHECK(out,
                (m_a * v_a + m_b * v_b - p).norm() <= 1e-14 * p.norm() + 1e-15);
    PSMPM_CHECK(out,
                std::abs(e1 - e0 - s.normal_work - s.friction_work) <=
                  1e-14 * e0);
    PSMPM_CHECK(out, e1 <= e0);
    return s;
  }
} // namespace

int
main()
{
  return run_test([] {
    std::ofstream out("output");
    out << std::setprecision(10);

    out << "(a) head on" << std::endl;
    {
      Tensor<1, 1> v_a, v_b, n;
      v_a[0]       = 2;
      v_b[0]       = -1;
      n[0]         = 1;
      const auto s = run_pair<1>(out, "1D", 1., 2., v_a, v_b, n, 0.3);
      // v_cm = (2 - 2)/3 = 0; reduced mass 2/3, approach speed 3.
      PSMPM_CHECK(out, std::abs(v_a[0]) < 1e-15 && std::abs(v_b[0]) < 1e-15);
      PSMPM_CHECK(out, std::abs(s.normal_impulse - 2.) < 1e-14);
      PSMPM_CHECK(out, std::abs(s.normal_work + 3.) < 1e-14);
    }
    {
      Tensor<1, 2> v_a, v_b, n;
      v_a[1] = -1.5; // a above b, falling onto it
      v_b[1] = 0.5;
      n[1]   = -1; // from a towards b
      run_pair<2>(out, "2D", 3., 1., v_a, v_b, n, 0.);
      PSMPM_CHECK(out,
                  std::abs(v_a[1] + 1.) < 1e-15 &&
                    std::abs(v_b[1] + 1.) < 1e-15);
    }

    out << "(b) separating or sliding" << std::endl;
    {
      Tensor<1, 2> v_a, v_b, n;
      v_a[0]                = 0.7;
      v_a[1]                = 1.;
      v_b[1]                = -1.;
      n[1]                  = -1;
      const Tensor<1, 2> a0 = v_a, b0 = v_b;
      run_pair<2>(out, "separating", 1., 1., v_a, v_b, n, 1.);
      PSMPM_CHECK(out, v_a == a0 && v_b == b0);
      v_a[1] = v_b[1]       = 0.25;
      const Tensor<1, 2> a1 = v_a, b1 = v_b;
      run_pair<2>(out, "sliding", 1., 1., v_a, v_b, n, 1.);
      PSMPM_CHECK(out, v_a == a1 && v_b == b1);
    }

    out << "(c) oblique approach" << std::endl;
    const double m_a = 2, m_b = 3, m = m_a * m_b / (m_a + m_b);
    for (const double mu :
         {0., 0.1, 10., std::numeric_limits<double>::infinity()})
      {
        Tensor<1, 2> v_a, v_b, n;
        v_a[0]                  = 1.;   // tangential relative velocity 1.2
        v_a[1]                  = -0.5; // normal approach speed 0.9
        v_b[0]                  = -0.2;
        v_b[1]                  = 0.4;
        n[1]                    = -1;
        const Tensor<1, 2> v_cm = (m_a * v_a + m_b * v_b) / (m_a + m_b);
        const Tensor<1, 2> a0 = v_a, b0 = v_b;
        const auto         s = run_pair<2>(out,
                                   "mu = " + std::to_string(mu),
                                   m_a,
                                   m_b,
                                   v_a,
                                   v_b,
                                   n,
                                   mu);
        PSMPM_CHECK(out,
                    std::abs(v_a[1] - v_cm[1]) < 1e-15 &&
                      std::abs(v_b[1] - v_cm[1]) < 1e-15);
        const double w_t = v_a[0] - v_b[0];
        if (mu == 0)
          PSMPM_CHECK(out,
                      v_a[0] == a0[0] && v_b[0] == b0[0] &&
                        s.friction_work == 0);
        else if (mu < 1)
          {
            // Slip: |w_t| drops from 1.2 by mu 0.9.
            PSMPM_CHECK(out, std::abs(w_t - (1.2 - mu * 0.9)) < 1e-14);
            PSMPM_CHECK(out,
                        std::abs(s.friction_work +
                                 0.5 * m * (1.2 * 1.2 - w_t * w_t)) < 1e-14);
          }
        else
          {
            PSMPM_CHECK(out,
                        (v_a - v_cm).norm() < 1e-15 &&
                          (v_b - v_cm).norm() < 1e-15);
            PSMPM_CHECK(out,
                        std::abs(s.friction_work + 0.5 * m * 1.44) < 1e-14);
          }
      }
  });
}
