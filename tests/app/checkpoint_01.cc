// Checkpoint and resume are bit-identical in serial: a run of N steps
// with Checkpoint/Interval = k keeps its last two checkpoints; a copy of
// its output directory without the last one is what a run killed after
// the checkpoint of step N - k leaves (statistics rows, VTU outputs and
// tracked history beyond it). `--resume` continues from there and must
// reproduce statistics.txt (but for the wall_time column), the .pvd
// series, tracked_particle.txt and every entry of the final checkpoint
// (particles, time, step, dt and the history of every component) bit for
// bit.
//
// Two scenes: (a) the vibrating bar (consistent mass, musl) with the
// ULFEM reference (advanced alongside the run: replayed on resume), a
// tracked particle, error norms every 3 steps and an output time interval;
// (b) a neo-Hookean block slumping over empty cells with the automatic
// time step, apic and the extrapolate mass strategy (whose hysteresis is
// part of the checkpoint); (c) the 1D bar with the OTM scheme, whose moved
// grid is part of the checkpoint.
#include "../checkpoint_tests.h"

namespace fs = std::filesystem;

/// The step of checkpoint file @p f.
unsigned int
step_of(const std::string &f)
{
  const std::string name = fs::path(f).filename().string();
  return std::stoul(name.substr(11));
}

void
check(std::ostream            &out,
      const std::string       &name,
      std::vector<std::string> scene)
{
  const std::string a = name + "_a", b = name + "_b";
  fs::remove_all(a);
  std::vector<std::string> args = scene;
  args.insert(args.end(), {"--set", "Output directory=" + a});
  std::string screen, message;
  int         code = run_app(args, screen, message);
  out << name << ": uninterrupted run: exit code " << code << std::endl;
  const auto files = psmpm::Simulator::Checkpoint::list(a);
  out << name << ": checkpoints kept:";
  for (const auto &f : files)
    out << " " << fs::path(f).filename().string();
  out << std::endl;
  if (files.size() != 2)
    return;
  const unsigned int last = step_of(files[0]), resumed = step_of(files[1]);

  // The run as it is left when killed after the checkpoint of step
  // `resumed` (with later rows, outputs and a half-written checkpoint).
  copy_directory(a, b);
  fs::remove(b + "/" + psmpm::Simulator::Checkpoint::file_name(last));
  std::ofstream(b + "/checkpoint.h5.tmp") << "half a checkpoint";

  args = scene;
  args.insert(args.end(), {"--set", "Output directory=" + b, "--resume"});
  code = run_app(args, screen, message);
  out << name << ": resumed run: exit code " << code << std::endl;
  if (code != 0)
    out << message << std::endl;
  const std::string summary = read_file(b + "/summary.json");
  PSMPM_CHECK(out,
              summary.find("\"resumed_step\": " + std::to_string(resumed)) !=
                std::string::npos);
  PSMPM_CHECK(out, !fs::exists(b + "/checkpoint.h5.tmp"));

  const auto rows_a = statistics_rows(a + "/statistics.txt");
  const auto rows_b = statistics_rows(b + "/statistics.txt");
  out << name << ": statistics rows " << rows_a.size() << " and "
      << rows_b.size() << std::endl;
  PSMPM_CHECK(out, rows_a == rows_b);
  // The .pvd records (but for the time of day deal.II writes into them).
  for (const std::string pvd : {"/particles.pvd", "/grid.pvd"})
    PSMPM_CHECK(out,
                without_date(read_file(a + pvd)) ==
                  without_date(read_file(b + pvd)));
  PSMPM_CHECK(out,
              read_file(a + "/tracked_particle.txt") ==
                read_file(b + "/tracked_particle.txt"));

  const std::string final_name =
    "/" + psmpm::Simulator::Checkpoint::file_name(last);
  const auto ca     = psmpm::Archive::read_hdf5(a + final_name);
  const auto cb     = psmpm::Archive::read_hdf5(b + final_name);
  const auto differ = differing_entries(ca, cb);
  out << name
      << ": final checkpoint entries compared: " << ca.get_entries().size() - 3
      << ", differing: " << differ.size() << std::endl;
  for (const auto &d : differ)
    out << "  differs: " << d << std::endl;
  // The last particle output of both runs is the same file (but for the
  // time of day deal.II writes into it).
  const std::string vtu =
    "/particles-" + Utilities::int_to_string(last, 5) + ".000.vtu";
  PSMPM_CHECK(out,
              without_date(read_file(a + vtu)) ==
                without_date(read_file(b + vtu)));
}

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");

  check(out,
        "bar",
        {"--set",
         "Time/End time=0.0006",
         "--set",
         "Reference solution/Type=vibrating bar ulfem",
         "--set",
         "Reference solution/ULFEM elements=200",
         "--set",
         "Output/Tracked point=12.5, 1",
         "--set",
         "Output/Error interval=3",
         "--set",
         "Output/Time interval=0.00007",
         "--set",
         "Checkpoint/Interval=20"});

  check(out, "block", {"--set", "Geometry/Length=3",
                       "--set", "Geometry/Height=1.5",
                       "--set", "Mesh/Blocks x=6",
                       "--set", "Mesh/Blocks y=3",
                       "--set", "Material/Model=neo-hookean",
                       "--set", "Material/Density=1000",
                       "--set", "Material/Young's modulus=2e4",
                       "--set", "Material/Poisson's ratio=0.3",
                       "--set", "Particles/Per block x=3",
                       "--set", "Particles/Per block y=3",
                       "--set", "Particles/Region=0, 0, 1, 1",
                       "--set", "Initial conditions/Velocity=0; 0",
                       "--set", "Body force/Gravity=0, -9.81",
                       "--set", "Boundary conditions/Fixed x=left",
                       "--set", "Boundary conditions/Fixed y=bottom",
                       "--set", "Reference solution/Type=none",
                       "--set", "Time/End time=0.3",
                       "--set", "Time/Time step=0",
                       "--set", "Mass matrix/Type=extrapolate",
                       "--set", "Transfer/Scheme=apic",
                       "--set", "Output/Interval=4",
                       "--set", "Checkpoint/Interval=5"});

  // (c) OTM: the moved grid and the last nodal velocity are the scheme's
  // own state (TransferScheme::save/load).
  check(out,
        "otm",
        {std::string(PSMPM_SOURCE_DIR) + "/prm/otm_bar_1d.prm",
         "--set",
         "Time/End time=0.003",
         "--set",
         "Output/Interval=10",
         "--set",
         "Checkpoint/Interval=10"});
}
