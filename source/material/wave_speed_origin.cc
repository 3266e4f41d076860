// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/base/format.h>
#include <psmpm/material/wave_speed_origin.h>

namespace psmpm
{
  namespace Material
  {
    template <int dim>
    std::string
    wave_speed_origin(const MaterialSet<dim> &materials)
    {
      const double c_p = materials.max_p_wave_speed();
      for (unsigned int b = 0; b < materials.material_ids().size(); ++b)
        {
          const Material<dim> &m = materials.of_body(b);
          if (m.p_wave_speed() == c_p)
            return m.path +
                   "/Young's modulus = " + prm_value(m.youngs_modulus) +
                   " (Poisson's ratio = " + prm_value(m.poisson_ratio) +
                   ", Density = " + prm_value(m.density) + ")";
        }
      return "";
    }

    template std::string
    wave_speed_origin(const MaterialSet<1> &);
    template std::string
    wave_speed_origin(const MaterialSet<2> &);
  } // namespace Material
} // namespace psmpm
