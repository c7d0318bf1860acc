// Linear elastic, small strain, objective (Jaumann) stress rate:
//   sigma_{n+1} = sigma_n + dt [lambda tr(D) I + 2 mu D] + dt (W sigma - sigma W),
// D = sym(L), W = skew(L). Plane strain keeps sigma_zz = lambda tr(D) integrated; plane stress
// uses lambda* = 2 lambda mu / (lambda + 2 mu) so that sigma_zz = 0.
// Strain energy density (complementary form, equal for a linear law):
//   w = [(1 + nu) sigma:sigma - nu (tr sigma)^2] / (2E).
#include <memory>

#include "engine/materials/material.hpp"

namespace dmi {
namespace {

template <int D> class LinearElastic final : public Material<D> {
 public:
  LinearElastic(const MaterialConfig& c, Plane plane) : rho_(c.density), el_(c.youngs_modulus, c.poisson_ratio), plane_(plane) {
    lambda_in_ = plane == Plane::stress ? 2 * el_.lambda * el_.mu / (el_.lambda + 2 * el_.mu) : el_.lambda;
  }
  double density() const override { return rho_; }
  double wave_speed() const override { return el_.wave_speed(rho_, plane_); }

  void update(Particles<D>& p, Index begin, Index end, double dt) override {
    const double lam = lambda_in_, mu = el_.mu, lam3 = el_.lambda;
    const bool strain2d = D == 2 && plane_ == Plane::strain;
#pragma omp parallel for schedule(static) if (end - begin > kParallelMin)
    for (Index i = begin; i < end; ++i) {
      const Mat<D>& L = p.L[i];
      const Mat<D> Dm = 0.5 * (L + L.transpose());
      const Mat<D> W = 0.5 * (L - L.transpose());
      Mat<D>& s = p.stress[i];
      const double trD = Dm.trace();
      s += dt * (lam * trD * Mat<D>::Identity() + 2 * mu * Dm) + dt * (W * s - s * W);
      if (strain2d) p.stress_zz[i] += dt * lam3 * trD;
      p.vol[i] = p.vol0[i] * p.F[i].determinant();
    }
  }

  double strain_energy(const Particles<D>& p, Index begin, Index end) const override {
    double e = 0;
    for (Index i = begin; i < end; ++i) {
      const Voigt6 s = voigt_stress(p, static_cast<std::size_t>(i));
      const double ss = s[0] * s[0] + s[1] * s[1] + s[2] * s[2] + 2 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]);
      const double tr = s[0] + s[1] + s[2];
      e += p.vol[i] * ((1 + el_.nu) * ss - el_.nu * tr * tr) / (2 * el_.E);
    }
    return e;
  }

 private:
  double rho_;
  Elastic el_;
  Plane plane_;
  double lambda_in_;
};

}  // namespace

template <int D> std::unique_ptr<Material<D>> make_linear_elastic(const MaterialConfig& c, Plane plane) {
  return std::make_unique<LinearElastic<D>>(c, plane);
}
template std::unique_ptr<Material<2>> make_linear_elastic<2>(const MaterialConfig&, Plane);
template std::unique_ptr<Material<3>> make_linear_elastic<3>(const MaterialConfig&, Plane);

}  // namespace dmi
