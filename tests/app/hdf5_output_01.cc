// Output/Particle format = hdf5: the same scene is run with vtu and with
// hdf5 output. The hdf5 run writes one particles-<step>.h5 per output and
// particles.xdmf (no particle VTU/PVD; the grid stays VTU). Checked:
// particles.xdmf is well-formed XML with one Polyvertex grid per output,
// the times and steps of the VTU run's particles.pvd and every DataItem
// naming a dataset of that shape in its file; the datasets hold the
// particles of the VTU run at every output (to the VTU's Float32) and,
// at the last step, exactly the particles of that run's final checkpoint
// (positions as doubles, fields rounded to Float32 as in the patches);
// every VTU field is there (tensors as components). A run resumed from
// its checkpoint after a kill rewrites particles.xdmf as the uninterrupted
// run has it, removes particle HDF5 files of later steps and writes the
// same final file; resuming it with vtu output is refused. A file that cannot
// be written ends the run with exit code 8 naming it; hdf5 in 1D is bad input.
#include "../checkpoint_tests.h"
#include "../vtu_tests.h"
#include "../xdmf_tests.h"

#include <set>

namespace fs = std::filesystem;
using psmpm::Simulator::Checkpoint;

const std::vector<std::string> scene = {"--set",
                                        "Time/End time=0.0003",
                                        "--set",
                                        "Reference solution/Type=none",
                                        "--set",
                                        "Output/Interval=10",
                                        "--set",
                                        "Checkpoint/Interval=20"};

std::vector<std::string>
with(const std::vector<std::string> &more)
{
  std::vector<std::string> args = scene;
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

/// The names of the point data arrays of a VTU piece.
std::vector<std::string>
vtu_fields(const std::string &vtu)
{
  std::vector<std::string> names;
  const auto               begin = vtu.find("<PointData");
  const auto               end   = vtu.find("</PointData>");
  for (auto at = vtu.find("Name=\"", begin); at < end;
       at      = vtu.find("Name=\"", at + 1))
    names.push_back(vtu.substr(at + 6, vtu.find('"', at + 6) - at - 6));
  return names;
}

/// Largest difference between the first @p columns of each row of @p h5
/// and the VTU array @p floats (@p stride values per point), relative to
/// the largest value.
double
float_difference(const H5Table            &h5,
                 const std::vector<float> &floats,
                 const unsigned int        stride,
                 const unsigned int        columns)
{
  if (floats.size() != h5.rows * stride)
    return 1;
  double scale = 0, diff = 0;
  for (std::uint64_t i = 0; i < h5.rows; ++i)
    for (unsigned int c = 0; c < columns; ++c)
      {
        scale = std::max(scale, std::abs(h5(i, c)));
        diff  = std::max(diff, std::abs(h5(i, c) - floats[i * stride + c]));
      }
  return scale > 0 ? diff / scale : diff;
}

/// Every dataset that @p grid names in @p directory, equal in @p a and
/// @p b (bit for bit).
bool
same_datasets(const XdmfGrid &grid, const std::string &a, const std::string &b)
{
  std::vector<XdmfItem> items = {grid.nodes, grid.cells};
  for (const auto &[name, item] : grid.attributes)
    items.push_back(item);
  for (const auto &item : items)
    if (read_h5_table(a + "/" + item.file, item.dataset).values !=
        read_h5_table(b + "/" + item.file, item.dataset).values)
      return false;
  return true;
}

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");
  std::string                      screen, message;
  for (const std::string d : {"vtu", "hdf5", "hdf5_resumed", "blocked"})
    fs::remove_all(d);

  int code = run_app(with({"--set", "Output directory=vtu"}), screen, message);
  out << "vtu run: exit code " << code << std::endl;
  code = run_app(with({"--set",
                       "Output directory=hdf5",
                       "--set",
                       "Output/Particle format=hdf5"}),
                 screen,
                 message);
  out << "hdf5 run: exit code " << code << std::endl;
  if (code != 0)
    out << message << std::endl;

  // Which files: the particle series in HDF5/XDMF only, the grid in VTU.
  unsigned int n_h5 = 0, n_particle_vtu = 0;
  for (const auto &e : fs::directory_iterator("hdf5"))
    {
      const std::string name = e.path().filename().string();
      n_h5 += name.rfind("particles-", 0) == 0 && e.path().extension() == ".h5";
      n_particle_vtu +=
        name.rfind("particles-", 0) == 0 &&
        (e.path().extension() == ".vtu" || e.path().extension() == ".pvtu");
    }
  PSMPM_CHECK(out, fs::exists("hdf5/particles.xdmf"));
  PSMPM_CHECK(out, !fs::exists("hdf5/particles.pvd"));
  PSMPM_CHECK(out, n_particle_vtu == 0);
  PSMPM_CHECK(out, fs::exists("hdf5/grid.pvd"));
  PSMPM_CHECK(out, !fs::exists("vtu/particles.xdmf"));

  const auto pvd   = read_pvd("vtu/particles.pvd");
  const auto grids = read_xdmf("hdf5/particles.xdmf"); // throws if not XML
  out << "outputs: particles.pvd " << pvd.size() << ", particles.xdmf "
      << grids.size() << ", particle HDF5 files " << n_h5 << std::endl;
  PSMPM_CHECK(out, grids.size() == pvd.size() && n_h5 == pvd.size());
  PSMPM_CHECK(out, pvd.size() >= 3);

  const unsigned int last_step = output_step(pvd.back().second);
  const auto         last =
    psmpm::Archive::read_hdf5("vtu/" + Checkpoint::file_name(last_step));
  const auto         &ids = last.get_integers("particles/id");
  const std::uint64_t n   = ids.size();

  bool times = true, names = true, shapes = true, values = true;
  for (std::size_t k = 0; k < std::min(pvd.size(), grids.size()); ++k)
    {
      const XdmfGrid    &g    = grids[k];
      const unsigned int step = output_step(pvd[k].second);
      // particles.pvd keeps 12 digits.
      times = times && std::abs(g.time - pvd[k].first) <=
                         1e-11 * std::max(1e-3, std::abs(pvd[k].first));
      const std::string file =
        "particles-" + Utilities::int_to_string(step, 5) + ".h5";
      std::vector<XdmfItem> items = {g.nodes, g.cells};
      for (const auto &[name, item] : g.attributes)
        items.push_back(item);
      for (const auto &item : items)
        {
          names           = names && item.file == file;
          const H5Table t = read_h5_table("hdf5/" + item.file, item.dataset);
          shapes = shapes && t.rows == item.rows && t.columns == item.columns;
        }
      shapes = shapes && g.topology == "Polyvertex" && g.n_elements == n &&
               g.nodes.rows == n && g.nodes.columns == 2;

      // The particles of the VTU run at the same step.
      const std::string vtu = read_file(
        "vtu/particles-" + Utilities::int_to_string(step, 5) + ".000.vtu");
      const std::string h5    = "hdf5/" + file;
      const double d_position = float_difference(read_h5_table(h5, "nodes"),
                                                 read_floats(vtu, "<Points>"),
                                                 3,
                                                 2);
      const double d_velocity =
        float_difference(read_h5_table(h5, "velocity"),
                         read_floats(vtu, "Name=\"velocity\""),
                         3,
                         3);
      const double d_mass = float_difference(read_h5_table(h5, "mass"),
                                             read_floats(vtu, "Name=\"mass\""),
                                             1,
                                             1);
      values =
        values && d_position < 1e-6 && d_velocity < 1e-6 && d_mass < 1e-6;
      if (k == 0)
        {
          // Every field of the VTU output, tensors as their components.
          std::vector<std::string> missing;
          for (const auto &f : vtu_fields(vtu))
            if (g.attributes.count(f) == 0 &&
                g.attributes.count(f + "_xx") == 0)
              missing.push_back(f);
          out << "VTU fields missing in the HDF5 output: " << missing.size()
              << std::endl;
          for (const auto &m : missing)
            out << "  missing: " << m << std::endl;
          out << "HDF5 fields:";
          for (const auto &[name, item] : g.attributes)
            out << " " << name << "(" << item.columns << ")";
          out << std::endl;
        }
    }
  PSMPM_CHECK(out, times);
  PSMPM_CHECK(out, names);
  PSMPM_CHECK(out, shapes);
  PSMPM_CHECK(out, values);

  // The last output against the VTU run's final checkpoint, exactly.
  {
    const std::string h5 =
      "hdf5/particles-" + Utilities::int_to_string(last_step, 5) + ".h5";
    const H5Table id = read_h5_table(h5, "id"), x = read_h5_table(h5, "nodes"),
                  v      = read_h5_table(h5, "velocity"),
                  m      = read_h5_table(h5, "mass");
    const auto &position = last.get("particles/position");
    const auto &velocity = last.get("particles/velocity");
    const auto &mass     = last.get("particles/mass");
    std::map<std::uint64_t, std::size_t> where;
    for (std::size_t i = 0; i < n; ++i)
      where[ids[i]] = i;
    bool exact = id.rows == n && where.size() == n;
    for (std::uint64_t i = 0; exact && i < id.rows; ++i)
      {
        const auto it = where.find(static_cast<std::uint64_t>(id(i, 0)));
        if (it == where.end())
          {
            exact = false;
            break;
          }
        // Positions are the patches' vertices (doubles); field values
        // pass through the patches' Float32 table, as for VTU.
        const std::size_t j = it->second;
        exact =
          exact && m(i, 0) == static_cast<float>(mass[j]) && v(i, 2) == 0.;
        for (unsigned int d = 0; d < 2; ++d)
          exact = exact && x(i, d) == position[2 * j + d] &&
                  v(i, d) == static_cast<float>(velocity[2 * j + d]);
      }
    out << "last output (step " << last_step << "): " << id.rows
        << " particles, checkpoint of the VTU run: " << n << std::endl;
    PSMPM_CHECK(out, exact);
  }

  // A run killed after the checkpoint of step 20: its directory holds the
  // outputs of later steps (and one of a step the run never reached).
  copy_directory("hdf5", "hdf5_resumed");
  fs::remove("hdf5_resumed/" + Checkpoint::file_name(last_step));
  fs::copy_file("hdf5/particles-00000.h5", "hdf5_resumed/particles-00099.h5");
  code = run_app(with({"--set",
                       "Output directory=hdf5_resumed",
                       "--set",
                       "Output/Particle format=hdf5",
                       "--resume"}),
                 screen,
                 message);
  out << "resumed run: exit code " << code << std::endl;
  PSMPM_CHECK(out,
              read_file("hdf5/particles.xdmf") ==
                read_file("hdf5_resumed/particles.xdmf"));
  PSMPM_CHECK(out, !fs::exists("hdf5_resumed/particles-00099.h5"));
  PSMPM_CHECK(out, same_datasets(grids.back(), "hdf5", "hdf5_resumed"));
  PSMPM_CHECK(out,
              differing_entries(psmpm::Archive::read_hdf5(
                                  "hdf5/" + Checkpoint::file_name(last_step)),
                                psmpm::Archive::read_hdf5(
                                  "hdf5_resumed/" +
                                  Checkpoint::file_name(last_step)))
                .empty());

  // The series is of one format: resuming with the other is refused.
  code = run_app(with({"--set", "Output directory=hdf5_resumed", "--resume"}),
                 screen,
                 message);
  out << "resumed with vtu: exit code " << code << std::endl;
  PSMPM_CHECK(out, code == psmpm::App::bad_input);
  PSMPM_CHECK(out,
              message.find("Output/Particle format: 'hdf5' -> 'vtu'") !=
                std::string::npos);

  // A directory in the way of the first file: exit code 8 naming it, and
  // no series that names a missing file.
  fs::create_directories("blocked/particles-00000.h5.tmp");
  code = run_app(with({"--set",
                       "Output directory=blocked",
                       "--set",
                       "Output/Particle format=hdf5"}),
                 screen,
                 message);
  out << "blocked: exit code " << code << std::endl;
  PSMPM_CHECK(out, code == psmpm::App::write_failed);
  PSMPM_CHECK(out,
              message.find("cannot write blocked/particles-00000.h5") !=
                std::string::npos);
  PSMPM_CHECK(out, !fs::exists("blocked/particles.xdmf"));
  PSMPM_CHECK(out, !fs::exists("blocked/particles-00000.h5"));

  // HDF5 stores 2 or 3 coordinates: 1D is refused before the run.
  code = run_app({std::string(PSMPM_SOURCE_DIR) + "/prm/vibrating_bar_1d.prm",
                  "--set",
                  "Output/Particle format=hdf5",
                  "--validate"},
                 screen,
                 message);
  out << "1D: exit code " << code << std::endl;
  PSMPM_CHECK(out, code == psmpm::App::bad_input);
  PSMPM_CHECK(out, message.find("Output/Particle format") != std::string::npos);
}
