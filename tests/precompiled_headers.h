// ---------------------------------------------------------------------
// psmpm: headers precompiled once for every test program
// (PSMPM_PRECOMPILED_HEADERS). A test is a small file, so parsing these
// headers was nearly all of its compile time: tests/basis/linear_01.cc
// took 16.6 CPU s without and 6.8 s with them, tests/mpm/vibrating_bar_01.cc
// 15.5 and 4.8 s. Tests still include what they use.
// ---------------------------------------------------------------------
#include <deal.II/base/logstream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <psmpm/app/application.h>
#include <psmpm/basis/linear.h>
#include <psmpm/basis/powell_sabin.h>
#include <psmpm/mesh/mesh_generator.h>
#include <psmpm/simulator/simulator.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>
