#pragma once

#include <signorini/material/interface.h>

namespace Signorini
{
  namespace Material
  {
    /**
     * Small-strain linear elasticity, psi = lambda/2 (tr eps)^2 + mu eps:eps
     * with eps = sym(F - I). P = lambda tr(eps) I + 2 mu eps and
     * A_ijkl = lambda d_ij d_kl + mu (d_ik d_jl + d_il d_jk). The law is
     * defined for every F; the energy functional still rejects states with
     * J <= 0 (inverted elements) for every law.
     */
    class LinearElastic : public Interface
    {
    public:
      LinearElastic(const double mu, const double lambda);

      bool
      evaluate(const Tensor<2, 3> &F,
               Response<3>        &response,
               const bool          want_derivatives) const override;

      std::string
      name() const override;

      std::pair<double, double>
      small_strain_lame() const override;

    private:
      double mu;
      double lambda;
    };
  } // namespace Material
} // namespace Signorini
