// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_postprocess_references_soil_column_h
#define psmpm_postprocess_references_soil_column_h

namespace psmpm
{
  namespace Postprocess
  {
    /**
     * Displacement of the small-deformation soil column (height H, bottom
     * fixed, top free, released under gravity g at t = 0) at height y by
     * the corrected thesis eq. 4.6 summed to @p n_terms terms. The
     * "soil column" reference evaluates the equivalent closed d'Alembert
     * form; this series is kept to check it.
     */
    double
    soil_column_series(const double       density,
                       const double       youngs_modulus,
                       const double       g,
                       const double       height,
                       const double       y,
                       const double       t,
                       const unsigned int n_terms);
  } // namespace Postprocess
} // namespace psmpm

#endif
