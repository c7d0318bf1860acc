// Linear elastic, small strain, objective (Jaumann) stress rate:
//   sigma_{n+1} = sigma_n + dt [lambda tr(D) I + 2 mu D] + dt (W sigma - sigma W),
// D = sym(L), W = skew(L). Plane strain keeps sigma_zz = lambda tr(D) integrated; plane stress
// uses lambda* = 2 lambda mu / (lambda + 2 mu) so that sigma_zz = 0.
// Strain energy density (complementary form, equal for a linear law):
//   w = [(1 + nu) sigma:sigma - nu (tr sigma)^2] / (2E).
// Optional Kelvin-Voigt damping (stiffness-proportional, beta = zeta / (pi f)): the stress carries a viscous
// part beta [lambda tr(D) I + 2 mu D] on top of the elastic one, which is then integrated separately; its
// power sigma_v : D V is dissipated.
#include <memory>
#include <vector>

#include "engine/common/parallel.hpp"
#include "engine/materials/material.hpp"
#include "engine/common/reduce.hpp"

namespace dmi {
namespace {

template <int D> class LinearElastic final : public Material<D> {
 public:
  LinearElastic(const MaterialConfig& c, Plane plane)
      : rho_(c.density), el_(c.youngs_modulus, c.poisson_ratio), plane_(plane),
        beta_(c.damping_ratio > 0 ? c.damping_ratio / (3.14159265358979323846 * c.damping_frequency) : 0.0) {
    lambda_in_ = plane == Plane::stress ? 2 * el_.lambda * el_.mu / (el_.lambda + 2 * el_.mu) : el_.lambda;
  }
  double density() const override { return rho_; }
  double wave_speed() const override { return el_.wave_speed(rho_, plane_); }
  double damping_time() const override { return beta_; }
  bool viscous_coefficients(double& a, double& b) const override {
    a = beta_ * lambda_in_, b = beta_ * el_.mu;
    return beta_ > 0;
  }
  const std::vector<Mat<D>>* viscous_stress() const override { return &viscous_; }
  void set_implicit_viscosity(bool on) override { implicit_ = on; }
  void permute(const std::vector<Index>& perm) override {
    permute_array(elastic_, perm), permute_array(elastic_zz_, perm), permute_array(power_, perm), permute_array(viscous_, perm);
  }
  double dissipated() const override { return dissipated_; }
  // The stress is integrated from rates (hypoelastic): any stress may be the initial state.
  bool prestress(Particles<D>& p, Index i, const Mat<3>& sigma) override {
    p.stress[i] = sigma.template topLeftCorner<D, D>();
    if constexpr (D == 2) p.stress_zz[i] = sigma(2, 2);
    return true;
  }
  // The stress is integrated from rates (hypoelastic), so zero is a stress-free state at any F.
  bool relax(Particles<D>& p, Index begin, Index end) override {
    for (Index i = begin; i < end; ++i) {
      p.stress[i].setZero(), p.stress_zz[i] = 0;
      if (i < static_cast<Index>(elastic_.size())) elastic_[i].setZero(), elastic_zz_[i] = 0, viscous_[i].setZero();
    }
    return true;
  }
  void save_state(StateWriter& w) const override { w.put(elastic_), w.put(elastic_zz_), w.put(power_), w.put(viscous_), w.put(dissipated_); }
  void load_state(StateReader& r) override { r.get(elastic_), r.get(elastic_zz_), r.get(power_), r.get(viscous_), r.get(dissipated_); }
  void attach(const Particles<D>& p, Index begin, Index end) override {
    if (beta_ <= 0) return;
    elastic_.resize(p.size(), Mat<D>::Zero());
    elastic_zz_.resize(p.size(), 0.0);
    power_.resize(p.size(), 0.0);
    viscous_.resize(p.size(), Mat<D>::Zero());
    for (Index i = begin; i < end; ++i) {
      elastic_[i] = p.stress[i];
      elastic_zz_[i] = p.stress_zz[i];
    }
  }

  bool pointwise() const override { return beta_ == 0; }  // damped: dissipation is summed over the range
  void update(Particles<D>& p, Index begin, Index end, double dt) override {
    const double lam = lambda_in_, mu = el_.mu, lam3 = el_.lambda, beta = beta_;
    const bool strain2d = D == 2 && plane_ == Plane::strain;
    if (D == 2 && beta == 0) {  // the common case in scalars: Eigen's 2x2 W s - s W stalls on a store-forward
      update2d(p, begin, end, dt, lam, mu, strain2d ? lam3 : 0.0);
      return;
    }
    if (D == 3 && beta == 0) {
      update3d(p, begin, end, dt, lam, mu);
      return;
    }
    parallel_for(begin, end, [&](Index i) {
      const Mat<D>& L = p.L[i];
      const Mat<D> Dm = 0.5 * (L + L.transpose());
      const Mat<D> W = 0.5 * (L - L.transpose());
      Mat<D>& s = beta > 0 ? elastic_[i] : p.stress[i];
      double& szz = beta > 0 ? elastic_zz_[i] : p.stress_zz[i];
      const double trD = Dm.trace();
      const Mat<D> rate = lam * trD * Mat<D>::Identity() + 2 * mu * Dm;
      s += dt * rate + dt * (W * s - s * W);
      if (strain2d) szz += dt * lam3 * trD;
      p.vol[i] = p.vol0[i] * p.F[i].determinant();
      if (beta > 0) {  // total = elastic + viscous beta C:D; power sigma_v : D (D_zz = 0 in plane strain)
        viscous_[i] = beta * rate;
        p.stress[i] = s + viscous_[i];
        p.stress_zz[i] = szz + (strain2d ? beta * lam3 * trD : 0.0);
        power_[i] = beta * (rate.cwiseProduct(Dm)).sum() * p.vol[i];
      }
    });
    if (beta > 0 && !implicit_) dissipated_ += dt * deterministic_sum(end - begin, [&](Index k) { return power_[begin + k]; });
  }

  // Undamped 2D form of update(): sigma += dt (lam tr(D) I + 2 mu D) + dt (W sigma - sigma W), with
  // W = [[0, w], [-w, 0]], w = (L01 - L10) / 2, so W sigma - sigma W = w [[s01 + s10, s11 - s00], [s11 - s00, -(s01 + s10)]].
  static void update2d(Particles<D>& p, Index begin, Index end, double dt, double lam, double mu, double lam_zz) {
    if constexpr (D == 2) {
      parallel_for(begin, end, [&](Index i) {
        // Software prefetch 16 particles ahead of the arrays the chunk's gather did not touch (the loop otherwise waits
        // on the stress loads; docs/performance.md).
        __builtin_prefetch(p.stress.data() + i + 16, 1);
        __builtin_prefetch(p.vol.data() + i + 16, 1);
        __builtin_prefetch(p.vol0.data() + i + 16);
        const Mat<2>& L = p.L[i];
        Mat<2>& s = p.stress[i];
        const double tr = L(0, 0) + L(1, 1), d01 = 0.5 * (L(0, 1) + L(1, 0)), w = 0.5 * (L(0, 1) - L(1, 0));
        const double s00 = s(0, 0), s01 = s(0, 1), s10 = s(1, 0), s11 = s(1, 1);
        const double a = w * (s01 + s10), b = w * (s11 - s00);
        s(0, 0) = s00 + dt * (lam * tr + 2 * mu * L(0, 0) + a);
        s(1, 1) = s11 + dt * (lam * tr + 2 * mu * L(1, 1) - a);
        s(0, 1) = s01 + dt * (2 * mu * d01 + b);
        s(1, 0) = s10 + dt * (2 * mu * d01 + b);
        if (lam_zz != 0) p.stress_zz[i] += dt * lam_zz * tr;
        const Mat<2>& F = p.F[i];
        p.vol[i] = p.vol0[i] * (F(0, 0) * F(1, 1) - F(0, 1) * F(1, 0));
      });
    }
  }

  // Undamped 3D form: sigma += dt (lam tr(D) I + 2 mu D) + dt (W sigma - sigma W); for symmetric sigma and skew W the
  // Jaumann term is M + M^T with M = W sigma, W = [[0, a, b], [-a, 0, c], [-b, -c, 0]], a, b, c = (L01 - L10) / 2,
  // (L02 - L20) / 2, (L12 - L21) / 2. The stress stays exactly symmetric.
  static void update3d(Particles<D>& p, Index begin, Index end, double dt, double lam, double mu) {
    if constexpr (D == 3) {
      parallel_for(begin, end, [&](Index i) {
        __builtin_prefetch(p.stress.data() + i + 8, 1);
        __builtin_prefetch(p.vol.data() + i + 16, 1);
        __builtin_prefetch(p.vol0.data() + i + 16);
        const Mat<3>& L = p.L[i];
        Mat<3>& s = p.stress[i];
        const double a = 0.5 * (L(0, 1) - L(1, 0)), b = 0.5 * (L(0, 2) - L(2, 0)), c = 0.5 * (L(1, 2) - L(2, 1));
        const double s00 = s(0, 0), s11 = s(1, 1), s22 = s(2, 2), s01 = s(0, 1), s02 = s(0, 2), s12 = s(1, 2);
        // M = W s (s symmetric); the Jaumann term's entries R_ij = M_ij + M_ji.
        const double m00 = a * s01 + b * s02, m11 = -a * s01 + c * s12, m22 = -b * s02 - c * s12;
        const double m01 = a * s11 + b * s12, m10 = -a * s00 + c * s02;
        const double m02 = a * s12 + b * s22, m20 = -b * s00 - c * s01;
        const double m12 = -a * s02 + c * s22, m21 = -b * s01 - c * s11;
        const double tr = L(0, 0) + L(1, 1) + L(2, 2), lt = lam * tr;
        s(0, 0) = s00 + dt * (lt + 2 * mu * L(0, 0) + 2 * m00);
        s(1, 1) = s11 + dt * (lt + 2 * mu * L(1, 1) + 2 * m11);
        s(2, 2) = s22 + dt * (lt + 2 * mu * L(2, 2) + 2 * m22);
        s(0, 1) = s(1, 0) = s01 + dt * (mu * (L(0, 1) + L(1, 0)) + m01 + m10);
        s(0, 2) = s(2, 0) = s02 + dt * (mu * (L(0, 2) + L(2, 0)) + m02 + m20);
        s(1, 2) = s(2, 1) = s12 + dt * (mu * (L(1, 2) + L(2, 1)) + m12 + m21);
        p.vol[i] = p.vol0[i] * p.F[i].determinant();
      });
    }
  }

  double strain_energy(const Particles<D>& p, Index begin, Index end) const override {
    double e = 0;
    for (Index i = begin; i < end; ++i) {
      Voigt6 s = voigt_stress(p, static_cast<std::size_t>(i));
      if (beta_ > 0) {  // the elastic part only
        const Mat<D>& t = elastic_[i];
        if constexpr (D == 2) s << t(0, 0), t(1, 1), elastic_zz_[i], t(0, 1), 0.0, 0.0;
        else s << t(0, 0), t(1, 1), t(2, 2), t(0, 1), t(1, 2), t(0, 2);
      }
      e += p.vol[i] * el_.energy_density(s);
    }
    return e;
  }

 private:
  double rho_;
  Elastic el_;
  Plane plane_;
  double beta_;  // s
  double lambda_in_;
  std::vector<Mat<D>> elastic_, viscous_;  // elastic and viscous stress (damped laws only), by particle index
  std::vector<double> elastic_zz_, power_;
  double dissipated_ = 0;
  bool implicit_ = false;  // dissipation counted by the implicit viscous solve
};

}  // namespace

template <int D> std::unique_ptr<Material<D>> make_linear_elastic(const MaterialConfig& c, Plane plane) {
  return std::make_unique<LinearElastic<D>>(c, plane);
}
template std::unique_ptr<Material<2>> make_linear_elastic<2>(const MaterialConfig&, Plane);
template std::unique_ptr<Material<3>> make_linear_elastic<3>(const MaterialConfig&, Plane);

}  // namespace dmi
