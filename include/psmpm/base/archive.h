// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_base_archive_h
#define psmpm_base_archive_h

#include <boost/serialization/map.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace psmpm
{
  /**
   * Named arrays in memory, written to and read from one HDF5 file: the
   * content of a checkpoint. A name with slashes ("particles/position")
   * is a dataset in groups; every entry is one dataset of doubles,
   * unsigned 64-bit integers, bytes (uint8) or a variable-length string,
   * with a shape (rows x columns for a table of points or tensors).
   *
   * Components put what their future depends on under their own prefix
   * and read it back with get_*(), which throw ExcMessage naming the entry
   * when it is missing, of another type or of an unexpected size, so a
   * damaged or foreign file is reported rather than read as garbage.
   *
   * The file carries a checksum (FNV-1a over every entry's name, type,
   * shape and bytes) in the root attribute "psmpm_checksum": bit rot or a
   * partial copy that HDF5 itself would read without complaint is
   * rejected by read_hdf5().
   */
  class Archive
  {
  public:
    enum class Type : int
    {
      real    = 0,
      integer = 1,
      bytes   = 2,
      text    = 3
    };

    struct Entry
    {
      Type                       type = Type::real;
      std::vector<std::uint64_t> shape; ///< empty: one-dimensional
      std::vector<double>        reals;
      std::vector<std::uint64_t> integers;
      std::string                data; ///< bytes or text

      template <class Ar>
      void
      serialize(Ar &ar, const unsigned int)
      {
        ar &type &shape &reals &integers &data;
      }
    };

    /// @p columns > 0: a table of values.size() / columns rows.
    void
    put(const std::string         &name,
        const std::vector<double> &values,
        const unsigned int         columns = 0);
    void
    put(const std::string &name, const double value);
    void
    put_integers(const std::string                &name,
                 const std::vector<std::uint64_t> &values);
    void
    put_integer(const std::string &name, const std::uint64_t value);
    void
    put_bytes(const std::string &name, const std::string &bytes);
    void
    put_text(const std::string &name, const std::string &text);

    bool
    has(const std::string &name) const
    {
      return entries.count(name) > 0;
    }

    /// The doubles of @p name; @p size: the expected number (-1: any).
    const std::vector<double> &
    get(const std::string &name, const long long size = -1) const;
    double
    get_number(const std::string &name) const;
    const std::vector<std::uint64_t> &
    get_integers(const std::string &name, const long long size = -1) const;
    std::uint64_t
    get_integer(const std::string &name) const;
    const std::string &
    get_bytes(const std::string &name) const;
    const std::string &
    get_text(const std::string &name) const;

    const std::map<std::string, Entry> &
    get_entries() const
    {
      return entries;
    }

    /// Remove the entries whose names start with @p prefix.
    void
    erase_prefix(const std::string &prefix);

    /// Checksum of all entries (see the class documentation).
    std::uint64_t
    checksum() const;

    /**
     * Write every entry into the HDF5 file @p file (created or
     * truncated), close it and fsync it. Throws ExcWriteFailed naming
     * @p target (the file that @p file becomes when renamed; @p file if
     * empty) on any failure; the caller removes the partial file.
     */
    void
    write_hdf5(const std::string &file, const std::string &target = "") const;

    /**
     * Read every dataset of the HDF5 file @p file and check the checksum.
     * Throws ExcMessage naming the file and what is wrong.
     */
    static Archive
    read_hdf5(const std::string &file);

    template <class Ar>
    void
    serialize(Ar &ar, const unsigned int)
    {
      ar &entries;
    }

  private:
    const Entry &
    entry(const std::string &name, const Type type) const;

    std::map<std::string, Entry> entries;
  };
} // namespace psmpm

#endif
