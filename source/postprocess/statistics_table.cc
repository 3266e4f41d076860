// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <psmpm/postprocess/statistics_table.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <sstream>

namespace psmpm
{
  namespace Postprocess
  {
    using namespace dealii;

    namespace
    {
      std::uint64_t
      bits_of(const double x)
      {
        std::uint64_t b;
        std::memcpy(&b, &x, sizeof b);
        return b;
      }

      double
      double_of(const std::uint64_t b)
      {
        double x;
        std::memcpy(&x, &b, sizeof x);
        return x;
      }

      /// What an std::ostream with std::setprecision(precision) and the
      /// scientific or fixed floatfield writes for @p x.
      std::string
      format_real(const double       x,
                  const bool         scientific,
                  const unsigned int precision)
      {
        char       buffer[400];
        const auto result =
          std::to_chars(buffer,
                        buffer + sizeof buffer,
                        x,
                        scientific ? std::chars_format::scientific :
                                     std::chars_format::fixed,
                        static_cast<int>(precision));
        if (result.ec != std::errc())
          {
            std::ostringstream s;
            s.precision(precision);
            s.setf(scientific ? std::ios::scientific : std::ios::fixed,
                   std::ios::floatfield);
            s << x;
            return s.str();
          }
        return std::string(buffer, result.ptr);
      }
    } // namespace

    void
    StatisticsTable::Column::format_pending() const
    {
      for (std::size_t i = formatted.size(); i < kinds.size(); ++i)
        {
          std::string s;
          switch (kinds[i])
            {
              case real:
                s = format_real(double_of(bits[i]), scientific, precision);
                break;
              // Integers as TableHandler writes them: digits, or in a
              // scientific column the number in scientific notation.
              case signed_integer:
                s = scientific ?
                      format_real(static_cast<double>(
                                    static_cast<std::int64_t>(bits[i])),
                                  true,
                                  precision) :
                      std::to_string(static_cast<std::int64_t>(bits[i]));
                break;
              case unsigned_integer:
                s =
                  scientific ?
                    format_real(static_cast<double>(bits[i]), true, precision) :
                    std::to_string(bits[i]);
                break;
              default:
                s = texts[bits[i]];
                if (s.empty())
                  s = "\"\"";
            }
          width = std::max(width, s.size());
          formatted.push_back(std::move(s));
        }
    }

    StatisticsTable::Column &
    StatisticsTable::column(const std::string &key)
    {
      // Rows repeat the order of the columns: try the one after the last.
      if (!columns.empty())
        {
          const unsigned int next = (last + 1) % columns.size();
          if (columns[next].name == key)
            return columns[last = next];
        }
      const auto it = index.find(key);
      if (it != index.end())
        return columns[last = it->second];
      index[key] = columns.size();
      columns.emplace_back();
      columns.back().name = key;
      last                = columns.size() - 1;
      return columns.back();
    }

    StatisticsTable::Column &
    StatisticsTable::existing_column(const std::string &key)
    {
      const auto it = index.find(key);
      AssertThrow(it != index.end(),
                  ExcMessage("statistics: no column '" + key + "'"));
      return columns[it->second];
    }

    void
    StatisticsTable::add(const std::string  &key,
                         const Kind          kind,
                         const std::uint64_t value)
    {
      Column &c = column(key);
      c.kinds.push_back(kind);
      c.bits.push_back(value);
    }

    void
    StatisticsTable::add_value(const std::string &key, const double value)
    {
      add(key, real, bits_of(value));
    }

    void
    StatisticsTable::add_value(const std::string &key, const unsigned int value)
    {
      add(key, unsigned_integer, value);
    }

    void
    StatisticsTable::add_value(const std::string &key, const int value)
    {
      add(key,
          signed_integer,
          static_cast<std::uint64_t>(static_cast<std::int64_t>(value)));
    }

    void
    StatisticsTable::add_value(const std::string  &key,
                               const std::uint64_t value)
    {
      add(key, unsigned_integer, value);
    }

    void
    StatisticsTable::add_value(const std::string &key, const std::string &text)
    {
      Column &c = column(key);
      c.kinds.push_back(StatisticsTable::text);
      c.bits.push_back(c.texts.size());
      c.texts.push_back(text);
    }

    std::string
    StatisticsTable::non_finite_in_last_entries() const
    {
      for (const Column &c : columns)
        if (!c.kinds.empty() && c.kinds.back() == real &&
            !std::isfinite(double_of(c.bits.back())))
          return c.name + " = " +
                 (std::isnan(double_of(c.bits.back())) ? "nan" :
                  double_of(c.bits.back()) > 0         ? "inf" :
                                                         "-inf");
      return "";
    }

    void
    StatisticsTable::set_scientific(const std::string &key,
                                    const bool         scientific)
    {
      Column &c = existing_column(key);
      if (c.scientific != scientific)
        {
          c.scientific = scientific;
          c.invalidate();
        }
    }

    void
    StatisticsTable::set_precision(const std::string &key,
                                   const unsigned int precision)
    {
      Column &c = existing_column(key);
      if (c.precision != precision)
        {
          c.precision = precision;
          c.invalidate();
        }
    }

    unsigned int
    StatisticsTable::n_rows() const
    {
      std::size_t n = 0;
      for (const auto &c : columns)
        n = std::max(n, c.kinds.size());
      return n;
    }

    void
    StatisticsTable::write_text(std::ostream &out) const
    {
      write_header(out);
      write_rows(out, 0, n_rows());
      out << std::flush;
    }

    void
    StatisticsTable::write_header(std::ostream &out) const
    {
      for (unsigned int j = 0; j < columns.size(); ++j)
        out << "# " << j + 1 << ": " << columns[j].name << '\n';
    }

    void
    StatisticsTable::write_rows(std::ostream      &out,
                                const unsigned int begin,
                                const unsigned int end) const
    {
      for (const auto &c : columns)
        c.format_pending();
      const unsigned int n = std::min(end, n_rows());
      std::string        line;
      for (unsigned int i = begin; i < n; ++i)
        {
          line.clear();
          for (const auto &c : columns)
            {
              const std::string  empty;
              const std::string &s =
                i < c.formatted.size() ? c.formatted[i] : empty;
              line.append(c.width > s.size() ? c.width - s.size() : 0, ' ');
              line += s;
              line += ' ';
            }
          line += '\n';
          out << line;
        }
    }

    std::string
    StatisticsTable::layout() const
    {
      for (const auto &c : columns)
        c.format_pending();
      const unsigned int n = n_rows();
      std::string        result;
      for (const auto &c : columns)
        {
          result += c.name;
          result += c.scientific ? " e" : " f";
          result +=
            std::to_string(c.precision) + ' ' + std::to_string(c.width) + '\n';
        }
      for (const auto &c : columns)
        if (c.kinds.size() != n)
          {
            for (const auto &d : columns)
              result += std::to_string(d.kinds.size()) + ' ';
            break;
          }
      return result;
    }

    namespace
    {
      void
      put_u64(std::string &out, const std::uint64_t v)
      {
        char b[8];
        std::memcpy(b, &v, 8);
        out.append(b, 8);
      }

      void
      put_string(std::string &out, const std::string &s)
      {
        put_u64(out, s.size());
        out += s;
      }

      /// Reads from bytes at position pos, refusing to run past the end.
      struct Reader
      {
        const std::string &bytes;
        std::size_t        pos = 0;

        std::uint64_t
        u64()
        {
          AssertThrow(pos + 8 <= bytes.size(),
                      ExcMessage("statistics: truncated table"));
          std::uint64_t v;
          std::memcpy(&v, bytes.data() + pos, 8);
          pos += 8;
          return v;
        }
        std::string
        string()
        {
          const std::uint64_t n = u64();
          AssertThrow(n <= bytes.size() - pos,
                      ExcMessage("statistics: truncated table"));
          std::string s = bytes.substr(pos, n);
          pos += n;
          return s;
        }
      };
    } // namespace

    std::string
    StatisticsTable::to_bytes() const
    {
      std::string out = "psmpm-statistics-1";
      put_u64(out, columns.size());
      for (const auto &c : columns)
        {
          put_string(out, c.name);
          put_u64(out, c.scientific);
          put_u64(out, c.precision);
          put_u64(out, c.kinds.size());
          out.append(reinterpret_cast<const char *>(c.kinds.data()),
                     c.kinds.size());
          for (const std::uint64_t b : c.bits)
            put_u64(out, b);
          put_u64(out, c.texts.size());
          for (const auto &t : c.texts)
            put_string(out, t);
        }
      return out;
    }

    void
    StatisticsTable::from_bytes(const std::string &bytes)
    {
      const std::string magic = "psmpm-statistics-1";
      AssertThrow(bytes.compare(0, magic.size(), magic) == 0,
                  ExcMessage("statistics: not a psmpm statistics table"));
      Reader                              r{bytes, magic.size()};
      std::vector<Column>                 new_columns(r.u64());
      std::map<std::string, unsigned int> new_index;
      for (unsigned int j = 0; j < new_columns.size(); ++j)
        {
          Column &c    = new_columns[j];
          c.name       = r.string();
          c.scientific = r.u64() != 0;
          c.precision  = r.u64();
          const auto n = r.u64();
          AssertThrow(n <= bytes.size() - r.pos,
                      ExcMessage("statistics: truncated table"));
          c.kinds.assign(bytes.begin() + r.pos, bytes.begin() + r.pos + n);
          r.pos += n;
          c.bits.resize(n);
          for (auto &b : c.bits)
            b = r.u64();
          c.texts.resize(r.u64());
          for (auto &t : c.texts)
            t = r.string();
          for (std::size_t i = 0; i < n; ++i)
            AssertThrow(c.kinds[i] <= StatisticsTable::text &&
                          (c.kinds[i] != StatisticsTable::text ||
                           c.bits[i] < c.texts.size()),
                        ExcMessage("statistics: damaged entry"));
          new_index[c.name] = j;
        }
      AssertThrow(r.pos == bytes.size(),
                  ExcMessage("statistics: trailing bytes"));
      columns = std::move(new_columns);
      index   = std::move(new_index);
      last    = columns.empty() ? 0 : columns.size() - 1;
    }
  } // namespace Postprocess
} // namespace psmpm
