// GrowingTextFile keeps statistics.txt equal to a complete rewrite of the
// table after every write, and appends (the file keeps its inode) where
// the rows already written keep their text: unchanged columns and widths.
// A wider entry, a new column, a column that fills rows already written,
// a format change or a file changed behind its back rewrite it (new
// inode, by write_atomically's rename).
#include <psmpm/base/growing_text_file.h>
#include <psmpm/postprocess/statistics_table.h>

#include "../tests.h"

#include <filesystem>
#include <sstream>
#include <sys/stat.h>

namespace
{
  using psmpm::Postprocess::StatisticsTable;

  std::string
  contents(const std::string &file)
  {
    std::ifstream     in(file, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }

  std::string
  rewritten(const StatisticsTable &table)
  {
    std::ostringstream s;
    table.write_text(s);
    return s.str();
  }

  ino_t
  inode(const std::string &file)
  {
    struct stat s;
    return ::stat(file.c_str(), &s) == 0 ? s.st_ino : 0;
  }

  /// Write, then report whether the file equals a rewrite and whether
  /// it was appended to (same inode as before).
  void
  write(psmpm::GrowingTextFile &file,
        const StatisticsTable  &table,
        std::ostream           &out,
        const std::string      &what)
  {
    const ino_t before = inode(file.name());
    file.write(
      table.layout(),
      table.n_rows(),
      [&](std::ostream &o) { table.write_header(o); },
      [&](std::ostream &o, const unsigned int b, const unsigned int e) {
        table.write_rows(o, b, e);
      });
    const bool appended = before != 0 && inode(file.name()) == before;
    out << what << ": rows " << table.n_rows() << ", "
        << (appended ? "appended" : "rewritten") << ", "
        << (contents(file.name()) == rewritten(table) ? "equal" : "DIFFERENT")
        << std::endl;
  }

  void
  add_row(StatisticsTable &table, const unsigned int step, const double e)
  {
    table.add_value("step", step);
    table.add_value("energy", e);
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out("output");
  return run_test([&]() {
    const std::string name = "growing_statistics.txt";
    std::filesystem::remove(name);
    psmpm::GrowingTextFile file(name);
    StatisticsTable        table;
    table.add_value("step", 0u);
    table.add_value("energy", 1.25);
    table.set_scientific("energy", true);
    write(file, table, out, "first write");
    add_row(table, 1, 1.5);
    add_row(table, 2, 1.75);
    write(file, table, out, "two rows more");
    write(file, table, out, "no new row");
    add_row(table, 3, -2.5);
    write(file, table, out, "a wider entry (the sign)");
    add_row(table, 4, 3.0);
    write(file, table, out, "same widths again");
    add_row(table, 5, 3.5);
    table.add_value("iterations", 7u);
    write(file, table, out, "a new column (one entry: the first row's)");
    for (unsigned int k = 0; k < 5; ++k)
      table.add_value("iterations", 8u);
    write(file, table, out, "the new column fills the rows written");
    add_row(table, 6, 4.0);
    table.add_value("iterations", 9u);
    write(file, table, out, "rectangular again");
    add_row(table, 7, 4.5);
    table.add_value("iterations", 9u);
    table.set_precision("energy", 6);
    write(file, table, out, "a new precision");
    add_row(table, 8, 5.0);
    table.add_value("iterations", 9u);
    {
      std::ofstream changed(name, std::ios::app);
      changed << "# a line from elsewhere\n";
    }
    write(file, table, out, "file changed behind its back");
    add_row(table, 9, 5.5);
    table.add_value("iterations", 9u);
    write(file, table, out, "appended after that");
    std::filesystem::remove(name);
    add_row(table, 10, 6.0);
    table.add_value("iterations", 9u);
    write(file, table, out, "file removed");
  });
}
