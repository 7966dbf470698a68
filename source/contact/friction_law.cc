#include <signorini/contact/friction_law.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace Signorini
{
  namespace Contact
  {
    namespace SlipSmoothing
    {
      double
      f0(const double y, const double eps)
      {
        if (y >= eps)
          return y;
        return y * y / eps - y * y * y / (3. * eps * eps) + eps / 3.;
      }

      double
      f1(const double y, const double eps)
      {
        if (y >= eps)
          return 1.;
        return y * (2. / eps - y / (eps * eps));
      }

      double
      f1_over_y(const double y, const double eps)
      {
        if (y >= eps)
          return 1. / y;
        return 2. / eps - y / (eps * eps);
      }

      double
      df1(const double y, const double eps)
      {
        if (y >= eps)
          return 0.;
        return 2. / eps - 2. * y / (eps * eps);
      }
    } // namespace SlipSmoothing

    template <int dim>
    Tensor<1, dim - 1>
    TangentBasis<dim>::project(const Tensor<1, dim> &v) const
    {
      Tensor<1, dim - 1> s;
      for (unsigned int a = 0; a + 1 < dim; ++a)
        s[a] = t[a] * v;
      return s;
    }

    template <int dim>
    Tensor<1, dim>
    TangentBasis<dim>::lift(const Tensor<1, dim - 1> &g) const
    {
      Tensor<1, dim> v;
      for (unsigned int a = 0; a + 1 < dim; ++a)
        v += g[a] * t[a];
      return v;
    }

    template <int dim>
    Tensor<2, dim>
    TangentBasis<dim>::lift(const Tensor<2, dim - 1> &K) const
    {
      Tensor<2, dim> M;
      for (unsigned int a = 0; a + 1 < dim; ++a)
        for (unsigned int b = 0; b + 1 < dim; ++b)
          M += K[a][b] * outer_product(t[a], t[b]);
      return M;
    }

    template <int dim>
    TangentBasis<dim>
    tangent_basis(const Tensor<1, dim> &normal)
    {
      const double length = normal.norm();
      if (!(length > 0.) || !std::isfinite(length))
        throw std::invalid_argument("tangent_basis: the normal must be a finite, "
                                    "nonzero vector");
      const Tensor<1, dim> n = normal / length;
      TangentBasis<dim>    basis;
      if constexpr (dim == 2)
        {
          basis.t[0][0] = n[1];
          basis.t[0][1] = -n[0];
        }
      else
        {
          // sign(n_z) keeps 1/(sign + n_z) bounded by 1 for every n.
          const double sign = std::copysign(1., n[2]);
          const double a    = -1. / (sign + n[2]);
          const double b    = n[0] * n[1] * a;
          basis.t[0][0]     = 1. + sign * n[0] * n[0] * a;
          basis.t[0][1]     = sign * b;
          basis.t[0][2]     = -sign * n[0];
          basis.t[1][0]     = b;
          basis.t[1][1]     = sign + n[1] * n[1] * a;
          basis.t[1][2]     = -n[1];
        }
      return basis;
    }

    template <int dim>
    FrictionLaw<dim>::FrictionLaw(const double coefficient, const double slip_length)
      : mu(coefficient)
      , eps(slip_length)
    {
      if (!(mu >= 0.) || !std::isfinite(mu))
        throw std::invalid_argument("FrictionLaw: the friction coefficient must be "
                                    "finite and >= 0, got " + std::to_string(mu));
      if (!(eps > 0.) || !std::isfinite(eps))
        throw std::invalid_argument("FrictionLaw: the slip length must be finite "
                                    "and > 0, got " + std::to_string(eps));
    }

    namespace
    {
      void
      check_normal_force(const double lambda)
      {
        if (!(lambda >= 0.) || !std::isfinite(lambda))
          throw std::invalid_argument("FrictionLaw: the normal force must be "
                                      "finite and >= 0, got " +
                                      std::to_string(lambda));
      }
    } // namespace

    template <int dim>
    typename FrictionLaw<dim>::Response
    FrictionLaw<dim>::evaluate(const Slip &s, const double normal_force) const
    {
      check_normal_force(normal_force);
      Response r;
      const double scale = mu * normal_force;
      if (scale == 0.)
        return r; // exactly zero, whatever s
      const double y = s.norm();
      r.value        = scale * SlipSmoothing::f0(y, eps);
      // t_T = scale f1(y) s / y, with f1(y)/y finite at y = 0.
      const double f1y = SlipSmoothing::f1_over_y(y, eps);
      r.traction       = (scale * f1y) * s;
      // Hessian: scale [f1/y I + (f1' - f1/y) s s^T / y^2]. Below eps,
      // f1' - f1/y = -y/eps^2, so the second term is -s s^T/(eps^2 y),
      // which tends to zero with y; above eps it is -(1/y) s s^T / y^2.
      for (unsigned int a = 0; a + 1 < dim; ++a)
        r.stiffness[a][a] = scale * f1y;
      if (y > 0.)
        {
          const double c = (y >= eps) ? -1. / (y * y * y) : -1. / (eps * eps * y);
          // Each off-diagonal pair computed once: exactly symmetric.
          for (unsigned int a = 0; a + 1 < dim; ++a)
            for (unsigned int b = a; b + 1 < dim; ++b)
              {
                const double m = scale * c * s[a] * s[b];
                r.stiffness[a][b] += m;
                if (b != a)
                  r.stiffness[b][a] += m;
              }
        }
      return r;
    }

    template <int dim>
    double
    FrictionLaw<dim>::value(const Slip &s, const double normal_force) const
    {
      check_normal_force(normal_force);
      const double scale = mu * normal_force;
      if (scale == 0.)
        return 0.;
      return scale * SlipSmoothing::f0(s.norm(), eps);
    }

    template <int dim>
    FrictionStatus
    FrictionLaw<dim>::status(const Slip &s, const double normal_force) const
    {
      check_normal_force(normal_force);
      if (normal_force == 0.)
        return FrictionStatus::open;
      return s.norm() >= eps ? FrictionStatus::slip : FrictionStatus::stick;
    }

    template <int dim>
    double
    FrictionLaw<dim>::dissipated_energy(const Slip &s, const double normal_force) const
    {
      check_normal_force(normal_force);
      return mu * normal_force * s.norm();
    }

    template <int dim>
    typename FrictionLaw<dim>::Slip
    FrictionLaw<dim>::slip(const TangentBasis<dim>           &basis,
                           const std::vector<double>         &coefficients,
                           const std::vector<Tensor<1, dim>> &increments)
    {
      if (coefficients.size() != increments.size())
        throw std::invalid_argument("FrictionLaw::slip: " +
                                    std::to_string(coefficients.size()) +
                                    " coefficients for " +
                                    std::to_string(increments.size()) + " points");
      Tensor<1, dim> relative;
      for (unsigned int j = 0; j < increments.size(); ++j)
        relative += coefficients[j] * increments[j];
      return basis.project(relative);
    }

    template <int dim>
    double
    FrictionLaw<dim>::evaluate_points(const TangentBasis<dim>           &basis,
                                      const std::vector<double>         &coefficients,
                                      const std::vector<Tensor<1, dim>> &increments,
                                      const double                       normal_force,
                                      Vector<double>                    *gradient,
                                      FullMatrix<double>                *hessian) const
    {
      const Slip         s = slip(basis, coefficients, increments);
      const unsigned int n = increments.size();
      if (!gradient && !hessian)
        return value(s, normal_force);
      const Response r = evaluate(s, normal_force);
      if (gradient)
        {
          gradient->reinit(n * dim);
          const Tensor<1, dim> g = basis.lift(r.traction);
          for (unsigned int j = 0; j < n; ++j)
            for (unsigned int d = 0; d < dim; ++d)
              (*gradient)(j * dim + d) = coefficients[j] * g[d];
        }
      if (hessian)
        {
          hessian->reinit(n * dim, n * dim);
          const Tensor<2, dim> K = basis.lift(r.stiffness);
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
              for (unsigned int d = 0; d < dim; ++d)
                for (unsigned int e = 0; e < dim; ++e)
                  (*hessian)(i * dim + d, j * dim + e) =
                    coefficients[i] * coefficients[j] * K[d][e];
        }
      return r.value;
    }

    template <int dim>
    double
    FrictionLaw<dim>::evaluate_rigid(const TangentBasis<dim> &basis,
                                     const Tensor<1, dim>    &increment,
                                     const double             normal_force,
                                     Vector<double>          *gradient,
                                     FullMatrix<double>      *hessian) const
    {
      return evaluate_points(basis, {1.}, {increment}, normal_force, gradient, hessian);
    }

    template <int dim>
    double
    FrictionLaw<dim>::evaluate_pair(const TangentBasis<dim> &basis,
                                    const Tensor<1, dim>    &increment_1,
                                    const Tensor<1, dim>    &increment_2,
                                    const double             normal_force,
                                    Vector<double>          *gradient,
                                    FullMatrix<double>      *hessian) const
    {
      return evaluate_points(basis, {1., -1.}, {increment_1, increment_2},
                             normal_force, gradient, hessian);
    }

    template struct TangentBasis<2>;
    template struct TangentBasis<3>;
    template TangentBasis<2>
    tangent_basis(const Tensor<1, 2> &);
    template TangentBasis<3>
    tangent_basis(const Tensor<1, 3> &);
    template class FrictionLaw<2>;
    template class FrictionLaw<3>;
  } // namespace Contact
} // namespace Signorini
