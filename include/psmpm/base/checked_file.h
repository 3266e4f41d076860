// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_base_checked_file_h
#define psmpm_base_checked_file_h

#include <functional>
#include <ostream>
#include <stdexcept>
#include <string>

namespace psmpm
{
  /// An output file could not be written completely (disk full, no
  /// permission, a directory in the way); what() names the file.
  class ExcWriteFailed : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /// Flush @p out and throw ExcWriteFailed naming @p file unless every
  /// write into it succeeded.
  void
  check_written(std::ostream &out, const std::string &file);

  /**
   * Disk full on demand, for tests: with the environment variable
   * PSMPM_FAIL_WRITE_AT=n, the n-th checked write of this process (each
   * call of check_written() and each HDF5 checkpoint write counts) of a
   * file whose name contains PSMPM_FAIL_WRITE_MATCH (every file if unset)
   * throws ExcWriteFailed "cannot write <file>: No space left on device
   * (PSMPM_FAIL_WRITE_AT)". Without the variable: nothing.
   */
  void
  inject_write_failure(const std::string &file);

  /**
   * Write @p file completely or not at all: @p write fills "<file>.tmp",
   * which is checked, closed and renamed to @p file. A reader sees the
   * old file or the new one, never half of one. Throws ExcWriteFailed.
   */
  void
  write_atomically(const std::string                         &file,
                   const std::function<void(std::ostream &)> &write);
} // namespace psmpm

#endif
