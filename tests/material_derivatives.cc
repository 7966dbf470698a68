// Finite-difference checks of every registered material law (every example
// of every entry of Material::registered_laws(), built from a
// ParameterHandler as a parameter file would): P = dpsi/dF and the tangent
// A = dP/dF at random deformation gradients with J > 0, in plane strain (2D)
// and 3D; zero stress at F = I; frame invariance psi(QF) = psi(F),
// P(QF) = Q P(F) (for the laws registered as frame invariant); major
// symmetry of A; the small-strain limit. The checker is also run on a
// deliberately corrupted tangent of every law and must reject it, so this
// test can fail. Then checks of the Gent law: psi against its formula, the
// domain (I1b - 3 < J_m, J > 0), the neo-Hookean limit J_m -> infinity and
// its Lame pair. Last, every law that gives its invariant derivatives in
// closed form is compared with the same law differentiated by Sacado (the
// registry's oracle) at moderate and large strains, and that comparison
// must reject a corrupted tangent too.

#include <signorini/material/gent.h>
#include <signorini/material/interface.h>
#include <signorini/material/invariant_based.h>
#include <signorini/material/laws.h>
#include <signorini/material/linear_elastic.h>
#include <signorini/material/registry.h>

#include <deal.II/base/symmetric_tensor.h>

#include <fstream>
#include <iostream>
#include <limits>
#include <random>

using namespace dealii;
using namespace Signorini;

namespace
{
  /// A material whose tangent is wrong by 1e-3 relative in one entry.
  class CorruptedTangent : public Material::Interface
  {
  public:
    explicit CorruptedTangent(const Material::Interface &base)
      : base(base)
    {}
    bool
    evaluate(const Tensor<2, 3> &F, Material::Response<3> &r, bool d) const override
    {
      const bool ok = base.evaluate(F, r, d);
      if (d)
        r.A[0][1][1][0] *= 1.001;
      return ok;
    }
    std::string
    name() const override
    {
      return "corrupted";
    }
    std::pair<double, double>
    small_strain_lame() const override
    {
      return base.small_strain_lame();
    }

  private:
    const Material::Interface &base;
  };

  template <int dim>
  Tensor<2, dim>
  random_F(std::mt19937 &rng, const double amplitude)
  {
    std::uniform_real_distribution<double> u(-amplitude, amplitude);
    for (;;)
      {
        Tensor<2, dim> F = unit_symmetric_tensor<dim>();
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            F[i][j] += u(rng);
        if (determinant(F) > 0.3)
          return F;
      }
  }

  /// Largest relative error of P and of A against central differences.
  template <int dim>
  std::pair<double, double>
  fd_errors(const Material::Interface &m, const Tensor<2, dim> &F)
  {
    Material::Response<dim> r, rp, rm;
    AssertThrow(Material::evaluate(m, F, r, true), ExcInternalError());
    const double h     = 1e-6;
    double       err_P = 0., err_A = 0., scale_P = 0., scale_A = 0.;
    for (unsigned int k = 0; k < dim; ++k)
      for (unsigned int l = 0; l < dim; ++l)
        {
          Tensor<2, dim> Fp = F, Fm = F;
          Fp[k][l] += h;
          Fm[k][l] -= h;
          Material::evaluate(m, Fp, rp, true);
          Material::evaluate(m, Fm, rm, true);
          const double dpsi = (rp.psi - rm.psi) / (2 * h);
          err_P   = std::max(err_P, std::abs(dpsi - r.P[k][l]));
          scale_P = std::max(scale_P, std::abs(r.P[k][l]));
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              {
                const double dP = (rp.P[i][j] - rm.P[i][j]) / (2 * h);
                err_A   = std::max(err_A, std::abs(dP - r.A[i][j][k][l]));
                scale_A = std::max(scale_A, std::abs(r.A[i][j][k][l]));
              }
        }
    return {err_P / std::max(scale_P, 1e-12), err_A / std::max(scale_A, 1e-12)};
  }

  template <int dim>
  Tensor<2, dim>
  rotation(const double angle)
  {
    Tensor<2, dim> Q = unit_symmetric_tensor<dim>();
    Q[0][0] = Q[1][1] = std::cos(angle);
    Q[0][1]           = -std::sin(angle);
    Q[1][0]           = std::sin(angle);
    if constexpr (dim == 3)
      {
        // and a second rotation about x
        Tensor<2, 3> R = unit_symmetric_tensor<3>();
        R[1][1] = R[2][2] = std::cos(0.7);
        R[1][2]           = -std::sin(0.7);
        R[2][1]           = std::sin(0.7);
        Q                 = R * Q;
      }
    return Q;
  }

  template <int dim>
  void
  check(const std::string         &label,
        const Material::Interface &m,
        const bool                 frame_invariant,
        std::ostream              &out)
  {
    std::mt19937 rng(42);
    double       worst_P = 0., worst_A = 0., worst_frame = 0., worst_sym = 0.;
    for (unsigned int sample = 0; sample < 20; ++sample)
      {
        const Tensor<2, dim> F = random_F<dim>(rng, 0.3);
        const auto           e = fd_errors<dim>(m, F);
        worst_P                = std::max(worst_P, e.first);
        worst_A                = std::max(worst_A, e.second);

        Material::Response<dim> r, rq;
        Material::evaluate(m, F, r, true);
        const Tensor<2, dim> Q = rotation<dim>(0.3 + sample);
        Material::evaluate(m, Tensor<2, dim>(Q * F), rq, true);
        const double scale = std::max(r.P.norm(), 1e-12);
        worst_frame = std::max(worst_frame, std::abs(rq.psi - r.psi) / std::max(std::abs(r.psi), 1e-12));
        worst_frame = std::max(worst_frame, (rq.P - Q * r.P).norm() / scale);
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            for (unsigned int k = 0; k < dim; ++k)
              for (unsigned int l = 0; l < dim; ++l)
                worst_sym = std::max(worst_sym,
                                     std::abs(r.A[i][j][k][l] - r.A[k][l][i][j]) /
                                       std::max(r.A.norm(), 1e-12));
      }
    Material::Response<dim> r0;
    Material::evaluate(m, Tensor<2, dim>(unit_symmetric_tensor<dim>()), r0, true);
    const bool frame_ok = !frame_invariant || worst_frame < 1e-12;
    out << dim << "D " << label << ": P vs FD " << (worst_P < 1e-6 ? "ok" : "FAIL")
        << ", A vs FD " << (worst_A < 1e-6 ? "ok" : "FAIL")
        << ", zero stress at F = I " << (r0.P.norm() < 1e-12 && std::abs(r0.psi) < 1e-12 ? "ok" : "FAIL")
        << ", frame invariance " << (frame_ok ? "ok" : "FAIL")
        << ", major symmetry " << (worst_sym < 1e-13 ? "ok" : "FAIL") << "\n";
    if (worst_P >= 1e-6 || worst_A >= 1e-6)
      std::cerr << label << ": FD errors " << worst_P << " " << worst_A << "\n";
  }

  /// The material of @p model with the entries @p settings (others default).
  std::unique_ptr<Material::Interface>
  make_material(const std::string                                      &model,
                const std::vector<std::pair<std::string, std::string>> &settings)
  {
    ParameterHandler prm;
    Material::declare_parameters(prm);
    prm.set("Model", model);
    for (const auto &[key, value] : settings)
      prm.set(key, value);
    return Material::create(prm, "test");
  }

  /// Largest relative difference of psi, P and A of two materials over
  /// random deformation gradients.
  double
  difference(const Material::Interface &a, const Material::Interface &b)
  {
    std::mt19937 rng(7);
    double       worst = 0.;
    for (unsigned int sample = 0; sample < 20; ++sample)
      {
        const Tensor<2, 3>    F = random_F<3>(rng, 0.2);
        Material::Response<3> ra, rb;
        AssertThrow(a.evaluate(F, ra, true) && b.evaluate(F, rb, true),
                    ExcInternalError());
        worst = std::max({worst,
                          std::abs(ra.psi - rb.psi) / std::abs(rb.psi),
                          (ra.P - rb.P).norm() / rb.P.norm(),
                          (ra.A - rb.A).norm() / rb.A.norm()});
      }
    return worst;
  }

  /// Deformation gradients for the oracle comparison: random ones with
  /// entries of F - I up to 0.3 and large strains (stretch to 2.2,
  /// compression to 0.35, simple shear of 1.5, a rotated stretch).
  template <int dim>
  std::vector<Tensor<2, dim>>
  oracle_samples()
  {
    std::mt19937                rng(11);
    std::vector<Tensor<2, dim>> samples;
    for (unsigned int k = 0; k < 10; ++k)
      samples.push_back(random_F<dim>(rng, 0.3));
    Tensor<2, dim> F = unit_symmetric_tensor<dim>();
    F[0][0]          = 2.2;
    F[1][1]          = 0.8;
    samples.push_back(F);
    F       = unit_symmetric_tensor<dim>();
    F[0][0] = 0.35;
    F[1][1] = 0.6;
    samples.push_back(F);
    F       = unit_symmetric_tensor<dim>();
    F[0][1] = 1.5;
    samples.push_back(F);
    F       = unit_symmetric_tensor<dim>();
    F[0][0] = 1.7;
    F[1][1] = 1.0 / 1.7;
    samples.push_back(Tensor<2, dim>(rotation<dim>(0.4) * F));
    return samples;
  }

  /// Largest relative difference of psi, P and A of a law against its
  /// Sacado oracle over oracle_samples(); a difference in admissibility
  /// counts as infinite. @p n_compared receives the number of samples at
  /// which both are defined.
  template <int dim>
  double
  oracle_difference(const Material::Interface &law,
                    const Material::Interface &oracle,
                    unsigned int              &n_compared)
  {
    double worst = 0.;
    n_compared   = 0;
    for (const Tensor<2, dim> &F : oracle_samples<dim>())
      {
        Material::Response<dim> r, ro;
        const bool              ok  = Material::evaluate(law, F, r, true);
        const bool              oko = Material::evaluate(oracle, F, ro, true);
        if (ok != oko)
          return std::numeric_limits<double>::infinity();
        if (!ok)
          continue;
        ++n_compared;
        worst = std::max({worst,
                          std::abs(r.psi - ro.psi) /
                            std::max(std::abs(ro.psi), 1e-300),
                          (r.P - ro.P).norm() / std::max(ro.P.norm(), 1e-300),
                          (r.A - ro.A).norm() / ro.A.norm()});
        // The value alone (the line search's evaluation) as well.
        Material::Response<dim> v;
        Material::evaluate(law, F, v, false);
        worst = std::max(worst,
                         std::abs(v.psi - ro.psi) /
                           std::max(std::abs(ro.psi), 1e-300));
      }
    return worst;
  }

  void
  check_gent(std::ostream &out)
  {
    using namespace Material;
    const double E = 3.0, nu = 0.3, J_m = 2.;
    const double mu = E / (2 * (1 + nu)), K = E / (3 * (1 - 2 * nu));
    const auto   gent = make_material("Gent",
                                    {{"Young's modulus", "3"},
                                       {"Poisson's ratio", "0.3"},
                                       {"Gent limiting extensibility", "2"}});

    // psi against its formula, evaluated here from F directly.
    std::mt19937 rng(3);
    double       worst_psi = 0., largest_x = 0.;
    for (unsigned int sample = 0; sample < 20; ++sample)
      {
        const Tensor<2, 3> F  = random_F<3>(rng, 0.3);
        const double       J  = determinant(F);
        const double       x  = std::pow(J, -2. / 3.) * scalar_product(F, F) - 3.;
        const double       psi = -0.5 * mu * J_m * std::log(1. - x / J_m) +
                           0.5 * K * (J - 1.) * (J - 1.);
        Response<3> r;
        AssertThrow(gent->evaluate(F, r, false), ExcInternalError());
        worst_psi = std::max(worst_psi, std::abs(r.psi - psi) / std::abs(psi));
        largest_x = std::max(largest_x, x);
      }
    out << "Gent: psi equals -mu J_m/2 ln(1 - (I1b - 3)/J_m) + K/2 (J - 1)^2: "
        << (worst_psi < 1e-13 ? "ok" : "FAIL") << "\n";
    std::cerr << "Gent: psi against the formula " << worst_psi
              << ", largest (I1b - 3)/J_m of the samples " << largest_x / J_m << "\n";

    // The domain: I1b - 3 < J_m and J > 0. An isochoric stretch
    // diag(s, 1/s, 1) has I1b - 3 = s^2 + 1/s^2 - 2 = (s - 1/s)^2, which
    // equals J_m at s = (sqrt(J_m) + sqrt(J_m + 4))/2; and its dilation by
    // c^(1/3) in 3D leaves I1b unchanged.
    const double s_lock = 0.5 * (std::sqrt(J_m) + std::sqrt(J_m + 4.));
    auto         stretch = [](const double s, const double c) {
      Tensor<2, 3> F;
      F[0][0] = std::cbrt(c) * s;
      F[1][1] = std::cbrt(c) / s;
      F[2][2] = std::cbrt(c);
      return F;
    };
    Response<3> r;
    const bool  inside = gent->evaluate(stretch(s_lock * (1. - 1e-9), 1.3), r, true);
    const bool  inside_finite = inside && std::isfinite(r.psi) && r.psi > 1.;
    const bool  at_lock       = gent->evaluate(stretch(s_lock, 1.), r, true);
    const bool  beyond        = gent->evaluate(stretch(1.01 * s_lock, 0.7), r, true);
    Tensor<2, 3> inverted = unit_symmetric_tensor<3>();
    inverted[0][0]        = -1.;
    const bool   negative_J = gent->evaluate(inverted, r, true);
    Tensor<2, 2> flat;
    flat[0][0] = 1.;
    Response<2> r2;
    const bool  zero_J_2d = evaluate<2>(*gent, flat, r2, true);
    out << "Gent: admissible just inside I1b - 3 = J_m (psi finite and large): "
        << (inside_finite ? "ok" : "FAIL")
        << "; inadmissible at and beyond it, and for J <= 0 (3D, 2D): "
        << (!at_lock && !beyond && !negative_J && !zero_J_2d ? "ok" : "FAIL") << "\n";

    // J_m -> infinity: the isochoric neo-Hookean (ELAS_HYPER with
    // C10 = mu/2, K), with a difference of order 1/J_m.
    const InvariantLaw<ElasHyperLaw> neo(ElasHyperLaw{mu / 2., 0., 0., K, true});
    const double d3 = difference(InvariantLaw<GentLaw>(GentLaw{mu, K, 1e3}), neo);
    const double d6 = difference(InvariantLaw<GentLaw>(GentLaw{mu, K, 1e6}), neo);
    out << "Gent: tends to the isochoric neo-Hookean as J_m -> infinity, as 1/J_m: "
        << (d6 < 1e-6 && d3 / d6 > 900. && d3 / d6 < 1100. ? "ok" : "FAIL") << "\n";
    std::cerr << "Gent: relative difference to the isochoric neo-Hookean at J_m = 1e3: "
              << d3 << ", 1e6: " << d6 << "\n";

    // The small-strain Lame pair is that of E and nu.
    const auto lame = gent->small_strain_lame();
    out << "Gent: small-strain Lame pair (mu, lambda) of E and nu: "
        << (std::abs(lame.first - mu) < 1e-14 * mu &&
                std::abs(lame.second - E * nu / ((1 + nu) * (1 - 2 * nu))) < 1e-14 * mu ?
              "ok" :
              "FAIL")
        << "\n";
  }
} // namespace

int
main()
{
  std::ofstream out("output");

  // Every example of every registered law.
  struct Case
  {
    std::string                          label;
    std::unique_ptr<Material::Interface> material;
    bool                                 frame_invariant;
    // Incompressible = true: the law without its volumetric term.
    bool isochoric;
  };
  std::vector<Case> cases;
  for (const auto &law : Material::registered_laws())
    for (const auto &example : law.examples)
      {
        auto material = make_material(law.name, example.settings);
        const std::string label =
          example.label.empty() ? material->name() : example.label;
        bool isochoric = false;
        for (const auto &[key, value] : example.settings)
          isochoric = isochoric || (key == "Incompressible" && value == "true");
        cases.push_back(
          {label, std::move(material), law.frame_invariant, isochoric});
      }

  for (const auto &c : cases)
    {
      check<2>(c.label, *c.material, c.frame_invariant, out);
      check<3>(c.label, *c.material, c.frame_invariant, out);
    }

  // The small-strain limit of every finite-strain law is linear elasticity
  // with its Lamé constants: compare the tangents at F = I. A law without
  // its volumetric term (Incompressible = true, J = 1 imposed by the
  // solver) has bulk modulus 0 at F = I, i.e. lambda = -2 mu/3; its
  // small_strain_lame() does not describe that tangent (it keeps the
  // default K = 1 of ElasHyperLaw).
  for (const auto &c : cases)
    {
      auto lame = c.material->small_strain_lame();
      if (c.isochoric)
        lame.second = -2. * lame.first / 3.;
      Material::LinearElastic reference(lame.first, lame.second);
      Material::Response<3>   a, b;
      const Tensor<2, 3>      I = unit_symmetric_tensor<3>();
      c.material->evaluate(I, a, true);
      reference.evaluate(I, b, true);
      out << c.label << ": tangent at F = I equals the linear one with its "
          << "Lame constants: " << ((a.A - b.A).norm() < 1e-10 * b.A.norm() ? "ok" : "FAIL")
          << "\n";
    }

  // The stress alone (first_piola, the output's Cauchy stress) is the P of
  // the full evaluation, to the last bit, and is refused where it is.
  for (const auto &c : cases)
    {
      bool same = true;
      for (const Tensor<2, 3> &F : oracle_samples<3>())
        {
          Material::Response<3> full;
          Tensor<2, 3>          P;
          const bool            ok_full = c.material->evaluate(F, full, true);
          const bool            ok_P    = c.material->first_piola(F, P);
          same = same && ok_full == ok_P && (!ok_full || P == full.P);
        }
      Tensor<2, 3> inverted = unit_symmetric_tensor<3>(), P;
      inverted[0][0]        = -1.;
      const bool refused    = !c.material->first_piola(inverted, P) ||
                           c.material->name().find("linear") != std::string::npos;
      out << c.label << ": stress alone equals the P of the full evaluation: "
          << (same ? "ok" : "FAIL") << ", J < 0 refused: " << (refused ? "ok" : "FAIL")
          << "\n";
    }

  // The checker must catch a tangent that is off by 1e-3 in one entry, for
  // every law.
  bool all_detected = true;
  for (const auto &c : cases)
    {
      CorruptedTangent corrupted(*c.material);
      std::mt19937     rng(1);
      const auto       e = fd_errors<3>(corrupted, random_F<3>(rng, 0.2));
      all_detected       = all_detected && e.second > 1e-6;
      std::cerr << c.label << ": relative tangent error of the corrupted law "
                << e.second << "\n";
    }
  out << "corrupted tangent detected: " << (all_detected ? "yes" : "NO") << "\n";

  // Every law with closed-form invariant derivatives against the same law
  // differentiated by Sacado (its registered oracle): psi, P and A, 2D and
  // 3D, at moderate and large strains. The comparison must also reject
  // a tangent corrupted by 1e-3 in one entry.
  const double oracle_tolerance = 1e-12;
  bool         corrupted_rejected = true;
  for (const auto &law : Material::registered_laws())
    {
      if (!law.create_automatic)
        {
          out << law.name << ": not written in invariants (no Sacado "
              << "oracle; checked by finite differences above)\n";
          continue;
        }
      for (const auto &example : law.examples)
        {
          ParameterHandler prm;
          Material::declare_parameters(prm);
          prm.set("Model", law.name);
          for (const auto &[key, value] : example.settings)
            prm.set(key, value);
          const auto closed = law.create(prm, "test");
          const auto oracle = law.create_automatic(prm, "test");
          const std::string label =
            example.label.empty() ? closed->name() : example.label;
          unsigned int n2 = 0, n3 = 0;
          const double d2 = oracle_difference<2>(*closed, *oracle, n2);
          const double d3 = oracle_difference<3>(*closed, *oracle, n3);
          out << label << ": closed form equals the Sacado oracle (psi, P, A"
              << ") in 2D at " << n2 << " and 3D at " << n3
              << " deformations: "
              << (d2 < oracle_tolerance && d3 < oracle_tolerance ? "ok" :
                                                                   "FAIL")
              << "\n";
          std::cerr << label << ": closed form against Sacado, largest "
                    << "relative difference 2D " << d2 << ", 3D " << d3
                    << "\n";
          CorruptedTangent corrupted(*closed);
          unsigned int     n = 0;
          corrupted_rejected =
            corrupted_rejected &&
            oracle_difference<3>(corrupted, *oracle, n) > oracle_tolerance;
        }
    }
  out << "corrupted closed-form tangent rejected by the oracle comparison: "
      << (corrupted_rejected ? "yes" : "NO") << "\n";

  check_gent(out);
}
