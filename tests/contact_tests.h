// ---------------------------------------------------------------------
// psmpm: helpers for the tests that run contact scenes of prm/.
// ---------------------------------------------------------------------
#ifndef psmpm_tests_contact_tests_h
#define psmpm_tests_contact_tests_h

#include "app_tests.h"
#include "mpm_tests.h"

#include <filesystem>
#include <limits>
#include <string>
#include <vector>

/// psmpm on the scene prm/@p scene with its output in @p directory and
/// @p settings: entries "Subsection/Entry=value" (each passed after
/// --set) or flags ("--resume"). The run's screen output is left in
/// @p screen, its error messages written to @p out if it fails. Returns
/// the exit code.
inline int
run_prm_scene(std::ostream                   &out,
              const std::string              &scene,
              const std::string              &directory,
              const std::vector<std::string> &settings,
              std::string                    &screen)
{
  std::vector<std::string> args = {std::string(PSMPM_SOURCE_DIR) + "/prm/" +
                                     scene,
                                   "--set",
                                   "Output directory=" + directory};
  for (const auto &s : settings)
    {
      if (s.rfind("--", 0) != 0)
        args.push_back("--set");
      args.push_back(s);
    }
  std::string errors;
  const int   code = run_app(args, screen, errors);
  if (code != 0)
    out << errors << std::endl;
  return code;
}

/// run_prm_scene() into a fresh @p directory, checked to succeed: the
/// run's statistics.txt.
inline StatisticsTable
run_scene(std::ostream                   &out,
          const std::string              &scene,
          const std::string              &directory,
          const std::vector<std::string> &settings)
{
  std::filesystem::remove_all(directory);
  std::string screen;
  const int   code = run_prm_scene(out, scene, directory, settings, screen);
  PSMPM_CHECK(out, code == 0);
  return StatisticsTable(directory);
}

/// The coefficient a of the least squares fit x = c + b t + a t^2 / 2
/// over the rows with t >= @p from (all rows by default).
inline double
fitted_acceleration(
  const std::vector<double> &t,
  const std::vector<double> &x,
  const double               from = -std::numeric_limits<double>::infinity())
{
  // Normal equations of the fit in t (3 x 3, Cramer's rule).
  double s[5] = {0, 0, 0, 0, 0}, r[3] = {0, 0, 0};
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= from)
      {
        double p = 1;
        for (unsigned int k = 0; k < 5; ++k, p *= t[i])
          s[k] += p;
        r[0] += x[i];
        r[1] += x[i] * t[i];
        r[2] += x[i] * t[i] * t[i];
      }
  const auto det = [](const double a[3][3]) {
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
           a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  };
  const double m[3][3] = {{s[0], s[1], s[2]},
                          {s[1], s[2], s[3]},
                          {s[2], s[3], s[4]}};
  double       m2[3][3];
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = 0; j < 3; ++j)
      m2[i][j] = j == 2 ? r[i] : m[i][j];
  return 2 * det(m2) / det(m);
}

#endif
