#include <signorini/material/invariant_based.h>

#include <deal.II/base/tensor.h>

namespace Signorini
{
  namespace Material
  {
    bool
    InvariantBased::admissible(const std::array<double, 3> &) const
    {
      return true;
    }

    template <int dim>
    bool
    InvariantBased::evaluate_blocks(const Tensor<2, dim> &Fb,
                                    Response<dim>        &response,
                                    const bool want_derivatives,
                                    const bool want_tangent) const
    {
      // In plane strain (dim = 2) F = diag(F2, 1): every quantity below is
      // block diagonal with a 1 in the out-of-plane corner, so only the
      // in-plane blocks are formed (C2 = F2^T F2, tr C = tr C2 + 1,
      // C : C = C2 : C2 + 1, J = det F2). The values are those of the 3D
      // formulas on the embedded F; their last bits may differ, as the
      // sums are taken in another order. In 3D, Fb is F.
      const double J = determinant(Fb);
      if (!(J > 0.) || !std::isfinite(J))
        return false;

      const Tensor<2, dim> C    = transpose(Fb) * Fb;
      const double         I1   = trace(C) + (dim == 2 ? 1. : 0.);
      const double         trC2 = scalar_product(C, C) + (dim == 2 ? 1. : 0.);
      const double         I2   = 0.5 * (I1 * I1 - trC2);

      const std::array<double, 3> invariants = {{I1, I2, J}};
      if (!admissible(invariants))
        return false;

      std::array<double, 3>                dpsi{};
      std::array<std::array<double, 3>, 3> d2psi{};
      invariant_energy(invariants, response.psi, dpsi, d2psi,
                       want_derivatives);
      if (!std::isfinite(response.psi))
        return false;
      if (!want_derivatives)
        return true;

      // Only the dim x dim blocks are needed: in plane strain F33 = 1 is
      // held fixed, so P and A are the in-plane blocks of the 3D ones.
      const Tensor<2, dim> FC    = Fb * C;
      const Tensor<2, dim> FinvT = transpose(invert(Fb));
      const Tensor<2, dim> B     = Fb * transpose(Fb);

      // dIa/dF restricted to the block: G0 = 2F, G1 = 2(I1 F - F C),
      // G2 = J F^-T.
      std::array<Tensor<2, dim>, 3> G;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          {
            G[0][i][j] = 2. * Fb[i][j];
            G[1][i][j] = 2. * (I1 * Fb[i][j] - FC[i][j]);
            G[2][i][j] = J * FinvT[i][j];
          }
      response.P = dpsi[0] * G[0] + dpsi[1] * G[1] + dpsi[2] * G[2];
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          if (!std::isfinite(response.P[i][j]))
            return false;
      if (!want_tangent)
        return true;

      // H_b = sum_a psi_ab G_a: the psi_ab part of A is sum_b H_b (x) G_b
      // (three rank-one terms; d2psi is symmetric).
      std::array<Tensor<2, dim>, 3> H;
      for (unsigned int b = 0; b < 3; ++b)
        H[b] = d2psi[0][b] * G[0] + d2psi[1][b] * G[1] + d2psi[2][b] * G[2];

      // The second derivatives of the invariants (see the class
      // documentation), with F^-T = M:
      //   d2I1 = 2 d_ik d_jl,
      //   d2I2 = 2(2 F_ij F_kl + I1 d_ik d_jl - d_ik C_lj - F_il F_kj
      //            - B_ik d_jl),
      //   d2J  = J (M_ij M_kl - M_il M_kj).
      const double s1 = 2. * dpsi[0] + 2. * dpsi[1] * I1; // d_ik d_jl
      const double s2 = 2. * dpsi[1];
      const double sJ = dpsi[2] / J; // J M = FinvT J; (J M)(J M)/J
      // With N = J M = G2: sJ (N_ij N_kl - N_il N_kj) = psi_J J (...).
      const Tensor<2, dim> &N = G[2];

      Tensor<4, dim> &A = response.A;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          for (unsigned int k = i; k < dim; ++k)
            for (unsigned int l = (k == i ? j : 0); l < dim; ++l)
              {
                double value = H[0][i][j] * G[0][k][l] +
                               H[1][i][j] * G[1][k][l] +
                               H[2][i][j] * G[2][k][l];
                value += s2 * (2. * Fb[i][j] * Fb[k][l] - Fb[i][l] * Fb[k][j]);
                value += sJ * (N[i][j] * N[k][l] - N[i][l] * N[k][j]);
                if (i == k)
                  value -= s2 * C[l][j];
                if (j == l)
                  value -= s2 * B[i][k];
                if (i == k && j == l)
                  value += s1;
                A[i][j][k][l] = value;
                A[k][l][i][j] = value;
              }
      return true;
    }

    bool
    InvariantBased::evaluate(const Tensor<2, 3> &F,
                             Response<3>        &response,
                             const bool          want_derivatives) const
    {
      return evaluate_blocks<3>(F, response, want_derivatives);
    }

    bool
    InvariantBased::first_piola(const Tensor<2, 3> &F, Tensor<2, 3> &P) const
    {
      Response<3> response;
      if (!evaluate_blocks<3>(F, response, true, false))
        return false;
      P = response.P;
      return true;
    }

    bool
    InvariantBased::evaluate_plane_strain(const Tensor<2, 2> &F,
                                          Response<2>        &response,
                                          const bool want_derivatives) const
    {
      return evaluate_blocks<2>(F, response, want_derivatives);
    }
  } // namespace Material
} // namespace Signorini
