// Frame statics against closed forms (Roark's Formulas for Stress and Strain, 8th ed., table 8.1): cantilever,
// simply supported and propped beams, Timoshenko shear deflection, springs, hinges, a tapered cantilever,
// global equilibrium of the reactions; and the input validation.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <numbers>
#include <stdexcept>
#include <string>

#include "tests/engine/structure/beam_models.hpp"

namespace dmi {
namespace {

using test::Beam;
using test::rel;
using test::straight;
using test::support;

constexpr double kPi = std::numbers::pi;
constexpr double P = 1e4;  // N
constexpr double w = 5e3;  // N/m

void expect_vec3(const Vec3& a, const Vec3& b, double tol) { EXPECT_LT((a - b).norm(), tol) << a.transpose(); }

TEST(FrameStatic, CantileverTipLoadDeflectionReactionAndStresses) {
  const Beam b;
  FrameModel m = straight(b, 4);
  support(m, 0, true, true, true);
  Frame f(m);
  f.add_nodal_load(4, Vec3(0, -P, 0));
  f.solve_static();
  const double L = b.L, EI = b.EI();
  EXPECT_LT(rel(f.displacement()(13), -P * L * L * L / (3 * EI)), 1e-10);
  EXPECT_LT(rel(f.displacement()(14), -P * L * L / (2 * EI)), 1e-10);
  expect_vec3(f.reaction(0), Vec3(0, P, P * L), 1e-6 * P);
  EXPECT_NEAR((f.curve(3).point(1) - f.node_position(4)).norm(), 0, 1e-14);
  // M(x) = -P (L - x), V = dM/dx = P; top fibre in tension at the root.
  EXPECT_NEAR(f.forces_at(0, 0).M, -P * L, 1e-6 * P);
  EXPECT_NEAR(f.forces_at(1, 0.5).M, -P * L * 5 / 8, 1e-6 * P);
  EXPECT_NEAR(f.forces_at(2, 0.3).V, P, 1e-6 * P);
  const double c = 0.1, I = b.section.inertia(0), A = b.section.area(0);
  const FibreStresses root = f.stresses_at(0, 0);
  EXPECT_NEAR(root.sigma_top, P * L * c / I, 1e-6 * P * L * c / I);
  EXPECT_NEAR(root.sigma_bottom, -P * L * c / I, 1e-6 * P * L * c / I);
  EXPECT_NEAR(root.tau_max, 1.5 * P / A, 1e-6 * P / A);
  EXPECT_NEAR(root.von_mises_max, P * L * c / I, 1e-6 * P * L * c / I);  // bending dominated: extreme fibre
  const FibreStresses tip = f.stresses_at(3, 1);                         // M = 0: shear at the neutral axis
  EXPECT_NEAR(tip.von_mises_max, std::sqrt(3.0) * 1.5 * P / A, 1e-4 * P / A);
  EXPECT_NEAR(tip.von_mises_top, 0, 1e-3 * P / A);
  EXPECT_DOUBLE_EQ(f.half_depth(2, 0.4), 0.1);
}

TEST(FrameStatic, CantileverUniformLoad) {
  const Beam b;
  FrameModel m = straight(b, 4);
  support(m, 0, true, true, true);
  Frame f(m);
  for (int e = 0; e < 4; ++e) f.add_distributed_load(e, Vec2(0, -w));
  f.solve_static();
  const double L = b.L, EI = b.EI();
  EXPECT_LT(rel(f.displacement()(13), -w * std::pow(L, 4) / (8 * EI)), 1e-10);
  EXPECT_LT(rel(f.displacement()(14), -w * std::pow(L, 3) / (6 * EI)), 1e-10);
  expect_vec3(f.reaction(0), Vec3(0, w * L, w * L * L / 2), 1e-6 * w);
  for (double xi : {0.0, 0.5, 1.0}) {  // M(x) = -w (L - x)^2 / 2 inside the element too
    const double x = xi * L / 4;
    EXPECT_NEAR(f.forces_at(0, xi).M, -w * (L - x) * (L - x) / 2, 1e-6 * w);
    EXPECT_NEAR(f.forces_at(0, xi).V, w * (L - x), 1e-6 * w);
  }
}

TEST(FrameStatic, InclinedCantileverUnderSelfWeight) {
  const Beam b;
  const double a = kPi / 6, g = 9.81, L = b.L;
  FrameModel m = straight(b, 4, a);
  support(m, 0, true, true, true);
  m.gravity = Vec2(0, -g);
  Frame f(m);
  f.solve_static();
  const Vec2 e1(std::cos(a), std::sin(a)), e2(-e1.y(), e1.x());
  const double qt = b.rhoA() * g * std::cos(a), qa = b.rhoA() * g * std::sin(a);  // transverse, axial (N/m)
  const Vec2 tip = f.displacement().segment<2>(12);
  EXPECT_LT(rel(tip.dot(e2), -qt * std::pow(L, 4) / (8 * b.EI())), 1e-10);
  EXPECT_LT(rel(tip.dot(e1), -qa * L * L / (2 * b.EA())), 1e-9);
  EXPECT_NEAR(f.forces_at(0, 0).N, -qa * L, 1e-6 * qa * L);
  EXPECT_NEAR(f.forces_at(1, 0.5).N, -qa * L * 5 / 8, 1e-6 * qa * L);
  EXPECT_NEAR(f.forces_at(1, 0.5).M, -qt * std::pow(L * 5 / 8, 2) / 2, 1e-6 * qt * L * L);
  expect_vec3(f.reaction(0), Vec3(0, b.rhoA() * g * L, b.rhoA() * g * L * L / 2 * std::cos(a)), 1e-6 * qt * L);
}

FrameModel simply_supported(const Beam& b, int n) {
  FrameModel m = straight(b, n);
  support(m, 0, true, true, false);
  support(m, n, false, true, false);
  return m;
}

TEST(FrameStatic, SimplySupportedPointAndUniformLoads) {
  const Beam b;
  const double L = b.L, EI = b.EI();
  Frame f(simply_supported(b, 2));
  f.add_nodal_load(1, Vec3(0, -P, 0));
  f.solve_static();
  EXPECT_LT(rel(f.displacement()(4), -P * L * L * L / (48 * EI)), 1e-10);
  expect_vec3(f.reaction(0), Vec3(0, P / 2, 0), 1e-6 * P);
  expect_vec3(f.reaction(1), Vec3(0, P / 2, 0), 1e-6 * P);
  EXPECT_NEAR(f.forces_at(0, 1).M, P * L / 4, 1e-6 * P);

  f.clear_loads();
  for (int e = 0; e < 2; ++e) f.add_distributed_load(e, Vec2(0, -w));
  f.solve_static();
  EXPECT_LT(rel(f.displacement()(4), -5 * w * std::pow(L, 4) / (384 * EI)), 1e-10);

  Frame one(simply_supported(b, 1));  // one element: exact end rotations and mid-span moment
  one.add_distributed_load(0, Vec2(0, -w));
  one.solve_static();
  EXPECT_LT(rel(one.displacement()(2), -w * std::pow(L, 3) / (24 * EI)), 1e-10);
  EXPECT_NEAR(one.forces_at(0, 0.5).M, w * L * L / 8, 1e-6 * w);
  EXPECT_NEAR(one.forces_at(0, 0).M, 0, 1e-6 * w);
  EXPECT_NEAR(one.forces_at(0, 0).V, w * L / 2, 1e-6 * w);  // V = dM/dx, M = w x (L - x) / 2
  expect_vec3(one.reaction(1), Vec3(0, w * L / 2, 0), 1e-6 * w);
}

TEST(FrameStatic, TimoshenkoCantileverAddsShearDeflection) {
  Beam b;
  b.section = Section::rectangle(0.1, 0.6);
  FrameModel m = straight(b, 1);
  m.theory = BeamTheory::timoshenko;
  support(m, 0, true, true, true);
  Frame f(m);
  f.add_nodal_load(1, Vec3(0, -P, 0));
  f.solve_static();
  const double G = b.E / (2 * (1 + b.nu)), shear = P * b.L / (5.0 / 6.0 * G * b.section.area(0));
  const double bending = P * std::pow(b.L, 3) / (3 * b.EI());
  EXPECT_GT(shear, 0.05 * bending);
  EXPECT_LT(rel(f.displacement()(4), -(bending + shear)), 1e-10);
  EXPECT_LT(rel(f.displacement()(5), -P * b.L * b.L / (2 * b.EI())), 1e-10);
}

TEST(FrameStatic, TranslationalAndRotationalSprings) {
  const Beam b;
  const double L = b.L, EI = b.EI(), k = 3 * EI / (L * L * L);
  FrameModel m = straight(b, 2);
  support(m, 0, true, true, true);
  m.supports.push_back({2, {false, false, false}, {0, k, 0}});  // tip on a spring as stiff as the beam
  Frame f(m);
  f.add_nodal_load(2, Vec3(0, -P, 0));
  f.solve_static();
  EXPECT_LT(rel(f.displacement()(7), -P / (2 * k)), 1e-10);
  expect_vec3(f.reaction(1), Vec3(0, P / 2, 0), 1e-6 * P);
  expect_vec3(f.reaction(0) + f.reaction(1), Vec3(0, P, f.reaction(0)(2)), 1e-6 * P);

  FrameModel r = straight(b, 2);  // pinned base with a rotational spring: tip = P L^3/(3 EI) + P L^2 / k_r
  const double kr = EI / L;
  r.supports.push_back({0, {true, true, false}, {0, 0, kr}});
  Frame g(r);
  g.add_nodal_load(2, Vec3(0, -P, 0));
  g.solve_static();
  EXPECT_LT(rel(g.displacement()(7), -(P * L * L * L / (3 * EI) + P * L * L / kr)), 1e-10);
  expect_vec3(g.reaction(0), Vec3(0, P, P * L), 1e-6 * P);
}

TEST(FrameStatic, InternalHingeSplitsAFixedBeamIntoTwoCantilevers) {
  const Beam b;
  const double L = b.L, EI = b.EI();
  FrameModel m = straight(b, 2);
  m.elements[0].release_j = true;
  support(m, 0, true, true, true);
  support(m, 2, true, true, true);
  Frame f(m);
  f.add_nodal_load(1, Vec3(0, -P, 0));
  f.solve_static();
  EXPECT_LT(rel(f.displacement()(4), -(P / 2) * std::pow(L / 2, 3) / (3 * EI)), 1e-10);
  expect_vec3(f.reaction(0), Vec3(0, P / 2, P * L / 4), 1e-6 * P);
  expect_vec3(f.reaction(1), Vec3(0, P / 2, -P * L / 4), 1e-6 * P);
  EXPECT_NEAR(f.forces_at(0, 1).M, 0, 1e-6 * P);
  EXPECT_NEAR(f.forces_at(1, 0).M, 0, 1e-6 * P);
}

TEST(FrameStatic, ReleaseWithElementLoadGivesProppedCantilever) {
  const Beam b;
  const double L = b.L;
  for (bool release : {false, true}) {
    // Fixed at 0 and a roller at L, or (release) fixed at both ends with a hinge at 0: mirror images.
    FrameModel m = straight(b, 1);
    m.elements[0].release_i = release;
    support(m, 0, true, true, true);
    support(m, 1, !release, true, release);
    Frame f(m);
    f.add_distributed_load(0, Vec2(0, -w));
    f.solve_static();
    const Vec3 r0 = f.reaction(0), r1 = f.reaction(1);
    const double clamp = w * L * L / 8;
    expect_vec3(r0, release ? Vec3(0, 3 * w * L / 8, 0) : Vec3(0, 5 * w * L / 8, clamp), 1e-6 * w);
    expect_vec3(r1, release ? Vec3(0, 5 * w * L / 8, -clamp) : Vec3(0, 3 * w * L / 8, 0), 1e-6 * w);
    EXPECT_NEAR(f.forces_at(0, release ? 1 : 0).M, -clamp, 1e-6 * w);
    EXPECT_NEAR(f.forces_at(0, release ? 0 : 1).M, 0, 1e-6 * w);
  }
}

TEST(FrameStatic, TaperedCantileverMatchesFineSubdivision) {
  Beam b;
  b.section = Section::tapered(0.1, 0.4, 0.2);
  const auto tip = [&](const FrameModel& model) {
    FrameModel m = model;
    support(m, 0, true, true, true);
    Frame f(m);
    f.add_nodal_load(f.nnodes() - 1, Vec3(0, -P, 0));
    f.solve_static();
    return f.displacement()(3 * (f.nnodes() - 1) + 1);
  };
  const double one = tip(straight(b, 1));
  // Force interpolation is exact for a tip load, so chaining tapered elements changes nothing.
  EXPECT_LT(rel(tip(straight(b, 8)), one), 1e-9);
  FrameModel prismatic = straight(b, 64);  // 64 prismatic elements at their mid-depth
  for (int e = 0; e < 64; ++e) prismatic.elements[e].section = Section::rectangle(0.1, 0.4 - 0.2 * (e + 0.5) / 64);
  const double fine = tip(prismatic);
  std::cout << "tapered cantilever tip: 1 element " << one << " m, 64 prismatic " << fine << " m, rel diff "
            << rel(fine, one) << "\n";
  EXPECT_LT(rel(fine, one), 1e-3);
  // Bounds: between the prismatic cantilevers at the shallow and at the deep end.
  EXPECT_GT(-one, P * std::pow(b.L, 3) / (3 * b.E * Section::rectangle(0.1, 0.4).inertia(0)));
  EXPECT_LT(-one, P * std::pow(b.L, 3) / (3 * b.E * Section::rectangle(0.1, 0.2).inertia(0)));
}

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

TEST(FrameStatic, ReactionsBalanceAllAppliedLoads) {
  const Beam b;
  FrameModel m;
  m.nodes = {{0, 0}, {0, 3}, {2.5, 4}, {5, 3}, {5, 0}};
  const Section pipe = Section::pipe(0.3, 0.01);
  for (int e = 0; e < 4; ++e) {
    FrameElementDef d;
    d.i = e;
    d.j = e + 1;
    d.section = e == 1 || e == 2 ? pipe : b.section;
    d.E = b.E;
    d.nu = b.nu;
    d.rho = b.rho;
    m.elements.push_back(d);
  }
  support(m, 0, true, true, true);
  support(m, 4, true, true, false);
  m.gravity = Vec2(0, -9.81);
  Frame f(m);
  Vec2 force = Vec2::Zero();
  double moment = 0;  // about the origin
  const auto apply = [&](const Vec2& at, const Vec2& F, double mz) {
    force += F;
    moment += cross(at, F) + mz;
  };
  f.add_nodal_load(1, Vec3(5e3, 0, 2e3));
  apply(m.nodes[1], Vec2(5e3, 0), 2e3);
  f.add_point_load(1, 0.3, Vec2(1e3, -4e3), 500);
  apply(m.nodes[1] + 0.3 * (m.nodes[2] - m.nodes[1]), Vec2(1e3, -4e3), 500);
  f.add_distributed_load(2, Vec2(300, -2e3));
  const Vec2 e1 = (m.nodes[3] - m.nodes[2]).normalized(), e2(-e1.y(), e1.x());
  const double L2 = (m.nodes[3] - m.nodes[2]).norm();
  apply(0.5 * (m.nodes[2] + m.nodes[3]), L2 * (300 * e1 - 2e3 * e2), 0);
  for (int e = 0; e < 4; ++e) {
    const FrameElementDef& d = m.elements[e];
    const double mass = d.rho * d.section.area(0) * (m.nodes[d.j] - m.nodes[d.i]).norm();
    apply(0.5 * (m.nodes[d.i] + m.nodes[d.j]), mass * m.gravity, 0);
  }
  f.solve_static();
  for (int k = 0; k < 2; ++k) {
    const Vec3 r = f.reaction(k);
    apply(m.nodes[m.supports[k].node], r.head<2>(), r(2));
  }
  EXPECT_LT(force.norm(), 1e-8 * 5e3);
  EXPECT_LT(std::abs(moment), 1e-8 * 5e3);
}

void expect_invalid(const std::function<void()>& fn, const std::string& needle) {
  try {
    fn();
    ADD_FAILURE() << "no exception, expected one naming '" << needle << "'";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}

TEST(FrameStatic, RejectsInvalidModelsNamingTheCulprit) {
  const Beam b;
  const auto base = [&] {
    FrameModel m = straight(b, 2);
    support(m, 0, true, true, true);
    return m;
  };
  expect_invalid([&] { FrameModel m = base(); m.elements[1].j = 7; Frame f(m); }, "element 1");
  expect_invalid([&] { FrameModel m = base(); m.nodes[2] = m.nodes[1]; Frame f(m); }, "element 1: zero length");
  expect_invalid([&] { FrameModel m = base(); m.elements[0].E = 0; Frame f(m); }, "element 0");
  expect_invalid([&] { FrameModel m = base(); m.elements[1].rho = -1; Frame f(m); }, "element 1");
  expect_invalid([&] { FrameModel m = base(); m.elements[1].section = Section(); Frame f(m); }, "element 1: section");
  expect_invalid([&] { FrameModel m = base(); m.supports[0].node = 9; Frame f(m); }, "support 0");
  expect_invalid([&] { FrameModel m = base(); m.supports.clear(); Frame f(m); }, "mechanism");
  expect_invalid([&] {
    FrameModel m = base();
    m.elements[0].release_j = m.elements[1].release_i = true;
    Frame f(m);
  }, "rz of node 1");
  Frame f(base());
  expect_invalid([&] { f.forces_at(2, 0.5); }, "element index 2");
  expect_invalid([&] { f.velocity_at(0, 1.5); }, "element 0");
  expect_invalid([&] { f.add_nodal_load(3, Vec3::Zero()); }, "node index 3");
  expect_invalid([&] { f.advance(0); }, "dt");
  EXPECT_THROW(Section::pipe(0.2, 0.11), std::invalid_argument);  // wall thicker than the radius
}

}  // namespace
}  // namespace dmi
