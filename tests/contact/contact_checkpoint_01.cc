// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// A contact run resumed from its checkpoint repeats the run without one
// bit for bit: the accumulated friction and normal works travel in the
// checkpoint (contact/), the rest of the contact state is rebuilt each
// step. The sliding block of prm/contact_sliding_block.prm (mu = 0.3) to
// 0.1 s, once in one go and once stopped at 0.05 s and resumed; every
// column of statistics.txt but the wall time is equal.
#include "../app_tests.h"

namespace
{
  /// statistics.txt of @p directory without its wall_time column.
  std::vector<std::string>
  rows(const std::string &directory)
  {
    std::ifstream            in(directory + "/statistics.txt");
    std::vector<std::string> r;
    std::string              line;
    while (std::getline(in, line))
      if (!line.empty() && line[0] != '#')
        {
          line.erase(line.find_last_not_of(' ') + 1);
          r.push_back(line.substr(0, line.find_last_of(' ')));
        }
    return r;
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");
  const std::string scene =
    std::string(PSMPM_SOURCE_DIR) + "/prm/contact_sliding_block.prm";
  std::string screen, errors;
  for (const auto &d : {"whole", "split"})
    std::filesystem::remove_all(d);
  const auto run = [&](const std::string              &directory,
                       const std::string              &end,
                       const std::vector<std::string> &extra) {
    std::vector<std::string> args = {scene,
                                     "--set",
                                     "Output directory=" + directory,
                                     "--set",
                                     "Time/End time=" + end};
    args.insert(args.end(), extra.begin(), extra.end());
    return run_app(args, screen, errors);
  };
  PSMPM_CHECK(out, run("whole", "0.1", {}) == 0);
  PSMPM_CHECK(out, run("split", "0.05", {}) == 0);
  PSMPM_CHECK(out, run("split", "0.1", {"--resume"}) == 0);
  PSMPM_CHECK(out, screen.find("resumed from") != std::string::npos);
  const auto whole = rows("whole"), split = rows("split");
  out << "rows " << whole.size() << std::endl;
  PSMPM_CHECK(out, whole.size() > 100 && whole == split);
  PSMPM_CHECK(out,
              read_file("whole/statistics.txt").find("friction_work_1_2") !=
                std::string::npos);
}
