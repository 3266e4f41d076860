// The thesis' unstable Powell-Sabin configurations, with the thesis'
// unadapted consistent mass matrix (soil column small on
// 2 x 16 blocks with dt = 1e-3; large on 1 x 8 blocks) end with status
// "unstable", a reason and the failed step in summary.json, the exit code
// of the energy monitor (4),
// and the output written before stays readable and finite.
#include "../app_tests.h"

#include <filesystem>
#include <sstream>

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");
  const std::string prm = std::string(PSMPM_SOURCE_DIR) + "/prm/";
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
    {"soil_column_small.prm",
     {"Mesh/Blocks x=2",
      "Mesh/Blocks y=16",
      "Time/End time=0.2",
      "Mass matrix/Type=consistent"}},
    {"soil_column_large.prm",
     {"Mesh/Blocks y=8", "Time/End time=0.15", "Mass matrix/Type=consistent"}}};
  for (const auto &c : cases)
    {
      std::vector<std::string> args = {prm + c.first,
                                       "--set",
                                       "Output directory=run",
                                       "--set",
                                       "Output/Interval=50",
                                       "--set",
                                       "Output/Test output=true"};
      for (const auto &s : c.second)
        args.insert(args.end(), {"--set", s});
      std::filesystem::remove_all("run");
      std::string       screen, errors;
      const int         code    = run_app(args, screen, errors);
      const std::string summary = read_file("run/summary.json");
      out << c.first << ": exit code " << code << std::endl;
      PSMPM_CHECK(out, code == psmpm::App::unstable_energy);
      PSMPM_CHECK(out,
                  summary.find("\"status\": \"unstable\"") !=
                    std::string::npos);
      PSMPM_CHECK(out, summary.find("\"reason\":") != std::string::npos);
      PSMPM_CHECK(out, summary.find("\"failed_step\":") != std::string::npos);
      // The series of outputs is complete and holds no NaN.
      const std::string pvd   = read_file("run/particles.pvd");
      const std::string stats = read_file("run/statistics.txt");
      PSMPM_CHECK(out, pvd.find("</VTKFile>") != std::string::npos);
      PSMPM_CHECK(out, stats.find("nan") == std::string::npos);
      bool pieces = true;
      for (const auto &f : std::filesystem::directory_iterator("run"))
        if (f.path().extension() == ".vtu")
          pieces = pieces &&
                   read_file(f.path()).find("</VTKFile>") != std::string::npos;
      PSMPM_CHECK(out, pieces);
    }
}
