#include "engine/structure/space_element.hpp"

#include <cmath>

namespace dmi {
namespace {

// Local DOFs of the plane elements' [u_i, w_i, t_i, u_j, w_j, t_j] in the space element's 12, with the sign of t'.
constexpr int kPlane1[6] = {0, 1, 5, 6, 7, 11};
constexpr int kPlane2[6] = {0, 2, 4, 6, 8, 10};
constexpr double kSign2[6] = {1, 1, -1, 1, 1, -1};

FrameElementDef plane_def(const SpaceElementDef& d) {
  FrameElementDef p;
  p.i = d.i, p.j = d.j, p.section = d.section, p.s0 = d.s0, p.s1 = d.s1, p.E = d.E, p.nu = d.nu, p.rho = d.rho;
  p.release_i = d.release_i, p.release_j = d.release_j, p.member = d.member;
  return p;
}

Eigen::Vector4d pack1(const SpaceElementLoad& p) { return {p.a.x(), p.b.x(), p.a.y(), p.b.y()}; }
Eigen::Vector4d pack2(const SpaceElementLoad& p) { return {0, 0, p.a.z(), p.b.z()}; }

}  // namespace

SpaceBeamElement::SpaceBeamElement(const SpaceElementDef& def, double L, BeamTheory theory) : L_(L) {
  const FrameElementDef pd = plane_def(def);
  const Section& sec = def.section;
  p1_ = plane_basic(pd, L, theory, [&sec](double s) { return sec.inertia(s); });
  p2_ = plane_basic(pd, L, theory, [&sec](double s) { return sec.inertia_y(s); });
  m_ = p1_.m;
  rho_a0_ = def.rho * sec.area(def.s0);
  rho_a1_ = def.rho * sec.area(def.s1);

  // Torsion: flexibility int dx / (G J), inertia rho (Iz + Iy) with linear shapes.
  const double G = def.E / (2 * (1 + def.nu));
  double ft = 0, t11 = 0, t12 = 0, t22 = 0;
  for (const GaussPoint& g : gauss_legendre()) {
    const double s = def.s0 + g.xi * (def.s1 - def.s0), dx = g.w * L;
    ft += dx / (G * sec.torsion_constant(s));
    const double rip = def.rho * (sec.inertia(s) + sec.inertia_y(s));
    t11 += dx * rip * (1 - g.xi) * (1 - g.xi), t12 += dx * rip * g.xi * (1 - g.xi), t22 += dx * rip * g.xi * g.xi;
  }
  kt_ = 1 / ft;

  kb_.setZero();
  fb_.setZero();
  kb_.topLeftCorner<3, 3>() = p1_.kb;
  fb_.topLeftCorner<3, 3>() = p1_.fb;
  kb_.block<2, 2>(3, 3) = p2_.kb.bottomRightCorner<2, 2>();
  fb_.block<2, 2>(3, 3) = p2_.fb.bottomRightCorner<2, 2>();
  kb_(5, 5) = kt_;
  fb_(5, 5) = ft;

  mc_.setZero();
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 6; ++c) {
      mc_(kPlane1[r], kPlane1[c]) += p1_.mc(r, c);
      if (r % 3 != 0 && c % 3 != 0) mc_(kPlane2[r], kPlane2[c]) += kSign2[r] * kSign2[c] * p2_.mc(r, c);  // transverse only
    }
  mc_(3, 3) += t11, mc_(3, 9) += t12, mc_(9, 3) += t12, mc_(9, 9) += t22;

  // HRZ: the plane element's translational shares (isotropic), each rotation scaled to its motion's inertia.
  const Mat6& m1 = p1_.mc;
  const Mat6& m2 = p2_.mc;
  const double ti = m1(0, 0) + m1(1, 1), tj = m1(3, 3) + m1(4, 4);
  const double rot1 = m_ / (m1(1, 1) + m1(4, 4)), rot2 = m_ / (m2(1, 1) + m2(4, 4)), torsion = t11 + 2 * t12 + t22;
  Vec12 d;
  d << Vec3::Constant(m_ * ti / (ti + tj)), torsion * t11 / (t11 + t22), p2_.lumped_rotation(0, rot2), p1_.lumped_rotation(0, rot1),
      Vec3::Constant(m_ * tj / (ti + tj)), torsion * t22 / (t11 + t22), p2_.lumped_rotation(1, rot2), p1_.lumped_rotation(1, rot1);
  ml_ = d.asDiagonal();
}

double SpaceBeamElement::strain_energy(const Vec6& v) const {
  const Vec6 q = kb_ * v;
  return 0.5 * q.dot(fb_ * q);
}

Mat6x12 SpaceBeamElement::compatibility(double L) {
  Mat6x12 a = Mat6x12::Zero();
  a(0, 0) = -1, a(0, 6) = 1;
  a(1, 5) = 1, a(1, 1) = 1 / L, a(1, 7) = -1 / L;
  a(2, 11) = 1, a(2, 1) = 1 / L, a(2, 7) = -1 / L;
  a(3, 4) = -1, a(3, 2) = 1 / L, a(3, 8) = -1 / L;
  a(4, 10) = -1, a(4, 2) = 1 / L, a(4, 8) = -1 / L;
  a(5, 3) = -1, a(5, 9) = 1;
  return a;
}

Vec12 SpaceBeamElement::equivalent_loads(const SpaceElementLoad& p) const {
  const Vec6 f1 = p1_.feq * pack1(p), f2 = p2_.feq * pack2(p);
  Vec12 f = Vec12::Zero();
  for (int r = 0; r < 6; ++r) {
    f(kPlane1[r]) += f1(r);
    if (r % 3 != 0) f(kPlane2[r]) += kSign2[r] * f2(r);
  }
  return f;
}

SpaceSectionForces SpaceBeamElement::section_forces(const Vec6& q, double L, const SpaceElementLoad& p, double xi) const {
  const Vec3 f1 = plane_section_forces(Vec3(q(0), q(1), q(2)), p1_.q0, L_, L, pack1(p), xi);
  const Vec3 f2 = plane_section_forces(Vec3(q(0), q(3), q(4)), p2_.q0, L_, L, pack2(p), xi);
  SpaceSectionForces s;
  s.N = f1(0);
  s.Mz = f1(2), s.Vy = -f1(1);  // V of the plane element is dMz/dx = -Vy
  s.My = -f2(2), s.Vz = -f2(1);  // M' = -My, V' = dM'/dx = -Vz
  s.T = q(5);
  return s;
}

}  // namespace dmi
