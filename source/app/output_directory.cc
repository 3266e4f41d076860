// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <psmpm/app/output_directory.h>
#include <psmpm/simulator/checkpoint.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <regex>
#include <signal.h>
#include <sstream>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

namespace psmpm
{
  namespace App
  {
    using namespace dealii;
    namespace fs = std::filesystem;

    namespace
    {
      std::string
      host_name()
      {
        char buf[256] = {};
        gethostname(buf, sizeof(buf) - 1);
        return buf;
      }

      /// A temporary file of an interrupted atomic write.
      bool
      is_temporary(const std::string &name)
      {
        static const std::regex tmp(".*\\.tmp");
        return std::regex_match(name, tmp);
      }

      /// Files an earlier run of psmpm may have left.
      bool
      written_by_psmpm(const std::string &name)
      {
        static const std::regex series(
          "(particles|grid)(-[0-9]+(\\.[0-9]+)?\\.(vtu|pvtu)|\\.pvd)|"
          "particles(-[0-9]+\\.h5|\\.xdmf)");
        static const std::regex fixed(
          "statistics\\.txt|summary\\.json|parameters\\.prm|log\\.txt|"
          "tracked_particle\\.txt|projection\\.vtu|mesh\\.vtu|"
          "ps_refinement\\.vtu");
        return std::regex_match(name, series) ||
               std::regex_match(name, fixed) || is_temporary(name) ||
               Simulator::Checkpoint::is_checkpoint_file(name);
      }

      /// Take the lock (O_EXCL); a lock of a dead process on this host
      /// is replaced once. Returns "" or the reason for refusing.
      std::string
      take_lock(const std::string &directory, const std::string &file)
      {
        for (unsigned int attempt = 0; attempt < 2; ++attempt)
          {
            const int fd =
              ::open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
            if (fd >= 0)
              {
                const std::string text =
                  std::to_string(getpid()) + " " + host_name() + "\n";
                const bool ok = ::write(fd, text.data(), text.size()) ==
                                static_cast<ssize_t>(text.size());
                ::close(fd);
                if (!ok)
                  return "cannot write the lock file " + file;
                return "";
              }
            if (errno != EEXIST)
              return "cannot create the lock file " + file + " (" +
                     std::strerror(errno) + ")";
            // Reading a FIFO would wait forever, a device without end.
            std::error_code ec;
            if (!fs::is_regular_file(fs::symlink_status(file, ec)))
              return "the lock file " + file +
                     " is not a regular file; remove it if no psmpm run "
                     "writes into '" +
                     directory + "'.";
            std::ifstream in(file);
            long          pid = 0;
            std::string   host;
            in >> pid >> host;
            if (!in || pid <= 0 || host.empty())
              return "the lock file " + file +
                     " does not name a process and host (it is garbled or "
                     "empty); remove it if no psmpm run writes into '" +
                     directory + "'.";
            const bool dead = pid > 0 && host == host_name() &&
                              ::kill(static_cast<pid_t>(pid), 0) != 0 &&
                              errno == ESRCH;
            if (!dead)
              return "another psmpm run (process " + std::to_string(pid) +
                     (host.empty() ? "" : " on " + host) +
                     ") is writing into '" + directory + "' (lock file " +
                     file +
                     "); wait for it to end, choose another Output "
                     "directory, or remove the lock file if that run is "
                     "gone.";
            fs::remove(file, ec); // stale: the process is gone
          }
        return "cannot take the lock file " + file;
      }
    } // namespace

    void
    OutputDirectory::check_name(const std::string &directory)
    {
      AssertThrow(!directory.empty(),
                  ExcMessage("Output directory is empty: name a directory "
                             "(e.g. 'output')."));
      std::error_code ec;
      const auto      status = fs::status(directory, ec);
      AssertThrow(!fs::exists(status) || fs::is_directory(status),
                  ExcMessage("Output directory = " + directory +
                             ": exists and is not a directory."));
    }

    void
    OutputDirectory::open(const std::string &directory,
                          MPI_Comm           comm,
                          const bool         resume)
    {
      std::string error;
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        {
          try
            {
              check_name(directory);
              std::error_code ec;
              AssertThrow(!resume || fs::is_directory(directory, ec),
                          ExcMessage("--resume: no checkpoint "
                                     "(checkpoint-<step>.h5) in the output "
                                     "directory '" +
                                     directory +
                                     "': it does not exist (Output "
                                     "directory)."));
              fs::create_directories(directory, ec);
              if (ec || !fs::is_directory(directory))
                error = "Output directory = " + directory +
                        ": cannot create the directory (" +
                        (ec ? ec.message() : "not a directory") + ").";
              else
                {
                  const std::string file    = directory + "/" + lock_name;
                  const std::string refused = take_lock(directory, file);
                  if (!refused.empty())
                    error = "Output directory = " + directory + ": " + refused;
                  else
                    {
                      lock_file = file;
                      // A FIFO where psmpm writes a file would block the
                      // run (a device or a directory fails the write: exit
                      // code 8).
                      for (const auto &entry :
                           fs::directory_iterator(directory, ec))
                        {
                          const std::string name =
                            entry.path().filename().string();
                          const auto st = fs::status(entry.path(), ec);
                          if (name != lock_name && written_by_psmpm(name) &&
                              (fs::is_fifo(st) || fs::is_socket(st)))
                            {
                              error = "Output directory = " + directory + ": " +
                                      name +
                                      " is a FIFO or socket where psmpm "
                                      "writes a file (it would wait on it); "
                                      "remove it.";
                              break;
                            }
                        }
                      for (const auto &entry :
                           fs::directory_iterator(directory, ec))
                        {
                          const std::string name =
                            entry.path().filename().string();
                          if (error.empty() && entry.is_regular_file() &&
                              (resume ? is_temporary(name) :
                                        written_by_psmpm(name)))
                            fs::remove(entry.path(), ec);
                        }
                      // Can a file be created in it at all?
                      const std::string probe = directory + "/log.txt";
                      std::ofstream     test;
                      if (error.empty())
                        test.open(probe, std::ios::app);
                      if (error.empty() && !test.is_open())
                        error = "Output directory = " + directory +
                                ": cannot create files in it (" +
                                std::strerror(errno) + ").";
                    }
                }
            }
          catch (const ExceptionBase &e)
            {
              std::ostringstream s;
              e.print_info(s);
              error = s.str();
              while (!error.empty() &&
                     (error.back() == '\n' || error.back() == ' '))
                error.pop_back();
            }
          catch (const std::exception &e)
            {
              error = "Output directory = " + directory + ": " + e.what();
            }
        }
      error = Utilities::MPI::broadcast(comm, error, 0);
      if (!error.empty())
        {
          release();
          AssertThrow(false, ExcMessage(error));
        }
    }

    OutputDirectory::~OutputDirectory()
    {
      release();
    }

    void
    OutputDirectory::release()
    {
      if (!lock_file.empty())
        {
          std::error_code ec;
          fs::remove(lock_file, ec);
          lock_file.clear();
        }
    }

    namespace
    {
      /// A stream buffer that writes into two.
      class TeeBuffer : public std::streambuf
      {
      public:
        TeeBuffer(std::streambuf *a, std::streambuf *b)
          : a(a)
          , b(b)
        {
        }

      protected:
        int
        overflow(int c) override
        {
          if (c == EOF)
            return traits_type::not_eof(c);
          // Succeeds if either copy does: a closed terminal must not stop
          // the log.
          const int ra = a->sputc(static_cast<char>(c));
          const int rb = b->sputc(static_cast<char>(c));
          return ra != EOF ? ra : rb;
        }
        std::streamsize
        xsputn(const char *s, std::streamsize n) override
        {
          return std::max(a->sputn(s, n), b->sputn(s, n));
        }
        int
        sync() override
        {
          const int rb = b->pubsync();
          return a->pubsync() == 0 ? 0 : rb;
        }

      private:
        std::streambuf *a, *b;
      };
    } // namespace

    LogFile::LogFile(const std::string &file,
                     const bool         active,
                     const bool         append)
    {
      if (!active)
        return;
      log.open(file, append ? std::ios::app : std::ios::out);
      if (!log.is_open())
        return;
      old_out = std::cout.rdbuf();
      old_err = std::cerr.rdbuf();
      out_tee = std::make_unique<TeeBuffer>(old_out, log.rdbuf());
      err_tee = std::make_unique<TeeBuffer>(old_err, log.rdbuf());
      std::cout.rdbuf(out_tee.get());
      std::cerr.rdbuf(err_tee.get());
    }

    LogFile::~LogFile()
    {
      if (old_out)
        {
          std::cout.flush();
          std::cerr.flush();
          std::cout.rdbuf(old_out);
          std::cerr.rdbuf(old_err);
        }
    }
  } // namespace App
} // namespace psmpm
