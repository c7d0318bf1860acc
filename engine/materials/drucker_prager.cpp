// Drucker-Prager, elastic-perfectly plastic, small strain with the Jaumann rate (granular debris).
// Stresses tension positive; p = tr(sigma)/3, s = dev(sigma), q = sqrt(J2) = sqrt(s:s/2).
//   yield     f = q + alpha p - k <= 0,       flow potential g = q + alpha_psi p (non-associated, psi <= phi)
//   plane-strain match to Mohr-Coulomb (c, phi):  alpha = 3 tan(phi) / sqrt(9 + 12 tan^2(phi)),
//                                                   k = 3 c / sqrt(9 + 12 tan^2(phi))       (same for psi)
//   return (de Souza Neto, Peric & Owen 2008, sec. 8.3.3): from the elastic trial state,
//     dgamma = f_tr / (G + K alpha alpha_psi),  q = q_tr - G dgamma,  p = p_tr - K alpha_psi dgamma;
//     if q would be < 0 the state returns to the apex: s = 0, p = k / alpha.
// The full 3D stress is updated (sigma_zz kept in plane strain; plane stress is refused by the parser).
// Dissipated power per particle: sigma : d_eps_p with d_eps_p = C^-1 (sigma_tr - sigma) (exact for any return).
// Stored energy: the elastic complementary energy of the stress, as for linear elasticity.
// mu_i (the same elastic predictor; Dunatunga & Kamrin 2015's elastic-viscoplastic form of the mu(I) rheology):
//   yield q = mu(I) P, P = -p >= 0 the pressure, mu(I) = mu_s + (mu_2 - mu_s) / (I0 / I + 1) (Jop, Forterre &
//   Pouliquen 2006; below I_N1 Barker & Gray's 2017 partial regularisation, mu_of_i.hpp), I = gamma_dot_p d / sqrt(P / rho_s),
//   with the plastic shear rate
//   gamma_dot_p = dgamma / dt (dgamma = sqrt(2 de_p' : de_p'), the engineering shear in simple shear).
//   Return at constant pressure (no dilatancy): q = q_tr - G dgamma, dgamma the root of
//   f(dgamma) = q_tr - G dgamma - mu(dgamma / dt) P, strictly decreasing from f(0) = q_tr - mu(0) P > 0 to
//   f(q_tr / G) < 0 (bracketed Newton); regularised, mu(0) = 0 and every sheared state creeps. The rate dependence is implicit, so it does not bound the step; as
//   dt -> 0 at a fixed rate the law tends to the rigid-viscoplastic mu(I) fluid. P <= 0: stress free (separated).
#include <cmath>
#include <memory>
#include <vector>

#include "engine/common/parallel.hpp"
#include "engine/materials/material.hpp"
#include "engine/materials/mu_of_i.hpp"
#include "engine/common/reduce.hpp"

namespace dmi {
namespace {

using Mat3 = Eigen::Matrix3d;

template <int D> class DruckerPrager final : public Material<D> {
 public:
  DruckerPrager(const MaterialConfig& c, Plane plane) : rho_(c.density), el_(c.youngs_modulus, c.poisson_ratio), plane_(plane) {
    K_ = el_.lambda + 2 * el_.mu / 3;
    if (c.model == "mu_i") {
      mu_i_ = true, d_ = c.grain_diameter, rho_s_ = c.grain_density;
      law_.mu_s = c.mu_s, law_.mu_2 = c.mu_2, law_.I0 = c.inertial_I0;
      law_.regularise(c.regularisation_alpha);
      return;  // alpha_psi_ = k_ = 0: no dilatancy, no cohesion
    }
    const double deg = 3.14159265358979323846 / 180;
    auto match = [](double angle) { const double t = std::tan(angle); return 3 / std::sqrt(9 + 12 * t * t); };
    alpha_ = match(c.friction_angle * deg) * std::tan(c.friction_angle * deg);
    alpha_psi_ = match(c.dilation_angle * deg) * std::tan(c.dilation_angle * deg);
    k_ = match(c.friction_angle * deg) * c.cohesion;
  }
  double density() const override { return rho_; }
  double wave_speed() const override { return el_.wave_speed(rho_, plane_); }
  void permute(const std::vector<Index>& perm) override { permute_array(power_, perm); }
  double dissipated() const override { return dissipated_; }
  void save_state(StateWriter& w) const override { w.put(power_), w.put(dissipated_); }
  void load_state(StateReader& r) override { r.get(power_), r.get(dissipated_); }
  void attach(const Particles<D>& p, Index, Index) override { power_.resize(p.size(), 0.0); }

  // The stress is integrated from rates: a state inside the yield surface may be the initial one.
  bool prestress(Particles<D>& p, Index i, const Mat<3>& sigma) override {
    p.stress[i] = sigma.template topLeftCorner<D, D>();
    if constexpr (D == 2) p.stress_zz[i] = sigma(2, 2);
    return true;
  }

  // Full 3D stress of a particle, and back.
  static Mat3 full(const Particles<D>& p, Index i) {
    Mat3 s = Mat3::Zero();
    s.template topLeftCorner<D, D>() = p.stress[i];
    if constexpr (D == 2) s(2, 2) = p.stress_zz[i];
    return s;
  }

  // The mu_i plastic shear increment: the root of q - G dg - mu(I(dg / dt)) P on [0, q / G] (bracketed Newton);
  // I = (dg / dt) d / sqrt(P / rho_s).
  double mu_i_increment(double q, double P, double dt) const {
    const double G = el_.mu, scale = d_ / (dt * std::sqrt(P / rho_s_));  // I per unit dg
    double lo = 0, hi = q / G, x = std::clamp((q - law_.mu_s * P) / G, 0.0, hi);
    for (int it = 0; it < 100; ++it) {
      const double f = q - G * x - law_.mu(x * scale) * P;
      if (f > 0) lo = x; else hi = x;
      double next = x + f / (G + law_.slope(x * scale) * scale * P);
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      if (std::abs(next - x) <= 1e-14 * (q / G) || hi - lo <= 1e-15 * (q / G)) return next;
      x = next;
    }
    return x;
  }

  // Returns sigma onto the yield surface; the plastic strain increment's work sigma : C^-1 (tr - sigma).
  double return_map(Mat3& s, double dt) const {
    const double G = el_.mu, K = K_;
    const double p = s.trace() / 3;
    const Mat3 dev = s - p * Mat3::Identity();
    const double q = std::sqrt(0.5 * dev.squaredNorm());
    const Mat3 trial = s;
    if (mu_i_) {
      if (p >= 0) {  // no pressure: the grains separate
        s.setZero();
      } else {
        if (q <= 0 || (law_.I_N1 == 0 && q - law_.mu_s * (-p) <= 0)) return 0.0;  // regularised: no rigid range
        const double dg = mu_i_increment(q, -p, dt);
        s = (q > 0 ? std::max(q - G * dg, 0.0) / q : 0.0) * dev + p * Mat3::Identity();
      }
    } else {
      const double f = q + alpha_ * p - k_;
      if (f <= 0) return 0.0;
      const double dg = f / (G + K * alpha_ * alpha_psi_);
      if (q - G * dg >= 0) {
        s = (q > 0 ? (q - G * dg) / q : 0.0) * dev + (p - K * alpha_psi_ * dg) * Mat3::Identity();
      } else {  // apex (cohesionless: p = 0 and no stress)
        s = (alpha_ > 0 ? k_ / alpha_ : p) * Mat3::Identity();
      }
    }
    const Mat3 d = trial - s;  // C^-1 d = dev(d) / 2G + tr(d) / 9K I
    const double trd = d.trace();
    const Mat3 eps_p = (d - trd / 3 * Mat3::Identity()) / (2 * G) + trd / (9 * K) * Mat3::Identity();
    return (s.cwiseProduct(eps_p)).sum();
  }

  void update(Particles<D>& p, Index begin, Index end, double dt) override {
    const double lam = el_.lambda, mu = el_.mu;
    parallel_for(begin, end, [&](Index i) {
      Mat3 L = Mat3::Zero();
      L.template topLeftCorner<D, D>() = p.L[i];
      const Mat3 Dm = 0.5 * (L + L.transpose()), W = 0.5 * (L - L.transpose());
      Mat3 s = full(p, i);
      s += dt * (lam * Dm.trace() * Mat3::Identity() + 2 * mu * Dm) + dt * (W * s - s * W);  // elastic trial
      const double w = return_map(s, dt);
      p.stress[i] = s.template topLeftCorner<D, D>();
      if constexpr (D == 2) p.stress_zz[i] = s(2, 2);
      p.vol[i] = p.vol0[i] * p.F[i].determinant();
      power_[i] = w * p.vol[i];
    });
    dissipated_ += deterministic_sum(end - begin, [&](Index k) { return power_[begin + k]; });
  }

  double strain_energy(const Particles<D>& p, Index begin, Index end) const override {
    double e = 0;
    for (Index i = begin; i < end; ++i) {
      const Voigt6 s = voigt_stress(p, static_cast<std::size_t>(i));
      e += p.vol[i] * el_.energy_density(s);
    }
    return e;
  }

 private:
  double rho_;
  Elastic el_;
  Plane plane_;
  double alpha_ = 0, alpha_psi_ = 0, k_ = 0, K_ = 0;
  bool mu_i_ = false;
  MuOfI law_;                 // mu_i
  double d_ = 0, rho_s_ = 0;  // mu_i: grain diameter, grain density
  std::vector<double> power_;
  double dissipated_ = 0;
};

}  // namespace

template <int D> std::unique_ptr<Material<D>> make_drucker_prager(const MaterialConfig& c, Plane plane) {
  return std::make_unique<DruckerPrager<D>>(c, plane);
}
template std::unique_ptr<Material<2>> make_drucker_prager<2>(const MaterialConfig&, Plane);
template std::unique_ptr<Material<3>> make_drucker_prager<3>(const MaterialConfig&, Plane);

}  // namespace dmi
