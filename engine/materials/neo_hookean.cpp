// Compressible Neo-Hookean (Simo & Pister form), for rubber and large elastic strain:
//   W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2,   sigma = mu/J (B - I) + lambda ln J / J I,
// B = F F^T, J = det F. Plane strain: F_zz = 1. Plane stress: F_zz = s solves sigma_zz = 0,
//   g(s) = mu (s^2 - 1) + lambda ln(J2 s) = 0   (Newton from s = 1, step-limited; g'(1) = lambda + 2 mu > 0).
// Optional Kelvin-Voigt damping (tyre rubber): sigma += beta [lambda* tr(D) I + 2 mu D], beta = zeta / (pi f),
// lambda* the plane-stress modulus in plane stress; its power is dissipated.
#include <cmath>
#include <memory>
#include <vector>

#include "engine/common/parallel.hpp"
#include "engine/materials/material.hpp"
#include "engine/common/reduce.hpp"

namespace dmi {
namespace {

template <int D> class NeoHookean final : public Material<D> {
 public:
  NeoHookean(const MaterialConfig& c, Plane plane)
      : rho_(c.density), el_(c.youngs_modulus, c.poisson_ratio), plane_(plane),
        beta_(c.damping_ratio > 0 ? c.damping_ratio / (3.14159265358979323846 * c.damping_frequency) : 0.0) {
    lambda_v_ = plane == Plane::stress ? 2 * el_.lambda * el_.mu / (el_.lambda + 2 * el_.mu) : el_.lambda;
  }
  double density() const override { return rho_; }
  double wave_speed() const override { return el_.wave_speed(rho_, plane_); }
  double damping_time() const override { return beta_; }
  bool pointwise() const override { return beta_ == 0; }  // damped: dissipation is summed over the range
  bool viscous_coefficients(double& a, double& b) const override {
    a = beta_ * lambda_v_, b = beta_ * el_.mu;
    return beta_ > 0;
  }
  const std::vector<Mat<D>>* viscous_stress() const override { return &viscous_; }
  void set_implicit_viscosity(bool on) override { implicit_ = on; }
  void permute(const std::vector<Index>& perm) override { permute_array(power_, perm), permute_array(viscous_, perm); }
  double dissipated() const override { return dissipated_; }
  void save_state(StateWriter& w) const override { w.put(power_), w.put(viscous_), w.put(dissipated_); }
  void load_state(StateReader& r) override { r.get(power_), r.get(viscous_), r.get(dissipated_); }
  void attach(const Particles<D>& p, Index, Index) override {
    if (beta_ > 0) power_.resize(p.size(), 0.0), viscous_.resize(p.size(), Mat<D>::Zero());
  }

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

  void update(Particles<D>& p, Index begin, Index end, double dt) override {
    const double mu = el_.mu, lam = el_.lambda, beta = beta_, lamv = lambda_v_;
    parallel_for(begin, end, [&](Index i) {
      const Mat<D>& F = p.F[i];
      const double J2 = F.determinant();
      const double s = stretch_zz(J2);
      const double J = J2 * s, lnJ = std::log(J);
      p.stress[i] = (mu / J) * (F * F.transpose() - Mat<D>::Identity()) + (lam * lnJ / J) * Mat<D>::Identity();
      if constexpr (D == 2) p.stress_zz[i] = (mu / J) * (s * s - 1) + lam * lnJ / J;
      p.vol[i] = p.vol0[i] * J;
      if (beta > 0) {
        const Mat<D> Dm = 0.5 * (p.L[i] + p.L[i].transpose());
        const Mat<D> sv = beta * (lamv * Dm.trace() * Mat<D>::Identity() + 2 * mu * Dm);
        p.stress[i] += sv;
        viscous_[i] = sv;
        if constexpr (D == 2) if (plane_ == Plane::strain) p.stress_zz[i] += beta * lam * Dm.trace();
        power_[i] = sv.cwiseProduct(Dm).sum() * p.vol[i];
      }
    });
    if (beta > 0 && !implicit_) dissipated_ += dt * deterministic_sum(end - begin, [&](Index k) { return power_[begin + k]; });
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
  double beta_, lambda_v_;  // s, Pa
  std::vector<double> power_;
  std::vector<Mat<D>> viscous_;  // viscous stress of the last update (damped only), by particle index
  double dissipated_ = 0;
  bool implicit_ = false;  // dissipation counted by the implicit viscous solve
};

}  // namespace

template <int D> std::unique_ptr<Material<D>> make_neo_hookean(const MaterialConfig& c, Plane plane) {
  return std::make_unique<NeoHookean<D>>(c, plane);
}
template std::unique_ptr<Material<2>> make_neo_hookean<2>(const MaterialConfig&, Plane);
template std::unique_ptr<Material<3>> make_neo_hookean<3>(const MaterialConfig&, Plane);

}  // namespace dmi
