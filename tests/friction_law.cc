// The regularised Coulomb law (contact/friction_law.h) and its parameters
// (contact/friction_parameters.h):
// (1) D(s) = mu lambda f0(|s|): gradient (the tangential traction) and
//     Hessian against central differences in s, 2D (one tangential
//     component) and 3D (two), at slips below, at and above the slip
//     length eps and at s = 0, for two scalings of (mu, lambda, eps);
// (2) the same through the projection s = T^T sum_j c_j du_j with respect
//     to the displacement increments of one point (rigid foundation), two
//     points (s = T^T (du_1 - du_2)) and a combination of four (a body 1
//     point between two nodes against a body 2 material point);
// (3) the tangent basis: orthonormal, normal to n, right-handed, for
//     random and axis-aligned normals (n = (0, 0, -1) included);
// (4) the limits: |t_T| = mu lambda to 1e-12 for |s| >= eps; value,
//     gradient and Hessian continuous at |s| = eps and at s = 0, the
//     Hessian's jump across eps linear in the distance (C^2, not C^3);
// (5) convexity: the Hessian positive semidefinite at random slips, and
//     D((a + b)/2) <= (D(a) + D(b))/2 at random pairs;
// (6) mu = 0 (or lambda = 0) gives exactly zero; status and the exact
//     dissipated energy mu lambda |s|; invalid arguments throw;
// (7) FrictionParameters: defaults, and every bad value throws an
//     InputError naming its key.
// A corrupted Hessian must be rejected by the same checker (the test can
// fail). The largest errors are printed to stdout (not compared).

#include <signorini/contact/friction_law.h>
#include <signorini/contact/friction_parameters.h>
#include <signorini/input_error.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace dealii;
using namespace Signorini;
using namespace Signorini::Contact;

namespace
{
  std::mt19937 rng(20261130);

  double
  uniform(const double a, const double b)
  {
    return std::uniform_real_distribution<double>(a, b)(rng);
  }

  template <int n>
  Tensor<1, n>
  random_unit()
  {
    Tensor<1, n> v;
    do
      for (unsigned int i = 0; i < n; ++i)
        v[i] = uniform(-1., 1.);
    while (v.norm() < 0.1);
    return v / v.norm();
  }

  const char *
  yes(const bool ok)
  {
    return ok ? "yes" : "no";
  }

  /// Slips |s| / eps at which the derivatives are checked.
  const std::vector<double> ratios = {0., 1e-3, 0.3, 0.7, 0.999, 1., 1.001, 1.5, 10., 1e3};

  const double gradient_tolerance = 1e-7;
  const double hessian_tolerance  = 1e-5;

  /// Largest errors of the traction and of the Hessian against central
  /// differences in s, relative to mu lambda and to mu lambda / max(|s|,
  /// eps). @p corrupt scales the Hessian (checking the checker).
  template <int dim>
  std::pair<double, double>
  slip_space_errors(const FrictionLaw<dim>            &law,
                    const Tensor<1, dim - 1>          &s,
                    const double                       lambda,
                    const double                       corrupt = 1.)
  {
    const double eps     = law.slip_length();
    const double length  = std::max(s.norm(), eps);
    const double h       = 1e-6 * length;
    const double scale_g = law.coefficient() * lambda;
    const double scale_h = scale_g / length;
    const auto   r       = law.evaluate(s, lambda);
    double       eg = 0., eh = 0.;
    for (unsigned int a = 0; a + 1 < dim; ++a)
      {
        Tensor<1, dim - 1> sp = s, sm = s;
        sp[a] += h;
        sm[a] -= h;
        const double g = (law.value(sp, lambda) - law.value(sm, lambda)) / (2 * h);
        eg             = std::max(eg, std::abs(g - r.traction[a]) / scale_g);
        const auto rp = law.evaluate(sp, lambda), rm = law.evaluate(sm, lambda);
        for (unsigned int b = 0; b + 1 < dim; ++b)
          {
            const double H = (rp.traction[b] - rm.traction[b]) / (2 * h);
            eh = std::max(eh, std::abs(H - corrupt * r.stiffness[b][a]) / scale_h);
          }
      }
    return {eg, eh};
  }

  template <int dim>
  Tensor<1, dim - 1>
  slip_at(const double ratio, const double eps)
  {
    return (ratio * eps) * random_unit<dim - 1>();
  }

  template <int dim>
  void
  check_slip_space(std::ostream &out)
  {
    // (mu, lambda, eps): a unit-free case and SSNV128's scales (a nodal
    // force of 5e7 Pa x 1.25e-3 m, eps = 1e-4 h).
    const std::vector<std::array<double, 3>> cases = {{0.3, 2.5, 1e-3},
                                                      {1.0, 6.25e4, 1.25e-7}};
    double eg = 0., eh = 0.;
    for (const auto &c : cases)
      {
        const FrictionLaw<dim> law(c[0], c[2]);
        for (const double ratio : ratios)
          for (unsigned int k = 0; k < 3; ++k)
            {
              const auto e = slip_space_errors(law, slip_at<dim>(ratio, c[2]), c[1]);
              eg           = std::max(eg, e.first);
              eh           = std::max(eh, e.second);
            }
      }
    std::cout << dim << "D slip space: largest gradient error " << eg
              << ", Hessian error " << eh << std::endl;
    out << dim << "D, D(s) at |s|/eps = 0, 1e-3, 0.3, 0.7, 0.999, 1, 1.001, "
        << "1.5, 10, 1e3: gradient matches finite differences: "
        << yes(eg < gradient_tolerance)
        << "; Hessian matches finite differences: " << yes(eh < hessian_tolerance)
        << std::endl;
    // The checker rejects a Hessian off by 1e-3 (at a slip where it is
    // not zero: in 2D it vanishes beyond eps).
    const FrictionLaw<dim> law(0.3, 1e-3);
    const auto bad = slip_space_errors(law, slip_at<dim>(0.5, 1e-3), 2.5, 1.001);
    out << dim << "D: a Hessian scaled by 1.001 is rejected: "
        << yes(bad.second > hessian_tolerance) << std::endl;
  }

  /// Increments du_j whose slip T^T sum_j c_j du_j is @p s, with random
  /// normal parts and random other points.
  template <int dim>
  std::vector<Tensor<1, dim>>
  increments_for(const TangentBasis<dim>   &basis,
                 const Tensor<1, dim>      &n,
                 const std::vector<double> &c,
                 const Tensor<1, dim - 1>  &s,
                 const double               eps)
  {
    std::vector<Tensor<1, dim>> du(c.size());
    Tensor<1, dim>              rest = basis.lift(s) + uniform(-3., 3.) * eps * n;
    for (unsigned int j = 1; j < c.size(); ++j)
      {
        for (unsigned int d = 0; d < dim; ++d)
          du[j][d] = uniform(-2., 2.) * eps;
        rest -= c[j] * du[j];
      }
    du[0] = rest / c[0];
    return du;
  }

  /// Errors of the gradient and Hessian in the increments against
  /// central differences (relative as in slip_space_errors, times the
  /// largest |c_j| and |c_j|^2).
  template <int dim>
  std::pair<double, double>
  point_space_errors(const FrictionLaw<dim>            &law,
                     const TangentBasis<dim>           &basis,
                     const std::vector<double>         &c,
                     const std::vector<Tensor<1, dim>> &du,
                     const double                       lambda)
  {
    const unsigned int n_var = c.size() * dim;
    Vector<double>     g;
    FullMatrix<double> H;
    law.evaluate_points(basis, c, du, lambda, &g, &H);
    const double length =
      std::max(FrictionLaw<dim>::slip(basis, c, du).norm(), law.slip_length());
    double cmax = 0.;
    for (const double x : c)
      cmax = std::max(cmax, std::abs(x));
    const double h       = 1e-6 * length;
    const double scale_g = law.coefficient() * lambda * cmax;
    const double scale_h = scale_g * cmax / length;
    double       eg = 0., eh = 0.;
    for (unsigned int v = 0; v < n_var; ++v)
      {
        auto dp = du, dm = du;
        dp[v / dim][v % dim] += h;
        dm[v / dim][v % dim] -= h;
        Vector<double>     gp, gm;
        const double vp = law.evaluate_points(basis, c, dp, lambda, &gp, nullptr);
        const double vm = law.evaluate_points(basis, c, dm, lambda, &gm, nullptr);
        eg = std::max(eg, std::abs((vp - vm) / (2 * h) - g(v)) / scale_g);
        for (unsigned int w = 0; w < n_var; ++w)
          eh = std::max(eh, std::abs((gp(w) - gm(w)) / (2 * h) - H(w, v)) / scale_h);
      }
    return {eg, eh};
  }

  template <int dim>
  void
  check_point_space(std::ostream &out)
  {
    const std::vector<std::pair<std::string, std::vector<double>>> combinations = {
      {"one point (rigid foundation, s = T^T du)", {1.}},
      {"two points (s = T^T (du_1 - du_2))", {1., -1.}},
      {"four points (0.6, 0.4 of body 1 against -0.25, -0.75 of body 2)",
       {0.6, 0.4, -0.25, -0.75}}};
    const double mu = 0.4, lambda = 3.7, eps = 2e-3;
    const FrictionLaw<dim> law(mu, eps);
    for (const auto &combination : combinations)
      {
        double eg = 0., eh = 0.;
        for (const double ratio : ratios)
          for (unsigned int k = 0; k < 3; ++k)
            {
              const Tensor<1, dim> n     = random_unit<dim>();
              const auto           basis = tangent_basis(n);
              const auto du = increments_for(basis, n, combination.second,
                                             slip_at<dim>(ratio, eps), eps);
              const auto e = point_space_errors(law, basis, combination.second, du, lambda);
              eg           = std::max(eg, e.first);
              eh           = std::max(eh, e.second);
            }
        std::cout << dim << "D " << combination.first
                  << ": largest gradient error " << eg << ", Hessian error " << eh
                  << std::endl;
        out << dim << "D, " << combination.first
            << ", same slips: gradient in the displacements matches finite "
            << "differences: " << yes(eg < gradient_tolerance)
            << "; Hessian: " << yes(eh < hessian_tolerance) << std::endl;
      }
    // The normal part of an increment does not slip.
    const Tensor<1, dim> n     = random_unit<dim>();
    const auto           basis = tangent_basis(n);
    const auto           s     = FrictionLaw<dim>::slip(basis, {1.}, {2.5 * n});
    out << dim << "D: a normal increment gives no slip (|s| <= 1e-15 |du|): "
        << yes(s.norm() <= 1e-15 * 2.5) << std::endl;
  }

  template <int dim>
  void
  check_basis(std::ostream &out)
  {
    std::vector<Tensor<1, dim>> normals;
    for (unsigned int d = 0; d < dim; ++d)
      for (const double sign : {1., -1.})
        {
          Tensor<1, dim> e;
          e[d] = sign;
          normals.push_back(e);
        }
    if constexpr (dim == 3)
      {
        normals.push_back(Tensor<1, 3>({1e-9, 0., -1.}));
        normals.push_back(Tensor<1, 3>({1e-12, -1e-12, -1.}));
        normals.push_back(Tensor<1, 3>({-1e-12, 1e-12, 1.}));
      }
    for (unsigned int k = 0; k < 1000; ++k)
      normals.push_back(uniform(0.01, 100.) * random_unit<dim>());
    double worst = 0.;
    for (const auto &normal : normals)
      {
        const auto           T = tangent_basis(normal);
        const Tensor<1, dim> n = normal / normal.norm();
        for (unsigned int a = 0; a + 1 < dim; ++a)
          {
            worst = std::max(worst, std::abs(T.t[a] * n));
            for (unsigned int b = 0; b + 1 < dim; ++b)
              worst = std::max(worst, std::abs(T.t[a] * T.t[b] - (a == b ? 1. : 0.)));
          }
        if constexpr (dim == 2)
          worst = std::max(worst, std::abs(T.t[0][0] * n[1] - T.t[0][1] * n[0] - 1.));
        else
          worst = std::max(worst, (cross_product_3d(T.t[0], T.t[1]) - n).norm());
      }
    std::cout << dim << "D tangent basis: largest deviation " << worst << std::endl;
    out << dim << "D tangent basis of " << normals.size()
        << " normals (axes, near -e_z in 3D, random lengths): orthonormal, "
        << "normal to n and right-handed to 1e-14: " << yes(worst <= 1e-14)
        << std::endl;
    Tensor<1, dim> up;
    up[dim - 1]       = 1.;
    const auto T      = tangent_basis(up);
    bool       axes   = T.t[0][0] == 1. && T.t[0][1] == 0.;
    if constexpr (dim == 3)
      axes = axes && T.t[1][1] == 1. && T.t[1][0] == 0. && T.t[0][2] == 0. &&
             T.t[1][2] == 0.;
    out << dim << "D: the upward normal gives the coordinate axes as tangents: "
        << yes(axes) << std::endl;
    bool thrown = false;
    try
      {
        tangent_basis(Tensor<1, dim>());
      }
    catch (const std::invalid_argument &)
      {
        thrown = true;
      }
    out << dim << "D: a zero normal throws: " << yes(thrown) << std::endl;
  }

  template <int dim>
  double
  max_entry(const Tensor<2, dim - 1> &A)
  {
    double m = 0.;
    for (unsigned int a = 0; a + 1 < dim; ++a)
      for (unsigned int b = 0; b + 1 < dim; ++b)
        m = std::max(m, std::abs(A[a][b]));
    return m;
  }

  template <int dim>
  void
  check_limits(std::ostream &out)
  {
    const double           mu = 0.6, lambda = 4.2, eps = 1e-3;
    const FrictionLaw<dim> law(mu, eps);
    // |t_T| = mu lambda at and beyond eps.
    double worst = 0.;
    for (const double ratio : {1., 1. + 1e-12, 1.001, 2., 10., 1e6})
      for (unsigned int k = 0; k < 5; ++k)
        {
          const auto r = law.evaluate(slip_at<dim>(ratio, eps), lambda);
          worst        = std::max(worst, std::abs(r.traction.norm() - mu * lambda) / (mu * lambda));
        }
    std::cout << dim << "D: largest | |t_T| - mu lambda | / mu lambda beyond eps " << worst
              << std::endl;
    out << dim << "D: |t_T| = mu lambda within 1e-12 for |s|/eps = 1, 1 + 1e-12, "
        << "1.001, 2, 10, 1e6: " << yes(worst <= 1e-12) << std::endl;
    // Below eps the traction is below the Coulomb limit.
    bool below = true;
    for (const double ratio : {0., 0.1, 0.5, 0.9, 0.999999})
      below = below && law.evaluate(slip_at<dim>(ratio, eps), lambda).traction.norm() <
                         mu * lambda;
    out << dim << "D: |t_T| < mu lambda for |s| < eps: " << yes(below) << std::endl;

    // Jumps across [eps (1 - d), eps (1 + d)] along one direction: value
    // and gradient O(d) or smaller, Hessian 2 d (scaled by mu lambda
    // eps, mu lambda and mu lambda / eps).
    bool   continuous = true, lipschitz = true;
    double ratio_at_smallest = 0.;
    for (const double d : {1e-3, 1e-4, 1e-5, 1e-6})
      {
        const Tensor<1, dim - 1> e  = random_unit<dim - 1>();
        const auto               rm = law.evaluate((1. - d) * eps * e, lambda);
        const auto               rp = law.evaluate((1. + d) * eps * e, lambda);
        const double jv = std::abs(rp.value - rm.value) / (mu * lambda * eps);
        const double jg = (rp.traction - rm.traction).norm() / (mu * lambda);
        const double jh = max_entry<dim>(rp.stiffness - rm.stiffness) / (mu * lambda / eps);
        std::cout << dim << "D: jumps across eps (1 +- " << d << "): value " << jv
                  << ", gradient " << jg << ", Hessian " << jh << std::endl;
        continuous = continuous && jv <= 3. * d && jg <= 3. * d && jh <= 3. * d;
        ratio_at_smallest = jh / d;
        lipschitz = lipschitz && jh >= d; // the Hessian does jump at first order
      }
    out << dim << "D: value, gradient and Hessian continuous at |s| = eps "
        << "(jumps across eps (1 +- d) at most 3 d, d = 1e-3 ... 1e-6): "
        << yes(continuous) << std::endl;
    out << dim << "D: the Hessian's jump across eps (1 +- d) is 2 d to 1% "
        << "(f0''' jumps: C^2, not C^3): "
        << yes(lipschitz && std::abs(ratio_at_smallest - 2.) <= 0.02) << std::endl;
    // At s = 0: D = mu lambda eps / 3, t_T = 0, Hessian (2 mu lambda /
    // eps) I, and the Hessian at |s| = d eps within 3 d of it.
    const auto   r0 = law.evaluate(Tensor<1, dim - 1>(), lambda);
    bool         at_zero =
      std::abs(r0.value - mu * lambda * eps / 3.) <= 1e-15 * mu * lambda * eps &&
      r0.traction.norm() == 0.;
    Tensor<2, dim - 1> stick;
    for (unsigned int a = 0; a + 1 < dim; ++a)
      stick[a][a] = 2. * mu * lambda / eps;
    at_zero = at_zero && max_entry<dim>(r0.stiffness - stick) <= 1e-15 * mu * lambda / eps;
    bool near_zero = true;
    for (const double d : {1e-3, 1e-6, 1e-9})
      {
        const auto r = law.evaluate(d * eps * random_unit<dim - 1>(), lambda);
        near_zero = near_zero && max_entry<dim>(r.stiffness - stick) <= 3. * d * mu * lambda / eps;
      }
    out << dim << "D: at s = 0, D = mu lambda eps/3, t_T = 0, Hessian = "
        << "(2 mu lambda/eps) I (the stick stiffness): " << yes(at_zero)
        << "; Hessian within 3 d of it at |s| = d eps: " << yes(near_zero) << std::endl;
  }

  template <int dim>
  double
  smallest_eigenvalue(const Tensor<2, dim - 1> &A)
  {
    if constexpr (dim == 2)
      return A[0][0];
    else
      {
        const double m = 0.5 * (A[0][0] + A[1][1]);
        const double r = std::hypot(0.5 * (A[0][0] - A[1][1]), A[0][1]);
        return m - r;
      }
  }

  template <int dim>
  void
  check_convexity(std::ostream &out)
  {
    const double           mu = 0.8, lambda = 1.9, eps = 1e-3;
    const FrictionLaw<dim> law(mu, eps);
    double                 worst = 0.; // most negative eigenvalue / scale
    bool                   symmetric = true;
    for (unsigned int k = 0; k < 2000; ++k)
      {
        const double ratio = (k == 0 ? 0. : std::pow(10., uniform(-6., 3.)));
        const auto   r     = law.evaluate(slip_at<dim>(ratio, eps), lambda);
        const double scale = mu * lambda / std::max(ratio * eps, eps);
        worst = std::min(worst, smallest_eigenvalue<dim>(r.stiffness) / scale);
        if constexpr (dim == 3)
          symmetric = symmetric && r.stiffness[0][1] == r.stiffness[1][0];
      }
    std::cout << dim << "D: most negative Hessian eigenvalue / scale " << worst << std::endl;
    out << dim << "D: Hessian positive semidefinite (and symmetric) at 2000 slips, "
        << "|s|/eps in 0 and [1e-6, 1e3]: " << yes(worst >= -1e-14 && symmetric)
        << std::endl;
    bool midpoint = true;
    for (unsigned int k = 0; k < 2000; ++k)
      {
        const auto a = slip_at<dim>(uniform(0., 3.), eps);
        const auto b = slip_at<dim>(uniform(0., 3.), eps);
        const double da = law.value(a, lambda), db = law.value(b, lambda);
        midpoint = midpoint &&
                   law.value(0.5 * (a + b), lambda) <= 0.5 * (da + db) + 1e-15 * (da + db);
      }
    out << dim << "D: D((a + b)/2) <= (D(a) + D(b))/2 at 2000 random pairs, "
        << "|a|, |b| <= 3 eps: " << yes(midpoint) << std::endl;
  }

  template <int dim>
  void
  check_zero_and_status(std::ostream &out)
  {
    const double eps = 1e-3;
    bool         zero = true;
    for (const auto &ml : std::vector<std::pair<double, double>>{{0., 5.}, {0., 1e30}, {0.7, 0.}})
      {
        const FrictionLaw<dim> law(ml.first, eps);
        for (const double ratio : {0., 0.5, 1., 1e30})
          {
            const auto s = slip_at<dim>(ratio, eps);
            const auto r = law.evaluate(s, ml.second);
            zero         = zero && r.value == 0. && r.traction.norm() == 0. &&
                   max_entry<dim>(r.stiffness) == 0. && law.value(s, ml.second) == 0.;
            const Tensor<1, dim> n     = random_unit<dim>();
            const auto           basis = tangent_basis(n);
            Vector<double>       g;
            FullMatrix<double>   H;
            const auto du = increments_for(basis, n, {1., -1.}, s, eps);
            zero = zero && law.evaluate_pair(basis, du[0], du[1], ml.second, &g, &H) == 0. &&
                   g.linfty_norm() == 0. && H.linfty_norm() == 0.;
          }
      }
    out << dim << "D: mu = 0 (or lambda = 0) gives exactly zero value, traction "
        << "and Hessian, also for |s| = 1e30 eps and lambda = 1e30: " << yes(zero)
        << std::endl;

    const FrictionLaw<dim> law(0.5, eps);
    const Tensor<1, dim - 1> e = random_unit<dim - 1>();
    Tensor<1, dim - 1>       exactly_eps;
    exactly_eps[0] = eps; // |s| = eps without round-off
    const bool status =
      law.status(e * 0.5 * eps, 0.) == FrictionStatus::open &&
      law.status(Tensor<1, dim - 1>(), 2.) == FrictionStatus::stick &&
      law.status(e * (1. - 1e-12) * eps, 2.) == FrictionStatus::stick &&
      law.status(exactly_eps, 2.) == FrictionStatus::slip &&
      law.status(e * 2. * eps, 2.) == FrictionStatus::slip;
    out << dim << "D: status open for lambda = 0, stick for |s| < eps, slip for "
        << "|s| >= eps: " << yes(status) << std::endl;
    Tensor<1, dim - 1> s;
    s[0] = 1.5 * eps;
    if constexpr (dim == 3)
      s[1] = 2. * eps; // |s| = 2.5 eps
    const double expected = 0.5 * 3. * (dim == 3 ? 2.5 : 1.5) * eps;
    out << dim << "D: dissipated energy = mu lambda |s| (not smoothed): "
        << yes(std::abs(law.dissipated_energy(s, 3.) - expected) <= 1e-15 * expected)
        << std::endl;
  }

  template <class F>
  bool
  throws_invalid(const F &f)
  {
    try
      {
        f();
      }
    catch (const std::invalid_argument &)
      {
        return true;
      }
    return false;
  }

  void
  check_invalid_arguments(std::ostream &out)
  {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const bool   ok  = throws_invalid([] { FrictionLaw<2>(-0.1, 1e-3); }) &&
                    throws_invalid([&] { FrictionLaw<2>(nan, 1e-3); }) &&
                    throws_invalid([&] { FrictionLaw<3>(inf, 1e-3); }) &&
                    throws_invalid([] { FrictionLaw<3>(0.3, 0.); }) &&
                    throws_invalid([] { FrictionLaw<2>(0.3, -1e-3); }) &&
                    throws_invalid([&] { FrictionLaw<3>(0.3, inf); }) &&
                    throws_invalid([] { FrictionLaw<2>(0.3, 1e-3).value(Tensor<1, 1>(), -1.); }) &&
                    throws_invalid([&] { FrictionLaw<3>(0.3, 1e-3).evaluate(Tensor<1, 2>(), nan); }) &&
                    throws_invalid([] {
                      FrictionLaw<2>::slip(tangent_basis(Tensor<1, 2>({0., 1.})), {1., -1.},
                                           {Tensor<1, 2>()});
                    });
    out << "a negative or non-finite mu, eps <= 0 or non-finite, a negative or "
        << "non-finite normal force and mismatched point lists throw "
        << "std::invalid_argument: " << yes(ok) << std::endl;
  }

  /// A ParameterHandler with "Contact > Friction" declared and the given
  /// entries set (inside the subsection), and the parsed struct.
  FrictionParameters
  parse(const std::vector<std::pair<std::string, std::string>> &entries)
  {
    ParameterHandler prm;
    prm.enter_subsection("Contact");
    prm.enter_subsection("Friction");
    FrictionParameters::declare_parameters(prm);
    for (const auto &e : entries)
      prm.set(e.first, e.second);
    FrictionParameters p;
    p.parse_parameters(prm);
    prm.leave_subsection();
    prm.leave_subsection();
    return p;
  }

  /// Whether @p f throws an InputError whose message starts with
  /// "Contact > Friction > KEY:".
  bool
  names_key(const std::function<void()> &f, const std::string &key)
  {
    try
      {
        f();
      }
    catch (const InputError &e)
      {
        return std::string(e.what()).rfind("Contact > Friction > " + key + ":", 0) == 0;
      }
    return false;
  }

  void
  check_parameters(std::ostream &out)
  {
    const FrictionParameters d = parse({});
    out << "defaults: Coefficient 0 (friction inactive), Slip length 1e-4 "
        << "(of h), Outer tolerance 1e-6, Maximum outer iterations 10: "
        << yes(d.coefficient == 0. && !d.active() && d.slip_length == 1e-4 &&
               d.outer_tolerance == 1e-6 && d.max_outer_iterations == 10)
        << std::endl;
    const FrictionParameters p = parse({{"Coefficient", "0.3"},
                                        {"Slip length", "1e-3"},
                                        {"Outer tolerance", "1e-8"},
                                        {"Maximum outer iterations", "4"}});
    out << "Coefficient 0.3, Slip length 1e-3, Outer tolerance 1e-8, Maximum "
        << "outer iterations 4: parsed, active, eps = 1e-3 h: "
        << yes(p.coefficient == 0.3 && p.active() && p.outer_tolerance == 1e-8 &&
               p.max_outer_iterations == 4 &&
               std::abs(p.slip_length_at(0.02) - 2e-5) <= 1e-20)
        << std::endl;

    const std::vector<std::pair<std::string, std::string>> bad = {
      {"Coefficient", "-0.1"},
      {"Slip length", "0"},
      {"Slip length", "-1e-4"},
      {"Outer tolerance", "0"},
      {"Outer tolerance", "-1e-6"},
      {"Maximum outer iterations", "0"},
      {"Maximum outer iterations", "-2"}};
    for (const auto &b : bad)
      out << b.first << " = " << b.second << ": InputError naming 'Contact > "
          << "Friction > " << b.first << "': "
          << yes(names_key([&] { parse({b}); }, b.first)) << std::endl;

    // Non-finite values cannot come through the file's number pattern;
    // check() refuses them in the struct.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const std::vector<std::pair<std::string, std::function<void(FrictionParameters &)>>>
      direct = {{"Coefficient", [&](FrictionParameters &q) { q.coefficient = nan; }},
                {"Coefficient", [&](FrictionParameters &q) { q.coefficient = inf; }},
                {"Slip length", [&](FrictionParameters &q) { q.slip_length = nan; }},
                {"Slip length", [&](FrictionParameters &q) { q.slip_length = inf; }},
                {"Outer tolerance", [&](FrictionParameters &q) { q.outer_tolerance = nan; }},
                {"Maximum outer iterations",
                 [&](FrictionParameters &q) { q.max_outer_iterations = 0; }}};
    bool all = true;
    for (const auto &c : direct)
      all = all && names_key(
                     [&] {
                       FrictionParameters q;
                       c.second(q);
                       q.check();
                     },
                     c.first);
    out << "check() on NaN and infinite coefficient, slip length and outer "
        << "tolerance, and on 0 outer iterations: each an InputError naming "
        << "its key: " << yes(all) << std::endl;

    // "nan" or "inf" in a file: refused by the pattern (the driver then
    // names the file and line) or, should a library read it, by check().
    bool refused = true;
    for (const std::string value : {"nan", "inf"})
      {
        bool this_refused = false;
        try
          {
            parse({{"Coefficient", value}});
          }
        catch (const InputError &e)
          {
            this_refused = names_key([&] { throw e; }, "Coefficient");
          }
        catch (const std::exception &)
          {
            this_refused = true; // the pattern's own exception
          }
        refused = refused && this_refused;
      }
    out << "Coefficient = nan or inf in a file is refused: " << yes(refused) << std::endl;
  }
} // namespace

int
main()
{
  std::ofstream out("output");
  check_slip_space<2>(out);
  check_slip_space<3>(out);
  check_point_space<2>(out);
  check_point_space<3>(out);
  check_basis<2>(out);
  check_basis<3>(out);
  check_limits<2>(out);
  check_limits<3>(out);
  check_convexity<2>(out);
  check_convexity<3>(out);
  check_zero_and_status<2>(out);
  check_zero_and_status<3>(out);
  check_invalid_arguments(out);
  check_parameters(out);
  return 0;
}
