// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// The kinetic energy of apic's affine fields (statistics column
// affine_kinetic_energy, sum_p 1/2 m_p C_p : (C_p D_p)):
// (a) apic (Powell-Sabin, lumped mass) on the free rotating block of
//     prm/rotating_block.prm for a quarter turn: the column is there and
//     positive (the particles spin), and total + affine energy never rises
//     by more than 1 % of its initial value (the control-point fit keeps
//     the particles' energy below the grid's lumped kinetic energy; what
//     rises is the time integration's exchange of kinetic and strain
//     energy, 0.2 % here);
// (b) musl carries no affine field: no such column;
// (c) affine FLIP (FLIP fraction 1 for v_p and C_p) on the soft column of
//     prm/column_collapse.prm: C_p keeps and feeds back its own noise and
//     its energy grows beyond a tenth of the largest kinetic + strain
//     energy, while the statistics' total_energy (without the affine
//     part, what the stability monitor watches) does not rise by that
//     much: the column shows what the total hides.
#include "../mpm_tests.h"

#include <algorithm>
#include <filesystem>
#include <map>

namespace
{
  using namespace psmpm;

  struct Run
  {
    Simulator::Status                          status;
    std::map<std::string, std::vector<double>> columns;
  };

  Run
  run(const std::string              &scene,
      const std::string              &dir,
      const std::vector<std::string> &overrides)
  {
    auto solver = make_scene_solver(scene, overrides);
    std::filesystem::create_directories(dir);
    Run r;
    r.status = solver->run(dir);
    const StatisticsTable statistics(dir);
    for (const char *c : {"total_energy",
                          "affine_kinetic_energy",
                          "kinetic_energy",
                          "strain_energy"})
      r.columns[c] = statistics.column(c);
    return r;
  }
} // namespace

int
main(int argc, char **argv)
{
  MPISession    mpi(argc, argv);
  std::ofstream out("output");

  {
    out << "(a) apic, rotating block" << std::endl;
    const Run r = run("rotating_block.prm",
                      "run-apic",
                      {"Basis/Type=powell-sabin",
                       "Mass matrix/Type=lumped",
                       "Transfer/Scheme=apic",
                       "Time/End time=1.5707963",
                       "Output/Interval=0"});
    PSMPM_CHECK(out, r.status == Simulator::Status::completed);
    const auto &total  = r.columns.at("total_energy");
    const auto &affine = r.columns.at("affine_kinetic_energy");
    PSMPM_CHECK(out, !affine.empty() && affine.size() == total.size());
    PSMPM_CHECK(out, *std::min_element(affine.begin(), affine.end()) > 0);
    double rise = -1e300;
    for (std::size_t i = 0; i < total.size(); ++i)
      rise = std::max(rise, total[i] + affine[i] - total[0] - affine[0]);
    PSMPM_CHECK(out, rise < 0.01 * (total[0] + affine[0]));
  }
  {
    out << "(b) musl" << std::endl;
    const Run r = run("rotating_block.prm",
                      "run-musl",
                      {"Basis/Type=powell-sabin",
                       "Mass matrix/Type=lumped",
                       "Transfer/Scheme=musl",
                       "Time/End time=0.1",
                       "Output/Interval=0"});
    PSMPM_CHECK(out, r.status == Simulator::Status::completed);
    PSMPM_CHECK(out, r.columns.at("affine_kinetic_energy").empty());
    PSMPM_CHECK(out, !r.columns.at("total_energy").empty());
  }
  {
    out << "(c) affine FLIP, soft column" << std::endl;
    const Run r = run("column_collapse.prm",
                      "run-affine-flip",
                      {"Basis/Type=powell-sabin",
                       "Mass matrix/Type=lumped",
                       "Transfer/Scheme=apic",
                       "Transfer/FLIP fraction=1",
                       "Transfer/FLIP affine matrix=true",
                       "Output/Interval=0"});
    PSMPM_CHECK(out, r.status == Simulator::Status::completed);
    // The monitor's scale: the largest kinetic + strain + |gravity|
    // energy seen; here kinetic + strain bound it from below.
    const auto &total   = r.columns.at("total_energy");
    const auto &kinetic = r.columns.at("kinetic_energy");
    const auto &strain  = r.columns.at("strain_energy");
    double      scale = 0, rise = -1e300;
    for (std::size_t i = 0; i < total.size(); ++i)
      {
        scale = std::max(scale, kinetic[i] + strain[i]);
        rise  = std::max(rise, total[i] - total[0]);
      }
    PSMPM_CHECK(out, rise < 0.1 * scale);
    const auto &affine = r.columns.at("affine_kinetic_energy");
    PSMPM_CHECK(out,
                *std::max_element(affine.begin(), affine.end()) > 0.1 * scale);
  }
}
