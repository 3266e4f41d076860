// Watching and stopping a run of the psmpm executable: it prints its
// version, the output directory and progress lines (also into log.txt);
// a second run into the same directory is refused while the first one
// lives (exit code 2); SIGTERM ends the first run after its step, with its
// output, summary.json "status": "interrupted" and exit code 143; the
// lock is released. SIGINT (Ctrl-C) gives exit code 130.
#include <psmpm/base/archive.h>
#include <psmpm/simulator/checkpoint.h>

#include "../app_tests.h"

#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <filesystem>
#include <spawn.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

extern char **environ;

namespace fs = std::filesystem;

/// Start psmpm with @p args, its screen output into @p screen_file.
pid_t
spawn(const std::vector<std::string> &args, const std::string &screen_file)
{
  std::vector<std::string> all = {PSMPM_EXECUTABLE};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char *> argv;
  for (auto &a : all)
    argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions,
                                   1,
                                   screen_file.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  pid_t pid = -1;
  if (posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ) != 0)
    pid = -1;
  posix_spawn_file_actions_destroy(&actions);
  return pid;
}

/// Wait for @p pid; its exit code, or 1000 + the signal that killed it.
int
wait_for(const pid_t pid)
{
  int status = 0;
  waitpid(pid, &status, 0);
  if (WIFEXITED(status))
    return WEXITSTATUS(status);
  return 1000 + WTERMSIG(status);
}

int
main()
{
  std::ofstream out("output");
  if (!fs::exists(PSMPM_EXECUTABLE))
    {
      out << "psmpm executable missing: build the target psmpm first"
          << std::endl;
      return 1;
    }

  // --version
  int code = wait_for(spawn({"--version"}, "version.txt"));
  out << "--version: exit code " << code << std::endl;
  PSMPM_CHECK(out, read_file("version.txt").rfind("psmpm ", 0) == 0);

  // A run that would take hours.
  fs::remove_all("long");
  const std::vector<std::string> args = {"--set",
                                         "Output directory=long",
                                         "--set",
                                         "Time/End time=1000",
                                         "--set",
                                         "Limits/Allow large runs=true",
                                         "--set",
                                         "Output/Progress interval=0.2"};
  const pid_t                    pid  = spawn(args, "screen.txt");
  PSMPM_CHECK(out, pid > 0);
  bool running = false;
  for (unsigned int i = 0; i < 600 && !running; ++i)
    {
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
      running = read_file("long/log.txt").find("ETA") != std::string::npos;
    }
  PSMPM_CHECK(out, running);

  // A second run into the same directory is refused.
  code = wait_for(spawn(args, "second.txt"));
  out << "second run into the same directory: exit code " << code << std::endl;
  PSMPM_CHECK(out,
              read_file("second.txt").find("another psmpm run") !=
                std::string::npos);
  PSMPM_CHECK(out, fs::exists("long/psmpm.lock"));

  kill(pid, SIGTERM);
  code = wait_for(pid);
  out << "SIGTERM: exit code " << code << std::endl;
  const std::string summary = read_file("long/summary.json");
  PSMPM_CHECK(out,
              summary.find("\"status\": \"interrupted\"") != std::string::npos);
  PSMPM_CHECK(out, summary.find("\"signal\": 15") != std::string::npos);
  PSMPM_CHECK(out, !fs::exists("long/psmpm.lock"));
  PSMPM_CHECK(out, fs::exists("long/statistics.txt"));
  PSMPM_CHECK(out, fs::exists("long/particles.pvd"));
  const std::string screen = read_file("screen.txt");
  const std::string log    = read_file("long/log.txt");
  PSMPM_CHECK(out, screen.find("output in") != std::string::npos);
  PSMPM_CHECK(out,
              screen.find("interrupted by signal 15") != std::string::npos);
  PSMPM_CHECK(out, log.find("interrupted by signal 15") != std::string::npos);
  PSMPM_CHECK(out, log.find("psmpm: step ") != std::string::npos);
  // The last step written is the one the run stopped at.
  const auto steps = summary.find("\"steps\": ");
  PSMPM_CHECK(out, steps != std::string::npos);
  if (steps != std::string::npos)
    {
      const unsigned int n = std::stoul(summary.substr(steps + 9));
      PSMPM_CHECK(out,
                  fs::exists("long/particles-" +
                             Utilities::int_to_string(n, 5) + ".pvtu"));
      // And a checkpoint of that step to resume from.
      const std::string checkpoint =
        "long/" + psmpm::Simulator::Checkpoint::file_name(n);
      PSMPM_CHECK(out, fs::exists(checkpoint));
      PSMPM_CHECK(out,
                  psmpm::Archive::read_hdf5(checkpoint)
                      .get_integer("simulator/step") == n);
    }

  // Ctrl-C: the same, with exit code 130.
  fs::remove_all("ctrl_c");
  std::vector<std::string> ctrl_c = args;
  ctrl_c[1]                       = "Output directory=ctrl_c";
  const pid_t pid2                = spawn(ctrl_c, "ctrl_c.txt");
  running                         = false;
  for (unsigned int i = 0; i < 600 && !running; ++i)
    {
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
      running = read_file("ctrl_c/log.txt").find("ETA") != std::string::npos;
    }
  PSMPM_CHECK(out, running);
  kill(pid2, SIGINT);
  code = wait_for(pid2);
  out << "SIGINT: exit code " << code << std::endl;
  const std::string summary2 = read_file("ctrl_c/summary.json");
  PSMPM_CHECK(out,
              summary2.find("\"status\": \"interrupted\"") !=
                std::string::npos);
  PSMPM_CHECK(out, summary2.find("\"signal\": 2") != std::string::npos);
}
