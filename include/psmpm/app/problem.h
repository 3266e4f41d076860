// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_app_problem_h
#define psmpm_app_problem_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <psmpm/simulator/simulator.h>

#include <memory>
#include <string>
#include <vector>

namespace psmpm
{
  class Summary;

  namespace App
  {
    class RunLimits;

    /// The Output entries that the application reads for every Problem.
    struct OutputSettings
    {
      /// Output/Test output: machine-independent screen output only.
      bool test_output = false;
      /// Output/Time interval [s].
      double time_interval = 0;
      /// Output/Progress interval [s of wall time].
      double progress_interval = 0;
    };

    /**
     * What a scene computes (entry Problem): a material point simulation,
     * an L2 projection or a mass matrix study. App::run sees only this
     * interface, so that the choice of Problem is made in one place
     * (create_problem()) and a new kind of scene is one more class and one
     * more row of the table in problem.cc.
     *
     * The life of a Problem: set_up() while the input is being checked
     * (any exception is bad input, nothing is written yet); then, once the
     * output directory is open, resume() for --resume, announce() and
     * run().
     */
    class Problem
    {
    public:
      virtual ~Problem() = default;

      /// Parse and check the Problem's entries and build what it needs;
      /// throws with a message naming the entry on bad input.
      virtual void
      set_up(dealii::ParameterHandler &prm,
             const RunLimits          &limits,
             const OutputSettings     &output) = 0;

      /// Whether --resume can continue this Problem from a checkpoint.
      virtual bool
      resumable() const;

      /// Continue from the first readable of @p checkpoint_files (newest
      /// first; collective); only called if resumable().
      virtual void
      resume(const std::string              &output_directory,
             const std::vector<std::string> &checkpoint_files);

      /// Screen lines before the run (printed if @p print; collective).
      virtual void
      announce(const bool print) const;

      /// Compute, write the output files into @p output_directory and fill
      /// @p summary (status included).
      virtual Simulator::Status
      run(const std::string    &output_directory,
          Summary &summary,
          MPI_Comm              comm) = 0;

      /// The exit code of a run that ended with @p status.
      virtual int
      exit_code(const Simulator::Status status) const;

      /// The summary keys printed with Output/Test output: sizes as they
      /// are, errors with 5 significant digits (if present).
      struct TestOutputKeys
      {
        std::vector<std::string> sizes;
        std::vector<std::string> errors;
      };
      virtual TestOutputKeys
      test_output_keys() const = 0;
    };

    /// Declare the entry Problem and the entries of every Problem.
    void
    declare_problem_parameters(dealii::ParameterHandler &prm);

    /// The Problem named @p name (a value of the entry Problem).
    std::unique_ptr<Problem>
    create_problem(const std::string &name, MPI_Comm comm);
  } // namespace App
} // namespace psmpm

#endif
