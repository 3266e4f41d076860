// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// The stability suite with the defaults (Mass matrix/Type = automatic,
// Transfer/Scheme = automatic, Time/Time step = 0: the automatic step
// recomputed every step), both bases, short versions of the scenes of
// contrib/studies/stability/defaults_suite.sh (which runs them in full):
// * every run completes (no monitor fires: volume, CG, energy growth
//   without external work, non-finite values);
// * particle mass is unchanged;
// * free bodies without gravity (the rotating block: plain, stiff E = 1e9
//   and nearly incompressible nu = 0.49) keep their linear momentum (zero)
//   to 1e-6 of m omega R, and their angular momentum and mean rotation
//   angle to 1 % (RotationStatistics: particles plus their affine part),
//   both bases: Powell-Sabin with lumped mass and APIC, P1 with the
//   ghost-penalty mass matrix and MUSL (P1's earlier default, partially
//   lumped, lost about 45 % of it; doc/transfers.md "Defaults").
#include <psmpm/postprocess/rotation_statistics.h>

#include "../mpm_tests.h"

#include <cctype>
#include <filesystem>

namespace
{
  using namespace psmpm;

  struct Scene
  {
    std::string              name;
    std::string              file;
    std::vector<std::string> overrides;
    bool                     free_rotation;
  };

  void
  run(std::ofstream &out, const Scene &scene, const std::string &basis)
  {
    std::vector<std::string> o = {"Basis/Type=" + basis,
                                  "Mass matrix/Type=automatic",
                                  "Transfer/Scheme=automatic",
                                  "Time/Time step=0",
                                  "Output/Interval=0"};
    o.insert(o.end(), scene.overrides.begin(), scene.overrides.end());
    auto        solver = make_scene_solver(scene.file, o);
    const auto &p      = solver->get_particles();
    auto        total  = [&p]() {
      double m = 0;
      for (const double mi : p.mass)
        m += mi;
      return m;
    };
    Postprocess::RotationStatistics<2> rotation;
    const double                       m0 = total();
    const double h0  = rotation.compute(solver->get_state()).angular_momentum;
    std::string  dir = "run-" + scene.name + "-" + basis;
    for (char &c : dir)
      c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    std::filesystem::create_directories(dir);
    const auto status = solver->run(dir);
    out << scene.name << ", " << basis << ": " << Simulator::status_name(status)
        << std::endl;
    PSMPM_CHECK(out, status == Simulator::Status::completed);
    PSMPM_CHECK(out, total() == m0);
    if (!scene.free_rotation)
      return;
    Tensor<1, 2> momentum;
    double       scale = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      {
        momentum += p.mass[i] * p.velocity[i];
        scale += p.mass[i] * p.velocity[i].norm();
      }
    const auto   now  = rotation.compute(solver->get_state());
    const double turn = solver->get_time(); // omega = 1 rad/s
    out << "  L(T)/L(0) = " << std::fixed << std::setprecision(3)
        << now.angular_momentum / h0
        << ", angle / (omega T) = " << now.rotation_angle / turn
        << std::defaultfloat << std::endl;
    PSMPM_CHECK(out, momentum.norm() < 1e-6 * scale);
    PSMPM_CHECK(out, std::abs(now.angular_momentum / h0 - 1) < 0.01);
    PSMPM_CHECK(out, std::abs(now.rotation_angle / turn - 1) < 0.01);
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");
  const std::vector<Scene>         scenes = {
            {"rotation", "rotating_block.prm", {}, true},
            {"rotation, E = 1e9",
             "rotating_block.prm",
             {"Material/Young's modulus=1e9", "Time/End time=0.05"},
             true},
            {"rotation, nu = 0.49",
             "rotating_block.prm",
             {"Material/Poisson's ratio=0.49"},
             true},
            {"slumping block", "spreading_block.prm", {}, false},
            {"falling block", "falling_block.prm", {}, false},
            {"soil column 2 x 16",
             "soil_column_small.prm",
             {"Mesh/Blocks x=2", "Mesh/Blocks y=16"},
             false},
            {"cantilever, 2 blocks deep",
             "cantilever.prm",
             {"Mesh/Blocks x=18",
              "Mesh/Blocks y=4",
              "Time/End time=0.05",
              "Reference solution/Type=none"},
             false}};
  for (const auto &scene : scenes)
    for (const std::string basis : {"linear", "powell-sabin"})
      run(out, scene, basis);
}
