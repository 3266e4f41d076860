// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_base_summary_h
#define psmpm_base_summary_h

#include <map>
#include <string>

namespace psmpm
{
  /**
   * The machine-readable outcome of a run, written as summary.json.
   * Keys may contain one dot to nest one level ("errors.L2" goes into
   * the object "errors"). Values keep their insertion type: numbers are
   * written with 17 significant digits, non-finite numbers as null.
   */
  class Summary
  {
  public:
    void
    set(const std::string &key, const double value);
    void
    set(const std::string &key, const std::string &value);
    void
    set_integer(const std::string &key, const long long value);

    bool
    has(const std::string &key) const;
    double
    get_number(const std::string &key) const;
    /// The first key (in key order) whose number is not finite (written
    /// as null), or "".
    std::string
    non_finite_key() const;

    /// The JSON text.
    std::string
    to_json() const;

    /// Write atomically (temporary file, then rename) to @p filename;
    /// throws ExcWriteFailed naming the file.
    void
    write(const std::string &filename) const;

  private:
    // key -> already formatted JSON value
    std::map<std::string, std::string> values;
    std::map<std::string, double>      numbers;
  };
} // namespace psmpm

#endif
