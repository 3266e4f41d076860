// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
// With Transfer/Scheme = otm the grid moves with the material, so the
// automatic time step (Time/Time step = 0) must follow the smallest
// height of the moved cells, not the initial mesh's: before every step
// dt = C f h(t) / max_p (c_p + |v_p|). h(t) is measured here without the
// scheme: particles keep their barycentric coordinates in their cell, so
// the affine map of a cell is fitted to dim + 1 of its particles (initial
// to current positions) and applied to the cell's initial vertices.
// (1D) a bar squeezed by v = -10 x^2 against a fixed left end: the last
//      cell shrinks to below half its length and the step with it (with
//      the initial h_min the cell inverted at step 52 of a fixed step).
// (2D) prm/otm_tangling.prm, whose halves collide: the same formula
//      while cells compress.
// (fixed) a fixed step is checked against the initial mesh only; when the
//      moving grid compresses below it (the bar of prm/otm_bar_1d.prm at
//      0.01 s, 0.89 of the initial h_min / c_p) the run says so once in
//      summary.json; the same bar at rest does not.
#include <deal.II/base/tensor.h>

#include <psmpm/mesh/triangle_geometry.h>

#include "../app_tests.h"
#include "otm_tests.h"

#include <filesystem>
#include <limits>

namespace
{
  using namespace psmpm;

  /// Smallest height of the current (moved) cells that hold particles.
  /// A vertex's moved position comes from any cell around it that holds
  /// dim + 1 or more particles (criss-cross cells may hold fewer).
  template <int dim>
  double
  moved_minimum_height(const Simulator::Simulator<dim> &solver)
  {
    const auto                           &state     = solver.get_state();
    const auto                           &particles = state.particles;
    const auto                           &X = particles.initial_position;
    std::vector<std::vector<std::size_t>> in_cell(
      state.triangulation->n_active_cells());
    for (std::size_t p = 0; p < particles.size(); ++p)
      in_cell[particles.cell[p]].push_back(p);
    std::vector<Point<dim>> moved(state.triangulation->n_vertices());
    std::vector<bool>       known(moved.size(), false);
    for (const auto &cell : state.triangulation->active_cell_iterators())
      {
        const auto &ps = in_cell[cell->active_cell_index()];
        if (ps.size() < dim + 1)
          continue;
        // x = A X + b from dim + 1 particles spanning the cell well: the
        // first, the farthest from it and (2D) the one of largest area.
        std::array<std::size_t, dim + 1> use;
        use.fill(ps[0]);
        double best = 0;
        for (const auto q : ps)
          if (X[q].distance(X[ps[0]]) > best)
            best = X[q].distance(X[ps[0]]), use[1] = q;
        if constexpr (dim == 2)
          {
            best = 0;
            for (const auto q : ps)
              {
                const double a = std::abs(Mesh::signed_area(
                  std::array<Point<2>, 3>{{X[use[0]], X[use[1]], X[q]}}));
                if (a > best)
                  best = a, use[2] = q;
              }
          }
        Tensor<2, dim> D0, D;
        for (unsigned int k = 1; k <= dim; ++k)
          for (unsigned int d = 0; d < dim; ++d)
            {
              D0[d][k - 1] = X[use[k]][d] - X[use[0]][d];
              D[d][k - 1] =
                particles.position[use[k]][d] - particles.position[use[0]][d];
            }
        const Tensor<2, dim> A = D * invert(D0);
        for (unsigned int k = 0; k <= dim; ++k)
          {
            moved[cell->vertex_index(k)] =
              particles.position[use[0]] + A * (cell->vertex(k) - X[use[0]]);
            known[cell->vertex_index(k)] = true;
          }
      }
    double h = std::numeric_limits<double>::max();
    for (const auto &cell : state.triangulation->active_cell_iterators())
      if (!in_cell[cell->active_cell_index()].empty())
        {
          std::array<Point<dim>, dim + 1> v;
          for (unsigned int k = 0; k <= dim; ++k)
            {
              AssertThrow(known[cell->vertex_index(k)],
                          ExcMessage("a vertex without a filled cell"));
              v[k] = moved[cell->vertex_index(k)];
            }
          h = std::min(h, Mesh::minimum_height(v));
        }
    return h;
  }

  /// Steps the solver while no failure and the moved h_min stays above
  /// @p h_stop times the initial one (at most @p max_steps); checks every
  /// automatic step against C f h(t) / c(t).
  template <int dim>
  void
  check(std::ofstream             &out,
        Simulator::Simulator<dim> &solver,
        const double               h_stop,
        const unsigned int         max_steps)
  {
    const auto  &state = solver.get_state();
    const auto  &p     = state.particles;
    const double Cf =
      0.5 * state.space->stability_factor(!state.grid->uses_matrix());
    const double h0        = moved_minimum_height(solver);
    double       deviation = 0, dt_first = 0, dt_last = 0, h = h0;
    unsigned int steps = 0;
    for (; steps < max_steps && h > h_stop * h0 &&
           solver.get_failure() == Simulator::Failure::none;
         ++steps)
      {
        const double dt   = solver.next_time_step();
        double       vmax = 0;
        for (std::size_t i = 0; i < p.size(); ++i)
          vmax = std::max(vmax, p.velocity[i].norm());
        const double c =
          std::max(state.materials.primary().max_wave_speed(p.size(),
                                                            p.stress.data(),
                                                            p.state.data()),
                   state.materials.primary().p_wave_speed()) +
          vmax;
        h         = moved_minimum_height(solver);
        deviation = std::max(deviation, std::abs(dt / (Cf * h / c) - 1));
        (steps == 0 ? dt_first : dt_last) = dt;
        solver.do_time_step(dt);
      }
    out << "steps: " << steps << std::endl;
    PSMPM_CHECK(out, solver.get_failure() == Simulator::Failure::none);
    // The moved cells did shrink, and the step followed them.
    PSMPM_CHECK(out, h <= h_stop * h0);
    PSMPM_CHECK(out, dt_last < dt_first);
    // Round-off of the affine fit (positions O(1), cells O(0.01)).
    PSMPM_CHECK(out, deviation < 1e-10);
    if (!(deviation < 1e-10))
      out << "deviation " << deviation << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  psmpm::MPISession                mpi(argc, argv);
  std::ofstream                    out("output");

  out << "1D squeezed bar" << std::endl;
  auto bar = make_simulator<1>("prm/otm_bar_1d.prm",
                               {"Initial conditions/Velocity=-10*x*x",
                                "Boundary conditions/Fixed x=left",
                                "Reference solution/Type=none",
                                "Time/End time=1",
                                "Time/Time step=0",
                                "Material/Young's modulus=1"});
  check(out, *bar, 0.5, 1000);

  out << "2D tangling block" << std::endl;
  auto block = make_simulator<2>("prm/otm_tangling.prm",
                                 {"Time/End time=1", "Time/Time step=0"});
  check(out, *block, 0.5, 1000);

  out << "fixed step" << std::endl;
  for (const std::string velocity : {"v0*sin(pi*x/L)", "0"})
    {
      std::filesystem::remove_all("run");
      std::string screen, errors;
      const int   code =
        run_app({std::string(PSMPM_SOURCE_DIR) + "/prm/otm_bar_1d.prm",
                 "--set",
                 "Output directory=run",
                 "--set",
                 "Initial conditions/Velocity=" + velocity,
                 "--set",
                 "Reference solution/Type=none",
                 "--set",
                 "Time/Time step=0.01",
                 "--set",
                 "Time/End time=0.06"},
                screen,
                errors);
      const bool warned = read_file("run/summary.json")
                            .find("exceeds the stability bound h_min/c_p = ") !=
                          std::string::npos;
      out << "v = " << velocity << ": exit code " << code << std::endl;
      PSMPM_CHECK(out, code == psmpm::App::success);
      PSMPM_CHECK(out, warned == (velocity != "0"));
    }
}
