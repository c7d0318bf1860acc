// Weakly compressible viscous fluid for slurry surges: Newtonian, and Bingham with Papanastasiou
// regularisation. Stress tension positive, pressure p compression positive: sigma = -p I + s.
//   pressure   p = max(K (1/J - 1), 0),   J = det F,  K = rho0 c0^2 (bulk_modulus).
//              The gamma = 1 member of Monaghan's (1994, J. Comput. Phys. 110, 399) Tait family
//              p = B [(rho/rho0)^gamma - 1], B = rho0 c0^2 / gamma, with rho/rho0 = 1/J. dp/drho = c0^2 at every density, so
//              wave_speed() = sqrt(K/rho0) bounds the CFL step at any compression (gamma = 7 stiffens it by
//              J^((1-gamma)/2)). Weak compressibility wants c0 >= 10 |v|max: density errors <= 1 % (Monaghan 1994).
//              Tension cut-off: a slurry separates rather than carry negative pressure, hence the max(., 0).
//   stored     W(J) = K (J - 1 - ln J) for J < 1, 0 for J >= 1, per reference volume (p = -dW/dJ).
//   viscous    s = 2 mu_eff D',  D' = D - tr(D)/3 I the 3D deviator of D = sym(L) (D_zz = 0 in plane strain,
//              so s_zz = -2 mu_eff tr(D)/3 and sigma_zz = s_zz - p), gamma_dot = sqrt(2 D':D') (the shear rate
//              in simple shear).  newtonian: mu_eff = mu.
//              bingham (Papanastasiou 1987, J. Rheol. 31, 385; his exponent m = 1/gamma_c):
//                mu_eff = mu + tau_y (1 - exp(-gamma_dot/gamma_c)) / gamma_dot,
//              i.e. tau = mu gamma_dot + tau_y (1 - exp(-gamma_dot/gamma_c)) in simple shear: tau_y + mu gamma_dot once
//              gamma_dot >> gamma_c; below yield (tau < tau_y) the material creeps at gamma_dot ~ -gamma_c ln(1 - tau/tau_y),
//              with viscosity at most mu_max = mu + tau_y/gamma_c.
//   dissipated power  s:D V = 2 mu_eff D':D' V >= 0, summed times dt (exact for constant rates).
//   stable step  the viscous stress is Kelvin-Voigt damping of the pressure waves: a longitudinal mode has
//              elastic modulus M = K (no shear modulus) and viscous modulus (4/3) mu_eff, so damping_time()
//              returns beta = (4/3) mu_max / K. The solver's damped CFL step (2/w)(sqrt(1 + zeta^2) - zeta),
//              w = 2 sqrt(D) c/h, zeta = beta w/2, then tends to h^2 rho / (2 D (4/3) mu_max) for strong viscosity: the
//              explicit limit of viscous diffusion on cells of size h in D dimensions (FTCS: h^2 / (2 D nu)).
//              Measured in 2D (the settling column of test_fluids.cpp at forced steps, GIMP and B-spline): unstable above
//              0.6-0.7 h^2 rho / (2 (4/3) mu), so without the factor D the default cfl 0.5 would leave no margin.
// Only J is a state of a fluid: after each update F is replaced by J^(1/D) I (as taichi's mpm99 does for water),
// so its isochoric part cannot grow without bound in long shear flows and det F stays accurate.
// Plane stress is refused (the parser's check_semantics, and make_viscous_fluid).
#pragma once
#include <cmath>
#include <memory>
#include <stdexcept>
#include <vector>

#include "engine/common/parallel.hpp"
#include "engine/materials/material.hpp"
#include "engine/common/reduce.hpp"

namespace dmi {

template <int D> class ViscousFluid final : public Material<D> {
 public:
  using Mat3 = Eigen::Matrix3d;
  // newtonian: tau_y = 0 (the regularisation then has no effect).
  explicit ViscousFluid(const MaterialConfig& c)
      : rho_(c.density), K_(c.bulk_modulus), mu_(c.viscosity), tau_y_(c.model == "bingham" ? c.yield_stress : 0.0),
        rate_c_(c.regularisation_rate), relax_(c.volume_relaxation) {
    if (!(rho_ > 0 && K_ > 0 && mu_ > 0 && tau_y_ >= 0 && (tau_y_ == 0 || rate_c_ > 0)))
      throw std::invalid_argument("material '" + c.name + "': " + c.model + " needs density, bulk_modulus, viscosity > 0, "
                                  "yield_stress >= 0 and regularisation_rate > 0");
  }
  double density() const override { return rho_; }
  double volume_relaxation() const override { return relax_; }
  double wave_speed() const override { return std::sqrt(K_ / rho_); }
  double damping_time() const override { return (4.0 / 3.0) * max_viscosity() / K_; }
  void permute(const std::vector<Index>& perm) override { permute_array(power_, perm); }
  double dissipated() const override { return dissipated_; }
  void save_state(StateWriter& w) const override { w.put(power_), w.put(dissipated_); }
  void load_state(StateReader& r) override { r.get(power_), r.get(dissipated_); }
  void attach(const Particles<D>& p, Index, Index) override { power_.resize(p.size(), 0.0); }

  // Largest effective viscosity (Pa s): at gamma_dot -> 0.
  double max_viscosity() const { return mu_ + (tau_y_ > 0 ? tau_y_ / rate_c_ : 0.0); }
  // Effective viscosity (Pa s) at the equivalent shear rate gamma_dot (1/s); (1 - e^-x)/x -> 1 as x -> 0.
  double viscosity(double gamma_dot) const {
    if (tau_y_ == 0) return mu_;
    const double x = gamma_dot / rate_c_;
    return mu_ + (tau_y_ / rate_c_) * (x > 1e-8 ? -std::expm1(-x) / x : 1 - 0.5 * x);
  }
  // Pressure (Pa) at volume ratio J, with the tension cut-off.
  double pressure(double J) const { return std::max(K_ * (1 / J - 1), 0.0); }
  // Stored energy per reference volume (J/m^3).
  double energy_density(double J) const { return J < 1 ? K_ * (J - 1 - std::log(J)) : 0.0; }

  void update(Particles<D>& p, Index begin, Index end, double dt) override {
    parallel_for(begin, end, [&](Index i) {
      Mat3 Dm = Mat3::Zero();
      Dm.template topLeftCorner<D, D>() = 0.5 * (p.L[i] + p.L[i].transpose());
      const Mat3 dev = Dm - Dm.trace() / 3 * Mat3::Identity();
      const double dd = dev.squaredNorm();
      const double mu = viscosity(std::sqrt(2 * dd));
      const double J = p.F[i].determinant();
      const double pr = pressure(J);
      p.stress[i] = 2 * mu * dev.template topLeftCorner<D, D>() - pr * Mat<D>::Identity();
      if constexpr (D == 2) p.stress_zz[i] = 2 * mu * dev(2, 2) - pr;
      p.vol[i] = p.vol0[i] * J;
      p.F[i] = std::pow(J, 1.0 / D) * Mat<D>::Identity();
      power_[i] = 2 * mu * dd * p.vol[i];
    });
    dissipated_ += dt * deterministic_sum(end - begin, [&](Index k) { return power_[begin + k]; });
  }

  // The pressure of sigma and the volume ratio J = K / (K + p) that gives it (the inverse of pressure(J)).
  bool prestress(Particles<D>& p, Index i, const Mat<3>& sigma) override {
    const double pr = std::max(0.0, -sigma.trace() / 3), J = K_ / (K_ + pr);
    p.F[i] = std::pow(J, 1.0 / D) * Mat<D>::Identity();
    p.vol[i] = p.vol0[i] * J;
    p.stress[i] = -pr * Mat<D>::Identity();
    if constexpr (D == 2) p.stress_zz[i] = -pr;
    return true;
  }

  double strain_energy(const Particles<D>& p, Index begin, Index end) const override {
    double e = 0;
    for (Index i = begin; i < end; ++i) e += p.vol0[i] * energy_density(p.F[i].determinant());
    return e;
  }

 private:
  double rho_, K_, mu_, tau_y_, rate_c_;  // kg/m^3, Pa, Pa s, Pa, 1/s
  double relax_;                          // acoustic cell transits (engine/mpm/fluid_volume.hpp)
  std::vector<double> power_;             // W, by particle index
  double dissipated_ = 0;                 // J
};

// Factory for the registry ("newtonian" and "bingham").
template <int D> std::unique_ptr<Material<D>> make_viscous_fluid(const MaterialConfig& c, Plane plane) {
  if (D == 2 && plane == Plane::stress)
    throw std::invalid_argument("material '" + c.name + "': " + c.model + " needs plane strain or 3D, not plane stress");
  return std::make_unique<ViscousFluid<D>>(c);
}

}  // namespace dmi
