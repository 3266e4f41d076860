// ---------------------------------------------------------------------
// psmpm: reading back the particle HDF5/XDMF output (tests): datasets
// through the HDF5 C API, particles.xdmf and .pvd series through Boost's
// XML parser (which rejects XML that is not well-formed).
// ---------------------------------------------------------------------
#ifndef psmpm_tests_xdmf_tests_h
#define psmpm_tests_xdmf_tests_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>
#include <cstdint>
#include <hdf5.h>
#include <map>
#include <string>
#include <vector>

using namespace dealii;

/// A dataset of an HDF5 file as doubles, rows x columns.
struct H5Table
{
  std::vector<double> values;
  std::uint64_t       rows    = 0;
  std::uint64_t       columns = 0;

  double
  operator()(const std::uint64_t i, const std::uint64_t c) const
  {
    return values[i * columns + c];
  }
};

/// Dataset @p name of @p file (HDF5 converts integers to doubles).
inline H5Table
read_h5_table(const std::string &file, const std::string &name)
{
  H5Table     t;
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  AssertThrow(f >= 0, ExcMessage("cannot open " + file));
  const hid_t d = H5Dopen2(f, name.c_str(), H5P_DEFAULT);
  if (d < 0)
    {
      H5Fclose(f);
      AssertThrow(false, ExcMessage("no dataset " + name + " in " + file));
    }
  const hid_t space   = H5Dget_space(d);
  hsize_t     dims[2] = {0, 1};
  const int   rank    = H5Sget_simple_extent_ndims(space);
  AssertThrow(rank == 1 || rank == 2, ExcMessage("unexpected rank"));
  H5Sget_simple_extent_dims(space, dims, nullptr);
  t.rows    = dims[0];
  t.columns = rank == 2 ? dims[1] : 1;
  t.values.resize(t.rows * t.columns);
  const herr_t status = H5Dread(d,
                                H5T_NATIVE_DOUBLE,
                                H5S_ALL,
                                H5S_ALL,
                                H5P_DEFAULT,
                                t.values.data());
  H5Sclose(space);
  H5Dclose(d);
  H5Fclose(f);
  AssertThrow(status >= 0, ExcMessage("cannot read " + name));
  return t;
}

/// One DataItem of an XDMF grid: "file:/dataset" and its dimensions.
struct XdmfItem
{
  std::string   file, dataset;
  std::uint64_t rows = 0, columns = 0;
};

/// One grid (output) of particles.xdmf.
struct XdmfGrid
{
  double                          time = 0;
  std::string                     topology;
  std::uint64_t                   n_elements = 0;
  XdmfItem                        nodes, cells;
  std::map<std::string, XdmfItem> attributes;
};

namespace xdmf_tests
{
  using boost::property_tree::ptree;

  inline XdmfItem
  item(const ptree &data_item)
  {
    XdmfItem    it;
    std::string text = Utilities::trim(data_item.get_value<std::string>());
    const auto  at   = text.find(":/");
    AssertThrow(at != std::string::npos, ExcMessage("DataItem " + text));
    it.file         = text.substr(0, at);
    it.dataset      = text.substr(at + 2);
    const auto dims = Utilities::split_string_list(data_item.get<std::string>(
                                                     "<xmlattr>.Dimensions"),
                                                   ' ');
    AssertThrow(dims.size() == 2, ExcMessage("Dimensions"));
    it.rows    = std::stoull(dims[0]);
    it.columns = std::stoull(dims[1]);
    return it;
  }
} // namespace xdmf_tests

/// The grids of a temporal XDMF collection; throws if the file is not
/// well-formed XML or not laid out as Xdmf/Domain/Grid/Grid.
inline std::vector<XdmfGrid>
read_xdmf(const std::string &file)
{
  using xdmf_tests::ptree;
  ptree tree;
  boost::property_tree::read_xml(file, tree);
  const ptree &collection = tree.get_child("Xdmf.Domain.Grid");
  AssertThrow(collection.get<std::string>("<xmlattr>.CollectionType") ==
                "Temporal",
              ExcMessage("not a temporal collection"));
  std::vector<XdmfGrid> grids;
  for (const auto &[tag, g] : collection)
    {
      if (tag != "Grid")
        continue;
      XdmfGrid grid;
      grid.time     = g.get<double>("Time.<xmlattr>.Value");
      grid.topology = g.get<std::string>("Topology.<xmlattr>.TopologyType");
      grid.n_elements =
        g.get<std::uint64_t>("Topology.<xmlattr>.NumberOfElements");
      grid.nodes = xdmf_tests::item(g.get_child("Geometry.DataItem"));
      grid.cells = xdmf_tests::item(g.get_child("Topology.DataItem"));
      for (const auto &[t, a] : g)
        if (t == "Attribute")
          grid.attributes[a.get<std::string>("<xmlattr>.Name")] =
            xdmf_tests::item(a.get_child("DataItem"));
      grids.push_back(grid);
    }
  return grids;
}

/// The (time, file) records of a .pvd series.
inline std::vector<std::pair<double, std::string>>
read_pvd(const std::string &file)
{
  using xdmf_tests::ptree;
  ptree tree;
  boost::property_tree::read_xml(file, tree);
  std::vector<std::pair<double, std::string>> records;
  for (const auto &[tag, d] : tree.get_child("VTKFile.Collection"))
    if (tag == "DataSet")
      records.emplace_back(d.get<double>("<xmlattr>.timestep"),
                           d.get<std::string>("<xmlattr>.file"));
  return records;
}

/// The step in an output file name "particles-00020.pvtu" or
/// "particles-00020.h5".
inline unsigned int
output_step(const std::string &file)
{
  const auto dash = file.rfind('-');
  return std::stoul(file.substr(dash + 1));
}

#endif
