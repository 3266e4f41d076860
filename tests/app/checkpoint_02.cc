// --resume when things are wrong: no checkpoint (exit code 2, saying so);
// a checkpoint.h5.tmp left by a run killed while writing one does not stop
// a resume from the last good checkpoint; a changed End time is allowed
// (the run is extended), a changed Material/Density is refused naming the
// entry, and so is an End time before the checkpoint's time; a damaged newest
// checkpoint is reported and the previous one used; with every checkpoint
// damaged or not HDF5 at all, exit code 2 naming the files. A fresh run
// (without --resume) removes the old checkpoints with the other files of the
// earlier run. Checkpoint/Wall interval writes checkpoints by wall time; a
// checkpoint that cannot be written ends the run with exit code 8 naming the
// file.
#include "../checkpoint_tests.h"

namespace fs = std::filesystem;

namespace
{
  /// Overwrite @p n bytes at a quarter, half and three quarters of
  /// @p file: at least one lands in the datasets' bytes (an HDF5 file
  /// also holds unused space, whose damage changes no content).
  void
  damage(const std::string &file, const std::size_t n)
  {
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    for (const std::size_t quarter : {1, 2, 3})
      {
        f.seekp(fs::file_size(file) / 4 * quarter);
        for (std::size_t i = 0; i < n; ++i)
          f.put(static_cast<char>(0x5a));
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");
  const std::vector<std::string>   scene = {"--set",
                                            "Output directory=run",
                                            "--set",
                                            "Time/End time=0.0001",
                                            "--set",
                                            "Checkpoint/Interval=5"};
  std::string                      screen, message;
  const auto with = [&scene](const std::vector<std::string> &more) {
    std::vector<std::string> args = scene;
    args.insert(args.end(), more.begin(), more.end());
    return args;
  };

  // Nothing to resume from.
  fs::remove_all("run");
  int code = run_app(with({"--resume"}), screen, message);
  out << "no checkpoint: exit code " << code << std::endl;
  PSMPM_CHECK(out, message.find("no checkpoint") != std::string::npos);
  PSMPM_CHECK(out, message.find("'run'") != std::string::npos);

  // 10 steps: checkpoints after steps 5 and 10.
  code = run_app(scene, screen, message);
  out << "run: exit code " << code << std::endl;
  PSMPM_CHECK(out, fs::exists("run/checkpoint-00000005.h5"));
  PSMPM_CHECK(out, fs::exists("run/checkpoint-00000010.h5"));

  // A run killed while writing a checkpoint leaves its temporary file.
  {
    const std::string good = read_file("run/checkpoint-00000010.h5");
    std::ofstream("run/checkpoint.h5.tmp", std::ios::binary)
      << good.substr(0, good.size() / 2);
  }
  // Extending the run is allowed: it continues from the state before the
  // last step (step 10, cut to land on the End time), kept in the final
  // checkpoint.
  code = run_app(with({"--set", "Time/End time=0.00015", "--resume"}),
                 screen,
                 message);
  out << "resume with a leftover checkpoint.h5.tmp and a later End time: "
         "exit code "
      << code << std::endl;
  std::string summary = read_file("run/summary.json");
  PSMPM_CHECK(out, summary.find("\"resumed_step\": 9") != std::string::npos);
  PSMPM_CHECK(out, summary.find("\"steps\": 15") != std::string::npos);
  PSMPM_CHECK(out, !fs::exists("run/checkpoint.h5.tmp"));
  PSMPM_CHECK(out, fs::exists("run/checkpoint-00000015.h5"));
  PSMPM_CHECK(out, !fs::exists("run/checkpoint-00000005.h5"));
  PSMPM_CHECK(out, statistics_rows("run/statistics.txt").size() == 16);

  // Another material is another scene.
  code = run_app(with({"--set",
                       "Time/End time=0.00015",
                       "--set",
                       "Material/Density=2",
                       "--resume"}),
                 screen,
                 message);
  out << "resume with another density: exit code " << code << std::endl;
  PSMPM_CHECK(out,
              message.find("Material/Density: '1' -> '2'") !=
                std::string::npos);
  PSMPM_CHECK(out,
              message.find("run/checkpoint-00000015.h5") != std::string::npos);

  // An End time before the checkpoint's time is refused, naming both and
  // the file, and the finished run's summary stays as it was.
  const std::string finished = read_file("run/summary.json");
  code                       = run_app(with({"--resume"}), screen, message);
  out << "resume with an End time before the checkpoint: exit code " << code
      << std::endl;
  PSMPM_CHECK(out,
              message.find("run/checkpoint-00000015.h5 is at t = 0.00015 "
                           "(step 15), after Time/End time = 0.0001") !=
                std::string::npos);
  PSMPM_CHECK(out, read_file("run/summary.json") == finished);

  // The newest checkpoint damaged: the previous one is used.
  damage("run/checkpoint-00000015.h5", 64);
  code = run_app(with({"--set", "Time/End time=0.00015", "--resume"}),
                 screen,
                 message);
  out << "resume with a damaged newest checkpoint: exit code " << code
      << std::endl;
  PSMPM_CHECK(out,
              message.find("checkpoint run/checkpoint-00000015.h5") !=
                std::string::npos);
  summary = read_file("run/summary.json");
  PSMPM_CHECK(out, summary.find("\"resumed_step\": 10") != std::string::npos);
  PSMPM_CHECK(out, summary.find("\"steps\": 15") != std::string::npos);

  // Every checkpoint damaged, and one that is not HDF5 at all.
  damage("run/checkpoint-00000010.h5", 64);
  damage("run/checkpoint-00000015.h5", 64);
  std::ofstream("run/checkpoint-00000099.h5") << "not a checkpoint\n";
  code = run_app(with({"--resume"}), screen, message);
  out << "resume with only damaged checkpoints: exit code " << code
      << std::endl;
  PSMPM_CHECK(out,
              message.find("run/checkpoint-00000099.h5: not an HDF5 file") !=
                std::string::npos);
  PSMPM_CHECK(out,
              message.find("run/checkpoint-00000010.h5") != std::string::npos);
  PSMPM_CHECK(out, !fs::exists("run/psmpm.lock"));

  // A fresh run starts over.
  code = run_app(with({"--set", "Checkpoint/Interval=0"}), screen, message);
  out << "fresh run: exit code " << code << std::endl;
  PSMPM_CHECK(out, !fs::exists("run/checkpoint-00000099.h5"));
  PSMPM_CHECK(out, !fs::exists("run/checkpoint-00000015.h5"));
  PSMPM_CHECK(out, psmpm::Simulator::Checkpoint::list("run").size() == 1);

  // Checkpoint/Wall interval: with a tiny one, a checkpoint after every
  // step (each announced on the screen).
  code                  = run_app(with({"--set",
                                        "Checkpoint/Interval=0",
                                        "--set",
                                        "Checkpoint/Wall interval=1e-9"}),
                 screen,
                 message);
  std::size_t announced = 0;
  for (auto at = screen.find("psmpm: checkpoint "); at != std::string::npos;
       at      = screen.find("psmpm: checkpoint ", at + 1))
    ++announced;
  out << "Wall interval = 1e-9 min: exit code " << code << ", " << announced
      << " checkpoints written" << std::endl;

  // A checkpoint that cannot be written ends the run with exit code 8,
  // naming the file; the earlier checkpoint stays.
  fs::remove_all("blocked");
  fs::create_directories("blocked/checkpoint.h5.tmp");
  code = run_app({"--set",
                  "Output directory=blocked",
                  "--set",
                  "Time/End time=0.0001",
                  "--set",
                  "Checkpoint/Interval=5"},
                 screen,
                 message);
  out << "checkpoint not writable: exit code " << code << std::endl;
  PSMPM_CHECK(out,
              message.find("cannot write blocked/checkpoint-00000005.h5") !=
                std::string::npos);
  PSMPM_CHECK(out,
              read_file("blocked/summary.json")
                  .find("\"status\": \"failed\"") != std::string::npos);
}
