// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <psmpm/app/application.h>
#include <psmpm/app/problem.h>
#include <psmpm/app/run_limits.h>
#include <psmpm/base/stop_request.h>
#include <psmpm/basis/space.h>
#include <psmpm/mesh/mesh_generator.h>
#include <psmpm/base/summary.h>
#include <psmpm/simulator/simulator.h>
#include <psmpm/solver/l2_projection.h>
#include <psmpm/solver/mass_matrix_study.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <set>
#include <sstream>

namespace psmpm
{
  namespace App
  {
    using namespace dealii;

    bool
    Problem::resumable() const
    {
      return false;
    }

    void
    Problem::resume(const std::string &, const std::vector<std::string> &)
    {
      AssertThrow(false, ExcInternalError());
    }

    void
    Problem::announce(const bool) const
    {
    }

    int
    Problem::exit_code(const Simulator::Status) const
    {
      // Only a simulation can end other than completed.
      return success;
    }

    namespace
    {
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

      /// Problem = mpm: the material point simulation (of dimension
      /// Geometry/Dimension).
      class Simulation : public Problem
      {
      public:
        explicit Simulation(MPI_Comm comm)
          : comm(comm)
        {
        }

        static void
        declare_parameters(ParameterHandler &prm)
        {
          prm.enter_subsection("Geometry");
          prm.declare_entry("Dimension",
                            "2",
                            Patterns::Integer(1, 2),
                            "1: a bar along x on [0, Length] (Mesh/Blocks x "
                            "elements, P1); 2: triangles in the plane.");
          prm.leave_subsection();
          Simulator::Simulator<2>::declare_parameters(prm);
        }

        void
        set_up(ParameterHandler     &prm,
               const RunLimits      &limits,
               const OutputSettings &output) override
        {
          prm.enter_subsection("Geometry");
          const unsigned int dimension = prm.get_integer("Dimension");
          prm.leave_subsection();
          // Checked before the scene is parsed: parsing builds the
          // reference solution, and the simulator would only say "Can't
          // convert <abc> to a double" of a bad function constant.
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
          solver->quiet                = output.test_output;
          solver->output_time_interval = output.time_interval;
          solver->progress_interval    = output.progress_interval;
          limits.check_run(solver->estimate_size());
        }

        bool
        resumable() const override
        {
          return true;
        }

        void
        resume(const std::string              &output_directory,
               const std::vector<std::string> &checkpoint_files) override
        {
          solver->resume(output_directory, checkpoint_files);
        }

        void
        announce(const bool print) const override
        {
          // Collective: every rank computes it.
          const auto size = solver->estimate_size();
          if (print)
            std::cout << "psmpm: about " << size.steps << " steps, "
                      << size.n_outputs << " outputs, "
                      << std::max(1., std::round(size.output_bytes / 1048576.))
                      << " MiB of output (estimated)" << std::endl;
        }

        Simulator::Status
        run(const std::string    &output_directory,
            Summary &summary,
            MPI_Comm) override
        {
          // SIGINT/SIGTERM finish the step and write the output only while
          // the simulation runs; otherwise they end psmpm as usual.
          stop              = std::make_unique<StopRequest>();
          const auto status = solver->run(output_directory);
          stop.reset();
          solver->fill_summary(summary);
          return status;
        }

        int
        exit_code(const Simulator::Status status) const override
        {
          if (status == Simulator::Status::completed)
            return success;
          if (status == Simulator::Status::interrupted)
            return interrupted + solver->stop_signal;
          return Simulator::failure_info(solver->get_failure()).exit_code;
        }

        TestOutputKeys
        test_output_keys() const override
        {
          return {{"steps", "n_dofs", "n_particles", "end_time"},
                  {"errors.displacement_L2",
                   "errors.velocity_L2",
                   "errors.stress_L2"}};
        }

      private:
        MPI_Comm                                  comm;
        std::unique_ptr<Simulator::SimulatorBase> solver;
        /// Reset after the run; if the run throws, its handlers stay until
        /// App::run returns, while the summary of the failure is written.
        std::unique_ptr<StopRequest> stop;
      };

      /// Problem = l2 projection of Projection/Function onto the basis.
      class Projection : public Problem
      {
      public:
        void
        set_up(ParameterHandler &prm,
               const RunLimits &,
               const OutputSettings &) override
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
          // The whole projection: a function that double numbers cannot
          // project is bad input, reported before any output is written.
          projection.prepare(mesh, basis);
        }

        Simulator::Status
        run(const std::string    &output_directory,
            Summary &summary,
            MPI_Comm              comm) override
        {
          projection.run(mesh, basis, output_directory, summary, comm);
          const std::string failure = projection.failure();
          if (failure.empty())
            {
              summary.set("status", "completed");
              return Simulator::Status::completed;
            }
          // As a simulation whose mass matrix solver fails: the reason on
          // the screen and in summary.json, exit code 7.
          summary.set("status", "unstable");
          summary.set("reason", failure);
          if (Utilities::MPI::this_mpi_process(comm) == 0)
            std::cerr << "psmpm: " << failure << "\n";
          return Simulator::Status::unstable;
        }

        int
        exit_code(const Simulator::Status status) const override
        {
          return status == Simulator::Status::completed ?
                   success :
                   Simulator::failure_info(Simulator::Failure::solver)
                     .exit_code;
        }

        TestOutputKeys
        test_output_keys() const override
        {
          return {{"n_dofs", "n_cells"}, {"errors.L2"}};
        }

      private:
        Mesh::MeshGenerator<2> mesh;
        Solver::L2Projection   projection;
        std::string            basis;
      };

      /// Problem = mass matrix study: condition numbers and iterations of
      /// B-spline mass matrices.
      class MassMatrixStudy : public Problem
      {
      public:
        void
        set_up(ParameterHandler &prm,
               const RunLimits &,
               const OutputSettings &) override
        {
          study.parse_parameters(prm);
        }

        Simulator::Status
        run(const std::string    &output_directory,
            Summary &summary,
            MPI_Comm              comm) override
        {
          study.run(output_directory, summary, comm);
          summary.set("status", "completed");
          return Simulator::Status::completed;
        }

        TestOutputKeys
        test_output_keys() const override
        {
          return {{"n_rows",
                   "most_cg_iterations",
                   "most_pmg_vcycles",
                   "n_not_converged"},
                  {"largest_condition_number"}};
        }

      private:
        Solver::MassMatrixStudy study;
      };

      /// The one table of Problems, in the order the entry lists them.
      struct ProblemType
      {
        const char *name;
        void (*declare_parameters)(ParameterHandler &);
        std::unique_ptr<Problem> (*create)(MPI_Comm);
      };

      const std::array<ProblemType, 3> problem_types = {
        {{"mpm",
          &Simulation::declare_parameters,
          [](MPI_Comm comm) -> std::unique_ptr<Problem> {
            return std::make_unique<Simulation>(comm);
          }},
         {"l2 projection",
          &Solver::L2Projection::declare_parameters,
          [](MPI_Comm) -> std::unique_ptr<Problem> {
            return std::make_unique<Projection>();
          }},
         {"mass matrix study",
          &Solver::MassMatrixStudy::declare_parameters,
          [](MPI_Comm) -> std::unique_ptr<Problem> {
            return std::make_unique<MassMatrixStudy>();
          }}}};
    } // namespace

    void
    declare_problem_parameters(ParameterHandler &prm)
    {
      std::string selection;
      for (const auto &type : problem_types)
        selection += (selection.empty() ? "" : "|") + std::string(type.name);
      prm.declare_entry("Problem",
                        problem_types[0].name,
                        Patterns::Selection(selection),
                        "mpm: material point simulation; l2 projection: "
                        "project Projection/Function onto the basis; mass "
                        "matrix study: condition numbers and CG and "
                        "p-multigrid iterations of B-spline mass matrices "
                        "(solver_study.tsv, doc/solver_study.md).");
      for (const auto &type : problem_types)
        type.declare_parameters(prm);
    }

    std::unique_ptr<Problem>
    create_problem(const std::string &name, MPI_Comm comm)
    {
      for (const auto &type : problem_types)
        if (name == type.name)
          return type.create(comm);
      // The entry's pattern admits only the names of the table.
      AssertThrow(false, ExcInternalError());
      return nullptr;
    }
  } // namespace App
} // namespace psmpm
