// Basic system (element.hpp) and coordinate transformations (transform.hpp) against closed forms:
// stiffness EA/L, (EI/L)[[4,2],[2,4]] and its Timoshenko form, releases, mass and load vectors, rigid-body
// invariance of the corotational deformations and its tangent against a finite difference.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "engine/structure/transform.hpp"

namespace dmi {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double E = 200e9, nu = 0.3, rho = 7850, L = 2.0;

FrameElementDef def(const Section& s, bool rel_i = false, bool rel_j = false) {
  FrameElementDef d;
  d.section = s;
  d.E = E;
  d.nu = nu;
  d.rho = rho;
  d.release_i = rel_i;
  d.release_j = rel_j;
  return d;
}

void expect_matrix_near(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, double rel_tol) {
  EXPECT_LE((a - b).cwiseAbs().maxCoeff(), rel_tol * b.cwiseAbs().maxCoeff()) << a << "\n vs\n" << b;
}

TEST(Element, PrismaticEulerBernoulliStiffnessIsExact) {
  const Section s = Section::rectangle(0.1, 0.2);
  const BeamElement e(def(s), L, BeamTheory::euler_bernoulli);
  const double EA = E * s.area(0), EI = E * s.inertia(0);
  Mat3 k;
  k << EA / L, 0, 0, 0, 4 * EI / L, 2 * EI / L, 0, 2 * EI / L, 4 * EI / L;
  expect_matrix_near(e.stiffness(), k, 1e-13);
  expect_matrix_near(e.flexibility() * e.stiffness(), Mat3::Identity(), 1e-13);
}

TEST(Element, PrismaticTimoshenkoStiffnessIsExact) {
  const Section s = Section::rectangle(0.1, 0.6);  // deep: phi = 0.81
  const BeamElement e(def(s), L, BeamTheory::timoshenko);
  const double EI = E * s.inertia(0), G = E / (2 * (1 + nu)), phi = 12 * EI / (5.0 / 6.0 * G * s.area(0) * L * L);
  Mat3 k = Mat3::Zero();
  k(0, 0) = E * s.area(0) / L;
  k.bottomRightCorner<2, 2>() << 4 + phi, 2 - phi, 2 - phi, 4 + phi;
  k.bottomRightCorner<2, 2>() *= EI / (L * (1 + phi));
  expect_matrix_near(e.stiffness(), k, 1e-13);
}

TEST(Element, ReleasesCondenseTheEndMoment) {
  const Section s = Section::rectangle(0.1, 0.2);
  const double EI = E * s.inertia(0), EA = E * s.area(0);
  const BeamElement rj(def(s, false, true), L, BeamTheory::euler_bernoulli);
  Mat3 k = Mat3::Zero();
  k(0, 0) = EA / L;
  k(1, 1) = 3 * EI / L;  // propped cantilever end stiffness
  expect_matrix_near(rj.stiffness(), k, 1e-13);
  const BeamElement truss(def(s, true, true), L, BeamTheory::euler_bernoulli);
  k(1, 1) = 0;
  expect_matrix_near(truss.stiffness(), k, 1e-13);
  // Released end carries no moment; strain energy 0.5 q^T f q equals 0.5 v^T kb v.
  const Vec3 v(1e-4, 2e-3, -5e-3), q = rj.forces(v);
  EXPECT_EQ(q(2), 0.0);
  EXPECT_NEAR(rj.strain_energy(v), 0.5 * v.dot(q), 1e-9 * v.dot(q));
}

TEST(Element, TaperedFlexibilityMatchesIndependentIntegration) {
  const double b = 0.2, h0 = 0.4, h1 = 0.2;
  const BeamElement e(def(Section::tapered(b, h0, h1)), L, BeamTheory::euler_bernoulli);
  // Axial: int dx / (E b h) = L ln(h0/h1) / (E b (h0 - h1)).
  EXPECT_NEAR(e.flexibility()(0, 0), L * std::log(h0 / h1) / (E * b * (h0 - h1)), 1e-12 * e.flexibility()(0, 0));
  // Bending: composite Simpson on 20000 intervals of b^T b / EI.
  const int n = 20000;
  Eigen::Matrix2d f = Eigen::Matrix2d::Zero();
  for (int k = 0; k <= n; ++k) {
    const double x = static_cast<double>(k) / n, h = h0 + x * (h1 - h0), w = (k == 0 || k == n) ? 1 : (k % 2 ? 4 : 2);
    const Eigen::Vector2d bx(-(1 - x), x);
    f += w / (3.0 * n) * L * bx * bx.transpose() * 12 / (E * b * h * h * h);
  }
  expect_matrix_near(e.flexibility().bottomRightCorner<2, 2>(), f, 1e-10);
}

TEST(Element, PrismaticConsistentAndLumpedMass) {
  const Section s = Section::rectangle(0.1, 0.2);
  const BeamElement e(def(s), L, BeamTheory::euler_bernoulli);
  const double m = rho * s.area(0) * L;
  EXPECT_NEAR(e.mass(), m, 1e-12 * m);
  Mat6 mc = Mat6::Zero();
  mc(0, 0) = mc(3, 3) = m / 3;
  mc(0, 3) = mc(3, 0) = m / 6;
  const int w[4] = {1, 2, 4, 5};
  Eigen::Matrix4d t;
  t << 156, 22 * L, 54, -13 * L, 22 * L, 4 * L * L, 13 * L, -3 * L * L, 54, 13 * L, 156, -22 * L, -13 * L,
      -3 * L * L, -22 * L, 4 * L * L;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) mc(w[r], w[c]) = m / 420 * t(r, c);
  expect_matrix_near(e.consistent_mass(), mc, 1e-13);
  Vec6 ml;
  ml << m / 2, m / 2, m * L * L / 78, m / 2, m / 2, m * L * L / 78;  // HRZ
  expect_matrix_near(e.lumped_mass(), ml, 1e-13);
}

TEST(Element, TaperedLumpedMassKeepsTheElementMass) {
  const double b = 0.2, h0 = 0.4, h1 = 0.2;
  const BeamElement e(def(Section::tapered(b, h0, h1)), L, BeamTheory::euler_bernoulli);
  const double m = rho * b * L * (h0 + h1) / 2;
  EXPECT_NEAR(e.mass(), m, 1e-12 * m);
  EXPECT_NEAR(e.lumped_mass()(0) + e.lumped_mass()(3), m, 1e-12 * m);
  // Consistent mass: a rigid translation along e1 or e2 carries the element mass.
  const Vec6 ux = (Vec6() << 1, 0, 0, 1, 0, 0).finished(), uy = (Vec6() << 0, 1, 0, 0, 1, 0).finished();
  EXPECT_NEAR(ux.dot(e.consistent_mass() * ux), m, 1e-12 * m);
  EXPECT_NEAR(uy.dot(e.consistent_mass() * uy), m, 1e-12 * m);
  EXPECT_GT(e.lumped_mass()(0), e.lumped_mass()(3));  // the deep end is heavier
}

TEST(Element, EquivalentLoadsMatchHermiteConsistentLoads) {
  const BeamElement e(def(Section::rectangle(0.1, 0.2)), L, BeamTheory::euler_bernoulli);
  const double px = 300, py = -1000;
  Vec6 uniform;
  uniform << px * L / 2, py * L / 2, py * L * L / 12, px * L / 2, py * L / 2, -py * L * L / 12;
  expect_matrix_near(e.equivalent_loads({{px, py}, {px, py}}), uniform, 1e-13);
  Vec6 triangle;  // intensity p xi: int N^T p xi dx
  triangle << px * L / 6, 3 * py * L / 20, py * L * L / 30, px * L / 3, 7 * py * L / 20, -py * L * L / 20;
  expect_matrix_near(e.equivalent_loads({Vec2::Zero(), {px, py}}), triangle, 1e-13);
  // Self-weight is rho A g.
  const Vec2 g(0, -9.81);
  const double rhoA = rho * 0.02;
  expect_matrix_near(e.equivalent_loads(e.self_weight(g)), e.equivalent_loads({rhoA * g, rhoA * g}), 1e-13);
}

TEST(Element, ReleasedElementLoadsArePropedCantileverReactions) {
  const BeamElement e(def(Section::rectangle(0.1, 0.2), true, false), L, BeamTheory::euler_bernoulli);
  const double p = -1000;  // N/m along e2
  Vec6 f;
  f << 0, 3 * p * L / 8, 0, 0, 5 * p * L / 8, -p * L * L / 8;
  expect_matrix_near(e.equivalent_loads({{0, p}, {0, p}}), f, 1e-13);
}

TEST(Element, SectionForcesOfAClampedElementUnderUniformLoad) {
  const BeamElement e(def(Section::rectangle(0.1, 0.2)), L, BeamTheory::timoshenko);
  const double p = -1000;  // downward: hogging wL^2/12 at the clamps, sagging wL^2/24 at mid-span
  const ElementLoad w{{0, p}, {0, p}};
  EXPECT_NEAR(e.section_forces(Vec3::Zero(), L, w, 0).M, p * L * L / 12, 1e-9);
  EXPECT_NEAR(e.section_forces(Vec3::Zero(), L, w, 0.5).M, -p * L * L / 24, 1e-9);
  EXPECT_NEAR(e.section_forces(Vec3::Zero(), L, w, 0).V, -p * L / 2, 1e-9);
  EXPECT_NEAR(e.section_forces(Vec3::Zero(), L, w, 1).V, p * L / 2, 1e-9);
}

// Global end displacements that rotate the element rigidly by phi about node i.
Vec6 rigid_rotation(const Chord& c, double phi) {
  const Vec2 r = c.L0 * c.e1, rr = Eigen::Rotation2Dd(phi) * r;
  Vec6 d;
  d << 0, 0, phi, rr - r, phi;
  return d;
}

TEST(ElementTransform, CorotationalIsExactForLargeRigidRotations) {
  const Chord c{Vec2(1, 0.5), Vec2(std::cos(0.5), std::sin(0.5)), L};
  const CorotationalTransform corot;
  const LinearTransform lin;
  for (double phi : {0.3, kPi / 2, 2.0, 3.5, -2.9, 2 * kPi + 0.1}) {
    const Vec6 d = rigid_rotation(c, phi) + (Vec6() << 0.3, -0.2, 0, 0.3, -0.2, 0).finished();
    EXPECT_LT(corot.state(c, d).v.norm(), 1e-12) << phi;
    EXPECT_GT(lin.state(c, d).v.norm(), 0.005) << phi;  // the linear map sees spurious deformation
  }
}

TEST(ElementTransform, CorotationalStartsAsLinear) {
  const Chord c{Vec2(0, 0), Vec2(0.6, 0.8), L};
  const BeamElement e(def(Section::rectangle(0.1, 0.2)), L, BeamTheory::euler_bernoulli);
  const CorotationalTransform corot;
  const LinearTransform lin;
  const Mat6 kc = corot.tangent(corot.state(c, Vec6::Zero()), e.stiffness(), Vec3::Zero());
  const Mat6 kl = lin.tangent(lin.state(c, Vec6::Zero()), e.stiffness(), Vec3::Zero());
  expect_matrix_near(kc, kl, 1e-14);
  // Stiffness has exactly three rigid modes: rank 3.
  EXPECT_EQ(Eigen::FullPivLU<Mat6>(kl).setThreshold(1e-10).rank(), 3);
}

TEST(ElementTransform, CorotationalTangentMatchesFiniteDifference) {
  const Chord c{Vec2(0, 0), Vec2(std::cos(0.4), std::sin(0.4)), L};
  // A stocky tapered Timoshenko element so that axial and bending terms are of comparable size.
  const BeamElement e(def(Section::tapered(0.3, 0.8, 0.5)), L, BeamTheory::timoshenko);
  const CorotationalTransform corot;
  const auto force = [&](const Vec6& d) {
    const ChordState s = corot.state(c, d);
    return Vec6(s.B.transpose() * e.forces(s.v));
  };
  Vec6 d = rigid_rotation(c, 1.9);
  d += (Vec6() << 0.002, -0.01, 0.05, 0.013, 0.02, -0.08).finished();
  const ChordState s = corot.state(c, d);
  const Mat6 kt = corot.tangent(s, e.stiffness(), e.forces(s.v));
  EXPECT_GT(std::abs(e.forces(s.v)(0)), 1e6);  // large axial force: the geometric terms matter
  const double h = 1e-6;
  double worst = 0;
  for (int k = 0; k < 6; ++k) {
    Vec6 dp = d, dm = d;
    dp(k) += h;
    dm(k) -= h;
    const Vec6 col = (force(dp) - force(dm)) / (2 * h);
    for (int r = 0; r < 6; ++r)
      worst = std::max(worst, std::abs(col(r) - kt(r, k)) / std::sqrt(kt(r, r) * kt(k, k)));
  }
  EXPECT_LT(worst, 1e-6);
  EXPECT_LT((kt - kt.transpose()).norm(), 1e-9 * kt.norm());
}

}  // namespace
}  // namespace dmi
