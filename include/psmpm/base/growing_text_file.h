// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_base_growing_text_file_h
#define psmpm_base_growing_text_file_h

#include <cstdint>
#include <functional>
#include <ostream>
#include <string>

namespace psmpm
{
  /**
   * A text file of a header and rows that only grow (statistics.txt,
   * tracked_particle.txt), written at every output of a run.
   *
   * Rewriting it whole at every output made the output phase quadratic
   * in the run's length: the large vibrating bar (35,000 rows, 8
   * outputs) spent most of its 0.58 s of output formatting the same rows
   * again, and a run with an output every 100 of 10^6 steps would write
   * terabytes. write() appends only the rows added since the last call,
   * as long as that gives the file a complete rewrite would: the layout
   * (what fixes the text of the rows already written, such as column
   * widths) is unchanged and the file is still the one this object left
   * (same size). Otherwise, and at the first call (a resumed run's rows
   * may differ from the file's), it rewrites the file atomically
   * (write_atomically()).
   *
   * An append is not atomic: a reader may see the last row in part while
   * it is written, and a failed write (disk full) throws ExcWriteFailed
   * and leaves the next call to rewrite the file.
   */
  class GrowingTextFile
  {
  public:
    explicit GrowingTextFile(const std::string &file);

    /**
     * Bring the file up to date with @p n_rows rows. @p header writes
     * everything before the first row; @p rows writes rows [begin, end).
     * @p layout is any text that changes whenever the text of a row
     * already written would change.
     */
    void
    write(
      const std::string                         &layout,
      const unsigned int                         n_rows,
      const std::function<void(std::ostream &)> &header,
      const std::function<
        void(std::ostream &, const unsigned int, const unsigned int)> &rows);

    const std::string &
    name() const;

  private:
    std::string file;
    /// What the last successful call left: layout, rows, bytes.
    std::string   written_layout;
    unsigned int  written_rows  = 0;
    std::uint64_t written_bytes = 0;
    bool          written       = false;
  };
} // namespace psmpm

#endif
