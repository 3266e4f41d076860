// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/affine_constraints.h>

#include <psmpm/base/format.h>
#include <psmpm/simulator/boundary_conditions.h>
#include <psmpm/simulator/function_of_time.h>
#include <psmpm/simulator/reconstruction.h>
#include <psmpm/simulator/state.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace psmpm
{
  namespace Simulator
  {
    namespace
    {
      constexpr unsigned int invalid           = numbers::invalid_unsigned_int;
      const char            *component_names[] = {"x", "y"};

      /// @p s split at @p separator outside parentheses, items trimmed,
      /// empty items dropped (muParser expressions hold commas in calls).
      std::vector<std::string>
      split_outside_parentheses(const std::string &s, const char separator)
      {
        std::vector<std::string> items;
        std::string              item;
        int                      depth = 0;
        for (const char c : s)
          {
            depth += (c == '(') - (c == ')');
            if (c == separator && depth == 0)
              {
                items.push_back(Utilities::trim(item));
                item.clear();
              }
            else
              item += c;
          }
        items.push_back(Utilities::trim(item));
        items.erase(std::remove(items.begin(), items.end(), std::string()),
                    items.end());
        return items;
      }

      /// "name: rest" -> {name, rest}; throws naming @p entry otherwise.
      std::pair<std::string, std::string>
      name_and_value(const std::string &item, const std::string &entry)
      {
        const auto colon = item.find(':');
        AssertThrow(colon != std::string::npos && colon > 0,
                    ExcMessage("Boundary conditions/" + entry + " = " + item +
                               ": expected 'boundary name: value'."));
        return {Utilities::trim(item.substr(0, colon)),
                Utilities::trim(item.substr(colon + 1))};
      }

      bool
      to_double(const std::string &s, double &value)
      {
        try
          {
            std::size_t end = 0;
            value           = std::stod(s, &end);
            return Utilities::trim(s.substr(end)).empty();
          }
        catch (...)
          {
            return false;
          }
      }
    } // namespace

    template <int dim>
    void
    BoundaryConditions<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Report reactions",
        "false",
        Patterns::Bool(),
        "Write the reaction force of every boundary with a fixed, "
        "prescribed or frictional velocity component into statistics.txt "
        "(reaction_<name>_<x|y>: the force the wall exerts on the body, "
        "(M a - f) summed over its constrained DoFs). On automatically "
        "with Friction coefficient or Prescribed velocity.");
      prm.declare_entry(
        "Friction coefficient",
        "",
        Patterns::Anything(),
        "Coulomb friction walls: 'name: mu, name: mu' (mu >= 0, or "
        "'no-slip' to fix the tangential velocity too). A frictional "
        "boundary must have its normal velocity fixed (Fixed x or Fixed "
        "y) and be straight and axis-aligned. Empty: frictionless walls. "
        "2D, not with a grid that moves (otm).");
      prm.declare_entry(
        "Prescribed velocity",
        "",
        Patterns::Anything(),
        "Boundaries moved with a velocity that is a function of the time "
        "t, one expression per component separated by ';', boundaries by "
        "',': e.g. 'footing: 0; -1e-3*min(t/0.1, 1)' (the boundary starts "
        "at rest: start smoothly, a sudden start is an impact); 'free' "
        "for a component leaves it unconstrained (a smooth plate: "
        "'top: free; -1e-3'). The "
        "boundary's grid velocity is the prescribed one and its "
        "acceleration the change over the step; its reaction and work "
        "(prescribed_work) are reported. Lumped mass only (Mass "
        "matrix/Type = lumped).");
      prm.declare_entry(
        "Local damping",
        "0",
        Patterns::Double(0, 1),
        "Local (Cundall) damping alpha, 0 <= alpha < 1: the grid force of "
        "every DoF and component is reduced by alpha |f_i| in the direction "
        "of the DoF's velocity (f_i -> f_i - alpha |f_i| sign(v_i)), which "
        "damps a body towards static equilibrium without damping a rigid "
        "motion at constant velocity; for quasi-static loading, not for "
        "dynamics (it slows a free fall too). Its work is the statistics "
        "column damping_work. 0: off.");
      prm.declare_entry(
        "Stop particles at walls",
        "false",
        Patterns::Bool(),
        "Whether the particles receive the velocity change with which the "
        "walls stop the grid: after MUSL's second projection the fixed and "
        "prescribed DoFs are set to their constrained velocity, and the "
        "same change, interpolated, goes to the particles' velocities (as "
        "a sticking frictional wall's hold does), so that particles at a "
        "wall keep no velocity into it that they do not move with. The "
        "particles' kinetic energy removed is the column wall_stop_work "
        "(material that meets a wall stops there: an inelastic impact). Transfer/Scheme = musl only.");
      prm.declare_entry(
        "Boundary parts",
        "",
        Patterns::Anything(),
        "New named boundaries made of part of one: 'name: parent, from, "
        "to; ...' gives the faces of boundary 'parent' whose centres lie "
        "in [from, to] along the face direction (x on a horizontal "
        "boundary, y on a vertical one) the new name, usable in every "
        "entry of this subsection (2D).");
    }

    template <int dim>
    void
    BoundaryConditions<dim>::parse_parameters(ParameterHandler &prm)
    {
      report_reactions = prm.get_bool("Report reactions");
      stop_at_walls    = prm.get_bool("Stop particles at walls");
      local_damping    = prm.get_double("Local damping");
      AssertThrow(local_damping < 1,
                  ExcMessage("Boundary conditions/Local damping = " +
                             prm_value(local_damping) +
                             ": must be below 1 (1 would cancel every "
                             "force that drives a motion)."));
      parse_friction(prm.get("Friction coefficient"));
      parse_prescribed(prm.get("Prescribed velocity"));
      parse_parts(prm.get("Boundary parts"));
    }

    template <int dim>
    void
    BoundaryConditions<dim>::parse_friction(const std::string &friction_text)
    {
      friction.clear();
      for (const auto &item : split_outside_parentheses(friction_text, ','))
        {
          const auto [name, value] =
            name_and_value(item, "Friction coefficient");
          Friction f;
          f.name    = name;
          f.no_slip = value == "no-slip";
          AssertThrow(f.no_slip || (to_double(value, f.mu) &&
                                    std::isfinite(f.mu) && f.mu >= 0),
                      ExcMessage("Boundary conditions/Friction coefficient = " +
                                 friction_text + ": '" + value + "' for '" +
                                 name +
                                 "' must be a number >= 0 or 'no-slip'."));
          for (const auto &g : friction)
            AssertThrow(g.name != name,
                        ExcMessage("Boundary conditions/Friction coefficient "
                                   "= " +
                                   friction_text + ": '" + name +
                                   "' is given twice."));
          friction.push_back(f);
        }
      AssertThrow(friction.empty() || dim == 2,
                  ExcMessage("Boundary conditions/Friction coefficient = " +
                             friction_text +
                             ": friction needs Geometry/Dimension = 2."));
    }

    template <int dim>
    void
    BoundaryConditions<dim>::parse_prescribed(
      const std::string &prescribed_text)
    {
      prescribed.clear();
      for (const auto &item : split_outside_parentheses(prescribed_text, ','))
        {
          const auto [name, value] =
            name_and_value(item, "Prescribed velocity");
          Prescribed p;
          p.name           = name;
          p.expression     = value;
          auto expressions = Utilities::split_string_list(p.expression, ';');
          for (unsigned int d = 0; d < expressions.size() && d < dim; ++d)
            if (expressions[d] == "free")
              {
                p.free[d]      = true;
                expressions[d] = "0";
              }
          AssertThrow(expressions.size() == dim,
                      ExcMessage("Boundary conditions/Prescribed velocity = " +
                                 prescribed_text + ": '" + value + "' for '" +
                                 name + "' needs " + std::to_string(dim) +
                                 " expression(s) separated by ';'."));
          // One variable, t: the velocity of a rigid boundary.
          try
            {
              p.velocity = parse_function_of_time(expressions);
            }
          catch (const std::exception &e)
            {
              AssertThrow(false,
                          ExcMessage(
                            "Boundary conditions/Prescribed velocity = " +
                            prescribed_text + ": '" + value + "' for '" + name +
                            "' is not a function of t (" +
                            Utilities::trim(e.what()) + ")."));
            }
          for (const auto &q : prescribed)
            AssertThrow(q.name != name,
                        ExcMessage("Boundary conditions/Prescribed velocity "
                                   "= " +
                                   prescribed_text + ": '" + name +
                                   "' is given twice."));
          prescribed.push_back(std::move(p));
        }
    }

    template <int dim>
    std::string
    BoundaryConditions<dim>::non_finite_velocity(const double t) const
    {
      for (const auto &p : prescribed)
        {
          const std::string bad =
            non_finite_at(*p.velocity, t, p.free.data());
          if (!bad.empty())
            return "Boundary conditions/Prescribed velocity: '" +
                   p.expression + "' for '" + p.name + "'" + bad;
        }
      return std::string();
    }

    template <int dim>
    void
    BoundaryConditions<dim>::parse_parts(const std::string &parts_text)
    {
      parts.clear();
      for (const auto &item : split_outside_parentheses(parts_text, ';'))
        {
          const auto [name, value] = name_and_value(item, "Boundary parts");
          const auto fields        = Utilities::split_string_list(value, ',');
          Part       part;
          part.name     = name;
          const bool ok = fields.size() == 3 && !fields[0].empty() &&
                          to_double(fields[1], part.from) &&
                          to_double(fields[2], part.to) && part.from <= part.to;
          AssertThrow(ok,
                      ExcMessage("Boundary conditions/Boundary parts = " +
                                 parts_text + ": '" + item +
                                 "' must be 'name: parent, from, to' with "
                                 "from <= to."));
          part.parent = fields[0];
          parts.push_back(part);
        }
      AssertThrow(parts.empty() || dim == 2,
                  ExcMessage("Boundary conditions/Boundary parts = " +
                             parts_text + ": needs Geometry/Dimension = 2."));
    }

    template <int dim>
    void
    BoundaryConditions<dim>::mark_boundary_parts(
      Triangulation<dim>             &tria,
      const Mesh::MeshGenerator<dim> &mesh) const
    {
      for (const auto &part : parts)
        {
          const std::string entry =
            "Boundary conditions/Boundary parts: '" + part.name + "'";
          AssertThrow(mesh.boundary_names().count(part.name) == 0,
                      ExcMessage(entry + ": this mesh has a boundary of "
                                         "that name already."));
          types::boundary_id parent = 0;
          try
            {
              parent = mesh.boundary_id(part.parent);
            }
          catch (const ExcMessage &e)
            {
              AssertThrow(false, ExcMessage(entry + ": " + e.what()));
            }
          types::boundary_id id = 0;
          for (const auto &n : mesh.boundary_names())
            id = std::max<types::boundary_id>(id, n.second + 1);
          AssertThrow(id < Mesh::rim_boundary_id, ExcInternalError());
          unsigned int marked = 0;
          for (const auto &cell : tria.active_cell_iterators())
            for (const auto f : cell->face_indices())
              if (cell->face(f)->at_boundary() &&
                  cell->face(f)->boundary_id() == parent)
                {
                  const auto         face = cell->face(f);
                  const auto         t    = face->vertex(1) - face->vertex(0);
                  const unsigned int axis =
                    std::abs(t[0]) >= std::abs(t[dim - 1]) ? 0 : dim - 1;
                  const double c = face->center()[axis];
                  if (c >= part.from && c <= part.to)
                    {
                      face->set_boundary_id(id);
                      ++marked;
                    }
                }
          AssertThrow(Utilities::MPI::max(marked, tria.get_communicator()) > 0,
                      ExcMessage(entry + ": no face of '" + part.parent +
                                 "' has its centre in [" +
                                 prm_value(part.from) + ", " +
                                 prm_value(part.to) + "]."));
          mesh.add_boundary_name(part.name, id);
        }
    }

    template <int dim>
    void
    BoundaryConditions<dim>::add_constrained(
      std::array<std::set<types::boundary_id>, dim> &fixed,
      const Mesh::MeshGenerator<dim>                &mesh) const
    {
      const auto id_of = [&](const std::string &name,
                             const std::string &entry) {
        try
          {
            return mesh.boundary_id(name);
          }
        catch (const ExcMessage &e)
          {
            AssertThrow(false,
                        ExcMessage("Boundary conditions/" + entry + ": " +
                                   e.what()));
          }
        return numbers::invalid_boundary_id;
      };
      for (const auto &p : prescribed)
        {
          const auto id = id_of(p.name, "Prescribed velocity");
          for (unsigned int d = 0; d < dim; ++d)
            if (!p.free[d])
              fixed[d].insert(id);
        }
      for (const auto &f : friction)
        {
          const auto   id      = id_of(f.name, "Friction coefficient");
          unsigned int n_fixed = 0, normal = 0;
          for (unsigned int d = 0; d < dim; ++d)
            if (fixed[d].count(id) > 0)
              ++n_fixed, normal = d;
          AssertThrow(n_fixed == 1,
                      ExcMessage("Boundary conditions/Friction coefficient: "
                                 "boundary '" +
                                 f.name +
                                 "' must have exactly one velocity component "
                                 "fixed, its normal (Fixed x or Fixed y; "
                                 "it has " +
                                 std::to_string(n_fixed) + ")."));
          if (f.no_slip)
            fixed[1 - normal].insert(id);
        }
    }

    template <int dim>
    void
    BoundaryConditions<dim>::reinit(
      const State<dim>                                &state,
      const std::array<std::vector<std::string>, dim> &fixed_names,
      const Mesh::MeshGenerator<dim>                  &mesh,
      const bool                                       grid_moves)
    {
      columns.clear();
      walls.clear();
      prescribed_dofs.clear();
      column_prescribed.clear();
      if (!active())
        return;
      const auto &grid = *state.grid;
      AssertThrow(!grid_moves,
                  ExcMessage("Boundary conditions/Report reactions, Friction "
                             "coefficient and Prescribed velocity: not with "
                             "a transfer whose grid moves (Transfer/Scheme = "
                             "otm); use musl, usl or apic."));
      lumped_acceleration =
        !grid.uses_matrix() ||
        (state.reconstruction && state.reconstruction->lumped_acceleration());
      AssertThrow(prescribed.empty() || !grid.uses_matrix(),
                  ExcMessage("Boundary conditions/Prescribed velocity: "
                             "needs Mass matrix/Type = lumped (with a mass "
                             "matrix the prescribed values would enter the "
                             "right-hand side of the other rows, which is "
                             "not implemented); this run has " +
                             grid.parameters.type + "."));

      assign_columns(state, attribution_order(fixed_names), mesh);
      wall_of.assign(grid.relevant_global_indices().size(), invalid);
      if constexpr (dim == 2)
        for (const auto &f : friction)
          if (!f.no_slip)
            add_friction_wall(state, f, fixed_names, mesh);
      collect_entries(state);
      collect_prescribed_dofs();
      allocate_results(state);
    }

    template <int dim>
    std::array<std::vector<std::string>, dim>
    BoundaryConditions<dim>::attribution_order(
      const std::array<std::vector<std::string>, dim> &fixed_names) const
    {
      std::array<std::vector<std::string>, dim> order;
      const auto add = [&](const unsigned int d, const std::string &name) {
        if (std::find(order[d].begin(), order[d].end(), name) == order[d].end())
          order[d].push_back(name);
      };
      for (const auto &p : prescribed)
        for (unsigned int d = 0; d < dim; ++d)
          if (!p.free[d])
            add(d, p.name);
      for (unsigned int d = 0; d < dim; ++d)
        for (const auto &name : fixed_names[d])
          add(d, name);
      for (const auto &f : friction)
        if (f.no_slip)
          for (unsigned int d = 0; d < dim; ++d)
            add(d, f.name);
      return order;
    }

    template <int dim>
    void
    BoundaryConditions<dim>::assign_columns(
      const State<dim>                                &state,
      const std::array<std::vector<std::string>, dim> &order,
      const Mesh::MeshGenerator<dim>                  &mesh)
    {
      const auto        &grid     = *state.grid;
      const auto        &relevant = grid.relevant_global_indices();
      const unsigned int n_dofs   = relevant.size();
      const auto        &space    = grid.get_space();
      const auto        &handler  = grid.get_dof_handler();
      for (unsigned int d = 0; d < dim; ++d)
        {
          dof_column[d].assign(n_dofs, invalid);
          const auto &constraints = grid.dirichlet_constraints(d);
          for (const auto &name : order[d])
            {
              AffineConstraints<double> own(grid.relevant_dofs());
              space.make_dirichlet_constraints(handler,
                                               {mesh.boundary_id(name)},
                                               Functions::ZeroFunction<dim>(),
                                               own);
              const unsigned int column = columns.size();
              columns.push_back({name, d});
              bool is_prescribed = false;
              for (const auto &p : prescribed)
                is_prescribed = is_prescribed || p.name == name;
              column_prescribed.push_back(is_prescribed);
              // DoFs fixed to zero by the grid (no ties to others).
              for (unsigned int l = 0; l < n_dofs; ++l)
                {
                  const auto g = relevant[l];
                  if (dof_column[d][l] == invalid && own.is_constrained(g) &&
                      constraints.is_constrained(g) &&
                      constraints.get_constraint_entries(g)->empty() &&
                      constraints.get_inhomogeneity(g) == 0)
                    dof_column[d][l] = column;
                }
            }
        }
    }

    template <int dim>
    void
    BoundaryConditions<dim>::add_friction_wall(
      const State<dim>                                &state,
      const Friction                                  &f,
      const std::array<std::vector<std::string>, dim> &fixed_names,
      const Mesh::MeshGenerator<dim>                  &mesh)
    {
      const auto  &grid   = *state.grid;
      const auto   id     = mesh.boundary_id(f.name);
      unsigned int normal = 0;
      for (unsigned int d = 0; d < dim; ++d)
        if (std::find(fixed_names[d].begin(), fixed_names[d].end(), f.name) !=
            fixed_names[d].end())
          normal = d;
      const unsigned int tangential = 1 - normal;
      double             outward    = 0;
      for (const auto &cell : grid.get_dof_handler().active_cell_iterators())
        for (const auto face_no : cell->face_indices())
          if (cell->face(face_no)->at_boundary() &&
              cell->face(face_no)->boundary_id() == id)
            {
              const auto face = cell->face(face_no);
              const auto t    = face->vertex(1) - face->vertex(0);
              AssertThrow(std::abs(t[normal]) <= 1e-10 * t.norm(),
                          ExcMessage(
                            "Boundary conditions/Friction coefficient: "
                            "boundary '" +
                            f.name + "' has its " + component_names[normal] +
                            " velocity fixed but is not perpendicular "
                            "to " +
                            component_names[normal] +
                            " (friction needs axis-aligned walls)."));
              outward += face->center()[normal] - cell->center()[normal];
            }
      const unsigned int column = columns.size();
      columns.push_back({f.name, tangential});
      column_prescribed.push_back(false);
      unsigned int normal_column = invalid;
      for (unsigned int c = 0; c < columns.size(); ++c)
        if (columns[c].name == f.name && columns[c].component == normal)
          normal_column = c;
      const auto &relevant = grid.relevant_global_indices();
      const auto &tangential_constraints =
        grid.dirichlet_constraints(tangential);
      for (unsigned int l = 0; l < relevant.size(); ++l)
        if (dof_column[normal][l] == normal_column &&
            !tangential_constraints.is_constrained(relevant[l]))
          {
            wall_of[l] = walls.size();
            walls.push_back(
              {l, normal, tangential, outward > 0 ? 1. : -1., f.mu, column});
          }
    }

    template <int dim>
    void
    BoundaryConditions<dim>::collect_entries(const State<dim> &state)
    {
      const auto        &grid  = *state.grid;
      const unsigned int n     = grid.dofs_per_cell;
      const auto        &cells = grid.cell_dofs();
      for (unsigned int d = 0; d < dim; ++d)
        {
          entries[d].clear();
          for (const unsigned int c : grid.owned_cells())
            for (unsigned int k = 0; k < n; ++k)
              {
                const unsigned int l = cells[c * n + k];
                if (dof_column[d][l] == invalid)
                  continue;
                const unsigned int w = wall_of[l];
                entries[d].push_back(
                  {c * n + k,
                   dof_column[d][l],
                   w != invalid && walls[w].normal == d ? w : invalid});
              }
        }
    }

    template <int dim>
    void
    BoundaryConditions<dim>::collect_prescribed_dofs()
    {
      const unsigned int n_dofs = wall_of.size();
      for (unsigned int b = 0; b < prescribed.size(); ++b)
        for (unsigned int d = 0; d < dim; ++d)
          for (unsigned int l = 0; l < n_dofs; ++l)
            {
              const unsigned int column = dof_column[d][l];
              if (column != invalid &&
                  columns[column].name == prescribed[b].name)
                prescribed_dofs.push_back({l, d, b});
            }
    }

    template <int dim>
    void
    BoundaryConditions<dim>::allocate_results(const State<dim> &state)
    {
      const auto &grid = *state.grid;
      reactions.assign(columns.size(), 0.);
      wall_normal.assign(walls.size(), 0.);
      hold_capacity.assign(walls.size(), 0.);
      hold_change.assign(walls.size(), 0.);
      wall_owned.assign(walls.size(), true);
      sum_over_ranks =
        (!friction.empty() || stop_at_walls) &&
        Utilities::MPI::n_mpi_processes(grid.get_communicator()) > 1;
      for (unsigned int d = 0; d < dim; ++d)
        {
          stop_momentum[d].assign(stop_at_walls ? wall_of.size() : 0, 0.);
          stop_mass[d].assign(stop_at_walls ? wall_of.size() : 0, 0.);
        }
      stop_cell.assign(stop_at_walls ?
                         grid.cell_dofs().size() / grid.dofs_per_cell :
                         0,
                       0);
      if (stop_at_walls)
        for (unsigned int d = 0; d < dim; ++d)
          for (const Entry &e : entries[d])
            stop_cell[e.index / grid.dofs_per_cell] = 1;
      if (sum_over_ranks)
        {
          const auto &owned    = grid.locally_owned_dofs();
          const auto &relevant = grid.relevant_global_indices();
          for (unsigned int w = 0; w < walls.size(); ++w)
            wall_owned[w] = owned.is_element(relevant[walls[w].dof]);
          relevant_buffer.assign(relevant.size(), 0.);
          owned_buffer.assign(owned.n_elements(), 0.);
        }
    }

    template <int dim>
    void
    BoundaryConditions<dim>::after_acceleration(State<dim> &state)
    {
      apply_local_damping(state);
      prescribe_acceleration(state);
      compute_reactions(state);
      if (sum_over_ranks)
        sum_wall_normals(state);
      apply_friction(state);
      const MPI_Comm comm = state.grid->get_communicator();
      if (Utilities::MPI::n_mpi_processes(comm) > 1)
        Utilities::MPI::sum(reactions, comm, reactions);
      if (!prescribed.empty())
        add_prescribed_work(state.dt);
    }

    template <int dim>
    void
    BoundaryConditions<dim>::apply_local_damping(State<dim> &state)
    {
      // A force -alpha |f_i| sign(v_i) per component, with f_i = m_i a_i
      // of the lumped mass (constrained DoFs have a = 0).
      auto        &a  = state.grid_acceleration;
      const double dt = state.dt;
      if (!(local_damping > 0 && state.grid_velocity.size() == a.size()))
        return;
      const auto &mass = state.grid->lumped_mass();
      double      work = 0;
      for (unsigned int l = 0; l < a.size(); ++l)
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double v = state.grid_velocity[l][d];
            if (v == 0)
              continue;
            const double change =
              -local_damping * std::abs(a[l][d]) * (v > 0 ? 1. : -1.);
            a[l][d] += change;
            work += mass[l] * change * v * dt;
          }
      accumulated_damping_work += work;
    }

    template <int dim>
    void
    BoundaryConditions<dim>::prescribe_acceleration(State<dim> &state)
    {
      // From the velocity imposed at the end of the last step to
      // v(t + dt), the time derivative for a smooth v; a jump at the start
      // (a plate set moving at once) is an impulse whose reaction and work
      // are then counted, not lost.
      const double dt = state.dt;
      for (auto &p : prescribed)
        for (unsigned int d = 0; d < dim; ++d)
          {
            p.old_value[d] = p.imposed[d];
            p.new_value[d] = p.velocity->value(Point<1>(state.time + dt), d);
            p.imposed[d]   = p.new_value[d];
          }
      for (const auto &p : prescribed_dofs)
        state.grid_acceleration[p.dof][p.component] =
          (prescribed[p.boundary].new_value[p.component] -
           prescribed[p.boundary].old_value[p.component]) /
          dt;
    }

    template <int dim>
    void
    BoundaryConditions<dim>::compute_reactions(State<dim> &state)
    {
      // R = M a - b on the constrained DoFs, from the cell arrays the
      // solve was assembled from (owned cells: the sum over ranks is the
      // boundary's total).
      const auto &a    = state.grid_acceleration;
      auto       &grid = *state.grid;
      std::fill(reactions.begin(), reactions.end(), 0.);
      std::fill(wall_normal.begin(), wall_normal.end(), 0.);
      const unsigned int n     = grid.dofs_per_cell;
      const auto        &dofs  = grid.cell_dofs();
      const auto        &cells = grid.cell_arrays();
      for (unsigned int d = 0; d < dim; ++d)
        for (const Entry &e : entries[d])
          {
            double ma = 0;
            if (lumped_acceleration)
              ma = cells.lumped[e.index] * a[dofs[e.index]][d];
            else
              {
                const unsigned int first = e.index - e.index % n;
                const double      *row   = &cells.mass[e.index * n];
                for (unsigned int m = 0; m < n; ++m)
                  ma += row[m] * a[dofs[first + m]][d];
              }
            const double r = ma - cells.rhs[e.index][d];
            reactions[e.column] += r;
            // Friction takes the lumped row's normal force: with the
            // full row of a matrix strategy the inertial coupling to the
            // DoFs above changes sign from DoF to DoF, and friction
            // (bounded only where the wall pushes) came out 40 % above
            // mu N on the sliding block of tests/mpm/wall_friction_01
            // (P1, ghost penalty, MUSL; its acceleration 2.7 % low, 0.4 %
            // with the lumped row).
            if (e.wall != invalid)
              wall_normal[e.wall] +=
                cells.lumped[e.index] * a[dofs[e.index]][d] -
                cells.rhs[e.index][d];
          }
      // A strategy's patch blocks (the ghost penalty) are part of M too.
      if (!lumped_acceleration)
        for (const auto &patch : grid.patch_blocks())
          for (unsigned int k = 0; k < patch.n; ++k)
            for (unsigned int d = 0; d < dim; ++d)
              {
                const unsigned int column = dof_column[d][patch.dofs[k]];
                if (column == invalid)
                  continue;
                double ma = 0;
                for (unsigned int m = 0; m < patch.n; ++m)
                  ma += patch.values[k * patch.n + m] * a[patch.dofs[m]][d];
                reactions[column] += patch.weight * ma;
              }
    }

    template <int dim>
    void
    BoundaryConditions<dim>::sum_wall_normals(const State<dim> &state)
    {
      // A wall DoF's normal force is summed over the cells of every rank
      // that holds some of them, so that every rank that sees the DoF
      // applies the same friction to it.
      const auto &exchange = state.grid->ghost_exchange();
      for (unsigned int w = 0; w < walls.size(); ++w)
        relevant_buffer[walls[w].dof] = wall_normal[w];
      exchange.sum_to_owned(relevant_buffer, owned_buffer.data());
      exchange.owned_to_relevant(owned_buffer.data(), relevant_buffer);
      for (unsigned int w = 0; w < walls.size(); ++w)
        wall_normal[w] = relevant_buffer[walls[w].dof];
    }

    template <int dim>
    void
    BoundaryConditions<dim>::apply_friction(State<dim> &state)
    {
      // Coulomb friction on the DoFs in contact (the wall pushes into the
      // body: R_n against the outward normal).
      auto        &a          = state.grid_acceleration;
      const double dt         = state.dt;
      const auto  &mass       = state.grid->lumped_mass();
      const bool   have_speed = state.grid_velocity.size() == a.size();
      double       work       = 0;
      for (unsigned int w = 0; w < walls.size(); ++w)
        {
          const WallDof &wall = walls[w];
          const double   rn   = wall_normal[w];
          const double   m    = mass[wall.dof];
          hold_capacity[w]    = 0;
          if (!(rn * wall.outward < 0) || !(m > 0))
            continue;
          const double v =
            have_speed ? state.grid_velocity[wall.dof][wall.tangential] : 0.;
          double      &at    = a[wall.dof][wall.tangential];
          const double trial = v + dt * at;
          const double bound = wall.mu * std::abs(rn) * dt / m;
          const double next =
            trial - std::copysign(std::min(std::abs(trial), bound), trial);
          hold_capacity[w]     = bound - std::abs(next - trial);
          const double changed = (next - v) / dt;
          const double force   = m * (changed - at);
          at                   = changed;
          if (!wall_owned[w])
            continue;
          reactions[wall.column] += force;
          work += force * 0.5 * (v + next) * dt;
        }
      if (sum_over_ranks)
        work = Utilities::MPI::sum(work, state.grid->get_communicator());
      accumulated_friction_work += work;
    }

    template <int dim>
    void
    BoundaryConditions<dim>::add_prescribed_work(const double dt)
    {
      // The reaction at the middle of the step times the step's mean
      // velocity. The reaction of the step is that of the stress at its
      // start; a plate loading a body at constant speed raises it
      // linearly, and R_n v dt alone would lag the strain energy by 1/n
      // after n steps (the energy monitor then saw growth without work in
      // the first steps). Extrapolated to the middle, R_n + (R_n -
      // R_{n-1}) / 2, the sum is exact for that ramp.
      if (previous_reactions.size() != reactions.size())
        previous_reactions = reactions;
      for (unsigned int c = 0; c < columns.size(); ++c)
        if (column_prescribed[c])
          for (const auto &p : prescribed)
            if (p.name == columns[c].name)
              accumulated_prescribed_work +=
                (1.5 * reactions[c] - 0.5 * previous_reactions[c]) * 0.5 *
                (p.old_value[columns[c].component] +
                 p.new_value[columns[c].component]) *
                dt;
      previous_reactions = reactions;
    }

    template <int dim>
    void
    BoundaryConditions<dim>::impose_velocity(State<dim> &state)
    {
      for (const auto &p : prescribed_dofs)
        state.grid_velocity[p.dof][p.component] =
          prescribed[p.boundary].new_value[p.component];
      // The same Coulomb bound on the velocity particles move with: a
      // projection after the friction (MUSL's, APIC's second) gives a DoF
      // that sticks a tangential velocity again, from its neighbours'
      // accelerations. A wall that sticks holds it with what is left of
      // mu |R_n| dt, and the particles receive the same change (as FLIP
      // receives the grid's), so that their velocities and motion stay
      // one field. (Left sliding, the next step's friction pulled the DoF
      // back and fed energy into a slope at rest on a frictional floor;
      // held without the particles' change, the particles kept a velocity
      // that they did not move with, and column collapses went unstable.)
      if (state.grid_velocity.size() != wall_of.size())
        return;
      bool held = false;
      for (unsigned int w = 0; w < walls.size(); ++w)
        {
          const WallDof &wall = walls[w];
          double        &vt   = state.grid_velocity[wall.dof][wall.tangential];
          double         change = 0;
          if (hold_capacity[w] > 0 && vt != 0)
            {
              change =
                -std::copysign(std::min(std::abs(vt), hold_capacity[w]), vt);
              vt += change;
              held = true;
            }
          hold_change[w] = change;
        }
      // The work is the particles' kinetic energy change, which the
      // grid's m_i dv (v + dv / 2) misses where the particles' velocities
      // differ within a DoF's support.
      double work = held ? hold_particles(state) : 0.;
      if (sum_over_ranks)
        work = Utilities::MPI::sum(work, state.grid->get_communicator());
      accumulated_friction_work += work;
    }

    template <int dim>
    double
    BoundaryConditions<dim>::hold_particles(State<dim> &state) const
    {
      auto              &particles = state.particles;
      const auto        &grid      = *state.grid;
      const unsigned int n         = grid.dofs_per_cell;
      const auto        &dofs      = grid.cell_dofs();
      double             work      = 0;
      for (std::size_t p = 0; p < particles.size(); ++p)
        {
          const unsigned int base = particles.cell[p] * n;
          const double      *phi  = &state.shape_values[p * n];
          Tensor<1, dim>     change;
          bool               changed = false;
          for (unsigned int k = 0; k < n; ++k)
            {
              const unsigned int w = wall_of[dofs[base + k]];
              if (w != invalid && hold_change[w] != 0)
                {
                  change[walls[w].tangential] += phi[k] * hold_change[w];
                  changed = true;
                }
            }
          if (!changed)
            continue;
          work += particles.mass[p] *
                  (particles.velocity[p] * change + 0.5 * change * change);
          particles.velocity[p] += change;
        }
      return work;
    }

    template <int dim>
    void
    BoundaryConditions<dim>::check_transfer(const std::string &scheme) const
    {
      AssertThrow(!stop_at_walls || scheme == "musl",
                  ExcMessage("Boundary conditions/Stop particles at walls = "
                             "true: needs Transfer/Scheme = musl (the "
                             "change is taken from MUSL's second "
                             "projection); this run has " +
                             scheme + "."));
    }

    template <int dim>
    bool
    BoundaryConditions<dim>::stop_change(const State<dim> &state)
    {
      // The velocity each constrained DoF had before its constraint: the
      // projected momentum of its cells over their lumped mass (owned
      // cells, summed over the ranks that hold the DoF). stop_momentum
      // becomes the constraint's change dv_i = v_i - p_i / m_i.
      const auto &grid     = *state.grid;
      const auto &dofs     = grid.cell_dofs();
      const auto &cells    = grid.cell_arrays();
      const auto &exchange = grid.ghost_exchange();
      bool        any      = false;
      for (unsigned int d = 0; d < dim; ++d)
        {
          auto &dv   = stop_momentum[d];
          auto &mass = stop_mass[d];
          std::fill(dv.begin(), dv.end(), 0.);
          std::fill(mass.begin(), mass.end(), 0.);
          for (const Entry &e : entries[d])
            {
              dv[dofs[e.index]] += cells.rhs[e.index][d];
              mass[dofs[e.index]] += cells.lumped[e.index];
            }
          if (sum_over_ranks)
            for (auto *sums : {&dv, &mass})
              {
                exchange.sum_to_owned(*sums, owned_buffer.data());
                exchange.owned_to_relevant(owned_buffer.data(), *sums);
              }
          for (unsigned int l = 0; l < dv.size(); ++l)
            {
              dv[l] =
                mass[l] > 0 ? state.grid_velocity[l][d] - dv[l] / mass[l] : 0.;
              any = any || dv[l] != 0;
            }
        }
      return Utilities::MPI::logical_or(any, grid.get_communicator());
    }

    template <int dim>
    void
    BoundaryConditions<dim>::stop_particles(State<dim> &state)
    {
      if (!stop_at_walls || !stop_change(state))
        return;
      // The particles' kinetic energy change is the work.
      const auto        &grid      = *state.grid;
      auto              &particles = state.particles;
      const unsigned int n         = grid.dofs_per_cell;
      const auto        &dofs      = grid.cell_dofs();
      double             work      = 0;
      for (std::size_t p = 0; p < particles.size(); ++p)
        {
          if (!stop_cell[particles.cell[p]])
            continue;
          const unsigned int base = particles.cell[p] * n;
          const double      *phi  = &state.shape_values[p * n];
          Tensor<1, dim>     change;
          for (unsigned int k = 0; k < n; ++k)
            for (unsigned int d = 0; d < dim; ++d)
              change[d] += phi[k] * stop_momentum[d][dofs[base + k]];
          work += particles.mass[p] *
                  (particles.velocity[p] * change + 0.5 * change * change);
          particles.velocity[p] += change;
        }
      accumulated_stop_work +=
        Utilities::MPI::sum(work, grid.get_communicator());
    }

    template <int dim>
    std::vector<std::string>
    BoundaryConditions<dim>::column_names() const
    {
      std::vector<std::string> names;
      for (const auto &c : columns)
        names.push_back("reaction_" + c.name + "_" +
                        component_names[c.component]);
      return names;
    }

    template <int dim>
    std::vector<std::string>
    BoundaryConditions<dim>::statistics_columns() const
    {
      auto names = column_names();
      if (!friction.empty())
        names.emplace_back("friction_work");
      if (!prescribed.empty())
        names.emplace_back("prescribed_work");
      if (local_damping > 0)
        names.emplace_back("damping_work");
      if (stop_at_walls)
        names.emplace_back("wall_stop_work");
      return names;
    }

    template <int dim>
    void
    BoundaryConditions<dim>::add_columns(
      Postprocess::StatisticsTable &table) const
    {
      const auto names = column_names();
      for (unsigned int c = 0; c < columns.size(); ++c)
        table.add_value(names[c], reactions[c]);
      if (!friction.empty())
        table.add_value("friction_work", accumulated_friction_work);
      if (!prescribed.empty())
        table.add_value("prescribed_work", accumulated_prescribed_work);
      if (local_damping > 0)
        table.add_value("damping_work", accumulated_damping_work);
      if (stop_at_walls)
        table.add_value("wall_stop_work", accumulated_stop_work);
    }

    template <int dim>
    double
    BoundaryConditions<dim>::monitored_energy(const double       total,
                                              const unsigned int step)
    {
      const double balance = total - accumulated_friction_work -
                             accumulated_prescribed_work -
                             accumulated_damping_work - accumulated_stop_work;
      if (step == 0)
        initial_balance = balance;
      else if (step == 1 && !prescribed.empty())
        first_step_offset = balance - initial_balance;
      return balance - first_step_offset;
    }

    template <int dim>
    void
    BoundaryConditions<dim>::save(Archive &archive) const
    {
      archive.put("boundary_conditions/initial_balance", initial_balance);
      archive.put("boundary_conditions/first_step_offset", first_step_offset);
      archive.put("boundary_conditions/friction_work",
                  accumulated_friction_work);
      archive.put("boundary_conditions/prescribed_work",
                  accumulated_prescribed_work);
      archive.put("boundary_conditions/damping_work", accumulated_damping_work);
      if (stop_at_walls)
        archive.put("boundary_conditions/wall_stop_work",
                    accumulated_stop_work);
      if (!previous_reactions.empty())
        archive.put("boundary_conditions/previous_reactions",
                    previous_reactions);
      std::vector<double> imposed;
      for (const auto &p : prescribed)
        imposed.insert(imposed.end(), p.imposed.begin(), p.imposed.end());
      if (!imposed.empty())
        archive.put("boundary_conditions/imposed_velocity", imposed);
    }

    template <int dim>
    void
    BoundaryConditions<dim>::load(const Archive &archive)
    {
      accumulated_friction_work =
        archive.get_number("boundary_conditions/friction_work");
      accumulated_prescribed_work =
        archive.get_number("boundary_conditions/prescribed_work");
      accumulated_damping_work =
        archive.get_number("boundary_conditions/damping_work");
      accumulated_stop_work =
        stop_at_walls ?
          archive.get_number("boundary_conditions/wall_stop_work") :
          0.;
      initial_balance =
        archive.get_number("boundary_conditions/initial_balance");
      first_step_offset =
        archive.get_number("boundary_conditions/first_step_offset");
      previous_reactions.clear();
      if (archive.has("boundary_conditions/previous_reactions"))
        previous_reactions =
          archive.get("boundary_conditions/previous_reactions");
      if (!prescribed.empty())
        {
          const auto imposed =
            archive.get("boundary_conditions/imposed_velocity",
                        prescribed.size() * dim);
          for (unsigned int b = 0; b < prescribed.size(); ++b)
            for (unsigned int d = 0; d < dim; ++d)
              prescribed[b].imposed[d] = imposed[b * dim + d];
        }
    }

    template class BoundaryConditions<1>;
    template class BoundaryConditions<2>;
  } // namespace Simulator
} // namespace psmpm
