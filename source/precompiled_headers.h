// ---------------------------------------------------------------------
// psmpm: headers precompiled once for every library source file
// (PSMPM_PRECOMPILED_HEADERS). Parsing deal.II's and Trilinos' headers is
// most of a translation unit's compile time; precompiling these cut the
// compile of source/basis/powell_sabin.cc from 17.2 to 9.4 CPU s and
// source/solver/grid_system.cc from 24.7 to 16.6 s. Only headers that many
// source files include belong here: a change to any of them rebuilds all.
// Source files still include what they use, so that they also compile
// without this header.
// ---------------------------------------------------------------------
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/table_handler.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/timer.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_simplex_p.h>

#include <deal.II/grid/tria.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>
