// Coordinate transformations of a space beam-column: the global end displacements and rotations
// d = [u_i (3), th_i (3), u_j (3), th_j (3)] to the basic deformations v (space_element.hpp), the basic forces q to
// global end forces B^T q, and the global tangent. Stateless, as the plane ones (transform.hpp).
//   linear: v = a T d with T = diag(R, R, R, R), R the initial local axes (rows e1, e2, e3); K = B^T kb B.
#pragma once
#include <memory>

#include "engine/structure/space_element.hpp"

namespace dmi {

struct SpaceChord {
  Vec3 X = Vec3::Zero();                      // initial position of node i (m)
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();  // initial local axes, rows e1, e2, e3
  double L0 = 0;                              // initial length (m)
};

struct SpaceChordState {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();  // local axes used for loads and results (rows)
  double L = 0;                                     // chord length used by the basic system (m)
  Vec6 v = Vec6::Zero();                            // basic deformations
  Mat6x12 B = Mat6x12::Zero();                      // dv/dd
};

// Local axes of an element along unit e1 with orientation hint o (zero: global z x e1, or global y along z); rows
// e1, e2, e3. Returns false when o (or the default) is parallel to e1.
bool local_axes(const Vec3& e1, const Vec3& o, Eigen::Matrix3d& R);
// diag(R, R, R, R): local = T global for the 12 end DOFs.
Mat12 rotation12(const Eigen::Matrix3d& R);

class SpaceTransform {
 public:
  virtual ~SpaceTransform() = default;
  virtual SpaceChordState state(const SpaceChord& c, const Vec12& d) const = 0;
  virtual Mat12 tangent(const SpaceChordState& s, const Mat6& kb, const Vec6& q) const = 0;
};

class LinearSpaceTransform final : public SpaceTransform {
 public:
  SpaceChordState state(const SpaceChord& c, const Vec12& d) const override;
  Mat12 tangent(const SpaceChordState& s, const Mat6& kb, const Vec6& q) const override;
};

std::unique_ptr<SpaceTransform> make_space_transform(FrameTransform kind);

}  // namespace dmi
