// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/base/checked_file.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

namespace psmpm
{
  namespace
  {
    std::string
    reason(const int error)
    {
      return error != 0 ? std::strerror(error) : "write error";
    }
  } // namespace

  void
  inject_write_failure(const std::string &file)
  {
    const char *at    = std::getenv("PSMPM_FAIL_WRITE_AT");
    const char *match = std::getenv("PSMPM_FAIL_WRITE_MATCH");
    // Counting restarts when the variables change: a test process runs
    // several cases one after the other.
    static std::string setting;
    static long        count = 0;
    const std::string  now =
      std::string(at != nullptr ? at : "") + '\n' + (match ? match : "");
    if (now != setting)
      {
        setting = now;
        count   = 0;
      }
    if (at == nullptr ||
        (match != nullptr && file.find(match) == std::string::npos))
      return;
    if (++count == std::atol(at))
      throw ExcWriteFailed("cannot write " + file + ": " +
                           std::strerror(ENOSPC) + " (PSMPM_FAIL_WRITE_AT)");
  }

  void
  check_written(std::ostream &out, const std::string &file)
  {
    inject_write_failure(file);
    // A stream that failed earlier keeps the errno of its failed write.
    if (!out.good())
      throw ExcWriteFailed("cannot write " + file + ": " + reason(errno));
    errno = 0;
    out.flush();
    if (!out.good())
      throw ExcWriteFailed("cannot write " + file + ": " + reason(errno));
  }

  void
  write_atomically(const std::string                         &file,
                   const std::function<void(std::ostream &)> &write)
  {
    const std::string tmp = file + ".tmp";
    {
      errno = 0;
      std::ofstream out(tmp, std::ios::binary);
      if (!out.is_open())
        throw ExcWriteFailed("cannot write " + file + ": cannot create " + tmp +
                             " (" + reason(errno) + ")");
      try
        {
          try
            {
              write(out);
            }
          catch (const ExcWriteFailed &)
            {
              throw;
            }
          catch (...)
            {
              // A writer that checks its stream (deal.II's ExcIO) failed:
              // the stream says why.
              check_written(out, file);
              throw;
            }
          check_written(out, file);
        }
      catch (...)
        {
          out.close();
          std::remove(tmp.c_str());
          throw;
        }
      errno = 0;
      out.close();
      if (out.fail())
        {
          const int error = errno;
          std::remove(tmp.c_str());
          throw ExcWriteFailed("cannot write " + file + ": " + reason(error));
        }
    }
    if (std::rename(tmp.c_str(), file.c_str()) != 0)
      {
        const int error = errno;
        std::remove(tmp.c_str());
        throw ExcWriteFailed("cannot write " + file + ": rename from " + tmp +
                             " failed (" + reason(error) + ")");
      }
  }
} // namespace psmpm
