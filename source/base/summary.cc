// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <psmpm/base/checked_file.h>
#include <psmpm/base/summary.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <vector>

namespace psmpm
{
  namespace
  {
    /// Length of the valid UTF-8 sequence at s[i] (0: not valid).
    std::size_t
    utf8_length(const std::string &s, const std::size_t i)
    {
      const auto byte = [&](const std::size_t k) {
        return static_cast<unsigned char>(s[k]);
      };
      const unsigned char c    = byte(i);
      std::size_t         n    = 0;
      unsigned int        code = 0;
      if (c < 0x80)
        return 1;
      else if ((c & 0xE0) == 0xC0)
        n = 2, code = c & 0x1F;
      else if ((c & 0xF0) == 0xE0)
        n = 3, code = c & 0x0F;
      else if ((c & 0xF8) == 0xF0)
        n = 4, code = c & 0x07;
      else
        return 0;
      if (i + n > s.size())
        return 0;
      for (std::size_t k = 1; k < n; ++k)
        {
          if ((byte(i + k) & 0xC0) != 0x80)
            return 0;
          code = (code << 6) | (byte(i + k) & 0x3F);
        }
      // No overlong forms, surrogates or code points above U+10FFFF.
      const unsigned int smallest[] = {0, 0, 0x80, 0x800, 0x10000};
      if (code < smallest[n] || code > 0x10FFFF ||
          (code >= 0xD800 && code <= 0xDFFF))
        return 0;
      return n;
    }

    /// A JSON string: control characters escaped, and bytes that are
    /// not UTF-8 (a file name in another encoding) read as Latin-1, so
    /// that the file is always valid JSON.
    std::string
    quote(const std::string &s)
    {
      std::string out = "\"";
      char        buf[8];
      for (std::size_t i = 0; i < s.size();)
        {
          const char        c = s[i];
          const std::size_t n = utf8_length(s, i);
          if (n == 0)
            {
              std::snprintf(buf,
                            sizeof(buf),
                            "\\u%04x",
                            static_cast<unsigned char>(c));
              out += buf;
              ++i;
              continue;
            }
          if (n > 1)
            {
              out.append(s, i, n);
              i += n;
              continue;
            }
          if (c == '"')
            out += "\\\"";
          else if (c == '\\')
            out += "\\\\";
          else if (c == '\n')
            out += "\\n";
          else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
            {
              std::snprintf(buf,
                            sizeof(buf),
                            "\\u%04x",
                            static_cast<unsigned char>(c));
              out += buf;
            }
          else
            out += c;
          ++i;
        }
      return out + "\"";
    }
  } // namespace

  void
  Summary::set(const std::string &key, const double value)
  {
    numbers[key] = value;
    if (!std::isfinite(value))
      values[key] = "null";
    else
      {
        char buf[64];
        std::snprintf(buf, sizeof(buf), "%.17g", value);
        values[key] = buf;
      }
  }

  std::string
  Summary::non_finite_key() const
  {
    for (const auto &[key, value] : numbers)
      if (!std::isfinite(value))
        return key;
    return "";
  }

  void
  Summary::set(const std::string &key, const std::string &value)
  {
    values[key] = quote(value);
  }

  void
  Summary::set_integer(const std::string &key, const long long value)
  {
    numbers[key] = static_cast<double>(value);
    values[key]  = std::to_string(value);
  }

  bool
  Summary::has(const std::string &key) const
  {
    return values.count(key) > 0;
  }

  double
  Summary::get_number(const std::string &key) const
  {
    const auto it = numbers.find(key);
    AssertThrow(it != numbers.end(),
                dealii::ExcMessage("summary has no number " + key));
    return it->second;
  }

  std::string
  Summary::to_json() const
  {
    // Group "a.b" keys under "a".
    std::map<std::string, std::vector<std::pair<std::string, std::string>>>
                                                     groups;
    std::vector<std::pair<std::string, std::string>> top;
    for (const auto &kv : values)
      {
        const auto dot = kv.first.find('.');
        if (dot == std::string::npos)
          top.emplace_back(kv.first, kv.second);
        else
          groups[kv.first.substr(0, dot)].emplace_back(kv.first.substr(dot + 1),
                                                       kv.second);
      }
    std::ostringstream out;
    out << "{\n";
    bool first = true;
    for (const auto &kv : top)
      {
        out << (first ? "" : ",\n") << "  " << quote(kv.first) << ": "
            << kv.second;
        first = false;
      }
    for (const auto &g : groups)
      {
        out << (first ? "" : ",\n") << "  " << quote(g.first) << ": {";
        bool first_in_group = true;
        for (const auto &kv : g.second)
          {
            out << (first_in_group ? "\n" : ",\n") << "    " << quote(kv.first)
                << ": " << kv.second;
            first_in_group = false;
          }
        out << "\n  }";
        first = false;
      }
    out << "\n}\n";
    return out.str();
  }

  void
  Summary::write(const std::string &filename) const
  {
    const std::string json = to_json();
    write_atomically(filename, [&](std::ostream &out) { out << json; });
  }
} // namespace psmpm
