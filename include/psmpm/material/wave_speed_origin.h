// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_material_wave_speed_origin_h
#define psmpm_material_wave_speed_origin_h

#include <psmpm/material/material_set.h>

#include <string>

namespace psmpm
{
  namespace Material
  {
    /**
     * The entries of the material whose p-wave speed is
     * MaterialSet::max_p_wave_speed(), for messages about the time step
     * it bounds: "Material/Young's modulus = 1e+08 (Poisson's ratio =
     * 0.3, Density = 1000)" or with "Materials/Material k"; "" if no
     * material of a body has that speed.
     */
    template <int dim>
    std::string
    wave_speed_origin(const MaterialSet<dim> &materials);
  } // namespace Material
} // namespace psmpm

#endif
