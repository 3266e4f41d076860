// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Transfer/Scheme = apic (affine particle-in-cell with the space's control
// points):
// (a) the free block of prm/rotating_block.prm (neo-Hookean, 1 rad/s, no
//     boundary conditions, no gravity) for a quarter turn: angular momentum
//     (particles plus their affine part) at the end over its initial value,
//     and the mean rotation angle over pi/2, from
//     Postprocess::RotationStatistics. Powell-Sabin with lumped mass must
//     keep both within 1 %, and so must P1 with lumped mass and the
//     automatic affine matrix, the rotational one (RPIC; MUSL: 0.16 and
//     0.59 of the momentum). Not asserted, known failures (contrib/
//     transfer_study.sh reports them): P1 with the full velocity gradient
//     or B_p D_p^{-1} (its C_p loop amplifies) and partially lumped
//     Powell-Sabin (unstable with MUSL too on this scene: 9 particles per
//     block leave the consistent rows singular);
// (b) an affine velocity v = A x + b on a filled mesh is carried through
//     one step exactly with lumped, partially lumped and consistent mass
//     (the strategy's change of the cell matrices is applied to the
//     particles' affine fields): every particle's new velocity is
//     A x_p + b at its old position and its affine matrix is A (P1: its
//     skew part, the rotational affine matrix);
// (c) linear momentum of (b) after 20 more steps (a stressed, deforming
//     body) equals the initial one to round-off (to the CG tolerance for
//     the matrix strategies).
#include <psmpm/postprocess/rotation_statistics.h>

#include "../mpm_tests.h"

#include <map>

namespace
{
  using namespace psmpm;

  std::unique_ptr<Simulator::Simulator<2>>
  make_solver(std::vector<std::string> overrides)
  {
    overrides.insert(overrides.begin(), "Transfer/Scheme=apic");
    return make_scene_solver("rotating_block.prm", overrides);
  }

  Tensor<1, 2>
  momentum(const Particles::ParticleSet<2> &p)
  {
    Tensor<1, 2> m;
    for (std::size_t i = 0; i < p.size(); ++i)
      m += p.mass[i] * p.velocity[i];
    return m;
  }

  void
  rotation(std::ofstream     &out,
           const std::string &basis,
           const std::string &mass,
           const bool         must_conserve)
  {
    auto solver =
      make_solver({"Basis/Type=" + basis, "Mass matrix/Type=" + mass});
    Postprocess::RotationStatistics<2> rotation;
    const double h0  = rotation.compute(solver->get_state()).angular_momentum;
    const double end = numbers::PI / 2;
    while (solver->get_time() < end * (1 - 1e-12) &&
           solver->get_failure() == Simulator::Failure::none)
      solver->do_time_step(
        std::min(solver->get_time_step(), end - solver->get_time()));
    out << "failure " << static_cast<int>(solver->get_failure())
        << " at t = " << std::setprecision(3) << solver->get_time() << "; ";
    const auto   now   = rotation.compute(solver->get_state());
    const double ratio = now.angular_momentum / h0;
    const double angle = now.rotation_angle / (numbers::PI / 2);
    out << basis << ", " << mass << ": L(T)/L(0) = " << std::fixed
        << std::setprecision(2) << ratio << ", angle/(pi/2) = " << angle
        << std::defaultfloat << std::endl;
    if (must_conserve)
      {
        PSMPM_CHECK(out, std::abs(ratio - 1) < 0.01);
        PSMPM_CHECK(out, std::abs(angle - 1) < 0.01);
      }
  }

  void
  affine(std::ofstream &out, const std::string &basis, const std::string &mass)
  {
    // A = [[0.3, -0.7], [0.5, 0.1]], b = (0.2, -0.4).
    auto solver = make_solver(
      {"Basis/Type=" + basis,
       "Mass matrix/Type=" + mass,
       // 9 particles per triangle: a consistent Powell-Sabin mass matrix
       // (9 functions per triangle) needs them to be regular.
       "Particles/Per block x=6",
       "Particles/Per block y=6",
       "Mesh/Blocks x=4",
       "Mesh/Blocks y=4",
       "Particles/Region=",
       "Initial conditions/Velocity=0.3*x - 0.7*y + 0.2; 0.5*x + 0.1*y - 0.4"});
    const Tensor<2, 2> A({{0.3, -0.7}, {0.5, 0.1}});
    const Tensor<1, 2> b({0.2, -0.4});
    // P1's automatic affine matrix is the rotational part of the gradient.
    const Tensor<2, 2> C  = basis == "linear" ? 0.5 * (A - transpose(A)) : A;
    const auto        &p  = solver->get_particles();
    const Tensor<1, 2> p0 = momentum(p);
    const auto [v_error, c_error] = affine_step_errors(*solver, A, b, C, 1e-3);
    out << basis << ", " << mass << ", affine field:" << std::endl;
    // Exact up to the mass solve: lumped is a division, the matrix
    // strategies a CG solve to relative residual 1e-12.
    PSMPM_CHECK(out, v_error < 1e-10);
    PSMPM_CHECK(out, c_error < 1e-8);

    for (unsigned int n = 0; n < 20; ++n)
      solver->do_time_step(solver->get_time_step());
    PSMPM_CHECK(out, (momentum(p) - p0).norm() < 1e-10 * p0.norm());
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");
  rotation(out, "powell-sabin", "lumped", true);
  rotation(out, "linear", "lumped", true);
  for (const char *mass : {"lumped", "partially lumped", "consistent"})
    {
      affine(out, "powell-sabin", mass);
      affine(out, "linear", mass);
    }
}
