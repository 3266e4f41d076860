// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Multi-velocity contact gives the same run on one and on two MPI ranks
// (the .output and .mpirun=2.output files are identical): the two-disk
// contact scene (prm/contact_two_disks.prm) up to t = 1.4, through the
// first 0.35 s of the impact, linear (musl) and Powell-Sabin (apic,
// its default with contact: the per-body momenta of the affine fields,
// their increments to velocities and affine matrices). The per-body sums
// of a contact DoF whose cells two ranks hold are added up over both
// ranks before the correction, so both correct it alike; its force and
// works are counted once, by the owner. Printed: the last row's energies,
// centres, contact force and works (7 digits), and the largest contact
// force of the run.
#include "../app_tests.h"
#include "../mpm_tests.h"

#include <iomanip>

int
main(int argc, char **argv)
{
  psmpm::MPISession mpi(argc, argv);
  std::ofstream     out = root_output();
  for (const std::string basis : {"linear", "powell-sabin"})
    {
      const std::string directory = "ranks-" + basis;
      std::string       screen, errors;
      const int         code =
        run_app({std::string(PSMPM_SOURCE_DIR) + "/prm/contact_two_disks.prm",
                 "--set",
                 "Output directory=" + directory,
                 "--set",
                 "Basis/Type=" + basis,
                 "--set",
                 "Time/End time=1.4"},
                screen,
                errors);
      out << basis << ": exit code " << code << std::endl;
      if (!is_root_rank())
        continue;
      const StatisticsTable table(directory);
      double                max_force = 0;
      for (const double f : table.column("contact_force_1_2_x"))
        max_force = std::max(max_force, std::abs(f));
      for (const auto &n : table.names)
        for (const char *printed : {"kinetic_energy",
                                    "strain_energy",
                                    "body1_x",
                                    "body1_y",
                                    "contact_force_1_2_x",
                                    "contact_force_1_2_y",
                                    "normal_work_1_2"})
          if (n == printed)
            out << "  " << n << " " << std::setprecision(7)
                << table.column(n).back() << std::endl;
      out << "  largest |contact_force_1_2_x| " << std::setprecision(7)
          << max_force << std::endl;
      PSMPM_CHECK(out, max_force > 0);
    }
}
