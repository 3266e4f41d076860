// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_postprocess_updated_lagrangian_1d_h
#define psmpm_postprocess_updated_lagrangian_1d_h

#include <functional>
#include <vector>

namespace psmpm
{
  namespace Postprocess
  {
    /**
     * Updated Lagrangian FEM in 1D (thesis Sec. 4.2): linear elements that
     * move with the material, lumped mass, the same hypoelastic law as the
     * MPM particles (nu = 0: d sigma = E d eps - d eps sigma) and the same
     * semi-implicit Euler time stepping. It serves as the reference for
     * large deformations, where no closed-form solution exists; with many
     * elements and small steps its error is far below the MPM errors it
     * is used to measure (see tests/postprocess).
     *
     * The material occupies [0, length] in the reference configuration;
     * node 0 is fixed, the last node is fixed or traction free.
     */
    class UpdatedLagrangian1D
    {
    public:
      struct Parameters
      {
        double       length         = 1;
        double       density        = 1;
        double       youngs_modulus = 1;
        double       gravity        = 0; ///< body acceleration along the axis
        bool         fix_end        = true;
        unsigned int n_elements     = 2000;
        double       courant        = 0.25;
        std::function<double(double)> initial_velocity; ///< of X
      };

      explicit UpdatedLagrangian1D(const Parameters &p);

      /// Advance to time @p t (>= current time) with sub-steps.
      void
      advance_to(const double t);

      double
      time() const
      {
        return current_time;
      }

      /// Displacement, velocity and stress at reference position X.
      struct State
      {
        double displacement = 0, velocity = 0, stress = 0;
      };
      State
      evaluate(const double X) const;

      unsigned int
      n_steps() const
      {
        return steps;
      }

    private:
      void
      step(const double dt);

      Parameters          prm;
      std::vector<double> X;     ///< reference node positions
      std::vector<double> x;     ///< current node positions
      std::vector<double> v;     ///< node velocities
      std::vector<double> mass;  ///< lumped node masses
      std::vector<double> sigma; ///< element stresses
      double              current_time = 0;
      double              max_step     = 0;
      unsigned int        steps        = 0;
    };
  } // namespace Postprocess
} // namespace psmpm

#endif
