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

      // The materials whose particles exist, by body id (0 alone without
      // Bodies).
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
                        " cannot start from a prescribed stress (its stress "
                        "follows from the deformation gradient); use Stress "
                        "= none or a rate model such as hypoelastic."));
        }

      if (type == Type::function)
        {
          const auto constants = parse_function_constants(function_constants);
          const unsigned int n = n_stress_components<dim>;
          try
            {
              FunctionParser<dim> f(n);
              f.initialize(dim == 1 ? "x" : "x,y",
                           function_expression,
                           constants);
              // Parse errors of muParser surface at the first evaluation.
              Vector<double> values(n);
              f.vector_value(Point<dim>(), values);
            }
          catch (const std::exception &e)
            {
              AssertThrow(
                false,
                ExcMessage(
                  "Initial conditions/Stress function = '" +
                  function_expression + "': " + e.what() + " (expected " +
                  std::to_string(n) + " expressions separated by ';': " +
                  (dim == 2 ? "sxx; syy; sxy; szz" : "sxx; lateral") + ")."));
            }
          return;
        }

      AssertThrow(gravity.norm() > 0,
                  ExcMessage(entry +
                             " needs a non-zero Body force/Gravity (the "
                             "stress at rest under gravity)."));
      double k0_value = 0;
      if (k0_text != "automatic")
        {
          bool number = true;
          try
            {
              k0_value = Utilities::string_to_double(k0_text);
            }
          catch (...)
            {
              number = false;
            }
          AssertThrow(number && std::isfinite(k0_value) && k0_value > 0,
                      ExcMessage("Initial conditions/K0 = " + k0_text +
                                 ": must be automatic or a number > 0 (the "
                                 "ratio of horizontal to vertical stress)."));
        }
      k0.assign(bodies.bodies.size() + 1, k0_value);
      if (k0_value > 0)
        return;
      for (unsigned int id = 0; id < k0.size(); ++id)
        {
          const auto  &m   = materials.of_body(id);
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
          k0[id] =
            phi >= 0 ? 1 - std::sin(phi * numbers::PI / 180) : nu / (1 - nu);
        }
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
      const std::size_t  n     = particles.size();
      const unsigned int n_ids = k0.size();
      const double       g     = gravity.norm();
      // "Up" and, in 2D, the direction across it: the columns.
      const Tensor<1, dim> up = -gravity / g;
      Tensor<1, dim>       across;
      if constexpr (dim == 2)
        {
          across[0] = up[1];
          across[1] = -up[0];
        }
      // The layout's spacing along and across up; on Gmsh meshes each
      // particle's own size (volume^(1/dim)) and the largest for the bins.
      double along = 0, width = 0;
      for (unsigned int d = 0; d < dim; ++d)
        {
          along += std::abs(up[d]) * spacing[d];
          width += std::abs(across[d]) * spacing[d];
        }
      const bool lattice = along > 0;
      const auto size    = [&](const std::size_t p) {
        return std::pow(particles.volume[p], 1. / dim);
      };
      double largest = 0;
      if (!lattice)
        {
          for (std::size_t p = 0; p < n; ++p)
            largest = std::max(largest, size(p));
          largest = Utilities::MPI::max(largest, comm);
          along = width = largest;
        }
      const auto half_along = [&](const std::size_t p) {
        return lattice ? 0.5 * along : 0.5 * size(p);
      };

      // Columns across up: bins a quarter of the spacing wide. A particle
      // looks at its own bin and one on either side, that is between a
      // quarter and half a spacing to each side: its own column of a
      // regular layout, never the neighbouring ones.
      double lo = std::numeric_limits<double>::max(), hi = -lo;
      for (std::size_t p = 0; p < n; ++p)
        {
          const double s = particles.position[p] * across;
          lo             = std::min(lo, s);
          hi             = std::max(hi, s);
        }
      lo = Utilities::MPI::min(lo, comm);
      hi = Utilities::MPI::max(hi, comm);
      if (lo > hi)
        return; // no particle on any rank
      const double      bin = dim == 1 ? 1. : 0.25 * width;
      const std::size_t n_bins =
        dim == 1 ? 1 : std::size_t((hi - lo) / bin) + 1;
      const auto bin_of = [&](const std::size_t p) -> std::size_t {
        if (dim == 1)
          return 0;
        return std::min(n_bins - 1,
                        std::size_t((particles.position[p] * across - lo) /
                                    bin));
      };

      // Per body and bin: the top (largest z + half spacing) and minus the
      // bottom (so that one MPI max reduction finds both).
      const double        none = std::numeric_limits<double>::lowest();
      const std::size_t   m    = std::size_t(n_ids) * n_bins;
      std::vector<double> extent(2 * m, none);
      for (std::size_t p = 0; p < n; ++p)
        {
          const std::size_t k = particles.body_id[p] * n_bins + bin_of(p);
          const double      z = particles.position[p] * up;
          const double      c = half_along(p);
          extent[k]           = std::max(extent[k], z + c);
          extent[m + k]       = std::max(extent[m + k], -(z - c));
        }
      Utilities::MPI::max(extent, comm, extent);

      // Over the window of a bin and its neighbours: top, bottom, and the
      // weight resting on the body's top there.
      std::vector<double> top(m, none), bottom(m, -none), load(m, 0.);
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
                  std::min(bottom[k * n_bins + b], -extent[m + k * n_bins + w]);
              }
      // A body whose bottom lies within one spacing of the top of another
      // in the same column rests on it with its own column weight and what
      // rests on it in turn; bodies are taken from the highest top down so
      // that the upper loads are known.
      const double          contact = lattice ? along : largest;
      std::vector<unsigned> order(n_ids);
      for (std::size_t b = 0; b < n_bins && n_ids > 1; ++b)
        {
          const auto at = [&](const unsigned int k) { return k * n_bins + b; };
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

      for (std::size_t p = 0; p < n; ++p)
        {
          const unsigned int k  = particles.body_id[p];
          const std::size_t  at = k * n_bins + bin_of(p);
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
