// Basic system of a 2D elastic beam-column (OpenSees ElasticBeam2d; Filippou & Fenves (2004), "Methods of
// analysis for earthquake-resistant structures", sec. 6.3), free of rigid-body modes:
//   deformations v = [elongation, theta_i, theta_j] (end rotations relative to the chord, ccw +),
//   forces       q = [N (tension +), M_i, M_j]      (end moments acting on the element, ccw +).
// Section forces at xi = x/L: N = q0, M = -q1 (1 - xi) + q2 xi (M + compresses the +e2 fibre), V = dM/dx.
// Flexibility f = int_0^L b^T diag(1/EA, 1/EI) b dx + int_0^L b_V^T b_V / (kappa G A) dx (Timoshenko only),
// b = [[1, 0, 0], [0, -(1 - xi), xi]], b_V = [0, 1, 1] / L, G = E / (2 (1 + nu)); kb = f^-1, with released
// end moments condensed out (kb on the kept set is the inverse of f restricted to it, so q = 0 at a release).
// Integrals by 10-point Gauss-Legendre: tapered sections (EI ~ depth^3) need no closed form.
// Element loads (uniform or linearly varying intensity p, N per metre of initial length, along e1 / e2): the
// particular solution of the simply supported basic system s_p(x) gives v0 = int b^T D^-1 s_p dx (+ shear)
// and the fixed-end forces q0 = -kb v0, exact for any section variation and for releases; the equivalent
// nodal loads are -(a^T q0 + p0) (p0: simply supported reactions). For a prismatic Euler-Bernoulli element
// they equal the Hermite-consistent loads (p L/2, p L^2/12).
// Mass from the displacement interpolation (axial linear, transverse cubic Hermite; frame.hpp ElementCurve),
// rho A(x) integrated numerically; Timoshenko: the interdependent shapes (timoshenko_shape) and the section's rotary
// inertia rho I(x) on its rotation (Friedman & Kosmatka 1993); lumped = HRZ diagonal scaling (Hinton, Rock &
// Zienkiewicz 1976).
// Local DOF order [u_i, w_i, t_i, u_j, w_j, t_j] along (e1, e2).
#pragma once
#include <Eigen/Dense>
#include <array>
#include <functional>

#include "engine/structure/frame.hpp"

namespace dmi {

using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat3 = Eigen::Matrix3d;
using Mat6 = Eigen::Matrix<double, 6, 6>;
using Mat36 = Eigen::Matrix<double, 3, 6>;

// Interpolation at xi of an element of length L: axial weights, transverse Hermite weights on
// [w_i, t_i, w_j, t_j] (frame.hpp ElementCurve) and their x-derivatives (the slope weights).
struct BeamShape {
  double axial[2];
  double hermite[4];
  double slope[4];
};
BeamShape beam_shape(double xi, double L);
// The Timoshenko element's interdependent interpolation (Friedman & Kosmatka 1993): transverse
// displacement (`hermite`) and section rotation (`slope`) on [w_i, t_i, w_j, t_j] that satisfy the homogeneous
// Timoshenko equations for phi = 12 E I / (kappa G A L^2); phi = 0 gives beam_shape.
BeamShape timoshenko_shape(double xi, double L, double phi);

// Distributed load intensity varying linearly along the element, per metre of initial length (N/m),
// components along (e1, e2), at xi = 0 (a) and xi = 1 (b).
struct ElementLoad {
  Vec2 a = Vec2::Zero(), b = Vec2::Zero();
};

// 10-point Gauss-Legendre rule on [0, 1] (exact to degree 19): section integrals along an element.
constexpr int kGauss = 10;
struct GaussPoint { double xi, w; };
std::array<GaussPoint, kGauss> gauss_legendre();

using Mat34 = Eigen::Matrix<double, 3, 4>;
using Mat64 = Eigen::Matrix<double, 6, 4>;

// One bending plane of the basic system (the whole of a plane element; a space element has two, about its two
// section axes): flexibility fb and stiffness kb on [N, M_i, M_j] with releases condensed, fixed-end forces q0 and
// equivalent local nodal loads feq on [u_i, w_i, t_i, u_j, w_j, t_j] per unit intensity [pa_x, pb_x, pa_y, pb_y],
// consistent mass mc on the same DOFs and the element mass m; inertia(s) is the bending inertia about the plane's
// normal at the section fraction s.
struct PlaneBasic {
  Mat3 fb, kb;
  Mat34 q0;
  Mat64 feq;
  Mat6 mc;          // consistent mass, rotary inertia included (Timoshenko)
  Mat6 mr;          // its rotary-inertia part, int rho I(x) n_t n_t^T dx, n_t the slopes of the Hermite shapes; 0 for EB
  double m = 0;     // element mass
  double jr = 0;    // rotary inertia int rho I(x) dx (Timoshenko; 0 for EB)
  // HRZ lumped rotational mass at end i (k = 0) or j (k = 1): the transverse part scaled like the translations
  // (scale = element mass / transverse diagonal sum), plus the share of jr by the rotary part's diagonal.
  double lumped_rotation(int k, double scale) const {
    const int d = k == 0 ? 2 : 5;
    const double share = jr > 0 ? jr * mr(d, d) / (mr(2, 2) + mr(5, 5)) : 0.0;
    return scale * (mc(d, d) - mr(d, d)) + share;
  }
};
PlaneBasic plane_basic(const FrameElementDef& def, double L, BeamTheory theory, const std::function<double(double)>& inertia);
// [N, V, M] at xi of a plane whose deformations carry the basic forces q (kb v for an elastic element, the fibres'
// for a plastic one), with fixed-end forces q0 and load intensity pk; L0 the initial length (the load's particular
// solution), L the current chord (basic shear).
Vec3 plane_section_forces(const Vec3& q, const Mat34& q0, double L0, double L, const Eigen::Vector4d& pk, double xi);

class BeamElement {
 public:
  // Inputs are validated by the Frame (it names the element); L is the initial length.
  BeamElement(const FrameElementDef& def, double L, BeamTheory theory);

  double mass() const { return m_; }
  const Mat3& stiffness() const { return kb_; }      // kb (releases condensed)
  const Mat3& flexibility() const { return fb_; }    // f (no releases)
  Vec3 forces(const Vec3& v) const { return kb_ * v; }
  // 0.5 q^T f q of the basic forces q = kb v (zero at releases).
  double strain_energy(const Vec3& v) const;
  const Mat6& consistent_mass() const { return mc_; }  // local axes
  // HRZ lumped mass [m_i, m_i, J_i, m_j, m_j, J_j]: each node's translational mass is the same along e1 and
  // e2 (shares of the axial plus transverse diagonal), so the matrix is diagonal in any axes; J scaled by the
  // transverse factor (m L^2 / 78 for a prismatic element).
  const Vec6& lumped_mass() const { return ml_; }

  ElementLoad self_weight(const Vec2& g_local) const { return {rho_a0_ * g_local, rho_a1_ * g_local}; }
  Vec6 equivalent_loads(const ElementLoad& p) const { return feq_ * pack(p); }  // local nodal loads
  // N, V, M at xi from the basic forces q of the deformations (kb v, or a plastic element's) plus the load's fixed-end
  // forces and particular solution; L is the current chord length (basic shear V = (M_i + M_j) / L).
  SectionForces section_forces(const Vec3& q, double L, const ElementLoad& p, double xi) const;

 private:
  static Eigen::Vector4d pack(const ElementLoad& p) { return {p.a.x(), p.b.x(), p.a.y(), p.b.y()}; }

  double L_ = 0, m_ = 0, rho_a0_ = 0, rho_a1_ = 0;
  Mat3 fb_, kb_;
  Mat6 mc_;
  Vec6 ml_;
  Mat34 q0_;   // q0 = q0_ [pa_x, pb_x, pa_y, pb_y]
  Mat64 feq_;  // equivalent nodal loads, local
};

}  // namespace dmi
