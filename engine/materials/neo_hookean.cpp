// Compressible Neo-Hookean (Simo & Pister form), for rubber and large elastic strain:
//   W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2,   sigma = mu/J (B - I) + lambda ln J / J I,
// B = F F^T, J = det F. Plane strain: F_zz = 1. Plane stress: F_zz = s solves sigma_zz = 0,
//   g(s) = mu (s^2 - 1) + lambda ln(J2 s) = 0   (Newton from s = 1, step-limited; g'(1) = lambda + 2 mu > 0).
#include <cmath>
#include <memory>

#include "engine/materials/material.hpp"

namespace dmi {
namespace {

template <int D> class NeoHookean final : public Material<D> {
 public:
  NeoHookean(const MaterialConfig& c, Plane plane) : rho_(c.density), el_(c.youngs_modulus, c.poisson_ratio), plane_(plane) {}
  double density() const override { return rho_; }
  double wave_speed() const override { return el_.wave_speed(rho_, plane_); }

  // Out-of-plane stretch F_zz for an in-plane Jacobian J2.
  double stretch_zz(double J2) const {
    if (D == 3 || plane_ != Plane::stress) return 1.0;
    double s = 1.0;
    for (int it = 0; it < 30; ++it) {
      const double g = el_.mu * (s * s - 1) + el_.lambda * std::log(J2 * s);
      const double dg = 2 * el_.mu * s + el_.lambda / s;
      const double ds = g / dg;
      s = std::max(s - ds, 0.5 * s);
      if (std::abs(ds) < 1e-14 * s) break;
    }
    return s;
  }

  void update(Particles<D>& p, Index begin, Index end, double /*dt*/) override {
    const double mu = el_.mu, lam = el_.lambda;
#pragma omp parallel for schedule(static) if (end - begin > kParallelMin)
    for (Index i = begin; i < end; ++i) {
      const Mat<D>& F = p.F[i];
      const double J2 = F.determinant();
      const double s = stretch_zz(J2);
      const double J = J2 * s, lnJ = std::log(J);
      p.stress[i] = (mu / J) * (F * F.transpose() - Mat<D>::Identity()) + (lam * lnJ / J) * Mat<D>::Identity();
      if constexpr (D == 2) p.stress_zz[i] = (mu / J) * (s * s - 1) + lam * lnJ / J;
      p.vol[i] = p.vol0[i] * J;
    }
  }

  double strain_energy(const Particles<D>& p, Index begin, Index end) const override {
    double e = 0;
    for (Index i = begin; i < end; ++i) {
      const Mat<D>& F = p.F[i];
      const double J2 = F.determinant(), s = stretch_zz(J2), lnJ = std::log(J2 * s);
      const double I1 = (F * F.transpose()).trace() + (D == 2 ? s * s : 0.0);
      e += p.vol0[i] * (0.5 * el_.mu * (I1 - 3) - el_.mu * lnJ + 0.5 * el_.lambda * lnJ * lnJ);
    }
    return e;
  }

 private:
  double rho_;
  Elastic el_;
  Plane plane_;
};

}  // namespace

template <int D> std::unique_ptr<Material<D>> make_neo_hookean(const MaterialConfig& c, Plane plane) {
  return std::make_unique<NeoHookean<D>>(c, plane);
}
template std::unique_ptr<Material<2>> make_neo_hookean<2>(const MaterialConfig&, Plane);
template std::unique_ptr<Material<3>> make_neo_hookean<3>(const MaterialConfig&, Plane);

}  // namespace dmi
