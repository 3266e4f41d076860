// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// Multi-velocity contact gives the same run on one and on two MPI ranks
// (the .output and .mpirun=2.output files are identical): the two-disk
// contact scene (prm/contact_two_disks.prm) up to t = 1.4, through the
// first 0.35 s of the impact, linear and Powell-Sabin. The per-body sums
// of a contact DoF whose cells two ranks hold are added up over both
// ranks before the correction, so both correct it alike; its force and
// works are counted once, by the owner. Printed: the last row's energies,
// centres, contact force and works (7 digits), and the largest contact
// force of the run.
#include "../app_tests.h"

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
      std::ifstream            in(directory + "/statistics.txt");
      std::vector<std::string> names;
      std::vector<double>      last;
      double                   max_force = 0;
      std::string              line;
      while (std::getline(in, line))
        {
          if (line.empty())
            continue;
          if (line[0] == '#')
            {
              names.push_back(line.substr(line.find(':') + 2));
              continue;
            }
          std::istringstream s(line);
          last.assign(names.size(), 0.);
          for (auto &v : last)
            s >> v;
          for (unsigned int c = 0; c < names.size(); ++c)
            if (names[c] == "contact_force_1_2_x")
              max_force = std::max(max_force, std::abs(last[c]));
        }
      for (unsigned int c = 0; c < names.size(); ++c)
        for (const char *n : {"kinetic_energy",
                              "strain_energy",
                              "body1_x",
                              "body1_y",
                              "contact_force_1_2_x",
                              "contact_force_1_2_y",
                              "normal_work_1_2"})
          if (names[c] == n)
            out << "  " << n << " " << std::setprecision(7) << last[c]
                << std::endl;
      out << "  largest |contact_force_1_2_x| " << std::setprecision(7)
          << max_force << std::endl;
      PSMPM_CHECK(out, max_force > 0);
    }
}
