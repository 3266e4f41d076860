// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <deal.II/base/function_parser.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/mpi.templates.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <psmpm/base/format.h>
#include <psmpm/simulator/initial_stress.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

namespace psmpm
{
  namespace Simulator
  {
    std::map<std::string, double>
    parse_function_constants(const std::string &text)
    {
      std::map<std::string, double> constants{{"pi", numbers::PI}};
      for (const auto &c : Utilities::split_string_list(text, ','))
        {
          const auto kv = Utilities::split_string_list(c, '=');
          AssertThrow(kv.size() == 2,
                      ExcMessage("Initial conditions/Function constants: '" +
                                 c + "' is not name=value."));
          constants[kv[0]] = Utilities::string_to_double(kv[1]);
        }
      return constants;
    }



    namespace
    {

      /// Number of expressions of Stress function: sxx, syy, sxy, szz in
      /// 2D; sxx and the lateral stress in 1D.
      template <int dim>
      constexpr unsigned int n_stress_components = dim == 2 ? 4 : 2;

      /// Enter the subsections of @p path ("Materials/Material 2").
      unsigned int
      enter_path(ParameterHandler &prm, const std::string &path)
      {
        const auto parts = Utilities::split_string_list(path, '/');
        for (const auto &p : parts)
          prm.enter_subsection(p);
        return parts.size();
      }

      /// Whether the model @p name declares an entry "Friction angle"
      /// (checked on the model's own declarations: the entry exists in
      /// every material subsection once any model declares it).
      template <int dim>
      bool
      has_friction_angle(const std::string &name)
      {
        ParameterHandler probe;
        Material::MaterialRegistry<dim>::instance().declare_parameters(name,
                                                                       probe);
        // (ParameterHandler::get() of an undeclared entry throws only in
        // debug mode.)
        std::ostringstream text;
        probe.print_parameters(text, ParameterHandler::ShortPRM);
        return text.str().find("set Friction angle") != std::string::npos;
      }

      /// Refuse Stress = geostatic or function (@p entry) for a material
      /// whose particles exist (by body id; 0 alone without Bodies) and
      /// whose stress follows from the deformation.
      template <int dim>
      void
      check_accepts_initial_stress(const Material::MaterialSet<dim> &materials,
                                   const Particles::Bodies          &bodies,
                                   const std::string                &entry)
      {
        std::vector<unsigned int> ids{0};
        for (const auto &body : bodies.bodies)
          ids.push_back(body.number);
        for (const unsigned int id : ids)
          {
            if (id == 0 && !bodies.bodies.empty())
              continue;
            const auto &m = materials.of_body(id);
            AssertThrow(m.accepts_initial_stress(),
                        ExcMessage(
                          entry + ": " + m.path + "/Model = " + m.name() +
                          " cannot start from a prescribed stress (its "
                          "stress follows from the deformation gradient); "
                          "use Stress = none or a rate model such as "
                          "hypoelastic."));
          }
      }

      /// Refuse a Stress function that does not parse or evaluate.
      template <int dim>
      void
      check_stress_function(const std::string &expression,
                            const std::string &constants_text)
      {
        const auto         constants = parse_function_constants(constants_text);
        const unsigned int n         = n_stress_components<dim>;
        try
          {
            FunctionParser<dim> f(n);
            f.initialize(dim == 1 ? "x" : "x,y", expression, constants);
            // Parse errors of muParser surface at the first evaluation.
            Vector<double> values(n);
            f.vector_value(Point<dim>(), values);
          }
        catch (const std::exception &e)
          {
            AssertThrow(
              false,
              ExcMessage("Initial conditions/Stress function = '" + expression +
                         "': " + e.what() + " (expected " + std::to_string(n) +
                         " expressions separated by ';': " +
                         (dim == 2 ? "sxx; syy; sxy; szz" : "sxx; lateral") +
                         ")."));
          }
      }

      /// The number of K0 = @p text, 0 for automatic.
      double
      parse_k0(const std::string &text)
      {
        if (text == "automatic")
          return 0;
        double value  = 0;
        bool   number = true;
        try
          {
            value = Utilities::string_to_double(text);
          }
        catch (...)
          {
            number = false;
          }
        AssertThrow(number && std::isfinite(value) && value > 0,
                    ExcMessage("Initial conditions/K0 = " + text +
                               ": must be automatic or a number > 0 (the "
                               "ratio of horizontal to vertical stress)."));
        return value;
      }

      /// K0 = automatic for material @p m: 1 - sin(phi) with the Friction
      /// angle phi of its subsection of @p prm if its model has one, else
      /// the elastic nu / (1 - nu).
      template <int dim>
      double
      automatic_k0(ParameterHandler &prm, const Material::Material<dim> &m)
      {
        const double nu  = m.poisson_ratio;
        double       phi = -1;
        if (has_friction_angle<dim>(m.name()))
          {
            const unsigned int depth = enter_path(prm, m.path);
            try
              {
                phi = prm.get_double("Friction angle");
              }
            catch (...)
              {
                for (unsigned int i = 0; i < depth; ++i)
                  prm.leave_subsection();
                throw;
              }
            for (unsigned int i = 0; i < depth; ++i)
              prm.leave_subsection();
          }
        return phi >= 0 ? 1 - std::sin(phi * numbers::PI / 180) : nu / (1 - nu);
      }

      /// The columns of the geostatic stress: "up" (against gravity) and,
      /// in 2D, the direction across it; the layout's spacing along and
      /// across up (on Gmsh meshes each particle's own size,
      /// volume^(1/dim), and the largest for the bins); and bins across up
      /// a quarter of the spacing wide. A particle looks at its own bin
      /// and one on either side, that is between a quarter and half a
      /// spacing to each side: its own column of a regular layout, never
      /// the neighbouring ones.
      template <int dim>
      struct GeostaticColumns
      {
        Tensor<1, dim> up, across;
        double         along = 0, width = 0, largest = 0;
        bool           lattice = true;
        double         lo = 0, bin = 1;
        std::size_t    n_bins = 1;

        double
        size(const Particles::ParticleSet<dim> &particles,
             const std::size_t                  p) const
        {
          return std::pow(particles.volume[p], 1. / dim);
        }

        double
        half_along(const Particles::ParticleSet<dim> &particles,
                   const std::size_t                  p) const
        {
          return lattice ? 0.5 * along : 0.5 * size(particles, p);
        }

        std::size_t
        bin_of(const Particles::ParticleSet<dim> &particles,
               const std::size_t                  p) const
        {
          if (dim == 1)
            return 0;
          return std::min(n_bins - 1,
                          std::size_t((particles.position[p] * across - lo) /
                                      bin));
        }
      };

      /// The columns of @p particles under @p gravity (of norm @p g);
      /// false if there is no particle on any rank.
      template <int dim>
      bool
      make_columns(const Particles::ParticleSet<dim> &particles,
                   const Tensor<1, dim>              &gravity,
                   const double                       g,
                   const Tensor<1, dim>              &spacing,
                   MPI_Comm                           comm,
                   GeostaticColumns<dim>             &columns)
      {
        const std::size_t n = particles.size();
        columns.up          = -gravity / g;
        if constexpr (dim == 2)
          {
            columns.across[0] = columns.up[1];
            columns.across[1] = -columns.up[0];
          }
        for (unsigned int d = 0; d < dim; ++d)
          {
            columns.along += std::abs(columns.up[d]) * spacing[d];
            columns.width += std::abs(columns.across[d]) * spacing[d];
          }
        columns.lattice = columns.along > 0;
        if (!columns.lattice)
          {
            for (std::size_t p = 0; p < n; ++p)
              columns.largest =
                std::max(columns.largest, columns.size(particles, p));
            columns.largest = Utilities::MPI::max(columns.largest, comm);
            columns.along = columns.width = columns.largest;
          }
        double lo = std::numeric_limits<double>::max(), hi = -lo;
        for (std::size_t p = 0; p < n; ++p)
          {
            const double s = particles.position[p] * columns.across;
            lo             = std::min(lo, s);
            hi             = std::max(hi, s);
          }
        lo = Utilities::MPI::min(lo, comm);
        hi = Utilities::MPI::max(hi, comm);
        if (lo > hi)
          return false;
        columns.lo  = lo;
        columns.bin = dim == 1 ? 1. : 0.25 * columns.width;
        columns.n_bins =
          dim == 1 ? 1 : std::size_t((hi - lo) / columns.bin) + 1;
        return true;
      }

      /// Per body (of @p n_ids) and bin: the top (largest z + half
      /// spacing) and minus the bottom (so that one MPI max reduction
      /// finds both), over all ranks; @p none where a bin is empty.
      template <int dim>
      std::vector<double>
      column_extent(const Particles::ParticleSet<dim> &particles,
                    const GeostaticColumns<dim>       &columns,
                    const unsigned int                 n_ids,
                    const double                       none,
                    MPI_Comm                           comm)
      {
        const std::size_t   m = std::size_t(n_ids) * columns.n_bins;
        std::vector<double> extent(2 * m, none);
        for (std::size_t p = 0; p < particles.size(); ++p)
          {
            const std::size_t k = particles.body_id[p] * columns.n_bins +
                                  columns.bin_of(particles, p);
            const double z = particles.position[p] * columns.up;
            const double c = columns.half_along(particles, p);
            extent[k]      = std::max(extent[k], z + c);
            extent[m + k]  = std::max(extent[m + k], -(z - c));
          }
        Utilities::MPI::max(extent, comm, extent);
        return extent;
      }

      /// Over the window of a bin and its neighbours: the @p top and
      /// @p bottom of each body from its @p extent.
      void
      window_extent(const std::vector<double> &extent,
                    const unsigned int         n_ids,
                    const std::size_t          n_bins,
                    const double               none,
                    std::vector<double>       &top,
                    std::vector<double>       &bottom)
      {
        const std::size_t m = std::size_t(n_ids) * n_bins;
        top.assign(m, none);
        bottom.assign(m, -none);
        for (unsigned int k = 0; k < n_ids; ++k)
          for (std::size_t b = 0; b < n_bins; ++b)
            for (std::size_t w = (b > 0 ? b - 1 : 0);
                 w <= std::min(b + 1, n_bins - 1);
                 ++w)
              if (extent[k * n_bins + w] != none)
                {
                  top[k * n_bins + b] =
                    std::max(top[k * n_bins + b], extent[k * n_bins + w]);
                  bottom[k * n_bins + b] =
                    std::min(bottom[k * n_bins + b],
                             -extent[m + k * n_bins + w]);
                }
      }

      /// The weight resting on each body's top per bin: a body whose
      /// bottom lies within @p contact of the top of another in the same
      /// column rests on it with its own column weight and what rests on
      /// it in turn; bodies are taken from the highest top down so that
      /// the upper loads are known.
      std::vector<double>
      column_loads(const std::vector<double> &top,
                   const std::vector<double> &bottom,
                   const std::vector<double> &densities,
                   const double               g,
                   const double               contact,
                   const unsigned int         n_ids,
                   const std::size_t          n_bins,
                   const double               none)
      {
        std::vector<double>   load(top.size(), 0.);
        std::vector<unsigned> order(n_ids);
        for (std::size_t b = 0; b < n_bins && n_ids > 1; ++b)
          {
            const auto at = [&](const unsigned int k) {
              return k * n_bins + b;
            };
            for (unsigned int k = 0; k < n_ids; ++k)
              order[k] = k;
            std::sort(order.begin(), order.end(), [&](unsigned i, unsigned j) {
              return top[at(i)] > top[at(j)];
            });
            for (unsigned int i = 0; i < n_ids; ++i)
              {
                const unsigned int k = order[i];
                if (top[at(k)] == none)
                  break;
                for (unsigned int j = 0; j < i; ++j)
                  {
                    const unsigned int a = order[j];
                    if (top[at(a)] > top[at(k)] &&
                        std::abs(bottom[at(a)] - top[at(k)]) <= contact)
                      load[at(k)] +=
                        densities[a] * g * (top[at(a)] - bottom[at(a)]) +
                        load[at(a)];
                  }
              }
          }
        return load;
      }
    } // namespace



    template <int dim>
    void
    InitialStress<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Initial conditions");
      prm.declare_entry(
        "Stress",
        "none",
        Patterns::Selection("none|geostatic|function"),
        "Initial stress of the particles. none: zero. geostatic: each body "
        "at rest under Body force/Gravity: vertical (along -g) stress "
        "-rho |g| depth below the body's free surface above the particle "
        "(plus the weight of bodies resting on it), horizontal and "
        "out-of-plane stress K0 times that. function: Stress function.");
      prm.declare_entry(
        "K0",
        "automatic",
        Patterns::Anything(),
        "Stress = geostatic: ratio of the horizontal (and out-of-plane) to "
        "the vertical stress, a number > 0, or automatic: 1 - sin(phi) for "
        "a model with a Friction angle phi, else the elastic nu / (1 - nu).");
      prm.declare_entry(
        "Stress function",
        "0; 0; 0; 0",
        Patterns::Anything(),
        "Stress = function: the Cauchy stress [Pa] as expressions of x, y "
        "(with Function constants), tension positive: sxx; syy; sxy; szz "
        "(the out-of-plane stress of plane strain) in 2D, sxx; lateral in "
        "1D.");
      prm.leave_subsection();
    }



    template <int dim>
    void
    InitialStress<dim>::parse_parameters(
      ParameterHandler                 &prm,
      const Material::MaterialSet<dim> &materials,
      const Particles::Bodies          &bodies,
      const Tensor<1, dim>             &gravity)
    {
      prm.enter_subsection("Initial conditions");
      const std::string name    = prm.get("Stress");
      const std::string k0_text = Utilities::trim(prm.get("K0"));
      function_expression       = prm.get("Stress function");
      function_constants        = prm.get("Function constants");
      prm.leave_subsection();
      type = name == "geostatic" ? Type::geostatic :
             name == "function"  ? Type::function :
                                   Type::none;
      k0.clear();
      if (type == Type::none)
        return;
      const std::string entry = "Initial conditions/Stress = " + name;
      check_accepts_initial_stress(materials, bodies, entry);
      if (type == Type::function)
        {
          check_stress_function<dim>(function_expression, function_constants);
          return;
        }

      AssertThrow(gravity.norm() > 0,
                  ExcMessage(entry +
                             " needs a non-zero Body force/Gravity (the "
                             "stress at rest under gravity)."));
      const double k0_value = parse_k0(k0_text);
      k0.assign(bodies.bodies.size() + 1, k0_value);
      if (k0_value > 0)
        return;
      for (unsigned int id = 0; id < k0.size(); ++id)
        k0[id] = automatic_k0(prm, materials.of_body(id));
    }



    template <int dim>
    Tensor<1, dim>
    InitialStress<dim>::lattice_spacing(
      const Mesh::MeshGenerator<dim>          &mesh,
      const Particles::ParticleGenerator<dim> &generator)
    {
      Tensor<1, dim> h;
      if (dim == 2 && mesh.type == Mesh::MeshGenerator<dim>::Type::gmsh)
        return h;
      h[0] = mesh.length / mesh.blocks_x / generator.per_block_x;
      if constexpr (dim == 2)
        h[1] = mesh.height / mesh.blocks_y / generator.per_block_y;
      return h;
    }



    template <int dim>
    void
    InitialStress<dim>::apply(Particles::ParticleSet<dim>      &particles,
                              const Material::MaterialSet<dim> &materials,
                              const Tensor<1, dim>             &gravity,
                              const Tensor<1, dim>             &spacing,
                              MPI_Comm                          comm) const
    {
      if (type == Type::none)
        return;
      std::vector<double> out_of_plane(particles.size(), 0.);
      if (type == Type::geostatic)
        {
          std::vector<double> densities(k0.size());
          for (unsigned int id = 0; id < k0.size(); ++id)
            densities[id] = materials.of_body(id).density;
          apply_geostatic(particles,
                          densities,
                          gravity,
                          spacing,
                          out_of_plane,
                          comm);
        }
      else
        apply_function(particles, out_of_plane, comm);
      materials.set_initial_stress(particles, out_of_plane.data());
    }



    template <int dim>
    void
    InitialStress<dim>::apply_geostatic(Particles::ParticleSet<dim> &particles,
                                        const std::vector<double>   &densities,
                                        const Tensor<1, dim>        &gravity,
                                        const Tensor<1, dim>        &spacing,
                                        std::vector<double> &out_of_plane,
                                        MPI_Comm             comm) const
    {
      const unsigned int    n_ids = k0.size();
      const double          g     = gravity.norm();
      GeostaticColumns<dim> columns;
      if (!make_columns(particles, gravity, g, spacing, comm, columns))
        return; // no particle on any rank
      const std::size_t   n_bins = columns.n_bins;
      const double        none   = std::numeric_limits<double>::lowest();
      std::vector<double> top, bottom;
      window_extent(column_extent(particles, columns, n_ids, none, comm),
                    n_ids,
                    n_bins,
                    none,
                    top,
                    bottom);
      const double contact = columns.lattice ? columns.along : columns.largest;
      const std::vector<double> load =
        column_loads(top, bottom, densities, g, contact, n_ids, n_bins, none);

      const Tensor<1, dim> &up = columns.up, &across = columns.across;
      for (std::size_t p = 0; p < particles.size(); ++p)
        {
          const unsigned int k  = particles.body_id[p];
          const std::size_t  at = k * n_bins + columns.bin_of(particles, p);
          const double       sv =
            -(densities[k] * g * (top[at] - particles.position[p] * up) +
              load[at]);
          const double             sh = k0[k] * sv;
          SymmetricTensor<2, dim> &s  = particles.stress[p];
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = i; j < dim; ++j)
              s[i][j] = sv * up[i] * up[j] + sh * across[i] * across[j];
          out_of_plane[p] = sh;
        }
    }



    template <int dim>
    void
    InitialStress<dim>::apply_function(Particles::ParticleSet<dim> &particles,
                                       std::vector<double> &out_of_plane,
                                       MPI_Comm             comm) const
    {
      const unsigned int  nc = n_stress_components<dim>;
      FunctionParser<dim> f(nc);
      f.initialize(dim == 1 ? "x" : "x,y",
                   function_expression,
                   parse_function_constants(function_constants));
      Vector<double> v(nc);
      std::string    where;
      for (std::size_t p = 0; p < particles.size() && where.empty(); ++p)
        {
          f.vector_value(particles.position[p], v);
          SymmetricTensor<2, dim> &s = particles.stress[p];
          s[0][0]                    = v[0];
          if constexpr (dim == 2)
            {
              s[1][1] = v[1];
              s[0][1] = v[2];
            }
          out_of_plane[p] = v[nc - 1];
          bool finite     = true;
          for (unsigned int c = 0; c < nc; ++c)
            finite = finite && std::isfinite(v[c]);
          if (!finite)
            {
              where = "(" + prm_value(particles.position[p][0]);
              for (unsigned int d = 1; d < dim; ++d)
                where += ", " + prm_value(particles.position[p][d]);
              where += ")";
            }
        }
      // The first rank with a bad particle speaks for all.
      for (const auto &w : Utilities::MPI::all_gather(comm, where))
        AssertThrow(w.empty(),
                    ExcMessage(
                      "Initial conditions/Stress function = '" +
                      function_expression + "' (Function constants = '" +
                      function_constants +
                      "') is not finite at the particle at " + w + "."));
    }



    template class InitialStress<1>;
    template class InitialStress<2>;
  } // namespace Simulator
} // namespace psmpm
