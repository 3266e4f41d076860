// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <psmpm/postprocess/summary.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <vector>

namespace psmpm
{
  namespace Postprocess
  {
    namespace
    {
      std::string
      quote(const std::string &s)
      {
        std::string out = "\"";
        for (const char c : s)
          switch (c)
            {
              case '"':
                out += "\\\"";
                break;
              case '\\':
                out += "\\\\";
                break;
              case '\n':
                out += "\\n";
                break;
              default:
                if (static_cast<unsigned char>(c) < 0x20)
                  out += ' ';
                else
                  out += c;
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
            groups[kv.first.substr(0, dot)].emplace_back(kv.first.substr(dot +
                                                                         1),
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
              out << (first_in_group ? "\n" : ",\n") << "    "
                  << quote(kv.first) << ": " << kv.second;
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
      const std::string tmp = filename + ".tmp";
      {
        std::ofstream out(tmp);
        AssertThrow(out.good(), dealii::ExcMessage("cannot write " + filename));
        out << to_json();
      }
      std::rename(tmp.c_str(), filename.c_str());
    }
  } // namespace Postprocess
} // namespace psmpm
