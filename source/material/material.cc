// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/base/format.h>
#include <psmpm/material/material.h>

#include <cmath>
#include <set>
#include <sstream>

namespace psmpm
{
  namespace Material
  {
    namespace
    {
      /**
       * "a|b|c" of the names registered for dim 1 or dim 2. The parameter
       * file is dimension-independent and Material/Model is declared once,
       * so the selection must not depend on which dimension declared it;
       * create() then checks that the model exists for its own dimension.
       */
      std::string
      model_selection()
      {
        std::set<std::string> names;
        for (const std::string &list :
             {MaterialRegistry<1>::instance().selection(),
              MaterialRegistry<2>::instance().selection()})
          {
            std::istringstream s(list);
            std::string        name;
            while (std::getline(s, name, '|'))
              if (!name.empty())
                names.insert(name);
          }
        std::string selection;
        for (const auto &name : names)
          selection += (selection.empty() ? "" : "|") + name;
        return selection;
      }
    } // namespace



    template <int dim>
    void
    Material<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Material");
      declare_entries(prm);
      prm.leave_subsection();
    }



    template <int dim>
    void
    Material<dim>::declare_entries(ParameterHandler &prm)
    {
      prm.declare_entry("Model",
                        "hypoelastic",
                        Patterns::Selection(model_selection()),
                        "Constitutive model. " +
                          MaterialRegistry<2>::instance().documentation());
      // Density keeps the unbounded pattern of the old class: with
      // Patterns::Double(0), -1 would be rejected while the file is read,
      // with a message that names "Density" but not "Material/Density"
      // (tests/app/bad_input_01 requires the latter).
      prm.declare_entry("Density",
                        "1",
                        Patterns::Double(),
                        "Initial density [kg/m^3], > 0.");
      prm.declare_entry("Young's modulus",
                        "100",
                        Patterns::Double(),
                        "Young's modulus E [Pa], > 0.");
      // Patterns::Double bounds are inclusive, so 0.5 (and -1) still
      // reach the check in parse_parameters() with its explanation.
      prm.declare_entry("Poisson's ratio",
                        "0",
                        Patterns::Double(-1, 0.5),
                        "Poisson's ratio, -1 < nu < 0.5.");
      // Entries of the models of both dimensions, for the same reason as
      // the selection (declaring an entry twice is harmless).
      MaterialRegistry<1>::instance().declare_parameters(prm);
      MaterialRegistry<2>::instance().declare_parameters(prm);
    }



    template <int dim>
    std::unique_ptr<Material<dim>>
    Material<dim>::create(ParameterHandler &prm)
    {
      prm.enter_subsection("Material");
      std::unique_ptr<Material<dim>> material;
      try
        {
          material = create(prm, "Material");
        }
      catch (...)
        {
          // Leave the subsection so that the caller's handler stays usable.
          prm.leave_subsection();
          throw;
        }
      prm.leave_subsection();
      return material;
    }



    template <int dim>
    std::unique_ptr<Material<dim>>
    Material<dim>::create(ParameterHandler &prm, const std::string &path)
    {
      auto material = MaterialRegistry<dim>::instance().create(prm.get("Model"),
                                                               path + "/Model");
      material->path = path;
      material->parse_parameters(prm);
      return material;
    }



    template <int dim>
    void
    Material<dim>::parse_parameters(ParameterHandler &prm)
    {
      density        = prm.get_double("Density");
      youngs_modulus = prm.get_double("Young's modulus");
      poisson_ratio  = prm.get_double("Poisson's ratio");
      AssertThrow(density > 0,
                  ExcMessage(path + "/Density = " + prm_value(density) +
                             ": must be positive."));
      AssertThrow(youngs_modulus > 0,
                  ExcMessage(path +
                             "/Young's modulus = " + prm_value(youngs_modulus) +
                             ": must be positive."));
      AssertThrow(poisson_ratio > -1 && poisson_ratio < 0.5,
                  ExcMessage(path +
                             "/Poisson's ratio = " + prm_value(poisson_ratio) +
                             ": must satisfy -1 < nu < 0.5 (0.5 is "
                             "incompressible, which this explicit "
                             "formulation cannot represent)."));
      // The moduli and the wave speed derived from them: one beyond the
      // range of double numbers gives a time step of 0 or inf.
      const double c_p = p_wave_speed();
      AssertThrow(
        std::isfinite(p_wave_modulus()) && std::isfinite(c_p) && c_p > 0,
        ExcMessage(path + "/Young's modulus = " + prm_value(youngs_modulus) +
                   " with Poisson's ratio = " + prm_value(poisson_ratio) +
                   " and Density = " + prm_value(density) +
                   ": the p-wave modulus (" + prm_value(p_wave_modulus()) +
                   ") or the p-wave speed (" + prm_value(c_p) +
                   ") is beyond the range of double numbers."));
    }



    template <int dim>
    void
    Material<dim>::initialize(const unsigned int n, double *state) const
    {
      const unsigned int size = n_state(), s = state_stride();
      for (unsigned int p = 0; p < n; ++p)
        for (unsigned int k = 0; k < size; ++k)
          state[p * s + k] = 0;
    }



    template <int dim>
    void
    Material<dim>::set_initial_stress(const unsigned int,
                                      const SymmetricTensor<2, dim> *,
                                      const double *,
                                      double *) const
    {
      AssertThrow(false,
                  ExcMessage(path + "/Model = " + name() +
                             ": this model cannot start from a prescribed "
                             "initial stress."));
    }



    template <int dim>
    double
    Material<dim>::wave_speed(const SymmetricTensor<2, dim> &,
                              const double *) const
    {
      return p_wave_speed();
    }



    template <int dim>
    double
    Material<dim>::max_wave_speed(const unsigned int             n,
                                  const SymmetricTensor<2, dim> *stress,
                                  const double                  *state) const
    {
      double             c = 0;
      const unsigned int s = state_stride();
      for (unsigned int p = 0; p < n; ++p)
        c = std::max(c, wave_speed(stress[p], state + p * s));
      return c;
    }



    template class Material<1>;
    template class Material<2>;
  } // namespace Material
} // namespace psmpm
