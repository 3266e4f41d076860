// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_base_root_errors_h
#define psmpm_base_root_errors_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <exception>
#include <sstream>
#include <string>

namespace psmpm
{
  /// What psmpm reports of @p e: a deal.II exception's additional
  /// information (its message, without source location and stack trace),
  /// what() of any other.
  inline std::string
  error_text(const std::exception &e)
  {
    if (const auto *d = dynamic_cast<const dealii::ExceptionBase *>(&e))
      {
        std::ostringstream s;
        d->print_info(s);
        return dealii::Utilities::trim(s.str());
      }
    return e.what();
  }

  /**
   * Run @p work on rank 0 of @p comm only (reading a file, building the
   * whole mesh) and throw what it threw, as ExcMessage, on every rank.
   * A failure on rank 0 alone would leave the other ranks waiting in the
   * next collective call: a hang instead of a clear error.
   */
  template <typename Work>
  void
  on_root_or_throw_everywhere(const MPI_Comm comm, Work &&work)
  {
    std::string error;
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          work();
        }
      catch (const std::exception &e)
        {
          error = error_text(e);
        }
    error = dealii::Utilities::MPI::broadcast(comm, error, 0);
    AssertThrow(error.empty(), dealii::ExcMessage(error));
  }
} // namespace psmpm

#endif
