// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <psmpm/app/application.h>
#include <psmpm/app/output_directory.h>
#include <psmpm/app/parameter_file.h>
#include <psmpm/app/run_limits.h>
#include <psmpm/base/checked_file.h>
#include <psmpm/base/cpu_time.h>
#include <psmpm/base/stop_request.h>
#include <psmpm/base/version.h>
#include <psmpm/basis/space.h>
#include <psmpm/postprocess/summary.h>
#include <psmpm/simulator/checkpoint.h>
#include <psmpm/simulator/simulator.h>
#include <psmpm/solver/l2_projection.h>
#include <psmpm/solver/mass_matrix_study.h>

#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
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

      /// Initial conditions/Function constants: name=value with a number
      /// (the simulator would only say "Can't convert <abc> to a double").
      void
      check_function_constants(ParameterHandler &prm)
      {
        prm.enter_subsection("Initial conditions");
        const std::string constants = prm.get("Function constants");
        prm.leave_subsection();
        std::set<std::string> names;
        for (const auto &c : Utilities::split_string_list(constants, ','))
          {
            const auto kv = Utilities::split_string_list(c, '=');
            AssertThrow(kv.size() == 2 && !kv[0].empty(),
                        ExcMessage("Initial conditions/Function constants = '" +
                                   constants + "': '" + c +
                                   "' is not name=value."));
            bool number = true;
            try
              {
                Utilities::string_to_double(kv[1]);
              }
            catch (...)
              {
                number = false;
              }
            AssertThrow(number,
                        ExcMessage("Initial conditions/Function constants = '" +
                                   constants + "': the value of " + kv[0] +
                                   ", '" + kv[1] + "', is not a number."));
            // muParser's names: a letter or _, then letters, digits, _;
            // the variables x, y, z and t cannot be constants (muParser
            // throws an exception deal.II does not catch).
            bool identifier =
              std::isalpha(static_cast<unsigned char>(kv[0][0])) ||
              kv[0][0] == '_';
            for (const char ch : kv[0])
              identifier =
                identifier &&
                (std::isalnum(static_cast<unsigned char>(ch)) || ch == '_');
            AssertThrow(identifier,
                        ExcMessage("Initial conditions/Function constants = '" +
                                   constants + "': '" + kv[0] +
                                   "' is not a name (a letter, then letters, "
                                   "digits or _)."));
            AssertThrow(kv[0] != "x" && kv[0] != "y" && kv[0] != "z" &&
                          kv[0] != "t",
                        ExcMessage("Initial conditions/Function constants = '" +
                                   constants + "': '" + kv[0] +
                                   "' is a variable of the expressions (x, "
                                   "y, z, t), not a constant."));
            AssertThrow(names.insert(kv[0]).second,
                        ExcMessage("Initial conditions/Function constants = '" +
                                   constants + "': " + kv[0] +
                                   " is given twice."));
          }
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

      /// Deterministic results of each Problem for the scene tests: its
      /// sizes as they are, then its errors with 5 significant digits
      /// (those in the summary).
      void
      print_test_output(const std::string          &problem,
                        const Postprocess::Summary &summary,
                        std::ostream               &out)
      {
        using Keys = std::vector<std::string>;
        const Keys sizes =
          problem == "mpm" ?
            Keys{"steps", "n_dofs", "n_particles", "end_time"} :
          problem == "mass matrix study" ? Keys{"n_rows",
                                                "most_cg_iterations",
                                                "most_pmg_vcycles",
                                                "n_not_converged"} :
                                           Keys{"n_dofs", "n_cells"};
        const Keys errors =
          problem == "mpm"               ? Keys{"errors.displacement_L2",
                                  "errors.velocity_L2",
                                  "errors.stress_L2"} :
          problem == "mass matrix study" ? Keys{"largest_condition_number"} :
                                           Keys{"errors.L2"};
        for (const std::string &key : sizes)
          out << key << " = " << summary.get_number(key) << "\n";
        for (const std::string &key : errors)
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
      prm.declare_entry("Problem",
                        "mpm",
                        Patterns::Selection(
                          "mpm|l2 projection|mass matrix study"),
                        "mpm: material point simulation; l2 projection: "
                        "project Projection/Function onto the basis; mass "
                        "matrix study: condition numbers and CG and "
                        "p-multigrid iterations of B-spline mass matrices "
                        "(solver_study.tsv, doc/solver_study.md).");
      prm.enter_subsection("Geometry");
      prm.declare_entry("Dimension",
                        "2",
                        Patterns::Integer(1, 2),
                        "1: a bar along x on [0, Length] (Mesh/Blocks x "
                        "elements, P1); 2: triangles in the plane.");
      prm.leave_subsection();
      Simulator::Simulator<2>::declare_parameters(prm);
      Solver::L2Projection::declare_parameters(prm);
      Solver::MassMatrixStudy::declare_parameters(prm);
      RunLimits::declare_parameters(prm);
    }

    int
    run(const std::vector<std::string> &args, MPI_Comm comm)
    {
      const bool root = Utilities::MPI::this_mpi_process(comm) == 0;
      Timer      wall;
      wall.start();

      CommandLine      cl;
      ParameterHandler prm;
      declare_parameters(prm);
      std::unique_ptr<Simulator::SimulatorBase> solver;
      Mesh::MeshGenerator<2>                    mesh;
      Solver::L2Projection                      projection;
      Solver::MassMatrixStudy                   mass_matrix_study;
      RunLimits                                 limits;
      std::string                               problem, basis, dir;
      bool                                      test_output = false;
      std::string                               where = "the command line";
      try
        {
          cl = parse_command_line(args);
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
          if (cl.print_parameters && cl.prm_file.empty() &&
              cl.overrides.empty())
            {
              if (root)
                prm.print_parameters(std::cout, ParameterHandler::PRM);
              return success;
            }
          where = cl.prm_file.empty() ? "the embedded default scene" :
                                        "file " + cl.prm_file;
          if (cl.prm_file.empty())
            prm.parse_input_from_string(default_scene, "default scene");
          else
            {
              check_parameter_file(cl.prm_file);
              prm.parse_input(cl.prm_file);
            }
          for (const auto &o : cl.overrides)
            apply_override(prm, o);
          if (cl.print_parameters)
            {
              if (root)
                prm.print_parameters(std::cout, ParameterHandler::PRM);
              return success;
            }
          resolve_mesh_file(prm, cl.prm_file);
          limits.parse_parameters(prm);
          dir = prm.get("Output directory");
          OutputDirectory::check_name(dir);
          prm.enter_subsection("Output");
          test_output                    = prm.get_bool("Test output");
          const double time_interval     = prm.get_double("Time interval");
          const double progress_interval = prm.get_double("Progress interval");
          prm.leave_subsection();
          problem = prm.get("Problem");
          if (problem == "mpm")
            {
              prm.enter_subsection("Geometry");
              const unsigned int dimension = prm.get_integer("Dimension");
              prm.leave_subsection();
              limits.check_entries(prm);
              check_function_constants(prm);
              solver = Simulator::create_simulator(dimension, comm);
              {
                // deal.II's FunctionParser prints the muParser error to
                // std::cerr before it throws; psmpm's message says it.
                std::ostringstream parser_noise;
                struct Restore
                {
                  std::streambuf *old;
                  ~Restore()
                  {
                    std::cerr.rdbuf(old);
                  }
                } restore{std::cerr.rdbuf(parser_noise.rdbuf())};
                solver->parse_parameters(prm);
                limits.check_scene(prm);
                solver->setup();
              }
              solver->check_initial_state();
              solver->quiet                = test_output;
              solver->output_time_interval = time_interval;
              solver->progress_interval    = progress_interval;
              limits.check_run(solver->estimate_size());
            }
          else if (problem == "mass matrix study")
            mass_matrix_study.parse_parameters(prm);
          else
            {
              mesh.parse_parameters(prm);
              projection.parse_parameters(prm);
              prm.enter_subsection("Basis");
              basis = prm.get("Type");
              prm.leave_subsection();
              // The projection integrates on Powell-Sabin sub-triangles.
              AssertThrow(mesh.type != Mesh::MeshGenerator<2>::Type::cartesian,
                          ExcMessage("Mesh/Type = cartesian: Problem = l2 "
                                     "projection runs on triangles only."));
              AssertThrow(!mesh.distributed,
                          ExcMessage("Mesh/Distribution = distributed: "
                                     "Problem = l2 projection runs on a "
                                     "serial mesh (use replicated)."));
              AssertThrow(
                Basis::create_space<2>(basis)->dof_layout().reference_cell() ==
                  ReferenceCells::Triangle,
                ExcMessage("Basis/Type = " + basis +
                           ": Problem = l2 projection runs on "
                           "triangles only (a basis of "
                           "triangles: linear or powell-sabin)."));
              projection.check_scene(mesh, basis);
            }
        }
      catch (const std::bad_alloc &)
        {
          if (root)
            std::cerr << "psmpm: error in " << where
                      << ": out of memory while setting up the scene (reduce "
                         "the number of blocks or particles).\n";
          return bad_input;
        }
      catch (const std::exception &e)
        {
          if (root)
            std::cerr << "psmpm: error in " << where << ": " << message_of(e)
                      << "\n";
          return bad_input;
        }
      catch (...)
        {
          // muParser's exceptions are not std::exceptions.
          if (root)
            std::cerr << "psmpm: error in " << where
                      << ": an expression or its constants could not be "
                         "parsed (Initial conditions/Function constants, "
                         "Velocity, Stress function).\n";
          return bad_input;
        }
      if (cl.validate)
        {
          if (root)
            std::cout << "psmpm: " << where << " is valid.\n";
          return success;
        }
      if (cl.resume && !solver)
        {
          if (root)
            std::cerr << "psmpm: error in " << where
                      << ": --resume needs an mpm scene (Problem = mpm).\n";
          return bad_input;
        }

      // The output directory: created, locked and cleared on rank 0 (kept
      // for --resume); all ranks learn of a failure and stop with
      // bad_input.
      OutputDirectory output;
      try
        {
          output.open(dir, comm, cl.resume);
          if (cl.resume)
            {
              // The newest checkpoint; a damaged one is reported, not
              // skipped: the user decides whether to remove it.
              std::vector<std::string> files;
              if (root)
                files = Simulator::Checkpoint::list(dir);
              files = Utilities::MPI::broadcast(comm, files, 0);
              AssertThrow(!files.empty(),
                          ExcMessage(
                            "--resume: no checkpoint (checkpoint-<step>.h5) "
                            "in the output directory '" +
                            dir +
                            "'. A run writes one at its end, when it is "
                            "interrupted and every Checkpoint/Interval "
                            "steps."));
              solver->resume(dir, files);
            }
        }
      catch (const std::exception &e)
        {
          if (root)
            std::cerr << "psmpm: error in " << where << ": " << message_of(e)
                      << "\n";
          return bad_input;
        }
      LogFile                      log_file(dir + "/log.txt", root, cl.resume);
      Postprocess::Summary         summary;
      std::unique_ptr<StopRequest> stop;
      const std::string            parameter_file =
        cl.prm_file.empty() ? "(default scene)" : cl.prm_file;
      const auto finish_summary = [&]() {
        summary.set("wall_time_s", wall.wall_time());
        summary.set("cpu_time_s", process_cpu_seconds());
        summary.set("parameter_file", parameter_file);
        summary.set("version", version());
      };
      try
        {
          if (root && !test_output)
            std::cout
              << "psmpm " << version() << ": " << where << ", output in "
              << std::filesystem::absolute(dir).lexically_normal().string()
              << " (screen output also in log.txt)" << std::endl;
          if (solver)
            {
              // Collective: every rank computes it.
              const auto size = solver->estimate_size();
              if (root && !test_output)
                std::cout << "psmpm: about " << size.steps << " steps, "
                          << size.n_outputs << " outputs, "
                          << std::max(1.,
                                      std::round(size.output_bytes / 1048576.))
                          << " MiB of output (estimated)" << std::endl;
            }
          std::string error;
          if (root)
            try
              {
                write_atomically(dir + "/parameters.prm",
                                 [&](std::ostream &out) {
                                   prm.print_parameters(out,
                                                        ParameterHandler::PRM);
                                 });
              }
            catch (const ExcWriteFailed &e)
              {
                error = e.what();
              }
          error = Utilities::MPI::broadcast(comm, error, 0);
          if (!error.empty())
            throw ExcWriteFailed(error);

          auto status = Simulator::Status::completed;
          if (problem == "mpm")
            {
              stop   = std::make_unique<StopRequest>();
              status = solver->run(dir);
              stop.reset();
              solver->fill_summary(summary);
            }
          else if (problem == "mass matrix study")
            {
              mass_matrix_study.run(dir, summary, comm);
              summary.set("status", "completed");
            }
          else
            {
              projection.run(mesh, basis, dir, summary, comm);
              summary.set("status", "completed");
            }
          finish_summary();
          if (root)
            {
              summary.write(dir + "/summary.json");
              if (test_output)
                {
                  std::cout << "status = " << Simulator::status_name(status)
                            << "\n";
                  print_test_output(problem, summary, std::cout);
                }
              else
                std::cout << "psmpm: " << summary.to_json();
            }
          if (status == Simulator::Status::completed)
            return success;
          if (status == Simulator::Status::interrupted)
            return interrupted + solver->stop_signal;
          return Simulator::failure_info(solver->get_failure()).exit_code;
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
                  Postprocess::Summary failed;
                  failed.set("status", "failed");
                  failed.set("reason", e.what());
                  failed.set("wall_time_s", wall.wall_time());
                  failed.set("cpu_time_s", process_cpu_seconds());
                  failed.set("parameter_file", parameter_file);
                  failed.set("version", version());
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
