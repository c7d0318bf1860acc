// Coordinate transformations of a 2D beam-column: map the global end displacements
// d = [ux_i, uy_i, rz_i, ux_j, uy_j, rz_j] to the basic deformations v (element.hpp), the basic forces q to
// global end forces B^T q, and give the global tangent. Stateless: everything follows from the initial
// chord and d. Geometric nonlinearity lives here only (as OpenSees CrdTransf).
//   linear:        v = a d, a constant (small displacements); K = a^T kb a.
//   corotational:  Crisfield (1991), Non-linear Finite Element Analysis of Solids and Structures, vol. 1,
//                  sec. 7.3: l_n = |x_j - x_i|, chord rotation psi = atan2 of the current chord against the
//                  initial one, v = [l_n - L0, rz_i - psi, rz_j - psi] (rotations wrapped to (-pi, pi], so
//                  any rigid rotation is exact); B = [r; e3 - z/l_n; e6 - z/l_n] with
//                  r = [-c, -s, 0, c, s, 0], z = [s, -c, 0, -s, c, 0];
//                  K_t = B^T kb B + N z z^T / l_n + (M_i + M_j) / l_n^2 (r z^T + z r^T)  (eq. 7.27 ff.).
#pragma once
#include <memory>

#include "engine/structure/element.hpp"

namespace dmi {

struct Chord {
  Vec2 X = Vec2::Zero();   // initial position of node i (m)
  Vec2 e1 = Vec2::UnitX(); // initial unit axis i -> j
  double L0 = 0;           // initial length (m)
};

struct ChordState {
  Vec2 o = Vec2::Zero(), e1 = Vec2::UnitX();  // origin (node i) and axis used for loads and results
  double L = 0;                               // chord length used by the basic system (m)
  Vec3 v = Vec3::Zero();                      // basic deformations
  Mat36 B = Mat36::Zero();                    // dv/dd
};

// Rotation of the end vector from global to local (e1, e2) axes: local = R global, per node [x, y, rz].
Mat6 global_to_local(const Vec2& e1);

class CoordTransform {
 public:
  virtual ~CoordTransform() = default;
  virtual ChordState state(const Chord& c, const Vec6& d) const = 0;
  // Global tangent stiffness at the state for basic stiffness kb and basic forces q.
  virtual Mat6 tangent(const ChordState& s, const Mat3& kb, const Vec3& q) const = 0;
  // Deformed centre-line in the layout of frame.hpp ElementCurve.
  virtual ElementCurve curve(const Chord& c, const Vec6& d) const = 0;
};

class LinearTransform final : public CoordTransform {
 public:
  ChordState state(const Chord& c, const Vec6& d) const override;
  Mat6 tangent(const ChordState& s, const Mat3& kb, const Vec3& q) const override;
  ElementCurve curve(const Chord& c, const Vec6& d) const override;
};

class CorotationalTransform final : public CoordTransform {
 public:
  ChordState state(const Chord& c, const Vec6& d) const override;
  Mat6 tangent(const ChordState& s, const Mat3& kb, const Vec3& q) const override;
  ElementCurve curve(const Chord& c, const Vec6& d) const override;
};

std::unique_ptr<CoordTransform> make_transform(FrameTransform kind);

}  // namespace dmi
