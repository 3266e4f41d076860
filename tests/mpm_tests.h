// ---------------------------------------------------------------------
// psmpm: helpers for tests that drive the MPM solver directly.
// ---------------------------------------------------------------------
#ifndef psmpm_tests_mpm_tests_h
#define psmpm_tests_mpm_tests_h

#include <deal.II/base/parameter_handler.h>

#include <psmpm/app/application.h>
#include <psmpm/simulator/simulator.h>

#include "tests.h"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

/// Set up @p solver from the default scene with the given overrides.
inline void
configure(psmpm::Simulator::Simulator<2> &solver,
          const std::vector<std::string> &overrides)
{
  ParameterHandler prm;
  psmpm::App::declare_parameters(prm);
  prm.parse_input_from_string(psmpm::App::default_scene, "default scene");
  for (const auto &o : overrides)
    psmpm::App::apply_override(prm, o);
  solver.quiet = true;
  solver.parse_parameters(prm);
  solver.setup();
}

/// A solver set up from the scene file prm/@p scene of the repository with
/// the given overrides ("Subsection/Entry=value"), quiet, on @p comm.
template <int dim = 2>
std::unique_ptr<psmpm::Simulator::Simulator<dim>>
make_scene_solver(const std::string              &scene,
                  const std::vector<std::string> &overrides,
                  const MPI_Comm                  comm = MPI_COMM_WORLD)
{
  ParameterHandler prm;
  psmpm::App::declare_parameters(prm);
  prm.parse_input(std::string(PSMPM_SOURCE_DIR) + "/prm/" + scene);
  for (const auto &o : overrides)
    psmpm::App::apply_override(prm, o);
  auto solver   = std::make_unique<psmpm::Simulator::Simulator<dim>>(comm);
  solver->quiet = true;
  solver->parse_parameters(prm);
  solver->setup();
  return solver;
}

/// Largest violation of "the particle lies in its triangle" and whether
/// every particle's cell agrees with a brute-force search.
inline std::pair<double, bool>
check_particles_in_cells(const psmpm::Simulator::Simulator<2> &solver)
{
  const auto &particles = solver.get_particles();
  const auto &locator   = solver.get_locator();
  double      worst     = 0;
  bool        agree     = true;
  for (std::size_t p = 0; p < particles.size(); ++p)
    {
      const auto l =
        locator.barycentric(particles.cell[p], particles.position[p]);
      worst      = std::max(worst, -std::min({l[0], l[1], l[2]}));
      bool found = false;
      for (unsigned int c = 0; c < locator.n_cells() && !found; ++c)
        found = locator.contains(c, particles.position[p]) &&
                locator.contains(particles.cell[p], particles.position[p]);
      agree = agree && found;
    }
  return {worst, agree};
}

/// One step of @p dt from particles that carry the affine velocity field
/// v = A x + b: the largest error of their new velocities against that
/// field at their old positions, and of their affine matrices against
/// @p C (particles may be reordered by locating; matched by id).
inline std::pair<double, double>
affine_step_errors(psmpm::Simulator::Simulator<2> &solver,
                   const Tensor<2, 2>             &A,
                   const Tensor<1, 2>             &b,
                   const Tensor<2, 2>             &C,
                   const double                    dt)
{
  const auto &p = solver.get_particles();
  std::map<std::uint64_t, Point<2>> old;
  for (std::size_t i = 0; i < p.size(); ++i)
    old[p.id[i]] = p.position[i];
  solver.do_time_step(dt);
  double v_error = 0, c_error = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    {
      v_error =
        std::max(v_error, (p.velocity[i] - (A * old[p.id[i]] + b)).norm());
      c_error = std::max(c_error, (p.affine[i] - C).norm());
    }
  return {v_error, c_error};
}

/// The rows of @p directory/statistics.txt by column name.
struct StatisticsTable
{
  explicit StatisticsTable(const std::string &directory)
  {
    std::ifstream in(directory + "/statistics.txt");
    std::string   line;
    while (std::getline(in, line))
      if (line.rfind("# ", 0) == 0)
        names.push_back(line.substr(line.find(':') + 2));
      else if (!line.empty())
        {
          std::istringstream  row(line);
          std::vector<double> values;
          for (std::string v; row >> v;)
            values.push_back(std::atof(v.c_str()));
          rows.push_back(values);
        }
  }

  /// Column @p name of every row (NaN where a row is short; empty if
  /// there is no such column).
  std::vector<double>
  column(const std::string &name) const
  {
    std::vector<double> c;
    for (unsigned int k = 0; k < names.size(); ++k)
      if (names[k] == name)
        for (const auto &r : rows)
          c.push_back(k < r.size() ? r[k] : std::nan(""));
    return c;
  }

  std::vector<std::string>         names;
  std::vector<std::vector<double>> rows;
};

/// The energy books of a run under gravity on frictional walls: the
/// released gravitational energy (-gravity_energy at the end) and the
/// change of total_energy minus the walls' friction_work over it (what is
/// conserved: kinetic + strain + gravity + dissipated - friction work).
struct EnergyBooks
{
  explicit EnergyBooks(const StatisticsTable &statistics)
  {
    const auto total    = statistics.column("total_energy");
    const auto friction = statistics.column("friction_work");
    released            = -statistics.column("gravity_energy").back();
    balance = (total.back() - friction.back() - total.front()) / released;
  }

  double released = 0;
  double balance  = 0;
};

/// Observed rates log2(e_i / e_(i+1)) between successive meshes of the
/// four values @p e, printed after @p what.
inline std::vector<double>
rates(std::ostream &out, const std::string &what, const double (&e)[4])
{
  std::vector<double> r;
  out << what << ": rates";
  for (unsigned int i = 0; i + 1 < 4; ++i)
    {
      r.push_back(std::log2(e[i] / e[i + 1]));
      out << ' ' << std::fixed << std::setprecision(1) << r.back();
    }
  out << std::endl;
  return r;
}

#endif
