#include "engine/structure/transform.hpp"

#include <cmath>
#include <numbers>

namespace dmi {
namespace {

// Compatibility matrix of a chord with unit axis (c, s) and length L: rows [r; e3 - z/L; e6 - z/L].
Mat36 compatibility(const Vec2& e1, double L) {
  const double c = e1.x(), s = e1.y();
  Mat36 B;
  B << -c, -s, 0, c, s, 0,
       -s / L, c / L, 1, s / L, -c / L, 0,
       -s / L, c / L, 0, s / L, -c / L, 1;
  return B;
}

double wrap(double a) {  // to (-pi, pi]
  a = std::remainder(a, 2 * std::numbers::pi);
  return a <= -std::numbers::pi ? a + 2 * std::numbers::pi : a;
}

}  // namespace

Mat6 global_to_local(const Vec2& e1) {
  Eigen::Matrix3d r;
  r << e1.x(), e1.y(), 0, -e1.y(), e1.x(), 0, 0, 0, 1;
  Mat6 R = Mat6::Zero();
  R.topLeftCorner<3, 3>() = r;
  R.bottomRightCorner<3, 3>() = r;
  return R;
}

ChordState LinearTransform::state(const Chord& c, const Vec6& d) const {
  ChordState s;
  s.o = c.X;
  s.e1 = c.e1;
  s.L = c.L0;
  s.B = compatibility(c.e1, c.L0);
  s.v = s.B * d;
  return s;
}

Mat6 LinearTransform::tangent(const ChordState& s, const Mat3& kb, const Vec3&) const {
  return s.B.transpose() * kb * s.B;
}

ElementCurve LinearTransform::curve(const Chord& c, const Vec6& d) const {
  const Vec2 e2(-c.e1.y(), c.e1.x());
  ElementCurve k;
  k.o = c.X;
  k.e1 = c.e1;
  k.e2 = e2;
  k.L = c.L0;
  k.u1 = d.head<2>().dot(c.e1);
  k.w1 = d.head<2>().dot(e2);
  k.t1 = d(2);
  k.u2 = d.segment<2>(3).dot(c.e1);
  k.w2 = d.segment<2>(3).dot(e2);
  k.t2 = d(5);
  return k;
}

ChordState CorotationalTransform::state(const Chord& c, const Vec6& d) const {
  const Vec2 chord = c.L0 * c.e1 + d.segment<2>(3) - d.head<2>();
  ChordState s;
  s.L = chord.norm();
  s.e1 = chord / s.L;
  s.o = c.X + d.head<2>();
  // Chord rotation from the initial axis, robust for any angle: atan2(e1_0 x e1, e1_0 . e1).
  const double psi = std::atan2(c.e1.x() * s.e1.y() - c.e1.y() * s.e1.x(), c.e1.dot(s.e1));
  s.v << s.L - c.L0, wrap(d(2) - psi), wrap(d(5) - psi);
  s.B = compatibility(s.e1, s.L);
  return s;
}

Mat6 CorotationalTransform::tangent(const ChordState& s, const Mat3& kb, const Vec3& q) const {
  const double c = s.e1.x(), sn = s.e1.y();
  Vec6 r, z;
  r << -c, -sn, 0, c, sn, 0;
  z << sn, -c, 0, -sn, c, 0;
  const Mat6 rz = r * z.transpose();
  return s.B.transpose() * kb * s.B + (q(0) / s.L) * z * z.transpose() +
         ((q(1) + q(2)) / (s.L * s.L)) * (rz + rz.transpose());
}

ElementCurve CorotationalTransform::curve(const Chord& c, const Vec6& d) const {
  const ChordState s = state(c, d);
  ElementCurve k;
  k.o = s.o;
  k.e1 = s.e1;
  k.e2 = Vec2(-s.e1.y(), s.e1.x());
  k.L = s.L;
  k.t1 = s.v(1);
  k.t2 = s.v(2);
  return k;
}

std::unique_ptr<CoordTransform> make_transform(FrameTransform kind) {
  if (kind == FrameTransform::corotational) return std::make_unique<CorotationalTransform>();
  return std::make_unique<LinearTransform>();
}

}  // namespace dmi
