// Hostile input, continued: unusable output directories, a directory in
// use by another run, work that would never end, non-finite initial
// velocities, values that name no entry, nested error messages and a
// parameter file name that is not UTF-8 all end with exit code 2 and a
// message naming the entry and the file, and nothing is written. An
// earlier run's files are removed (others are kept), Output/Time interval
// writes output by simulated time, and summary.json carries the version.
#include <psmpm/base/version.h>

#include "../app_tests.h"

#include <filesystem>
#include <sstream>
#include <unistd.h>

namespace fs = std::filesystem;

struct Case
{
  std::string              name;
  std::vector<std::string> args;
  std::vector<std::string> must_mention;
};

/// No deal.II source location or stack trace in a message.
bool
clean(const std::string &message)
{
  return message.find("Stacktrace") == std::string::npos &&
         message.find("An error occurred in line") == std::string::npos &&
         message.find("Can't convert") == std::string::npos;
}

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");
  const std::string                quick = "Time/End time=0.001";

  std::ofstream("a_file") << "not a directory\n";
  std::ofstream("case.prm") << "set Output directory = never\n";
  fs::remove_all("never");
  fs::remove_all("busy");
  fs::create_directories("busy");
  // A lock held by a live process (this one).
  std::ofstream("busy/psmpm.lock") << getpid() << " " << [] {
    char buf[256] = {};
    gethostname(buf, sizeof(buf) - 1);
    return std::string(buf);
  }() << "\n";

  const std::vector<Case> cases = {
    {"output directory is a file",
     {"case.prm", "--set", "Output directory=a_file"},
     {"Output directory", "a_file", "not a directory", "case.prm"}},
    {"output directory inside a file",
     {"case.prm", "--set", "Output directory=a_file/sub", "--set", quick},
     {"Output directory", "a_file/sub", "cannot create", "case.prm"}},
    // No permission, even for root: sysfs refuses new directories; in
    // /proc/self no file can be created.
    {"output directory without permission",
     {"case.prm", "--set", "Output directory=/sys/psmpm_test", "--set", quick},
     {"Output directory", "/sys/psmpm_test", "cannot create", "case.prm"}},
    {"output directory where no file can be created",
     {"case.prm", "--set", "Output directory=/proc/self", "--set", quick},
     {"Output directory", "/proc/self", "cannot create", "case.prm"}},
    {"empty output directory",
     {"case.prm", "--set", "Output directory="},
     {"Output directory", "empty", "case.prm"}},
    {"output directory in use",
     {"case.prm", "--set", "Output directory=busy", "--set", quick},
     {"Output directory", "busy", "another psmpm run", "psmpm.lock"}},
    {"end time 1e12 at a fixed step",
     {"case.prm", "--set", "Time/End time=1e12"},
     {"Time/End time", "Limits/Maximum steps", "Allow large runs", "case.prm"}},
    {"automatic step of 1e-14 s",
     {"case.prm",
      "--set",
      "Time/Time step=0",
      "--set",
      "Material/Young's modulus=1e30",
      "--set",
      "Reference solution/Type=none"},
     {"Time/End time", "Limits/Maximum steps", "Allow large runs"}},
    {"ULFEM elements = 1e9",
     {"case.prm",
      "--set",
      "Reference solution/Type=vibrating bar ulfem",
      "--set",
      "Reference solution/ULFEM elements=1000000000"},
     {"Reference solution/ULFEM elements", "Allow large runs", "case.prm"}},
    {"Blocks x = 1e7",
     {"case.prm",
      "--set",
      "Mesh/Blocks x=10000000",
      "--set",
      "Particles/Per block x=1",
      "--set",
      "Particles/Per block y=1"},
     {"Mesh/Blocks x", "Limits/Maximum memory", "Allow large runs"}},
    {"output every step of a long run",
     {"case.prm",
      "--set",
      "Time/End time=20",
      "--set",
      "Output/Interval=1",
      "--set",
      "Mesh/Blocks x=100",
      "--set",
      "Mesh/Blocks y=10"},
     {"Output/Interval", "Limits/Maximum output", "Allow large runs"}},
    {"initial velocity 1/0",
     {"case.prm", "--set", "Initial conditions/Velocity=1/0; 0"},
     {"Initial conditions/Velocity", "1/0", "not finite", "case.prm"}},
    {"initial velocity nan",
     {"case.prm", "--set", "Initial conditions/Velocity=nan; 0"},
     {"Initial conditions/Velocity", "nan", "case.prm"}},
    {"function constant nan",
     {"case.prm",
      "--set",
      "Initial conditions/Function constants=v0=nan, L=25"},
     {"Initial conditions/Velocity", "v0=nan", "not finite", "case.prm"}},
    {"function constant not a number",
     {"case.prm",
      "--set",
      "Initial conditions/Function constants=v0=abc, L=25"},
     {"Initial conditions/Function constants", "abc", "case.prm"}},
    {"unknown boundary (nested message)",
     {"case.prm", "--set", "Boundary conditions/Fixed x=west"},
     {"Boundary conditions/Fixed x", "west", "case.prm"}},
    {"bad expression (nested message)",
     {"case.prm", "--set", "Initial conditions/Velocity=sin(; 0"},
     {"Initial conditions/Velocity", "case.prm"}},
  };
  for (const auto &c : cases)
    {
      std::string screen, message;
      const int   code     = run_app(c.args, screen, message);
      bool        mentions = true;
      for (const auto &m : c.must_mention)
        mentions = mentions && message.find(m) != std::string::npos;
      out << c.name << ": exit code " << code << std::endl;
      PSMPM_CHECK(out, code == psmpm::App::bad_input);
      PSMPM_CHECK(out, mentions);
      PSMPM_CHECK(out, clean(message));
      PSMPM_CHECK(out, !fs::exists("never") && !fs::exists("a_file/sub"));
      if (!mentions || !clean(message) || code != psmpm::App::bad_input)
        out << "  message: " << message;
    }
  // The lock of the other run is left alone.
  PSMPM_CHECK(out, fs::exists("busy/psmpm.lock"));

  // The same limits with the override: valid.
  {
    std::string screen, message;
    const int   code = run_app({"case.prm",
                                "--set",
                                "Time/End time=1e12",
                                "--set",
                                "Limits/Allow large runs=true",
                                "--validate"},
                             screen,
                             message);
    out << "end time 1e12 with Allow large runs: exit code " << code
        << std::endl;
    PSMPM_CHECK(out, code == psmpm::App::success);
  }

  // A stale lock (a process that no longer exists) is taken over; the
  // files of the earlier run go, other files stay; the lock is released.
  {
    fs::remove_all("stale");
    fs::create_directories("stale");
    char host[256] = {};
    gethostname(host, sizeof(host) - 1);
    std::ofstream("stale/psmpm.lock") << 99999999 << " " << host << "\n";
    std::ofstream("stale/particles-00999.000.vtu") << "old";
    std::ofstream("stale/statistics.txt") << "old";
    std::ofstream("stale/notes.txt") << "mine";
    std::string screen, message;
    const int   code = run_app({"--set",
                                "Output directory=stale",
                                "--set",
                                quick,
                                "--set",
                                "Output/Time interval=0.0002"},
                             screen,
                             message);
    out << "stale lock: exit code " << code << std::endl;
    PSMPM_CHECK(out, code == psmpm::App::success);
    PSMPM_CHECK(out, !fs::exists("stale/psmpm.lock"));
    PSMPM_CHECK(out, !fs::exists("stale/particles-00999.000.vtu"));
    PSMPM_CHECK(out, fs::exists("stale/notes.txt"));
    PSMPM_CHECK(out, read_file("stale/statistics.txt") != "old");
    // Output at steps 0, 20, 40, 60, 80 and 100 (dt = 1e-5).
    unsigned int n_outputs = 0;
    for (const auto &e : fs::directory_iterator("stale"))
      n_outputs += e.path().extension() == ".pvtu" &&
                   e.path().filename().string().rfind("particles-", 0) == 0;
    out << "particle outputs with Time interval = 0.0002: " << n_outputs
        << std::endl;
    PSMPM_CHECK(out, fs::exists("stale/particles-00020.pvtu"));
    PSMPM_CHECK(out, fs::exists("stale/particles-00100.pvtu"));
    const std::string summary = read_file("stale/summary.json");
    PSMPM_CHECK(out,
                summary.find("\"version\": \"" + psmpm::version() + "\"") !=
                  std::string::npos);
    const std::string log = read_file("stale/log.txt");
    PSMPM_CHECK(out, log.find("output in") != std::string::npos);
    PSMPM_CHECK(out,
                log.find("\"status\": \"completed\"") != std::string::npos);
  }

  // A parameter file name that is not UTF-8 (Latin-1 "é") still gives
  // valid JSON: the byte is escaped.
  {
    fs::remove_all("latin1");
    const std::string name = "sc\xe9ne.prm";
    std::ofstream(name) << "set Output directory = latin1\n"
                        << "subsection Time\n set End time = 0.0001\nend\n";
    std::string screen, message;
    const int   code = run_app({name}, screen, message);
    out << "non-UTF-8 file name: exit code " << code << std::endl;
    PSMPM_CHECK(out, code == psmpm::App::success);
    const std::string summary = read_file("latin1/summary.json");
    PSMPM_CHECK(out,
                summary.find("\"parameter_file\": \"sc\\u00e9ne.prm\"") !=
                  std::string::npos);
    bool ascii = true;
    for (const char ch : summary)
      ascii = ascii && static_cast<unsigned char>(ch) < 0x80;
    PSMPM_CHECK(out, ascii);
  }
}
