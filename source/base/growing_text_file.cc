// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/base/checked_file.h>
#include <psmpm/base/growing_text_file.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

namespace psmpm
{
  namespace
  {
    /// Size of @p file, or -1 if it cannot be read.
    std::uintmax_t
    size_of(const std::string &file)
    {
      std::error_code error;
      return std::filesystem::file_size(file, error);
    }
  } // namespace

  GrowingTextFile::GrowingTextFile(const std::string &file)
    : file(file)
  {
  }

  const std::string &
  GrowingTextFile::name() const
  {
    return file;
  }

  void
  GrowingTextFile::write(
    const std::string                         &layout,
    const unsigned int                         n_rows,
    const std::function<void(std::ostream &)> &header,
    const std::function<
      void(std::ostream &, const unsigned int, const unsigned int)> &rows)
  {
    const bool append = written && layout == written_layout &&
                        n_rows >= written_rows &&
                        size_of(file) == written_bytes;
    // Until the new state is known, the next call rewrites.
    written = false;
    if (append)
      {
        errno = 0;
        std::ofstream out(file, std::ios::binary | std::ios::app);
        if (!out.is_open())
          throw ExcWriteFailed(
            "cannot write " + file + ": " +
            (errno != 0 ? std::strerror(errno) : "cannot open it"));
        rows(out, written_rows, n_rows);
        check_written(out, file);
      }
    else
      write_atomically(file, [&](std::ostream &out) {
        header(out);
        rows(out, 0, n_rows);
      });
    written_bytes  = size_of(file);
    written_rows   = n_rows;
    written_layout = layout;
    written        = written_bytes != static_cast<std::uintmax_t>(-1);
  }
} // namespace psmpm
