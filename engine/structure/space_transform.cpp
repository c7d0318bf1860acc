#include "engine/structure/space_transform.hpp"

#include <stdexcept>

namespace dmi {

bool local_axes(const Vec3& e1, const Vec3& o, Eigen::Matrix3d& R) {
  Vec3 hint = o;
  if (hint.squaredNorm() == 0) {  // global z x e1, or global y for a member along z
    hint = Vec3::UnitZ().cross(e1);
    if (hint.norm() < 1e-6) hint = Vec3::UnitY();
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

Mat12 LinearSpaceTransform::tangent(const SpaceChordState& s, const Mat6& kb, const Vec6&) const {
  return s.B.transpose() * kb * s.B;
}

std::unique_ptr<SpaceTransform> make_space_transform(FrameTransform kind) {
  if (kind == FrameTransform::linear) return std::make_unique<LinearSpaceTransform>();
  throw std::invalid_argument("SpaceFrame: the corotational transformation is not available for space frames yet");
}

}  // namespace dmi
