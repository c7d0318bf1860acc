#include "engine/structure/element.hpp"

#include <array>
#include <functional>
#include <cmath>
#include <numbers>

namespace dmi {

// Gauss-Legendre rule on [0, 1]: roots of P_n by Newton from Chebyshev guesses (Press et al., Numerical
// Recipes 3rd ed., sec. 4.6.1). Exact for polynomials of degree 2n - 1 = 19.
std::array<GaussPoint, kGauss> gauss_legendre() {
  std::array<GaussPoint, kGauss> g{};
  for (int k = 0; k < kGauss; ++k) {
    double z = std::cos(std::numbers::pi * (k + 0.75) / (kGauss + 0.5)), dp = 0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = 0;
      for (int n = 1; n <= kGauss; ++n) {
        const double p2 = p1;
        p1 = p0;
        p0 = ((2 * n - 1) * z * p1 - (n - 1) * p2) / n;
      }
      dp = kGauss * (z * p0 - p1) / (z * z - 1);
      const double dz = p0 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-16) break;
    }
    g[k] = {0.5 * (1 - z), 1 / ((1 - z * z) * dp * dp)};  // weight 2/((1-z^2) P'^2), halved for [0, 1]
  }
  return g;
}

namespace {

// Particular section forces [N; V; M] at xi of the simply supported basic system (axial load held at
// node i) under the linear intensity p = [pa_x, pb_x, pa_y, pb_y]: N = int_x^L p_x, M'' = p_y, M(0) = M(L) = 0.
Eigen::Matrix<double, 3, 4> particular(double xi, double L) {
  const double x2 = xi * xi, lin = (1 - x2) / 2, cub = (x2 * xi - xi) / 6, dcub = (3 * x2 - 1) / 6;
  Eigen::Matrix<double, 3, 4> s;
  s << L * (1 - xi - lin), L * lin, 0, 0,
       0, 0, L * ((2 * xi - 1) / 2 - dcub), L * dcub,
       0, 0, L * L * ((x2 - xi) / 2 - cub), L * L * cub;
  return s;
}

}  // namespace

BeamShape beam_shape(double xi, double L) {
  const double x2 = xi * xi, x3 = x2 * xi;
  return {{1 - xi, xi},
          {1 - 3 * x2 + 2 * x3, L * (xi - 2 * x2 + x3), 3 * x2 - 2 * x3, L * (x3 - x2)},
          {(6 * x2 - 6 * xi) / L, 1 - 4 * xi + 3 * x2, (6 * xi - 6 * x2) / L, 3 * x2 - 2 * xi}};
}

BeamShape timoshenko_shape(double xi, double L, double phi) {
  const double x2 = xi * xi, x3 = x2 * xi, c = 1 / (1 + phi);
  return {{1 - xi, xi},
          {c * (2 * x3 - 3 * x2 - phi * xi + 1 + phi), c * L * (x3 - (2 + phi / 2) * x2 + (1 + phi / 2) * xi),
           -c * (2 * x3 - 3 * x2 - phi * xi), c * L * (x3 - (1 - phi / 2) * x2 - phi / 2 * xi)},
          {6 * c / L * (x2 - xi), c * (3 * x2 - (4 + phi) * xi + 1 + phi), -6 * c / L * (x2 - xi), c * (3 * x2 - (2 - phi) * xi)}};
}

PlaneBasic plane_basic(const FrameElementDef& def, double L, BeamTheory theory, const std::function<double(double)>& inertia) {
  PlaneBasic r;
  const bool shear = theory == BeamTheory::timoshenko;
  const double G = def.E / (2 * (1 + def.nu)), kappa = def.section.shear_coefficient();
  const auto at = [&](double xi) { return def.s0 + xi * (def.s1 - def.s0); };

  // Timoshenko: the shear-to-bending flexibility ratio phi = 12 E I / (kappa G A L^2) at the element's middle shapes
  // its mass (timoshenko_shape).
  const double phi = shear ? 12 * def.E * inertia(at(0.5)) / (kappa * G * def.section.area(at(0.5)) * L * L) : 0.0;
  r.fb.setZero();
  r.mc.setZero();
  r.mr.setZero();
  Eigen::Matrix<double, 3, 4> v0 = Eigen::Matrix<double, 3, 4>::Zero();  // basic deformations per unit load
  for (const GaussPoint& g : gauss_legendre()) {
    const double s = at(g.xi), A = def.section.area(s), dx = g.w * L;
    const double fa = 1 / (def.E * A), fm = 1 / (def.E * inertia(s));
    Eigen::Matrix<double, 2, 3> b;
    b << 1, 0, 0, 0, -(1 - g.xi), g.xi;
    r.fb += dx * b.transpose() * Eigen::Vector2d(fa, fm).asDiagonal() * b;
    const Eigen::Matrix<double, 3, 4> sp = particular(g.xi, L);
    v0 += dx * b.transpose() * (Eigen::Matrix<double, 2, 4>() << fa * sp.row(0), fm * sp.row(2)).finished();
    if (shear) {
      const double fv = 1 / (kappa * G * A * L);  // b_V = [0, 1, 1] / L
      r.fb.bottomRightCorner<2, 2>().array() += dx * fv / L;
      v0.row(1) += dx * fv * sp.row(1);
      v0.row(2) += dx * fv * sp.row(1);
    }
    // Consistent mass: axial [u_i, u_j] linear, transverse [w_i, t_i, w_j, t_j] Hermite (Timoshenko: the
    // interdependent shapes, with the section rotation's for the rotary inertia).
    const BeamShape sh = shear ? timoshenko_shape(g.xi, L, phi) : beam_shape(g.xi, L);
    Vec6 nu, nw;
    nu << sh.axial[0], 0, 0, sh.axial[1], 0, 0;
    nw << 0, sh.hermite[0], sh.hermite[1], 0, sh.hermite[2], sh.hermite[3];
    const double rho_a = def.rho * A;
    r.mc += dx * rho_a * (nu * nu.transpose() + nw * nw.transpose());
    r.m += dx * rho_a;
    if (shear) {
      Vec6 nt;
      nt << 0, sh.slope[0], sh.slope[1], 0, sh.slope[2], sh.slope[3];
      const double rho_i = def.rho * inertia(s);
      r.mr += dx * rho_i * nt * nt.transpose();
      r.jr += dx * rho_i;
    }
  }

  r.mc += r.mr;

  // Stiffness: inverse flexibility on the kept set (axial always; moments unless released).
  r.kb.setZero();
  const bool keep[3] = {true, !def.release_i, !def.release_j};
  int idx[3], n = 0;
  for (int k = 0; k < 3; ++k)
    if (keep[k]) idx[n++] = k;
  Eigen::MatrixXd fk(n, n);
  for (int i = 0; i < n; ++i)
    for (int c = 0; c < n; ++c) fk(i, c) = r.fb(idx[i], idx[c]);
  const Eigen::MatrixXd kk = fk.inverse();
  for (int i = 0; i < n; ++i)
    for (int c = 0; c < n; ++c) r.kb(idx[i], idx[c]) = kk(i, c);

  // Loads: q0 = -kb v0; equivalent nodal loads -(a^T q0 + p0), a the local (unrotated) compatibility matrix.
  r.q0 = -r.kb * v0;
  Mat36 a;
  a << -1, 0, 0, 1, 0, 0,
       0, 1 / L, 1, 0, -1 / L, 0,
       0, 1 / L, 0, 0, -1 / L, 1;
  Eigen::Matrix<double, 6, 4> p0 = Eigen::Matrix<double, 6, 4>::Zero();
  p0.row(0) << -L / 2, -L / 2, 0, 0;
  p0.row(1) << 0, 0, -L / 3, -L / 6;
  p0.row(4) << 0, 0, -L / 6, -L / 3;
  r.feq = -(a.transpose() * r.q0 + p0);
  return r;
}

Vec3 plane_section_forces(const Vec3& qv, const Mat34& q0, double L0, double L, const Eigen::Vector4d& pk, double xi) {
  const Vec3 q = qv + q0 * pk;
  const Vec3 sp = particular(xi, L0) * pk;  // [N, V, M]
  return {q(0) + sp(0), (q(1) + q(2)) / L + sp(1), -q(1) * (1 - xi) + q(2) * xi + sp(2)};
}

BeamElement::BeamElement(const FrameElementDef& def, double L, BeamTheory theory) : L_(L) {
  rho_a0_ = def.rho * def.section.area(def.s0);
  rho_a1_ = def.rho * def.section.area(def.s1);
  const PlaneBasic p = plane_basic(def, L, theory, [&def](double s) { return def.section.inertia(s); });
  fb_ = p.fb, kb_ = p.kb, mc_ = p.mc, m_ = p.m, q0_ = p.q0, feq_ = p.feq;
  // HRZ lumping: node translational share of the (axial + transverse) diagonal, rotary scaled as transverse.
  const double ti = mc_(0, 0) + mc_(1, 1), tj = mc_(3, 3) + mc_(4, 4), rot = m_ / (mc_(1, 1) + mc_(4, 4));
  ml_ << m_ * ti / (ti + tj), m_ * ti / (ti + tj), p.lumped_rotation(0, rot), m_ * tj / (ti + tj), m_ * tj / (ti + tj),
      p.lumped_rotation(1, rot);
}

double BeamElement::strain_energy(const Vec3& v) const {
  const Vec3 q = kb_ * v;
  return 0.5 * q.dot(fb_ * q);
}

SectionForces BeamElement::section_forces(const Vec3& q, double L, const ElementLoad& p, double xi) const {
  const Vec3 f = plane_section_forces(q, q0_, L_, L, pack(p), xi);
  return {f(0), f(1), f(2)};
}

}  // namespace dmi
