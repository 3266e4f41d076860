// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// A contact run resumed from its checkpoint repeats the run without one
// bit for bit: the accumulated friction and normal works travel in the
// checkpoint (contact/), the rest of the contact state is rebuilt each
// step. The sliding block of prm/contact_sliding_block.prm (mu = 0.3) to
// 0.1 s, once in one go and once stopped at 0.05 s and resumed; every
// column of statistics.txt but the wall time is equal.
#include "../checkpoint_tests.h"
#include "../contact_tests.h"

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");
  std::string       screen;
  for (const auto &d : {"whole", "split"})
    std::filesystem::remove_all(d);
  const auto run = [&](const std::string              &directory,
                       const std::string              &end,
                       const std::vector<std::string> &extra) {
    std::vector<std::string> settings = {"Time/End time=" + end};
    settings.insert(settings.end(), extra.begin(), extra.end());
    return run_prm_scene(out,
                         "contact_sliding_block.prm",
                         directory,
                         settings,
                         screen);
  };
  PSMPM_CHECK(out, run("whole", "0.1", {}) == 0);
  PSMPM_CHECK(out, run("split", "0.05", {}) == 0);
  PSMPM_CHECK(out, run("split", "0.1", {"--resume"}) == 0);
  PSMPM_CHECK(out, screen.find("resumed from") != std::string::npos);
  const auto whole = statistics_rows("whole/statistics.txt"),
             split = statistics_rows("split/statistics.txt");
  out << "rows " << whole.size() << std::endl;
  PSMPM_CHECK(out, whole.size() > 100 && whole == split);
  PSMPM_CHECK(out,
              read_file("whole/statistics.txt").find("friction_work_1_2") !=
                std::string::npos);
}
