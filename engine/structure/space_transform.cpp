#include "engine/structure/space_transform.hpp"

#include <stdexcept>

#include <unsupported/Eigen/AutoDiff>

namespace dmi {

bool local_axes(const Vec3& e1, const Vec3& o, Eigen::Matrix3d& R) {
  Vec3 hint = o;
  if (hint.squaredNorm() == 0) {  // the vertical (global z), or global x (the flow) for a vertical member
    hint = Vec3::UnitZ();
    if (hint.cross(e1).norm() < 1e-6) hint = Vec3::UnitX();
  }
  Vec3 e2 = hint - hint.dot(e1) * e1;
  if (!(e2.norm() > 1e-6 * hint.norm())) return false;
  e2.normalize();
  R.row(0) = e1.transpose();
  R.row(1) = e2.transpose();
  R.row(2) = e1.cross(e2).transpose();
  return true;
}

Mat12 rotation12(const Eigen::Matrix3d& R) {
  Mat12 T = Mat12::Zero();
  for (int k = 0; k < 4; ++k) T.block<3, 3>(3 * k, 3 * k) = R;
  return T;
}

SpaceChordState LinearSpaceTransform::state(const SpaceChord& c, const Vec12& d) const {
  SpaceChordState s;
  s.R = c.R;
  s.L = c.L0;
  s.B = SpaceBeamElement::compatibility(c.L0) * rotation12(c.R);
  s.v = s.B * d;
  return s;
}

Mat12 LinearSpaceTransform::tangent(const SpaceChord&, const Vec12&, const SpaceChordState& s, const Mat6& kb, const Vec6&) const {
  return s.B.transpose() * kb * s.B;
}

namespace {

template <class S> using M3 = Eigen::Matrix<S, 3, 3>;
template <class S> using V3 = Eigen::Matrix<S, 3, 1>;

template <class S> M3<S> skew(const V3<S>& w) {
  M3<S> K;
  K << S(0), -w(2), w(1), w(2), S(0), -w(0), -w(1), w(0), S(0);
  return K;
}

// R = I + a [psi]x + b [psi]x^2, a = sin t / t, b = (1 - cos t) / t^2 (Rodrigues); Taylor series below t = 1e-4 in
// t^2 = psi . psi, so the derivatives stay finite at psi = 0.
template <class S> M3<S> exp_map(const V3<S>& psi) {
  using std::cos, std::sin, std::sqrt;
  const S t2 = psi.squaredNorm();
  S a, b;
  if (t2 < S(1e-8)) {
    a = S(1) - t2 / S(6) + t2 * t2 / S(120);
    b = S(0.5) - t2 / S(24) + t2 * t2 / S(720);
  } else {
    const S t = sqrt(t2);
    a = sin(t) / t;
    b = (S(1) - cos(t)) / t2;
  }
  const M3<S> K = skew(psi);
  return M3<S>::Identity() + a * K + b * K * K;
}

// psi = t / sin t * axial(R), axial = (R - R^T)^v / 2 = sin t n, t = atan2(|axial|, (tr R - 1) / 2); series of
// asin(s) / s in s^2 = |axial|^2 below s = 1e-4 (rotations below pi).
template <class S> V3<S> log_map(const M3<S>& R) {
  using std::atan2, std::sqrt;
  const V3<S> w(S(0.5) * (R(2, 1) - R(1, 2)), S(0.5) * (R(0, 2) - R(2, 0)), S(0.5) * (R(1, 0) - R(0, 1)));
  const S s2 = w.squaredNorm(), c = S(0.5) * (R.trace() - S(1));
  if (s2 < S(1e-8)) return (S(1) + s2 / S(6) + S(3) * s2 * s2 / S(40)) * w;
  const S s = sqrt(s2);
  return (atan2(s, c) / s) * w;
}

// Basic deformations of the corotational element at d (global end displacements and rotation vectors) and the
// element frame (columns e1, e2, e3) and chord length.
template <class S> Eigen::Matrix<S, 6, 1> corotational_v(const SpaceChord& c, const Eigen::Matrix<S, 12, 1>& d, M3<S>& Qe, S& l) {
  const M3<S> Q0 = c.R.transpose().cast<S>();  // columns: initial axes
  const V3<S> Xi = c.X.cast<S>(), Xj = Xi + S(c.L0) * Q0.col(0);
  const V3<S> du = d.template segment<3>(6) - d.template segment<3>(0), chord = Xj - Xi + du;
  l = chord.norm();
  // l - L0 = (2 L0 e1_0 . du + du . du) / (l + L0): no cancellation for small stretches (Crisfield 1991, sec. 3.3).
  const S stretch = (S(2 * c.L0) * Q0.col(0).dot(du) + du.squaredNorm()) / (l + S(c.L0));
  const V3<S> e1 = chord / l;
  const M3<S> Qi = exp_map<S>(d.template segment<3>(3)) * Q0, Qj = exp_map<S>(d.template segment<3>(9)) * Q0;
  const V3<S> q = Qi.col(1) + Qj.col(1);
  V3<S> e3 = e1.cross(q);
  e3 /= e3.norm();
  const V3<S> e2 = e3.cross(e1);
  Qe.col(0) = e1, Qe.col(1) = e2, Qe.col(2) = e3;
  const V3<S> ti = log_map<S>(Qe.transpose() * Qi), tj = log_map<S>(Qe.transpose() * Qj);
  Eigen::Matrix<S, 6, 1> v;
  v << stretch, ti(2), tj(2), -ti(1), -tj(1), tj(0) - ti(0);
  return v;
}

using AD = Eigen::AutoDiffScalar<Vec12>;

// v and B = dv/dd at d by forward automatic differentiation.
void corotational_b(const SpaceChord& c, const Vec12& d, Vec6& v, Mat6x12& B, Eigen::Matrix3d& Qe, double& l) {
  Eigen::Matrix<AD, 12, 1> x;
  for (int k = 0; k < 12; ++k) x(k) = AD(d(k), 12, k);
  M3<AD> Q;
  AD len;
  const Eigen::Matrix<AD, 6, 1> va = corotational_v<AD>(c, x, Q, len);
  for (int r = 0; r < 6; ++r) v(r) = va(r).value(), B.row(r) = va(r).derivatives().transpose();
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) Qe(r, k) = Q(r, k).value();
  l = len.value();
}

}  // namespace

Eigen::Matrix3d rotation_exp(const Vec3& psi) { return exp_map<double>(psi); }
Vec3 rotation_log(const Eigen::Matrix3d& R) { return log_map<double>(R); }

SpaceChordState CorotationalSpaceTransform::state(const SpaceChord& c, const Vec12& d) const {
  SpaceChordState s;
  Eigen::Matrix3d Qe;
  corotational_b(c, d, s.v, s.B, Qe, s.L);
  s.R = Qe.transpose();
  return s;
}

Mat12 CorotationalSpaceTransform::tangent(const SpaceChord& c, const Vec12& d, const SpaceChordState& s, const Mat6& kb, const Vec6& q) const {
  Mat12 K = s.B.transpose() * kb * s.B;
  // Geometric part d(B^T q)/dd at fixed q: central differences, steps 1e-7 L0 (translations) and 1e-7 rad.
  Vec6 v;
  Mat6x12 Bp, Bm;
  Eigen::Matrix3d Qe;
  double l = 0;
  for (int k = 0; k < 12; ++k) {
    const double h = (k % 6 < 3 ? c.L0 : 1.0) * 1e-7;
    Vec12 dp = d, dm = d;
    dp(k) += h, dm(k) -= h;
    corotational_b(c, dp, v, Bp, Qe, l);
    corotational_b(c, dm, v, Bm, Qe, l);
    K.col(k) += (Bp - Bm).transpose() * q / (2 * h);
  }
  return 0.5 * (K + K.transpose());  // the exact tangent is symmetric (conservative internal forces)
}

std::unique_ptr<SpaceTransform> make_space_transform(FrameTransform kind) {
  if (kind == FrameTransform::linear) return std::make_unique<LinearSpaceTransform>();
  return std::make_unique<CorotationalSpaceTransform>();
}

}  // namespace dmi
