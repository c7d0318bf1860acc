// Basic system of a 3D elastic beam-column (OpenSees ElasticBeam3d; Filippou & Fenves (2004), sec. 6.3), free of
// rigid-body modes: deformations v = [elongation, th_i, th_j, th'_i, th'_j, twist] and forces
// q = [N, Mz_i, Mz_j, M'_i, M'_j, T]. Two bending planes, each the plane element of element.hpp (plane_basic: tapered
// sections, Timoshenko shear, releases, fixed-end forces, consistent mass):
//   plane 1 (e1, e2): transverse u2, rotation th3, moments Mz, inertia Section::inertia (about e3);
//   plane 2 (e1, e3), written as a plane element whose normal is e1 x e3 = -e2: transverse u3, rotation t' = -th2,
//   moments M' = -My, inertia Section::inertia_y (about e2).
// Torsion (St Venant): T = twist / int_0^L dx / (G J(x)), J = Section::torsion_constant; torsional inertia
// rho (Iz + Iy) with linear interpolation. Local DOF order per node [u1, u2, u3, th1, th2, th3], node i then j.
// Releases free both bending moments at an end (the torque stays: a ball joint that carries torsion would be a
// mechanism otherwise).
#pragma once
#include <Eigen/Dense>

#include "engine/structure/element.hpp"
#include "engine/structure/space_frame.hpp"

namespace dmi {

using Vec12 = Eigen::Matrix<double, 12, 1>;
using Mat12 = Eigen::Matrix<double, 12, 12>;
using Mat6x12 = Eigen::Matrix<double, 6, 12>;

// Distributed load intensity varying linearly along the element, per metre of initial length (N/m), components
// along (e1, e2, e3), at xi = 0 (a) and xi = 1 (b).
struct SpaceElementLoad {
  Vec3 a = Vec3::Zero(), b = Vec3::Zero();
};

class SpaceBeamElement {
 public:
  // Inputs are validated by the SpaceFrame (it names the element); L is the initial length.
  SpaceBeamElement(const SpaceElementDef& def, double L, BeamTheory theory);

  double mass() const { return m_; }
  const Mat6& stiffness() const { return kb_; }  // kb on v (releases condensed)
  Vec6 forces(const Vec6& v) const { return kb_ * v; }
  double strain_energy(const Vec6& v) const;
  // Small-displacement compatibility v = a u, u the 12 local end displacements and rotations.
  static Mat6x12 compatibility(double L);
  const Mat12& consistent_mass() const { return mc_; }  // local axes
  // HRZ lumped (Hinton, Rock & Zienkiewicz 1976), local axes: translations m_i along every axis, rotations
  // diag(J_torsion, J_y, J_z) per node, each scaled to its motion's total inertia.
  const Mat12& lumped_mass() const { return ml_; }

  SpaceElementLoad self_weight(const Vec3& g_local) const { return {rho_a0_ * g_local, rho_a1_ * g_local}; }
  Vec12 equivalent_loads(const SpaceElementLoad& p) const;  // local nodal loads
  // Section forces at xi from the basic forces q of the deformations (kb v, or a plastic element's) plus the load's
  // fixed-end forces and particular solution; L the current chord.
  SpaceSectionForces section_forces(const Vec6& q, double L, const SpaceElementLoad& p, double xi) const;

 private:
  double L_ = 0, m_ = 0, rho_a0_ = 0, rho_a1_ = 0;
  PlaneBasic p1_, p2_;
  double kt_ = 0;  // torsional stiffness GJ / L (tapered: the inverse of the integrated flexibility)
  Mat6 kb_, fb_;
  Mat12 mc_, ml_;
};

}  // namespace dmi
