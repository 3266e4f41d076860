// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_app_application_h
#define psmpm_app_application_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace psmpm
{
  namespace App
  {
    /// Exit codes of the psmpm executable.
    enum ExitCode : int
    {
      success   = 0,
      internal  = 1, ///< unexpected failure (a bug)
      bad_input = 2, ///< command line, parameter file or mesh rejected
      /// The run stopped as unstable (status, reason, step and time in
      /// summary.json); one code per stability monitor:
      unstable           = 3, ///< non-finite energy or momentum
      unstable_energy    = 4, ///< total energy growth
      unstable_left_mesh = 5, ///< a particle left the mesh
      unstable_volume    = 6, ///< non-positive particle volume
      unstable_solver    = 7, ///< mass matrix solver did not converge
      write_failed       = 8, ///< an output file could not be written
      /// A cell of a grid that moves with the material (Transfer/Scheme =
      /// otm) turned inside out: unstable, like 3 to 7.
      unstable_inverted_cell = 9,
      /// A run stopped by signal N (SIGINT, SIGTERM) after finishing its
      /// step and writing its output ends with interrupted + N.
      interrupted = 128,
    };

    /// The scene that runs when no parameter file is given: the small
    /// deformation vibrating bar of thesis Table 4.1 on 4 blocks.
    extern const char *default_scene;

    /// Declare every parameter of every scene type.
    void
    declare_parameters(dealii::ParameterHandler &prm);

    /**
     * Run psmpm with the command line @p args (without the program name):
     * `[scene.prm] [--set "Subsection/Entry=value"]... [--validate]
     * [--resume] [--print-parameters] [--version] [--help]`. Returns an
     * ExitCode; messages go to std::cout / std::cerr on rank 0. Nothing is
     * written unless the whole input is valid.
     */
    int
    run(const std::vector<std::string> &args, MPI_Comm comm);

    int
    run(int argc, char **argv, MPI_Comm comm);

    /// Apply "Subsection/Entry=value" to @p prm (as --set does).
    void
    apply_override(dealii::ParameterHandler &prm,
                   const std::string        &assignment);
  } // namespace App
} // namespace psmpm

#endif
