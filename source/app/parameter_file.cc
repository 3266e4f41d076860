// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <psmpm/app/parameter_file.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace psmpm
{
  namespace App
  {
    using namespace dealii;
    namespace fs = std::filesystem;

    namespace
    {
      constexpr unsigned int max_include_depth = 16;
      constexpr unsigned int max_json_depth    = 32;

      /// "a FIFO", "a directory", ...: what a non-regular file is.
      std::string
      kind_of(const fs::file_status &status)
      {
        if (!fs::exists(status))
          return "no such file";
        if (fs::is_directory(status))
          return "a directory, not a file";
        if (fs::is_fifo(status))
          return "a FIFO, not a regular file";
        if (fs::is_character_file(status) || fs::is_block_file(status))
          return "a device, not a regular file";
        return "not a regular file";
      }

      void
      check_regular(const std::string &file, const std::string &what)
      {
        std::error_code ec;
        const auto      status = fs::status(file, ec);
        AssertThrow(fs::is_regular_file(status),
                    ExcMessage(what + " '" + file + "': " + kind_of(status) +
                               "."));
      }

      /// The include lines of @p file, recursively; @p chain: the files
      /// that include it (canonical paths).
      void
      check_includes(const std::string &file, std::vector<fs::path> &chain)
      {
        std::error_code ec;
        const fs::path  canonical = fs::weakly_canonical(file, ec);
        for (const auto &f : chain)
          AssertThrow(f != canonical,
                      ExcMessage("parameter file '" + chain.front().string() +
                                 "': '" + file +
                                 "' includes itself (through include lines: " +
                                 "a cycle)."));
        AssertThrow(chain.size() < max_include_depth,
                    ExcMessage("parameter file '" + chain.front().string() +
                               "': include lines nested deeper than " +
                               std::to_string(max_include_depth) +
                               " levels (at '" + file + "')."));
        chain.push_back(canonical);
        std::ifstream in(file);
        std::string   line;
        for (unsigned int number = 1; std::getline(in, line); ++number)
          {
            const auto hash = line.find('#');
            if (hash != std::string::npos)
              line.erase(hash);
            line = Utilities::trim(line);
            if (line.rfind("include ", 0) != 0 &&
                line.rfind("INCLUDE ", 0) != 0 && line != "include" &&
                line != "INCLUDE")
              continue;
            const std::string included = Utilities::trim(line.substr(7));
            const std::string where    = "file '" + file + "', line " +
                                      std::to_string(number) + ": include";
            AssertThrow(!included.empty(),
                        ExcMessage(where + " without a file name."));
            check_regular(included, where);
            check_includes(included, chain);
          }
        chain.pop_back();
      }

      /// A JSON scanner that only follows the structure: the key path,
      /// the depth, the kind of each value.
      class JsonScan
      {
      public:
        JsonScan(const std::string &text, const std::string &file)
          : text(text)
          , file(file)
        {
        }

        void
        run()
        {
          skip_space();
          value(0);
        }

      private:
        const std::string       &text;
        const std::string        file;
        std::size_t              pos = 0;
        std::vector<std::string> path;

        std::string
        where() const
        {
          std::string p;
          for (const auto &s : path)
            p += (p.empty() ? "" : "/") + s;
          return "file '" + file + "'" + (p.empty() ? "" : ", entry " + p);
        }

        [[noreturn]] void
        fail(const std::string &what) const
        {
          throw ExcMessage(where() + ": " + what);
        }

        void
        skip_space()
        {
          while (pos < text.size() && (text[pos] == ' ' || text[pos] == '\n' ||
                                       text[pos] == '\r' || text[pos] == '\t'))
            ++pos;
        }

        std::string
        string()
        {
          std::string s;
          ++pos; // opening quote
          while (pos < text.size() && text[pos] != '"')
            {
              if (text[pos] == '\\')
                ++pos;
              if (pos < text.size())
                s += text[pos++];
            }
          if (pos >= text.size())
            fail("a string without its closing quote (a truncated file?).");
          ++pos;
          return s;
        }

        void
        value(const unsigned int depth)
        {
          if (depth > max_json_depth)
            fail("nested deeper than " + std::to_string(max_json_depth) +
                 " levels.");
          if (pos >= text.size())
            fail("a value is missing (a truncated file?).");
          const char c = text[pos];
          if (c == '{')
            {
              ++pos;
              skip_space();
              if (pos < text.size() && text[pos] == '}')
                {
                  ++pos;
                  return;
                }
              while (true)
                {
                  skip_space();
                  if (pos >= text.size() || text[pos] != '"')
                    fail("expected a quoted name in an object.");
                  path.push_back(string());
                  skip_space();
                  if (pos >= text.size() || text[pos] != ':')
                    fail("expected ':' after the name.");
                  ++pos;
                  skip_space();
                  value(depth + 1);
                  path.pop_back();
                  skip_space();
                  if (pos < text.size() && text[pos] == ',')
                    {
                      ++pos;
                      continue;
                    }
                  if (pos < text.size() && text[pos] == '}')
                    {
                      ++pos;
                      return;
                    }
                  fail("expected ',' or '}' in an object (a truncated "
                       "file?).");
                }
            }
          if (c == '[')
            fail("an array; psmpm reads an object of subsections (objects) "
                 "and entries (strings).");
          if (c == '"')
            {
              string();
              return;
            }
          if (text.compare(pos, 4, "null") == 0)
            fail("null; give the entry a value (a string) or leave it out.");
          // A number or a boolean: boost's reader keeps its text.
          const std::size_t start = pos;
          while (pos < text.size() &&
                 std::string(",}] \t\r\n").find(text[pos]) == std::string::npos)
            ++pos;
          if (pos == start)
            fail("unexpected character '" + std::string(1, c) + "'.");
        }
      };
    } // namespace



    void
    check_parameter_file(const std::string &file)
    {
      check_regular(file, "parameter file");
      const std::string extension = fs::path(file).extension().string();
      if (extension == ".json")
        {
          std::ifstream     in(file);
          std::stringstream s;
          s << in.rdbuf();
          JsonScan(s.str(), file).run();
        }
      else if (extension != ".xml")
        {
          std::vector<fs::path> chain;
          check_includes(file, chain);
        }
    }
  } // namespace App
} // namespace psmpm
