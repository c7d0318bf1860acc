// Coordinate transformations of a space beam-column: the global end displacements and rotations
// d = [u_i (3), th_i (3), u_j (3), th_j (3)] to the basic deformations v (space_element.hpp), the basic forces q to
// global end forces B^T q, and the global tangent. Stateless, as the plane ones (transform.hpp).
//   linear: v = a T d with T = diag(R, R, R, R), R the initial local axes (rows e1, e2, e3); K = B^T kb B.
//   corotational: the nodal rotations are total rotation vectors psi (additive DOFs, the nodal triads
//                 Q = exp(psi) Q0; any rotation below 2 pi in magnitude). The element frame follows the chord
//                 e1 = (x_j - x_i) / l and the mean of the nodal triads' e2 (Battini & Pacoste 2002, sec. 3.1):
//                 e3 = e1 x (Q_i e2_0 + Q_j e2_0) / |.|, e2 = e3 x e1; each node's rotation relative to the
//                 element frame, theta = log(Qe^T Q), gives v = [l - L0, theta_i3, theta_j3, -theta_i2,
//                 -theta_j2, theta_j1 - theta_i1] (Crisfield 1990, sec. 4). Any rigid motion is exact. B = dv/dd by
//                 forward automatic differentiation; K_t = B^T kb B + d(B^T q)/dd at fixed q, the second part by
//                 central differences of the differentiated B.
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

// Local axes of an element along unit e1 with orientation hint o (zero: global z, or global x for a member along z);
// rows e1, e2, e3. Returns false when o is parallel to e1.
bool local_axes(const Vec3& e1, const Vec3& o, Eigen::Matrix3d& R);
// diag(R, R, R, R): local = T global for the 12 end DOFs.
Mat12 rotation12(const Eigen::Matrix3d& R);

class SpaceTransform {
 public:
  virtual ~SpaceTransform() = default;
  virtual SpaceChordState state(const SpaceChord& c, const Vec12& d) const = 0;
  // Global tangent stiffness at d (state s = state(c, d)) for basic stiffness kb and basic forces q.
  virtual Mat12 tangent(const SpaceChord& c, const Vec12& d, const SpaceChordState& s, const Mat6& kb, const Vec6& q) const = 0;
};

class LinearSpaceTransform final : public SpaceTransform {
 public:
  SpaceChordState state(const SpaceChord& c, const Vec12& d) const override;
  Mat12 tangent(const SpaceChord& c, const Vec12& d, const SpaceChordState& s, const Mat6& kb, const Vec6& q) const override;
};

class CorotationalSpaceTransform final : public SpaceTransform {
 public:
  SpaceChordState state(const SpaceChord& c, const Vec12& d) const override;
  Mat12 tangent(const SpaceChord& c, const Vec12& d, const SpaceChordState& s, const Mat6& kb, const Vec6& q) const override;
};

// exp of a rotation vector (Rodrigues) and its inverse, for rotations below pi (the series near 0 keep derivatives).
Eigen::Matrix3d rotation_exp(const Vec3& psi);
Vec3 rotation_log(const Eigen::Matrix3d& R);

std::unique_ptr<SpaceTransform> make_space_transform(FrameTransform kind);

}  // namespace dmi
