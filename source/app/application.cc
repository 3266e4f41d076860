// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <psmpm/app/application.h>
#include <psmpm/app/output_directory.h>
#include <psmpm/app/parameter_file.h>
#include <psmpm/app/problem.h>
#include <psmpm/app/run_limits.h>
#include <psmpm/base/checked_file.h>
#include <psmpm/base/cpu_time.h>
#include <psmpm/base/summary.h>
#include <psmpm/base/version.h>
#include <psmpm/simulator/checkpoint.h>
#include <psmpm/simulator/simulator.h>

#include <algorithm>
#include <csignal>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <optional>
#include <sstream>

namespace psmpm
{
  namespace App
  {
    using namespace dealii;

    const char *default_scene =
      R"(# Embedded default scene: vibrating bar, small deformation (thesis Table 4.1)
set Output directory = output-default
subsection Geometry
  set Length = 25
  set Height = 2
end
subsection Mesh
  set Type = criss-cross
  set Blocks x = 4
  set Blocks y = 1
end
subsection Basis
  set Type = linear
end
subsection Material
  set Density = 1
  set Young's modulus = 100
  set Poisson's ratio = 0
end
subsection Particles
  set Per block x = 16
  set Per block y = 14
end
subsection Initial conditions
  set Velocity = v0*sin(pi*x/L); 0
  set Function constants = v0=0.1, L=25
end
subsection Boundary conditions
  set Fixed x = left, right
  set Fixed y = left, right, bottom, top
end
subsection Time
  set End time = 0.02
  set Time step = 1e-5
end
subsection Mass matrix
  set Type = consistent
end
subsection Reference solution
  set Type = vibrating bar
  set Velocity amplitude = 0.1
end
subsection Output
  set Interval = 500
end
)";

    namespace
    {
      const char *usage =
        "Usage: psmpm [scene.prm] [options]\n"
        "  Runs the scene in scene.prm (or the embedded default scene, the\n"
        "  small-deformation vibrating bar) and writes VTU/PVD output,\n"
        "  statistics.txt, parameters.prm and summary.json into the\n"
        "  'Output directory'.\n"
        "Options:\n"
        "  --set \"Subsection/Entry=value\"  override one entry (repeatable)\n"
        "  --validate            check the input (parameters, mesh, time step), write nothing\n"
        "  --resume              continue from the newest checkpoint in the output\n"
        "                        directory (same scene; Time/End time may grow)\n"
        "  --print-parameters    print all entries with documentation: the\n"
        "                        defaults, or with a scene (and --set) its values\n"
        "  --version             print the version\n"
        "  --help                this text\n"
        "Exit codes: 0 success, 1 internal error, 2 bad input; an unstable run\n"
        "  ends with 3 (non-finite values), 4 (energy growth), 5 (particle left\n"
        "  the mesh), 6 (non-positive volume), 7 (solver not converging) or 9\n"
        "  (a cell of the moving otm grid inverted); 8: an output file could\n"
        "  not be written; 128 + N: stopped by signal\n"
        "  N (SIGINT 130, SIGTERM 143, SIGUSR1 138: what mpirun forwards) after\n"
        "  finishing the step and writing the output (status \"interrupted\" in\n"
        "  summary.json).\n";

      /**
       * A deal.II exception's what() nested in another message (an
       * ExcMessage built from e.what()) carries the source location, the
       * violated condition and a stack trace; keep only its additional
       * information.
       */
      std::string
      strip_nested(std::string m)
      {
        const std::string dashes(56, '-');
        for (std::size_t a;
             (a = m.find("An error occurred in line")) != std::string::npos;)
          {
            std::size_t begin = m.rfind(dashes, a);
            if (begin == std::string::npos)
              begin = a;
            const std::size_t info_key = m.find("Additional information:", a);
            const std::size_t stack    = m.find("Stacktrace:", a);
            std::size_t       end      = m.size();
            if (stack != std::string::npos)
              {
                const std::size_t close = m.find(dashes, stack + 25);
                end =
                  close == std::string::npos ? m.size() : close + dashes.size();
              }
            else
              {
                const std::size_t close = m.find(dashes, a);
                if (close != std::string::npos)
                  end = close + dashes.size();
              }
            std::string info;
            if (info_key != std::string::npos && info_key < end)
              {
                const std::size_t from = info_key + 23;
                const std::size_t to =
                  stack != std::string::npos && stack < end ? stack : end;
                info            = m.substr(from, to - from);
                const auto last = info.rfind(dashes);
                if (last != std::string::npos)
                  info.erase(last);
              }
            // One line, single spaces.
            std::string flat;
            for (const char c : info)
              if (c == '\n' || c == ' ' || c == '\t')
                {
                  if (!flat.empty() && flat.back() != ' ')
                    flat += ' ';
                }
              else
                flat += c;
            while (!flat.empty() && flat.back() == ' ')
              flat.pop_back();
            m.replace(begin, end - begin, flat);
          }
        return m;
      }

      /// The message of an exception without deal.II's source location.
      std::string
      message_of(const std::exception &e)
      {
        if (const auto *d = dynamic_cast<const ExceptionBase *>(&e))
          {
            std::ostringstream s;
            d->print_info(s);
            std::string m = strip_nested(s.str());
            while (!m.empty() && (m.back() == '\n' || m.back() == ' '))
              m.pop_back();
            m.erase(0, m.find_first_not_of(" \n"));
            // One line: a nested message's line breaks become spaces.
            std::string line;
            for (const char c : m)
              if (c == '\n')
                {
                  while (!line.empty() && line.back() == ' ')
                    line.pop_back();
                  line += ' ';
                }
              else if (c != ' ' || line.empty() || line.back() != ' ')
                line += c;
            m = line;
            if (!m.empty())
              return m;
            return d->get_exc_name();
          }
        return strip_nested(e.what());
      }

      /// Relative mesh and body geometry files (entry File of the current
      /// subsection) are taken relative to the parameter file.
      void
      resolve_file_entry(ParameterHandler &prm, const std::string &prm_file)
      {
        const std::filesystem::path file = prm.get("File");
        if (!file.empty() && file.is_relative() && !prm_file.empty())
          {
            const auto candidate =
              std::filesystem::path(prm_file).parent_path() / file;
            if (std::filesystem::exists(candidate))
              prm.set("File", candidate.string());
          }
      }

      void
      resolve_mesh_file(ParameterHandler &prm, const std::string &prm_file)
      {
        prm.enter_subsection("Mesh");
        resolve_file_entry(prm, prm_file);
        prm.leave_subsection();
        prm.enter_subsection("Bodies");
        for (unsigned int b = 1; b <= Particles::Bodies::max_bodies; ++b)
          {
            prm.enter_subsection("Body " + std::to_string(b));
            resolve_file_entry(prm, prm_file);
            prm.leave_subsection();
          }
        prm.leave_subsection();
      }

      /// Deterministic results of a Problem for the scene tests: its
      /// sizes as they are, then its errors with 5 significant digits
      /// (those in the summary).
      void
      print_test_output(const Problem::TestOutputKeys &keys,
                        const Summary                 &summary,
                        std::ostream                  &out)
      {
        for (const std::string &key : keys.sizes)
          out << key << " = " << summary.get_number(key) << "\n";
        for (const std::string &key : keys.errors)
          if (summary.has(key))
            {
              char buf[64];
              std::snprintf(buf, sizeof(buf), "%.4e", summary.get_number(key));
              out << key << " = " << buf << "\n";
            }
      }

      struct CommandLine
      {
        std::string              prm_file;
        std::vector<std::string> overrides;
        bool                     validate         = false;
        bool                     resume           = false;
        bool                     print_parameters = false;
        bool                     help             = false;
        bool                     version          = false;
      };

      CommandLine
      parse_command_line(const std::vector<std::string> &args)
      {
        CommandLine cl;
        for (unsigned int i = 0; i < args.size(); ++i)
          {
            const std::string &a = args[i];
            if (a == "--help" || a == "-h")
              cl.help = true;
            else if (a == "--version")
              cl.version = true;
            else if (a == "--validate")
              cl.validate = true;
            else if (a == "--resume")
              cl.resume = true;
            else if (a == "--print-parameters")
              cl.print_parameters = true;
            else if (a == "--set")
              {
                AssertThrow(i + 1 < args.size(),
                            ExcMessage("--set needs an argument "
                                       "\"Subsection/Entry=value\"."));
                cl.overrides.push_back(args[++i]);
              }
            else if (a.rfind("--", 0) == 0)
              {
                AssertThrow(false,
                            ExcMessage("unknown option " + a +
                                       " (see --help)."));
              }
            else
              {
                AssertThrow(cl.prm_file.empty(),
                            ExcMessage("more than one parameter file given ('" +
                                       cl.prm_file + "' and '" + a + "')."));
                cl.prm_file = a;
              }
          }
        return cl;
      }
    } // namespace

    void
    apply_override(ParameterHandler &prm, const std::string &assignment)
    {
      const auto eq = assignment.find('=');
      AssertThrow(eq != std::string::npos,
                  ExcMessage("--set '" + assignment +
                             "': expected Subsection/Entry=value."));
      const auto path =
        Utilities::split_string_list(assignment.substr(0, eq), '/');
      const auto value = Utilities::trim(assignment.substr(eq + 1));
      bool       names = !path.empty();
      for (const auto &p : path)
        names = names && !p.empty();
      AssertThrow(names,
                  ExcMessage("--set '" + assignment +
                             "': expected Subsection/Entry=value (an empty "
                             "subsection or entry name)."));
      for (unsigned int i = 0; i + 1 < path.size(); ++i)
        prm.enter_subsection(path[i]);
      try
        {
          prm.set(path.back(), value);
        }
      catch (const std::exception &e)
        {
          for (unsigned int i = 0; i + 1 < path.size(); ++i)
            prm.leave_subsection();
          AssertThrow(false,
                      ExcMessage("--set '" + assignment +
                                 "': " + message_of(e)));
        }
      for (unsigned int i = 0; i + 1 < path.size(); ++i)
        prm.leave_subsection();
    }


    void
    declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Output directory",
                        "output",
                        Patterns::FileName(Patterns::FileName::output),
                        "Directory for VTU/PVD output, statistics.txt, "
                        "parameters.prm, summary.json and log.txt (the screen "
                        "output); created if needed. The files of an earlier "
                        "psmpm run in it are removed first (unless the run "
                        "is resumed with --resume); a second run into a "
                        "directory in use (psmpm.lock) is refused.");
      prm.enter_subsection("Output");
      prm.declare_entry("Time interval",
                        "0",
                        Patterns::Double(0),
                        "Also write VTU output whenever the simulated time "
                        "passes a multiple of this [s] (0: off); with "
                        "Output/Interval (steps), output is written when "
                        "either is due.");
      prm.declare_entry("Progress interval",
                        "2",
                        Patterns::Double(0),
                        "Seconds of wall time between progress lines (step, "
                        "simulated time, percent, wall time, ETA) on the "
                        "screen; 0: none.");
      prm.declare_entry("Test output",
                        "false",
                        Patterns::Bool(),
                        "Print only machine-independent results (no timings) "
                        "to the screen, for scene tests.");
      prm.leave_subsection();
      declare_problem_parameters(prm);
      RunLimits::declare_parameters(prm);
    }

    namespace
    {
      /// What run() learns from the command line and the scene before
      /// anything is written.
      struct Scene
      {
        CommandLine cl;
        /// Where the input comes from, for the messages.
        std::string    where = "the command line";
        std::string    dir;
        OutputSettings output;
        /// Set up and checked; null until the whole input is valid.
        std::unique_ptr<Problem> problem;
      };

      /// --help, --version and --print-parameters without a scene need no
      /// scene: their exit code, or none if the command line asks for a
      /// run.
      std::optional<int>
      answer_without_scene(const CommandLine      &cl,
                           const ParameterHandler &prm,
                           const bool              root)
      {
        if (cl.help)
          {
            if (root)
              std::cout << usage;
            return success;
          }
        if (cl.version)
          {
            if (root)
              std::cout << "psmpm " << version() << "\n";
            return success;
          }
        // Without a scene: every entry with its default; with a scene
        // (and --set): the scene's values, documentation included.
        if (cl.print_parameters && cl.prm_file.empty() && cl.overrides.empty())
          {
            if (root)
              prm.print_parameters(std::cout, ParameterHandler::PRM);
            return success;
          }
        return std::nullopt;
      }

      /// The scene file (or the embedded default scene), then --set.
      void
      read_parameters(const CommandLine &cl, ParameterHandler &prm)
      {
        if (cl.prm_file.empty())
          prm.parse_input_from_string(default_scene, "default scene");
        else
          {
            check_parameter_file(cl.prm_file);
            prm.parse_input(cl.prm_file);
          }
        for (const auto &o : cl.overrides)
          apply_override(prm, o);
      }

      /// Rank 0's text and that of the first rank whose parameters differ
      /// from it, as the entries in which they differ ("" if none is
      /// found among the entries that matter for results).
      std::string
      first_difference(const std::vector<std::string> &texts)
      {
        for (unsigned int r = 1; r < texts.size(); ++r)
          if (texts[r] != texts[0])
            {
              const auto differences =
                Simulator::Checkpoint::parameter_differences(texts[0],
                                                             texts[r]);
              return "rank 0 and rank " + std::to_string(r) +
                     (differences.empty() ? std::string(" differ") :
                                            " differ in " + differences[0]);
            }
        return "";
      }

      /**
       * read_parameters() on every rank of @p comm, which must agree: a
       * parameter file that some ranks cannot read, or a scene that
       * differs between ranks (an MPMD launch, --set per rank), ends every
       * rank with bad input instead of a wait in a collective call of the
       * set-up. On one rank: read_parameters().
       */
      void
      read_parameters_on_all_ranks(const CommandLine &cl,
                                   ParameterHandler  &prm,
                                   MPI_Comm           comm)
      {
        if (Utilities::MPI::n_mpi_processes(comm) == 1)
          return read_parameters(cl, prm);
        std::exception_ptr failure;
        std::string        error;
        try
          {
            read_parameters(cl, prm);
          }
        catch (const std::exception &e)
          {
            failure = std::current_exception();
            error   = message_of(e);
          }
        const auto errors = Utilities::MPI::all_gather(comm, error);
        for (unsigned int r = 0; r < errors.size(); ++r)
          if (!errors[r].empty())
            {
              // Rank 0 prints the message: its own exception if it has one.
              if (failure && r == 0)
                std::rethrow_exception(failure);
              AssertThrow(false,
                          ExcMessage("on rank " + std::to_string(r) + ": " +
                                     errors[r]));
            }
        std::ostringstream text;
        prm.print_parameters(text, ParameterHandler::ShortPRM);
        const std::size_t hash   = std::hash<std::string>()(text.str());
        const auto        hashes = Utilities::MPI::all_gather(comm, hash);
        if (std::all_of(hashes.begin(), hashes.end(), [&](const auto h) {
              return h == hashes[0];
            }))
          return;
        const std::string difference =
          first_difference(Utilities::MPI::all_gather(comm, text.str()));
        AssertThrow(false,
                    ExcMessage("the parameters differ between ranks" +
                               (difference.empty() ? std::string() :
                                                     " (" + difference + ")") +
                               "; every rank must read the same scene and "
                               "--set arguments."));
      }

      /// The entries every Problem shares, then the Problem, set up: all
      /// checks of the input that can fail end here, before the output
      /// directory is touched.
      void
      set_up_scene(ParameterHandler &prm, MPI_Comm comm, Scene &scene)
      {
        resolve_mesh_file(prm, scene.cl.prm_file);
        RunLimits limits;
        limits.parse_parameters(prm);
        scene.dir = prm.get("Output directory");
        OutputDirectory::check_name(scene.dir);
        prm.enter_subsection("Output");
        scene.output.test_output       = prm.get_bool("Test output");
        scene.output.time_interval     = prm.get_double("Time interval");
        scene.output.progress_interval = prm.get_double("Progress interval");
        prm.leave_subsection();
        scene.problem = create_problem(prm.get("Problem"), comm);
        scene.problem->set_up(prm, limits, scene.output);
      }

      /**
       * The message and exit code (bad_input) of an exception thrown while
       * the input is read and checked; called from a catch block, it
       * rethrows the exception being handled to tell the kinds apart.
       */
      int
      report_bad_input(const std::string &where, const bool root)
      {
        try
          {
            throw;
          }
        catch (const std::bad_alloc &)
          {
            if (root)
              std::cerr << "psmpm: error in " << where
                        << ": out of memory while setting up the scene "
                           "(reduce the number of blocks or particles).\n";
          }
        catch (const std::exception &e)
          {
            if (root)
              std::cerr << "psmpm: error in " << where << ": " << message_of(e)
                        << "\n";
          }
        catch (...)
          {
            // muParser's exceptions are not std::exceptions.
            if (root)
              std::cerr << "psmpm: error in " << where
                        << ": an expression or its constants could not be "
                           "parsed (Initial conditions/Function constants, "
                           "Velocity, Stress function).\n";
          }
        return bad_input;
      }

      /// Read and check the whole input into @p scene: the exit code if
      /// psmpm ends here (an answer without a scene, --print-parameters
      /// or bad input), none if the scene is to run.
      std::optional<int>
      read_scene(const std::vector<std::string> &args,
                 ParameterHandler               &prm,
                 MPI_Comm                        comm,
                 const bool                      root,
                 Scene                          &scene)
      {
        try
          {
            scene.cl = parse_command_line(args);
            if (const auto code = answer_without_scene(scene.cl, prm, root))
              return code;
            scene.where = scene.cl.prm_file.empty() ?
                            "the embedded default scene" :
                            "file " + scene.cl.prm_file;
            read_parameters_on_all_ranks(scene.cl, prm, comm);
            if (scene.cl.print_parameters)
              {
                if (root)
                  prm.print_parameters(std::cout, ParameterHandler::PRM);
                return success;
              }
            set_up_scene(prm, comm, scene);
          }
        catch (...)
          {
            return report_bad_input(scene.where, root);
          }
        return std::nullopt;
      }

      /**
       * The output directory: created, locked and cleared on rank 0 (kept
       * for --resume, which then loads the newest checkpoint); all ranks
       * learn of a failure and stop with bad_input, whose exit code is
       * returned.
       */
      std::optional<int>
      open_output(OutputDirectory &output,
                  const Scene     &scene,
                  MPI_Comm         comm,
                  const bool       root)
      {
        try
          {
            output.open(scene.dir, comm, scene.cl.resume);
            if (scene.cl.resume)
              {
                // The newest checkpoint; a damaged one is reported, not
                // skipped: the user decides whether to remove it.
                std::vector<std::string> files;
                if (root)
                  files = Simulator::Checkpoint::list(scene.dir);
                files = Utilities::MPI::broadcast(comm, files, 0);
                AssertThrow(!files.empty(),
                            ExcMessage(
                              "--resume: no checkpoint (checkpoint-<step>.h5) "
                              "in the output directory '" +
                              scene.dir +
                              "'. A run writes one at its end, when it is "
                              "interrupted and every Checkpoint/Interval "
                              "steps."));
                scene.problem->resume(scene.dir, files);
              }
          }
        catch (const std::exception &e)
          {
            if (root)
              std::cerr << "psmpm: error in " << scene.where << ": "
                        << message_of(e) << "\n";
            return bad_input;
          }
        return std::nullopt;
      }

      /// Run @p write on rank 0; every rank throws ExcWriteFailed if it
      /// failed (no rank goes on alone).
      void
      write_on_root(const std::function<void()> &write,
                    MPI_Comm                     comm,
                    const bool                   root)
      {
        std::string error;
        if (root)
          try
            {
              write();
            }
          catch (const ExcWriteFailed &e)
            {
              error = e.what();
            }
        error = Utilities::MPI::broadcast(comm, error, 0);
        if (!error.empty())
          throw ExcWriteFailed(error);
      }

      /// parameters.prm, written on rank 0; every rank throws
      /// ExcWriteFailed if it could not be written.
      void
      write_parameters(const ParameterHandler &prm,
                       const std::string      &dir,
                       MPI_Comm                comm,
                       const bool              root)
      {
        write_on_root(
          [&]() {
            write_atomically(dir + "/parameters.prm", [&](std::ostream &out) {
              prm.print_parameters(out, ParameterHandler::PRM);
            });
          },
          comm,
          root);
      }

      /// The entries of summary.json that say how the run was made.
      void
      add_run_information(Summary           &summary,
                          const Timer       &wall,
                          const std::string &parameter_file)
      {
        summary.set("wall_time_s", wall.wall_time());
        summary.set("cpu_time_s", process_cpu_seconds());
        summary.set("parameter_file", parameter_file);
        summary.set("version", version());
      }

      /**
       * A completed run whose summary holds a number that is not finite
       * (an error norm or a sum beyond double range, written as null) has
       * no result: its status becomes unstable, the key is the reason,
       * and the exit code is that of non-finite values (3). Returns that
       * code, or none if every number is finite.
       */
      std::optional<int>
      refuse_non_finite(Summary &summary, const bool root)
      {
        const std::string key = summary.non_finite_key();
        if (key.empty())
          return std::nullopt;
        const std::string reason = "non-finite value in summary.json: " + key;
        summary.set("status", "unstable");
        summary.set("reason", reason);
        if (root)
          std::cerr << "psmpm: UNSTABLE: " << reason << "\n";
        return Simulator::failure_info(Simulator::Failure::non_finite)
          .exit_code;
      }

      /// Run the set-up Problem into its open output directory: screen
      /// lines, parameters.prm, the Problem's output, summary.json; the
      /// exit code.
      int
      run_problem(const Scene            &scene,
                  const ParameterHandler &prm,
                  const Timer            &wall,
                  MPI_Comm                comm,
                  const bool              root)
      {
        const std::string &dir         = scene.dir;
        const bool         test_output = scene.output.test_output;
        LogFile            log_file(dir + "/log.txt", root, scene.cl.resume);
        Summary            summary;
        const std::string  parameter_file =
          scene.cl.prm_file.empty() ? "(default scene)" : scene.cl.prm_file;
        try
          {
            if (root && !test_output)
              std::cout
                << "psmpm " << version() << ": " << scene.where
                << ", output in "
                << std::filesystem::absolute(dir).lexically_normal().string()
                << " (screen output also in log.txt)" << std::endl;
            scene.problem->announce(root && !test_output);
            write_parameters(prm, dir, comm, root);
            const auto status = scene.problem->run(dir, summary, comm);
            const auto non_finite =
              status == Simulator::Status::completed ?
                refuse_non_finite(summary, root) :
                std::nullopt;
            add_run_information(summary, wall, parameter_file);
            write_on_root([&]() { summary.write(dir + "/summary.json"); },
                          comm,
                          root);
            if (root)
              {
                if (test_output)
                  {
                    std::cout << "status = " << Simulator::status_name(status)
                              << "\n";
                    print_test_output(scene.problem->test_output_keys(),
                                      summary,
                                      std::cout);
                  }
                else
                  std::cout << "psmpm: " << summary.to_json();
              }
            return non_finite ? *non_finite : scene.problem->exit_code(status);
          }
        catch (const ExcWriteFailed &e)
          {
            // The disk is full or the directory went away: say which file,
            // and leave a summary if one can still be written.
            if (root)
              {
                std::cerr << "psmpm: error: " << e.what() << "\n";
                try
                  {
                    Summary failed;
                    failed.set("status", "failed");
                    failed.set("reason", e.what());
                    add_run_information(failed, wall, parameter_file);
                    failed.write(dir + "/summary.json");
                  }
                catch (const std::exception &)
                  {
                  }
              }
            return write_failed;
          }
        catch (const std::exception &e)
          {
            if (root)
              std::cerr << "psmpm: internal error: " << message_of(e) << "\n";
            return internal;
          }
      }
    } // namespace

    int
    run(const std::vector<std::string> &args, MPI_Comm comm)
    {
      const bool root = Utilities::MPI::this_mpi_process(comm) == 0;
      Timer      wall;
      wall.start();

      // Nothing is written unless the whole input is valid.
      ParameterHandler prm;
      declare_parameters(prm);
      Scene scene;
      if (const auto code = read_scene(args, prm, comm, root, scene))
        return *code;
      if (scene.cl.validate)
        {
          if (root)
            std::cout << "psmpm: " << scene.where << " is valid.\n";
          return success;
        }
      if (scene.cl.resume && !scene.problem->resumable())
        {
          if (root)
            std::cerr << "psmpm: error in " << scene.where
                      << ": --resume needs an mpm scene (Problem = mpm).\n";
          return bad_input;
        }

      OutputDirectory output;
      if (const auto code = open_output(output, scene, comm, root))
        return *code;
      return run_problem(scene, prm, wall, comm, root);
    }

    int
    run(int argc, char **argv, MPI_Comm comm)
    {
      // A closed pipe or terminal (psmpm | head) must not kill a run in
      // the middle of writing: the screen output is lost, log.txt and
      // the output files are not.
      std::signal(SIGPIPE, SIG_IGN);
      return run(std::vector<std::string>(argv + 1, argv + argc), comm);
    }
  } // namespace App
} // namespace psmpm
