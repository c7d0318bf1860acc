// The space frame's corotational transformation: rigid motions exact, the linear transformation at the start, the
// tangent as the derivative of the internal force, a cantilever curled into a half circle by an end moment about
// either section axis or a skew one (the chord polygon of uniformly bent elements), a large twist (rotation about a
// fixed axis: T L / (G J) exactly), and small motion as the linear transformation.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "engine/structure/space_frame.hpp"
#include "engine/structure/space_frame_system.hpp"
#include "engine/structure/space_transform.hpp"

namespace dmi {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double E = 200e9, nu = 0.3, rho = 7850;

SpaceChord chord_of(const Vec3& a, const Vec3& b, const Vec3& o = Vec3::Zero()) {
  SpaceChord c{a, Eigen::Matrix3d::Identity(), (b - a).norm()};
  EXPECT_TRUE(local_axes((b - a) / c.L0, o, c.R));
  return c;
}

TEST(SpaceCorotational, RigidMotionsLeaveNoDeformation) {
  const SpaceChord c = chord_of(Vec3(0.3, -1, 2), Vec3(2, 0.5, 1.2), Vec3(0, 0, 1));
  const CorotationalSpaceTransform t;
  for (const Vec3& psi : {Vec3(0.4, -1.2, 2.0), Vec3(0, 0, 3.0), Vec3(1e-9, 2e-9, 0)}) {
    const Eigen::Matrix3d Q = rotation_exp(psi);
    const Vec3 shift(0.7, -0.2, 5), Xj = c.X + c.L0 * c.R.row(0).transpose();
    Vec12 d;
    d << shift, psi, shift + (Q - Eigen::Matrix3d::Identity()) * (Xj - c.X), psi;
    const SpaceChordState s = t.state(c, d);
    EXPECT_LT(s.v.norm(), 1e-12) << psi.transpose();
    EXPECT_LT((s.R - c.R * Q.transpose()).norm(), 1e-12);  // the frame turned with the body
  }
  EXPECT_LT((rotation_log(rotation_exp(Vec3(0.3, 2.5, -1))) - Vec3(0.3, 2.5, -1)).norm(), 1e-12);
}

TEST(SpaceCorotational, StartsAsTheLinearTransformation) {
  const SpaceChord c = chord_of(Vec3(1, 2, 3), Vec3(-1, 4, 3.5), Vec3(0.2, 0.1, 1));
  const SpaceChordState a = LinearSpaceTransform().state(c, Vec12::Zero()), b = CorotationalSpaceTransform().state(c, Vec12::Zero());
  EXPECT_LT((a.B - b.B).norm(), 1e-12 * a.B.norm());
  EXPECT_LT((a.R - b.R).norm(), 1e-14);
}

TEST(SpaceCorotational, TangentIsTheDerivativeOfTheInternalForce) {
  SpaceElementDef def;
  def.section = Section::rectangle(0.2, 0.35), def.E = E, def.nu = nu, def.rho = rho;
  const SpaceChord c = chord_of(Vec3(0, 0, 0), Vec3(1.5, 0.4, -0.3));
  const SpaceBeamElement el(def, c.L0, BeamTheory::euler_bernoulli);
  const CorotationalSpaceTransform t;
  Vec12 d;
  d << 0.01, -0.02, 0.03, 0.3, -0.5, 0.2, 0.05, 0.12, -0.04, -0.1, 0.4, 0.6;
  const auto force = [&](const Vec12& x) -> Vec12 {
    const SpaceChordState s = t.state(c, x);
    return s.B.transpose() * el.forces(s.v);
  };
  const SpaceChordState s = t.state(c, d);
  const Mat12 K = t.tangent(c, d, s, el.stiffness(), el.forces(s.v));
  Mat12 Kfd;
  for (int k = 0; k < 12; ++k) {
    const double h = 1e-6;
    Vec12 p = d, m = d;
    p(k) += h, m(k) -= h;
    Kfd.col(k) = (force(p) - force(m)) / (2 * h);
  }
  EXPECT_LT((K - Kfd).norm(), 1e-5 * Kfd.norm());
}

// A cantilever along x, end moment M = pi E I / L about the unit axis n normal to it, in 10 static load steps or
// ramped quasi-statically (Newmark, mass damping critical for the first mode): each element bends uniformly and keeps
// its chord L / n_e, so the chords form a polygon, its tip at L / (n_e sin(pi / (2 n_e))) along n x e_x, turned by pi
// about n.
void curl(const Vec3& n, const Section& s, const char* label, bool dynamic) {
  const double L = 2;
  const int ne = 16;
  SpaceFrameModel m;
  for (int k = 0; k <= ne; ++k) m.nodes.push_back(Vec3(L * k / ne, 0, 0));
  for (int k = 0; k < ne; ++k) {
    SpaceElementDef e;
    e.i = k, e.j = k + 1, e.section = s, e.E = E, e.nu = nu, e.rho = rho;
    m.elements.push_back(e);
  }
  m.supports.push_back(SpaceSupportDef::fixed_support(0));
  m.integrator = FrameIntegrator::newmark;
  m.transform = FrameTransform::corotational;
  const double w1 = SpaceFrame(m).natural_frequencies(1)[0], T = 2 * kPi / w1;
  m.rayleigh_mass = 2 * w1;
  SpaceFrame f(m);
  const double EI = E * s.inertia(0), M = kPi * EI / L;
  Vec6 load;
  load << 0, 0, 0, M * n;
  if (!dynamic) {
    f.add_nodal_load(ne, load);
    f.solve_static(10);
  }
  for (int k = 1; dynamic && k <= 400; ++k) {
    const double ramp = k >= 200 ? 1.0 : 0.5 * (1 - std::cos(kPi * k / 200));
    f.clear_loads();
    f.add_nodal_load(ne, ramp * load);
    f.advance(T / 20);
  }
  const Vec3 tip = f.node_position(ne), expected = L / (ne * std::sin(kPi / (2 * ne))) * n.cross(Vec3::UnitX());
  const Vec3 psi = f.displacement().segment<3>(6 * ne + 3);
  std::printf("corotational half circle (%s): tip error %.2e m, tip rotation / pi = %.6f\n", label, (tip - expected).norm(), psi.dot(n) / kPi);
  EXPECT_LT((tip - expected).norm(), 1e-3 * L) << label;
  EXPECT_LT((psi - kPi * n).norm(), 1e-3) << label;
  const SpaceSectionForces mid = f.forces_at(ne / 2, 0.5);
  EXPECT_NEAR(std::hypot(mid.My, mid.Mz), M, 1e-3 * M) << label;
  EXPECT_NEAR(mid.N, 0, 1e-3 * M / L) << label;
  EXPECT_NEAR(mid.T, 0, 1e-3 * M) << label;
  // The centre-line inside an element lies on the circle of radius L / pi through the root.
  const Vec3 c = (L / kPi) * n.cross(Vec3::UnitX());
  const Vec3 x = m.nodes[3] + 0.5 * (m.nodes[4] - m.nodes[3]) + f.displacement_at(3, 0.5);
  EXPECT_NEAR((x - c).norm(), L / kPi, 2e-3 * L) << label;
}

TEST(SpaceCorotational, EndMomentCurlsACantileverIntoAHalfCircle) {
  curl(Vec3::UnitZ(), Section::rectangle(0.05, 0.05), "about z, static", false);
  curl(Vec3::UnitY(), Section::rectangle(0.05, 0.05), "about y, static", false);
  curl(Vec3(0, 0.6, 0.8), Section::pipe(0.08, 0.004), "skew, pipe, static", false);
  curl(Vec3(0, 0.6, 0.8), Section::pipe(0.08, 0.004), "skew, pipe, damped Newmark", true);
}

TEST(SpaceCorotational, LargeTwistIsLinearInTheTorque) {
  const double L = 3;
  const Section s = Section::pipe(0.1, 0.005);
  SpaceFrameModel m;
  for (int k = 0; k <= 4; ++k) m.nodes.push_back(Vec3(0, L * k / 4, 0));  // a column along y
  for (int k = 0; k < 4; ++k) {
    SpaceElementDef e;
    e.i = k, e.j = k + 1, e.section = s, e.E = E, e.nu = nu, e.rho = rho;
    m.elements.push_back(e);
  }
  m.supports.push_back(SpaceSupportDef::fixed_support(0));
  m.transform = FrameTransform::corotational;
  SpaceFrame f(m);
  const double GJ = E / (2 * (1 + nu)) * s.torsion_constant(0), Tq = 1.5 * GJ / L;  // 1.5 rad at the top
  Vec6 load;
  load << 0, 0, 0, 0, Tq, 0;
  f.add_nodal_load(4, load);
  f.solve_static(3);
  EXPECT_NEAR(f.displacement()(24 + 4), 1.5, 1e-6);
  EXPECT_LT(f.displacement().segment<3>(24).norm(), 1e-9);
  EXPECT_NEAR(f.forces_at(1, 0.5).T, Tq, 1e-6 * Tq);
}

TEST(SpaceCorotational, SmallMotionFollowsTheLinearTransformation) {
  const Section s = Section::rectangle(0.1, 0.2);
  SpaceFrameModel m;
  for (int k = 0; k <= 4; ++k) m.nodes.push_back(Vec3(2.0 * k / 4, 0, 0));
  for (int k = 0; k < 4; ++k) {
    SpaceElementDef e;
    e.i = k, e.j = k + 1, e.section = s, e.E = E, e.nu = nu, e.rho = rho;
    m.elements.push_back(e);
  }
  m.supports.push_back(SpaceSupportDef::fixed_support(0));
  SpaceFrameModel mc = m;
  mc.transform = FrameTransform::corotational;
  SpaceFrame lin(m), cor(mc);
  EXPECT_DOUBLE_EQ(lin.stable_time_step(), cor.stable_time_step());
  Vec6 load;
  load << 0, 1e3, 2e3, 50, 0, 0;
  lin.add_nodal_load(4, load);
  cor.add_nodal_load(4, load);
  const double dt = 0.5 * lin.stable_time_step();
  double worst = 0, amp = 0;
  for (int k = 0; k < 2000; ++k) {
    lin.advance(dt), cor.advance(dt);
    worst = std::max(worst, (lin.displacement() - cor.displacement()).cwiseAbs().maxCoeff());
    amp = std::max(amp, lin.displacement().cwiseAbs().maxCoeff());
  }
  EXPECT_LT(worst, 1e-3 * amp);
}

}  // namespace
}  // namespace dmi
