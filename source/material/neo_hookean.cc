// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#include <psmpm/material/neo_hookean.h>

#include <algorithm>
#include <limits>

namespace psmpm
{
  namespace Material
  {
    namespace
    {
      template <int dim>
      std::unique_ptr<Material<dim>>
      create_neo_hookean()
      {
        return std::make_unique<NeoHookean<dim>>();
      }

      const char *const description =
        "compressible neo-Hookean hyperelasticity (plane strain in 2D, "
        "uniaxial strain in 1D)";

      const Registration<MaterialRegistry<1>> registration_1d(
        {"neo-hookean", description, create_neo_hookean<1>, {}});
      const Registration<MaterialRegistry<2>> registration_2d(
        {"neo-hookean", description, create_neo_hookean<2>, {}});


      /// A stress that the solver's non-finite monitor stops on.
      template <int dim>
      void
      set_nan(SymmetricTensor<2, dim> &stress)
      {
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = i; j < dim; ++j)
            stress[i][j] = std::numeric_limits<double>::quiet_NaN();
      }
    } // namespace



    template <int dim>
    std::string
    NeoHookean<dim>::name() const
    {
      return "neo-hookean";
    }



    template <int dim>
    std::vector<std::string>
    NeoHookean<dim>::state_names() const
    {
      if constexpr (dim == 1)
        return {"F_xx"};
      else
        return {"F_xx", "F_xy", "F_yx", "F_yy"};
    }



    template <int dim>
    void
    NeoHookean<dim>::initialize(const unsigned int n, double *state) const
    {
      const unsigned int s = this->state_stride();
      for (unsigned int p = 0; p < n; ++p)
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            state[p * s + i * dim + j] = (i == j ? 1. : 0.);
    }



    template <int dim>
    void
    NeoHookean<dim>::update(const unsigned int       n,
                            const Tensor<2, dim>    *dL,
                            SymmetricTensor<2, dim> *stress,
                            double                  *state,
                            double                  *volume_ratio) const
    {
      const double       mu     = this->shear_modulus();
      const double       lambda = this->lame_lambda();
      const double       nan    = std::numeric_limits<double>::quiet_NaN();
      const unsigned int s      = this->state_stride();
      for (unsigned int p = 0; p < n; ++p)
        {
          this->request_ahead(n, stress, state, s, p);
          double *const F = state + p * s;

          // dF = A^{-1} B with A = I - dL/2, B = I + dL/2.
          Tensor<2, dim> A, B;
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              {
                A[i][j] = (i == j ? 1. : 0.) - 0.5 * dL[p][i][j];
                B[i][j] = (i == j ? 1. : 0.) + 0.5 * dL[p][i][j];
              }
          const double det_A = determinant(A);
          // NaN-safe: a non-finite dL fails the comparisons as well.
          if (!(det_A > 0))
            {
              set_nan(stress[p]);
              volume_ratio[p] = nan;
              continue;
            }
          const double det_dF = determinant(B) / det_A;
          if (!(det_dF > 0))
            {
              set_nan(stress[p]);
              volume_ratio[p] = det_dF;
              continue;
            }
          const Tensor<2, dim> dF = invert(A) * B;

          Tensor<2, dim> F_old;
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              F_old[i][j] = F[i * dim + j];
          const Tensor<2, dim> F_new = dF * F_old;
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              F[i * dim + j] = F_new[i][j];

          // The out-of-plane diagonal of F is 1: J and the in-plane b are
          // those of the dim x dim block.
          const double            J     = determinant(F_new);
          const double            ln_J  = std::log(J);
          const double            inv_J = 1. / J;
          SymmetricTensor<2, dim> sigma;
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = i; j < dim; ++j)
              {
                double b_ij = 0;
                for (unsigned int k = 0; k < dim; ++k)
                  b_ij += F_new[i][k] * F_new[j][k];
                sigma[i][j] = (mu * (b_ij - (i == j ? 1. : 0.)) +
                               (i == j ? lambda * ln_J : 0.)) *
                              inv_J;
              }
          stress[p]       = sigma;
          volume_ratio[p] = det_dF;
        }
    }



    template <int dim>
    void
    NeoHookean<dim>::energy_density(const unsigned int n,
                                    const SymmetricTensor<2, dim> *,
                                    const double *state,
                                    double       *energy) const
    {
      const double       mu     = this->shear_modulus();
      const double       lambda = this->lame_lambda();
      const unsigned int s      = this->state_stride();
      for (unsigned int p = 0; p < n; ++p)
        {
          const double *const F = state + p * s;
          // I1 - 3 = |F|^2 - dim: the out-of-plane ones cancel.
          double I1_minus_3 = -double(dim);
          for (unsigned int k = 0; k < dim * dim; ++k)
            I1_minus_3 += F[k] * F[k];
          const double J    = (dim == 1 ? F[0] : F[0] * F[3] - F[1] * F[2]);
          const double ln_J = std::log(J);
          energy[p] =
            (0.5 * mu * (I1_minus_3 - 2 * ln_J) + 0.5 * lambda * ln_J * ln_J) /
            J;
        }
    }



    template <int dim>
    double
    NeoHookean<dim>::max_wave_speed(const unsigned int             n,
                                    const SymmetricTensor<2, dim> *stress,
                                    const double                  *state) const
    {
      // The stride once per batch: n_state() builds the list of names.
      double             c = 0;
      const unsigned int s = this->state_stride();
      for (unsigned int p = 0; p < n; ++p)
        c = std::max(c, NeoHookean<dim>::wave_speed(stress[p], state + p * s));
      return c;
    }



    template <int dim>
    double
    NeoHookean<dim>::wave_speed(const SymmetricTensor<2, dim> &,
                                const double *state) const
    {
      const double mu     = this->shear_modulus();
      const double lambda = this->lame_lambda();
      double       J, b_max;
      if constexpr (dim == 1)
        {
          J     = state[0];
          b_max = state[0] * state[0];
        }
      else
        {
          const double *const F = state;
          J                     = F[0] * F[3] - F[1] * F[2];
          const double b_xx     = F[0] * F[0] + F[1] * F[1];
          const double b_yy     = F[2] * F[2] + F[3] * F[3];
          const double b_xy     = F[0] * F[2] + F[1] * F[3];
          const double half_gap = 0.5 * (b_xx - b_yy);
          b_max =
            0.5 * (b_xx + b_yy) + std::sqrt(half_gap * half_gap + b_xy * b_xy);
        }
      const double c2 =
        std::max(lambda * (1 - std::log(J)) + mu * (1 + b_max), mu * b_max) /
        this->density;
      return std::sqrt(c2);
    }



    template class NeoHookean<1>;
    template class NeoHookean<2>;
  } // namespace Material
} // namespace psmpm
