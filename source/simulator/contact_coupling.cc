// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include <psmpm/simulator/contact_coupling.h>
#include <psmpm/simulator/dof_body_masks.h>


namespace psmpm
{
  namespace Simulator
  {
    namespace
    {
      /// Values per (DoF, body) of the first per-body pass: mass, volume,
      /// momentum, force, mass gradient and first moment of the mass
      /// (sum m_p N_i x_p, the distance criterion's mass centre).
      template <int dim>
      constexpr unsigned int width = 2 + 4 * dim;

      /// The integral of each of the cell's functions over cell @p c with
      /// the vertices @p v: the centroids of a uniform subdivision into
      /// 64 triangles (8 intervals in 1D), a few per mille for the
      /// piecewise quadratic Powell-Sabin functions, which is what the
      /// volume fraction criterion needs.
      template <int dim>
      void
      cell_integrals(const Basis::Space<dim>       &space,
                     const unsigned int             c,
                     const std::vector<Point<dim>> &v,
                     const double                   measure,
                     std::vector<double>           &values,
                     std::vector<double>           &integrals)
      {
        constexpr unsigned int k = 8;
        std::fill(integrals.begin(), integrals.end(), 0.);
        const auto add = [&](const double l1, const double l2) {
          Point<dim> x = v[0];
          x += l1 * (v[1] - v[0]);
          if constexpr (dim == 2)
            x += l2 * (v[2] - v[0]);
          space.evaluate(c, x, values.data(), nullptr);
          const double w = measure / (dim == 2 ? k * k : k);
          for (unsigned int l = 0; l < values.size(); ++l)
            integrals[l] += w * values[l];
        };
        if constexpr (dim == 1)
          for (unsigned int i = 0; i < k; ++i)
            add((i + 0.5) / k, 0);
        else
          for (unsigned int i = 0; i < k; ++i)
            for (unsigned int j = 0; i + j < k; ++j)
              {
                add((i + 1. / 3) / k, (j + 1. / 3) / k);
                if (i + j + 1 < k)
                  add((i + 2. / 3) / k, (j + 2. / 3) / k);
              }
      }
    } // namespace

    template <int dim>
    void
    ContactCoupling<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Contact");
      Contact<dim>::declare_parameters(prm);
      prm.leave_subsection();
    }

    template <int dim>
    void
    ContactCoupling<dim>::parse_parameters(ParameterHandler  &prm,
                                           const unsigned int bodies)
    {
      prm.enter_subsection("Contact");
      contact.parse_parameters(prm);
      prm.leave_subsection();
      n_bodies = bodies;
      if (!contact.enabled())
        return;
      contact.check_bodies(n_bodies);
      const unsigned int n_pairs = n_bodies * (n_bodies - 1) / 2;
      pair_force.assign(n_pairs, Tensor<1, dim>());
      normal_force.assign(n_pairs, 0.);
      friction_force.assign(n_pairs, 0.);
      friction_work.assign(n_pairs, 0.);
      normal_work.assign(n_pairs, 0.);
      slip_work.assign(n_pairs, 0.);
    }

    template <int dim>
    void
    ContactCoupling<dim>::parse_driven(
      const std::vector<Particles::Body> &bodies)
    {
      driven_bodies.parse(bodies, contact.enabled());
      contact.driven.clear();
      if (driven_bodies.any())
        contact.driven = driven_bodies.flags();
      AssertThrow(dim == 2 || !contact.driven_nodes_from_geometry ||
                    !driven_bodies.any(),
                  ExcMessage("Contact/Driven body nodes = geometry: needs a "
                             "2D run (the bodies' shapes are 2D)."));
    }

    template <int dim>
    void
    ContactCoupling<dim>::mark_normal_only()
    {
      if (!contact.driven_nodes_from_geometry || !driven_bodies.any())
        return;
      fields.normal_only.assign(fields.mass.size(), 0);
      for (unsigned int i = 0; i < contact_dofs.size(); ++i)
        for (unsigned int b = 0; b < n_bodies; ++b)
          if (contact.driven[b] && fields.mass[i * n_bodies + b] > 0 &&
              !driven_bodies.inside(b, vertex_point[contact_dofs[i]]))
            fields.normal_only[i * n_bodies + b] = 1;
    }

    template <int dim>
    void
    ContactCoupling<dim>::set_driven_fields()
    {
      if (!driven_bodies.any())
        return;
      for (unsigned int i = 0; i < contact_dofs.size(); ++i)
        for (unsigned int b = 0; b < n_bodies; ++b)
          if (contact.driven[b] && fields.mass[i * n_bodies + b] > 0)
            fields.velocity[i * n_bodies + b] = driven_bodies.new_velocity(b);
    }

    template <int dim>
    void
    ContactCoupling<dim>::add_driven_work()
    {
      double work = driven_bodies.kinetic_energy_change();
      if (n_ranks > 1)
        work = Utilities::MPI::sum(work, comm);
      if (any_contact)
        for (unsigned int a = 0; a < n_bodies; ++a)
          for (unsigned int b = a + 1; b < n_bodies; ++b)
            {
              // The impulse on a is J, on b -J (pair statistics).
              const Tensor<1, dim> &J =
                step_statistics[Contact<dim>::pair_index(a, b, n_bodies)]
                  .impulse;
              if (contact.driven[b])
                work += J * driven_bodies.new_velocity(b);
              else if (contact.driven[a])
                work -= J * driven_bodies.new_velocity(a);
            }
      accumulated_driven_work += work;
    }

    template <int dim>
    void
    ContactCoupling<dim>::choose_automatic(ParameterHandler &prm,
                                           std::string      &mass_type)
    {
      (void)prm;
      automatic_note.clear();
      if (!contact.enabled() || mass_type != "automatic")
        return;
      mass_type      = "lumped";
      automatic_note = "Mass matrix/Type = automatic is lumped with "
                       "Contact/Type = multi-velocity (a mass matrix with "
                       "couplings mixes the bodies next to the contact DoFs)";
    }

    template <int dim>
    void
    ContactCoupling<dim>::check_transfer(const std::string &scheme,
                                         const std::string &reconstruction,
                                         const std::string &mass_type) const
    {
      if (!contact.enabled())
        return;
      // A mass matrix with couplings projects the bodies' velocities
      // together at the DoFs next to the contact DoFs, which the
      // increments do not reach (doc/contact.md).
      AssertThrow(mass_type == "lumped",
                  ExcMessage("Contact/Type = multi-velocity: not available "
                             "with Mass matrix/Type = " +
                             mass_type + " (lumped is)."));
      // USL with contact lost the sliding block (energy growth) and the
      // disks (a non-positive volume; without contact too): not offered.
      AssertThrow(scheme == "musl" || scheme == "apic",
                  ExcMessage("Contact/Type = multi-velocity: not available "
                             "with Transfer/Scheme = " +
                             scheme + " (musl and apic are)."));
      AssertThrow(reconstruction == "particles",
                  ExcMessage("Contact/Type = multi-velocity: not available "
                             "with Transfer/Reconstruction = " +
                             reconstruction + " (particles is)."));
    }

    template <int dim>
    void
    ContactCoupling<dim>::initialize(const State<dim> &state)
    {
      const auto        &grid       = *state.grid;
      const unsigned int n          = grid.dofs_per_cell;
      const unsigned int n_relevant = grid.relevant_dofs().n_elements();
      comm                          = state.comm;
      n_ranks                       = Utilities::MPI::n_mpi_processes(comm);
      dof_index.assign(n_relevant, numbers::invalid_unsigned_int);
      owned.assign(n_relevant, 0);
      for (unsigned int l = 0; l < n_relevant; ++l)
        owned[l] = grid.locally_owned_dofs().is_element(
          grid.relevant_global_indices()[l]);
      dof_volume.assign(n_relevant, 0.);
      const unsigned int *dofs = grid.cell_dofs().data();
      std::vector<double> values(n), integrals(n);
      for (const auto &cell : state.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const unsigned int      c = cell->active_cell_index();
            std::vector<Point<dim>> v;
            for (const unsigned int k : cell->vertex_indices())
              v.push_back(cell->vertex(k));
            cell_integrals(*state.space,
                           c,
                           v,
                           cell->measure(),
                           values,
                           integrals);
            for (unsigned int k = 0; k < n; ++k)
              dof_volume[dofs[c * n + k]] += integrals[k];
          }
      if (n_ranks > 1)
        {
          std::vector<double> sum(grid.locally_owned_dofs().n_elements());
          grid.ghost_exchange().sum_to_owned(dof_volume, sum.data());
          grid.ghost_exchange().owned_to_relevant(sum.data(), dof_volume);
        }
      contact_cell.assign(grid.cell_dofs().size() / n, 0);
      // The DoFs of one vertex (Powell-Sabin: three) share one normal:
      // their functions' own gradients lean towards their corners of the
      // macro triangles; the sum is the vertex's.
      vertex_dof.resize(n_relevant);
      for (unsigned int l = 0; l < n_relevant; ++l)
        vertex_dof[l] = l;
      const unsigned int per_vertex =
        state.space->dof_layout().n_dofs_per_vertex();
      if (per_vertex > 1 &&
          per_vertex *
              state.space->dof_layout().reference_cell().n_vertices() ==
            n)
        for (unsigned int c = 0; c < contact_cell.size(); ++c)
          for (unsigned int k = 0; k < n; ++k)
            vertex_dof[dofs[c * n + k]] = dofs[c * n + k - k % per_vertex];
      // Where a DoF is for a driven body's shape: at its vertex, whose
      // DoFs (Powell-Sabin: three) give the field's value and gradient
      // there (their control points lie around it, inside and outside an
      // outline through the vertex).
      vertex_point.clear();
      if (contact.driven_nodes_from_geometry && driven_bodies.any())
        {
          AssertThrow(
            per_vertex *
                state.space->dof_layout().reference_cell().n_vertices() ==
              n,
            ExcMessage("Contact/Driven body nodes = geometry: "
                       "needs a basis with DoFs at the vertices "
                       "alone (linear, powell-sabin)."));
          vertex_point.resize(n_relevant);
          for (const auto &cell : state.dof_handler.active_cell_iterators())
            if (cell->is_locally_owned())
              for (unsigned int k = 0; k < n; ++k)
                vertex_point[dofs[cell->active_cell_index() * n + k]] =
                  cell->vertex(k / per_vertex);
        }
    }

    template <int dim>
    unsigned int
    ContactCoupling<dim>::find_contact_dofs(const State<dim> &state)
    {
      const auto         &grid      = *state.grid;
      const auto         &particles = state.particles;
      const unsigned int  n         = grid.dofs_per_cell;
      const unsigned int *dofs      = grid.cell_dofs().data();
      const unsigned int  n_cells   = contact_cell.size();
      dof_body_masks(state, cell_mask, dof_mask);
      for (const unsigned int l : contact_dofs)
        dof_index[l] = numbers::invalid_unsigned_int;
      contact_dofs.clear();
      node_owned.clear();
      for (unsigned int l = 0; l < dof_mask.size(); ++l)
        if ((dof_mask[l] & (dof_mask[l] - 1)) != 0)
          {
            dof_index[l] = contact_dofs.size();
            contact_dofs.push_back(l);
            node_owned.push_back(owned[l]);
          }
      near_particles.clear();
      for (unsigned int c = 0; c < n_cells; ++c)
        {
          contact_cell[c] = 0;
          for (unsigned int k = 0; k < n && cell_mask[c] != 0; ++k)
            if (dof_index[dofs[c * n + k]] != numbers::invalid_unsigned_int)
              contact_cell[c] = 1;
        }
      for (std::size_t p = 0; p < particles.size(); ++p)
        if (contact_cell[particles.cell[p]])
          near_particles.push_back(p);
      const unsigned int n_here = contact_dofs.size();
      return n_ranks > 1 ? Utilities::MPI::sum(n_here, comm) : n_here;
    }

    template <int dim>
    void
    ContactCoupling<dim>::sum_over_ranks(const State<dim>    &state,
                                         std::vector<double> &values,
                                         const unsigned int   w) const
    {
      if (n_ranks == 1)
        return;
      const auto         &grid   = *state.grid;
      const unsigned int  stride = n_bodies * w;
      std::vector<double> full(dof_index.size(), 0.),
        sum(grid.locally_owned_dofs().n_elements());
      for (unsigned int j = 0; j < stride; ++j)
        {
          for (unsigned int i = 0; i < contact_dofs.size(); ++i)
            full[contact_dofs[i]] = values[i * stride + j];
          grid.ghost_exchange().sum_to_owned(full, sum.data());
          grid.ghost_exchange().owned_to_relevant(sum.data(), full);
          for (unsigned int i = 0; i < contact_dofs.size(); ++i)
            values[i * stride + j] = full[contact_dofs[i]];
        }
    }

    template <int dim>
    void
    ContactCoupling<dim>::particles_to_contact_dofs(const State<dim> &state)
    {
      constexpr unsigned int w         = width<dim>;
      const auto            &particles = state.particles;
      const unsigned int     n         = state.grid->dofs_per_cell;
      const unsigned int    *dofs      = state.grid->cell_dofs().data();
      sums.assign(contact_dofs.size() * n_bodies * w, 0.);
      for (const std::size_t p : near_particles)
        {
          const unsigned int    cell = particles.cell[p];
          const unsigned int    b    = particles.body_id[p] - 1;
          const double          m    = particles.mass[p];
          const double          V    = particles.volume[p];
          const Tensor<1, dim>  mv   = m * particles.velocity[p];
          const Tensor<1, dim>  mg   = m * state.gravity;
          const auto           &s    = state.stress_for_forces()[p];
          const double         *phi  = &state.shape_values[p * n];
          const Tensor<1, dim> *grad = state.gradients(p, cell);
          for (unsigned int k = 0; k < n; ++k)
            {
              const unsigned int l = dofs[cell * n + k];
              const unsigned int i = dof_index[l];
              if (i == numbers::invalid_unsigned_int)
                continue;
              double              *d = &sums[(i * n_bodies + b) * w];
              const Tensor<1, dim> f = phi[k] * mg - V * (s * grad[k]);
              // apic: the momentum of the particle's affine field.
              const Tensor<1, dim> q =
                affine_points == nullptr ?
                  mv :
                  mv + m * (particles.affine[p] *
                            (affine_points[l] - particles.position[p]));
              d[0] += m * phi[k];
              d[1] += V * phi[k];
              for (unsigned int e = 0; e < dim; ++e)
                {
                  d[2 + e] += phi[k] * q[e];
                  d[2 + dim + e] += f[e];
                  d[2 + 2 * dim + e] += m * grad[k][e];
                  d[2 + 3 * dim + e] += m * phi[k] * particles.position[p][e];
                }
            }
        }
      sum_over_ranks(state, sums, w);
    }

    template <int dim>
    void
    ContactCoupling<dim>::apply_correction()
    {
      contact.apply(fields, step_statistics, &node_owned);
      if (n_ranks == 1)
        return;
      // Every rank keeps the totals (statistics, checkpoints).
      constexpr unsigned int w = dim + 5;
      std::vector<double>    values(step_statistics.size() * w);
      for (unsigned int q = 0; q < step_statistics.size(); ++q)
        {
          for (unsigned int d = 0; d < dim; ++d)
            values[q * w + d] = step_statistics[q].impulse[d];
          values[q * w + dim]     = step_statistics[q].friction_work;
          values[q * w + dim + 1] = step_statistics[q].normal_work;
          values[q * w + dim + 2] = step_statistics[q].normal_impulse;
          values[q * w + dim + 3] = step_statistics[q].tangential_impulse;
          values[q * w + dim + 4] = step_statistics[q].slip_work;
        }
      Utilities::MPI::sum(values, comm, values);
      for (unsigned int q = 0; q < step_statistics.size(); ++q)
        {
          for (unsigned int d = 0; d < dim; ++d)
            step_statistics[q].impulse[d] = values[q * w + d];
          step_statistics[q].friction_work      = values[q * w + dim];
          step_statistics[q].normal_work        = values[q * w + dim + 1];
          step_statistics[q].normal_impulse     = values[q * w + dim + 2];
          step_statistics[q].tangential_impulse = values[q * w + dim + 3];
          step_statistics[q].slip_work          = values[q * w + dim + 4];
        }
    }

    template <int dim>
    void
    ContactCoupling<dim>::vertex_gradients()
    {
      const unsigned int n_contact = contact_dofs.size();
      vertex_slot.resize(n_contact);
      grouped.assign(n_contact * n_bodies, Tensor<1, dim>());
      for (unsigned int i = 0; i < n_contact; ++i)
        {
          unsigned int r = dof_index[vertex_dof[contact_dofs[i]]];
          if (r == numbers::invalid_unsigned_int)
            r = i;
          vertex_slot[i] = r;
          for (unsigned int b = 0; b < n_bodies; ++b)
            grouped[r * n_bodies + b] += fields.mass_gradient[i * n_bodies + b];
        }
      for (unsigned int i = 0; i < n_contact; ++i)
        for (unsigned int b = 0; b < n_bodies; ++b)
          fields.mass_gradient[i * n_bodies + b] =
            grouped[vertex_slot[i] * n_bodies + b];
    }

    template <int dim>
    void
    ContactCoupling<dim>::clear_fixed(const State<dim>            &state,
                                      std::vector<Tensor<1, dim>> &dv) const
    {
      for (unsigned int d = 0; d < dim; ++d)
        {
          const auto &fixed = state.grid->constrained_dofs(d);
          for (unsigned int i = 0; i < contact_dofs.size(); ++i)
            if (fixed[contact_dofs[i]])
              for (unsigned int b = 0; b < n_bodies; ++b)
                dv[i * n_bodies + b][d] = 0;
        }
    }

    template <int dim>
    void
    ContactCoupling<dim>::correct_momentum(State<dim> &state)
    {
      affine_points = nullptr;
      correct(state);
    }

    template <int dim>
    void
    ContactCoupling<dim>::correct(State<dim> &state)
    {
      constexpr unsigned int w = width<dim>;
      for (auto &f : pair_force)
        f = Tensor<1, dim>();
      std::fill(normal_force.begin(), normal_force.end(), 0.);
      std::fill(friction_force.begin(), friction_force.end(), 0.);
      moving_increment.clear();
      driven_bodies.start_step(state);
      any_contact = find_contact_dofs(state) > 0;
      if (!any_contact)
        {
          if (driven_bodies.any())
            add_driven_work();
          return;
        }
      particles_to_contact_dofs(state);
      const unsigned int n_contact = contact_dofs.size();
      const bool         volumes =
        contact.criterion == Contact<dim>::SeparationCriterion::volume_fraction;
      const bool centroids =
        contact.criterion == Contact<dim>::SeparationCriterion::distance;
      fields.reinit(n_contact, n_bodies, volumes, centroids);
      velocity_increment.assign(n_contact * n_bodies, Tensor<1, dim>());
      projected_velocity.assign(n_contact * n_bodies, Tensor<1, dim>());
      old_velocity.resize(near_particles.size());
      for (std::size_t j = 0; j < near_particles.size(); ++j)
        old_velocity[j] = state.particles.velocity[near_particles[j]];
      const double dt = state.dt;
      for (unsigned int i = 0; i < n_contact; ++i)
        {
          // The lumped mass average of the bodies' forces per unit mass.
          double         M = 0;
          Tensor<1, dim> F;
          for (unsigned int b = 0; b < n_bodies; ++b)
            {
              const double *d = &sums[(i * n_bodies + b) * w];
              M += d[0];
              for (unsigned int e = 0; e < dim; ++e)
                F[e] += d[2 + dim + e];
            }
          const Tensor<1, dim> &a = state.grid_acceleration[contact_dofs[i]];
          if (volumes)
            fields.node_volume[i] = dof_volume[contact_dofs[i]];
          for (unsigned int b = 0; b < n_bodies; ++b)
            {
              const unsigned int ib = i * n_bodies + b;
              const double      *d  = &sums[ib * w];
              fields.mass[ib]       = d[0];
              if (volumes)
                fields.volume[ib] = d[1];
              if (!(d[0] > 0))
                continue;
              Tensor<1, dim> v, f;
              for (unsigned int e = 0; e < dim; ++e)
                {
                  v[e]                        = d[2 + e] / d[0];
                  f[e]                        = d[2 + dim + e];
                  fields.mass_gradient[ib][e] = d[2 + 2 * dim + e];
                  if (centroids)
                    fields.centroid[ib][e] = d[2 + 3 * dim + e] / d[0];
                }
              // v_bi - v_bi* + dt a_i now, v_bi' - v_bi - dt a_i once the
              // corrected velocity is added below.
              fields.velocity[ib]    = v + dt * (a + f / d[0] - F / M);
              velocity_increment[ib] = -v - dt * a;
              projected_velocity[ib] = v;
            }
        }
      vertex_gradients();
      set_driven_fields();
      mark_normal_only();
      correction_direction = fields.velocity;
      fields.stuck.assign(n_contact * n_bodies, 0);
      apply_correction();
      for (unsigned int ib = 0; ib < n_contact * n_bodies; ++ib)
        {
          Tensor<1, dim> &d = correction_direction[ib];
          d                 = fields.velocity[ib] - d;
          const double norm = d.norm();
          d = norm > 0 && fields.stuck[ib] ? d / norm : Tensor<1, dim>();
          if (fields.mass[ib] > 0)
            velocity_increment[ib] += fields.velocity[ib];
        }
      clear_fixed(state, velocity_increment);
      const unsigned int n_pairs = pair_force.size();
      for (unsigned int q = 0; q < n_pairs; ++q)
        {
          pair_force[q]     = step_statistics[q].impulse / dt;
          normal_force[q]   = step_statistics[q].normal_impulse / dt;
          friction_force[q] = step_statistics[q].tangential_impulse / dt;
          friction_work[q] += step_statistics[q].friction_work;
          normal_work[q] += step_statistics[q].normal_work;
          slip_work[q] += step_statistics[q].slip_work;
        }
      if (driven_bodies.any())
        add_driven_work();
    }

    template <int dim>
    void
    ContactCoupling<dim>::add_velocity_increments(State<dim> &state,
                                                  const bool  momentum_to_grid)
    {
      if (!any_contact)
        {
          driven_bodies.set_velocities(state, false, nullptr, momentum_to_grid);
          return;
        }
      auto               &particles = state.particles;
      const unsigned int  n         = state.grid->dofs_per_cell;
      const unsigned int *dofs      = state.grid->cell_dofs().data();
      Tensor<1, dim>     *rhs       = state.grid->cell_arrays().rhs.data();
      for (std::size_t j = 0; j < near_particles.size(); ++j)
        {
          const std::size_t  p    = near_particles[j];
          const unsigned int cell = particles.cell[p];
          const unsigned int b    = particles.body_id[p] - 1;
          const double      *phi  = &state.shape_values[p * n];
          Tensor<1, dim>     dv;
          for (unsigned int k = 0; k < n; ++k)
            {
              const unsigned int i = dof_index[dofs[cell * n + k]];
              if (i == numbers::invalid_unsigned_int)
                continue;
              const unsigned int ib = i * n_bodies + b;
              // FLIP, and where the body sticks to another, PIC along
              // the correction's direction: the particle's deviation from
              // its body's nodal velocity in that direction is dropped (the
              // particle-grid round trip would bring it back at the next
              // projection as a relative velocity of the stuck bodies, and
              // the stuck node slip). The deviations sum to zero over the
              // node's particles, so momentum is kept.
              const Tensor<1, dim> &d = correction_direction[ib];
              dv +=
                phi[k] * (velocity_increment[ib] +
                          (d * (projected_velocity[ib] - old_velocity[j])) * d);
            }
          particles.velocity[p] += dv;
          if (momentum_to_grid)
            for (unsigned int k = 0; k < n; ++k)
              rhs[cell * n + k] += (phi[k] * particles.mass[p]) * dv;
        }
      driven_bodies.set_velocities(state, false, nullptr, momentum_to_grid);
    }

    template <int dim>
    void
    ContactCoupling<dim>::correct_moving_velocity(const State<dim> &state)
    {
      moving_increment.clear();
      if (!any_contact)
        return;
      const auto         &particles = state.particles;
      const unsigned int  n         = state.grid->dofs_per_cell;
      const unsigned int *dofs      = state.grid->cell_dofs().data();
      const unsigned int  n_contact = contact_dofs.size();
      sums.assign(n_contact * n_bodies * dim, 0.);
      for (const std::size_t p : near_particles)
        {
          const unsigned int   cell = particles.cell[p];
          const unsigned int   b    = particles.body_id[p] - 1;
          const double         m    = particles.mass[p];
          const Tensor<1, dim> mv   = m * particles.velocity[p];
          const double        *phi  = &state.shape_values[p * n];
          for (unsigned int k = 0; k < n; ++k)
            {
              const unsigned int l = dofs[cell * n + k];
              const unsigned int i = dof_index[l];
              if (i == numbers::invalid_unsigned_int)
                continue;
              const Tensor<1, dim> q =
                affine_points == nullptr ?
                  mv :
                  mv + m * (particles.affine[p] *
                            (affine_points[l] - particles.position[p]));
              for (unsigned int e = 0; e < dim; ++e)
                sums[(i * n_bodies + b) * dim + e] += phi[k] * q[e];
            }
        }
      sum_over_ranks(state, sums, dim);
      moving_increment.assign(n_contact * n_bodies, Tensor<1, dim>());
      for (unsigned int i = 0; i < n_contact; ++i)
        {
          double         M = 0;
          Tensor<1, dim> Q;
          for (unsigned int b = 0; b < n_bodies; ++b)
            {
              M += fields.mass[i * n_bodies + b];
              for (unsigned int e = 0; e < dim; ++e)
                Q[e] += sums[(i * n_bodies + b) * dim + e];
            }
          const Tensor<1, dim> &v = state.grid_velocity[contact_dofs[i]];
          for (unsigned int b = 0; b < n_bodies; ++b)
            {
              const unsigned int ib = i * n_bodies + b;
              const double       m  = fields.mass[ib];
              if (!(m > 0))
                continue;
              Tensor<1, dim> q;
              for (unsigned int e = 0; e < dim; ++e)
                q[e] = sums[ib * dim + e];
              fields.velocity[ib]  = v + (q / m - Q / M);
              moving_increment[ib] = -v;
            }
        }
      // The particles' velocities already carry the step's friction; this
      // correction only keeps the bodies from moving into each other, and
      // its impulse is no force on them (their velocities stay): normal
      // part alone, statistics dropped, so that friction does not slow a
      // sliding body's positions a second time.
      set_driven_fields();
      contact.apply(fields, scratch, nullptr, false);
      for (unsigned int ib = 0; ib < n_contact * n_bodies; ++ib)
        if (fields.mass[ib] > 0)
          moving_increment[ib] += fields.velocity[ib];
      clear_fixed(state, moving_increment);
    }

    template <int dim>
    void
    ContactCoupling<dim>::move(State<dim>       &state,
                               const std::size_t first,
                               const std::size_t last,
                               Tensor<2, dim>   *increments) const
    {
      // move_affine() (contact_apic.cc) with positions and strain
      // increments alone: the affine matrices are apic's.
      move_affine(state, first, last, increments, true, false, false);
    }

    template <int dim>
    std::vector<std::string>
    ContactCoupling<dim>::statistics_columns() const
    {
      std::vector<std::string> names;
      if (!contact.enabled())
        return names;
      const char *axis[] = {"_x", "_y"};
      for (unsigned int a = 0; a < n_bodies; ++a)
        for (unsigned int b = a + 1; b < n_bodies; ++b)
          {
            const std::string pair =
              std::to_string(a + 1) + "_" + std::to_string(b + 1);
            for (unsigned int d = 0; d < dim; ++d)
              names.push_back("contact_force_" + pair + axis[d]);
            names.push_back("normal_force_" + pair);
            names.push_back("friction_force_" + pair);
            names.push_back("friction_work_" + pair);
            names.push_back("normal_work_" + pair);
            names.push_back("slip_work_" + pair);
          }
      if (driven_bodies.any())
        names.push_back("driven_work");
      return names;
    }

    template <int dim>
    void
    ContactCoupling<dim>::add_columns(Postprocess::StatisticsTable &table) const
    {
      const auto          names = statistics_columns();
      std::vector<double> values;
      for (unsigned int q = 0; q < pair_force.size(); ++q)
        {
          for (unsigned int d = 0; d < dim; ++d)
            values.push_back(pair_force[q][d]);
          values.push_back(normal_force[q]);
          values.push_back(friction_force[q]);
          values.push_back(friction_work[q]);
          values.push_back(normal_work[q]);
          values.push_back(slip_work[q]);
        }
      if (driven_bodies.any())
        values.push_back(accumulated_driven_work);
      for (unsigned int c = 0; c < names.size(); ++c)
        table.add_value(names[c], values[c]);
    }

    template <int dim>
    double
    ContactCoupling<dim>::sliding_work() const
    {
      double sum = 0;
      for (const double w : slip_work)
        sum += w;
      return sum;
    }

    template <int dim>
    void
    ContactCoupling<dim>::save(Archive &archive) const
    {
      if (!contact.enabled())
        return;
      archive.put("contact/friction_work", friction_work);
      archive.put("contact/normal_work", normal_work);
      archive.put("contact/slip_work", slip_work);
      if (driven_bodies.any())
        archive.put("contact/driven_work",
                    std::vector<double>{accumulated_driven_work});
      if (driven_bodies.any() && contact.driven_nodes_from_geometry)
        archive.put("contact/driven_displacement",
                    driven_bodies.displacements());
    }

    template <int dim>
    void
    ContactCoupling<dim>::load(const Archive &archive)
    {
      if (!contact.enabled())
        return;
      friction_work =
        archive.get("contact/friction_work", friction_work.size());
      normal_work = archive.get("contact/normal_work", normal_work.size());
      slip_work   = archive.get("contact/slip_work", slip_work.size());
      if (driven_bodies.any())
        accumulated_driven_work = archive.get("contact/driven_work", 1)[0];
      if (driven_bodies.any() && contact.driven_nodes_from_geometry)
        driven_bodies.set_displacements(
          archive.get("contact/driven_displacement", n_bodies * dim));
    }

    template class ContactCoupling<1>;
    template class ContactCoupling<2>;
  } // namespace Simulator
} // namespace psmpm
