// Elasto-plastic fibre beam-columns: the steel law by hand, a fibre section's moment-curvature against the plastic
// moment and shape factor, a bar with a tip mass against the exact elastic-perfectly-plastic SDOF response to a
// rectangular pulse, and the plastic collapse load of a fixed-end beam (Neal 1977) under refinement.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "engine/structure/fibre_beam.hpp"
#include "engine/structure/space_frame.hpp"
#include "tests/engine/structure/beam_models.hpp"

namespace dmi {
namespace {

using test::Beam;
using test::rel;

TEST(SteelLaw, BilinearKinematicHardeningByHand) {
  const SteelLaw law{200e9, 250e6, 0.02};  // eps_y = 1.25e-3, E_t = 4 GPa, H = 4.0816 GPa
  FibreHistory h;
  FibreResponse r = steel_response(law, h, 1e-3);
  EXPECT_DOUBLE_EQ(r.sigma, 200e6);
  EXPECT_DOUBLE_EQ(r.tangent, 200e9);
  r = steel_response(law, h, 2.5e-3);  // 250 + 4 GPa (2.5e-3 - 1.25e-3) = 255 MPa
  EXPECT_NEAR(r.sigma, 255e6, 1e-3);
  EXPECT_NEAR(r.tangent, 4e9, 1e-3);
  h = r.history;                       // back stress 5 MPa: reversed yield at 255 - 500 = -245 MPa
  r = steel_response(law, h, 2.5e-3 - 2.45e-3);
  EXPECT_NEAR(r.sigma, 255e6 - 200e9 * 2.45e-3, 1e-3);  // -235 MPa: still elastic
  EXPECT_DOUBLE_EQ(r.tangent, 200e9);
  r = steel_response(law, h, -0.5e-3);  // reversed yield at -245 MPa reached at eps = 0, then E_t: -245 - 4 GPa 0.5e-3
  EXPECT_NEAR(r.sigma, -247e6, 1e-3);
  EXPECT_NEAR(r.tangent, 4e9, 1e-3);
}

// One element under constant curvature (v = [0, -theta, theta]: kappa = 2 theta / L everywhere), its end moment q_j = M.
double moment_at(const Section& s, double kappa, const SteelLaw& law) {
  const double L = 1;
  FibreBeam<1> b(s, 0, 1, L, law, 3);
  FibreBeam<1>::VecV v(0, -0.5 * kappa * L, 0.5 * kappa * L), q;
  b.respond(v, q, nullptr);
  return q(2);
}

TEST(FibreBeam, MomentCurvatureReachesThePlasticMoment) {
  const SteelLaw law{200e9, 355e6, 0.0};
  // Rectangle 0.1 x 0.2: I = b h^3 / 12, M_p = f_y b h^2 / 4, shape factor 1.5; M(kappa) = M_p (1 - (kappa_y/kappa)^2 / 3).
  const Section rect = Section::rectangle(0.1, 0.2);
  const double ky = law.fy / (law.E * 0.1), Mp = law.fy * 0.1 * 0.04 / 4, Mel = law.fy * rect.inertia(0) / 0.1;
  EXPECT_NEAR(moment_at(rect, 0.5 * ky, law) / (0.5 * law.E * rect.inertia(0) * ky), 1.0, 1e-12);  // elastic: EI exact
  EXPECT_NEAR(moment_at(rect, 3 * ky, law) / (Mp * (1 - 1.0 / 27)), 1.0, 2e-3);
  EXPECT_NEAR(moment_at(rect, 50 * ky, law) / Mp, 1.0, 2e-3);
  EXPECT_NEAR(Mp / Mel, 1.5, 1e-12);
  // CHS 0.5 x 0.016: M_p = f_y (D^3 - d^3) / 6 (EN 1993-1-1 W_pl); discretisation 2 rings x 32 fibres.
  const double D = 0.5, t = 0.016, d = D - 2 * t;
  const Section pipe = Section::pipe(D, t);
  const double Mp_pipe = law.fy * (D * D * D - d * d * d) / 6, ky_pipe = law.fy / (law.E * 0.5 * D);
  EXPECT_NEAR(moment_at(pipe, 0.5 * ky_pipe, law) / (0.5 * law.E * pipe.inertia(0) * ky_pipe), 1.0, 1e-12);
  EXPECT_NEAR(moment_at(pipe, 50 * ky_pipe, law) / Mp_pipe, 1.0, 2e-3);
}

// The exact response of an elastic-perfectly-plastic SDOF (m, k, R_y) at rest under F0 for td (Biggs 1964, ch. 2):
// elastic arcs x = x_p + F/k + A cos wt + B sin wt and plastic parabolas m x'' = F - R_y, joined at their events.
double epp_peak(double m, double k, double Ry, double F0, double td) {
  const double w = std::sqrt(k / m);
  double t = 0, x = 0, v = 0, xp = 0, peak = 0;
  const double dt = 1e-6 / w;  // marching the closed forms by a fine step to find the events (peak error ~ dt^2)
  bool plastic = false;
  while (t < 10 * td + 20 / w) {
    const double F = t < td ? F0 : 0.0;
    if (!plastic) {
      const double x0 = x - xp - F / k, c = std::cos(w * dt), s = std::sin(w * dt);
      const double xn = xp + F / k + x0 * c + v / w * s, vn = -x0 * w * s + v * c;
      x = xn, v = vn;
      if (k * (x - xp) > Ry && v > 0) plastic = true, xp = x - Ry / k;
    } else {
      const double a = (F - Ry) / m;
      x += v * dt + 0.5 * a * dt * dt, v += a * dt;
      xp = x - Ry / k;
      if (v <= 0) plastic = false;
    }
    t += dt;
    peak = std::max(peak, x);
    if (t > td && !plastic && v < 0 && x < peak) break;  // past the peak and unloading elastically
  }
  return peak;
}

TEST(FibreBeam, BarWithTipMassFollowsTheExactElasticPlasticSdof) {
  // Bar L 1 m, A from a 0.02 x 0.02 rectangle, E 200 GPa, f_y 250 MPa (R_y 100 kN), tip mass 1 t; light bar.
  const double L = 1, A = 4e-4, E = 200e9, fy = 250e6, m = 1000, k = E * A / L, Ry = fy * A;
  const double T = 2 * std::numbers::pi * std::sqrt(m / k);
  for (double ratio : {1.2, 1.5}) {  // F0 / R_y
    FrameModel fm;
    fm.nodes = {Vec2(0, 0), Vec2(L, 0)};
    FrameElementDef e;
    e.i = 0, e.j = 1, e.section = Section::rectangle(0.02, 0.02), e.E = E, e.nu = 0.3, e.rho = 1e-3;
    e.steel = SteelLaw{E, fy, 0.0};
    fm.elements = {e};
    fm.members = {{"bar", 0, 1}};
    test::support(fm, 0, true, true, true);
    test::support(fm, 1, false, true, true);
    fm.masses = {{1, m, 0.0}};
    fm.integrator = FrameIntegrator::newmark;
    Frame f(fm);
    // Loads held over a step enter the average-acceleration rule as the mean of its end values: n steps under F0
    // impose a pulse of (n + 1/2) dt (the acceleration at t = 0 already feels F0).
    const int n = 1000, steps = 5000;
    const double dt = T / 2000, td = (n + 0.5) * dt, F0 = ratio * Ry;
    double peak = 0;
    for (int s = 0; s < steps; ++s) {
      f.clear_loads();
      if (s < n) f.add_nodal_load(1, Vec3(F0, 0, 0));
      f.advance(dt);
      peak = std::max(peak, f.displacement()(3));
    }
    const double exact = epp_peak(m, k, Ry, F0, td);
    EXPECT_LT(rel(peak, exact), 2e-3) << "F0/Ry " << ratio << ": " << peak << " against " << exact;
    EXPECT_GT(f.plastic_work(), 0);
    // Energy: plastic work = R_y (peak - R_y / k) for one excursion into yield.
    EXPECT_LT(rel(f.plastic_work(), Ry * (exact - Ry / k)), 5e-3);
  }
}

// Fixed-end beam with a central point load: collapse load P_c = 8 M_p / L (Neal 1977, sec. 2.4), hinges at the ends and
// the centre. A spring under the centre node keeps the load-controlled solution stable past the collapse load; the
// beam's share P - k_s u traces its resistance. Loaded quasi-statically: a ramp over ~100 periods, then held.
double fixed_beam_resistance(int elements) {
  Beam b;
  b.L = 2.0;
  const int n = elements;
  FrameModel fm = test::straight(b, n);
  for (auto& e : fm.elements) e.steel = SteelLaw{b.E, 355e6, 0.0};
  test::support(fm, 0, true, true, true);
  test::support(fm, n, true, true, true);
  const double ks = 192 * b.EI() / std::pow(b.L, 3), Mp = 355e6 * 0.1 * 0.04 / 4, Pc = 8 * Mp / b.L;
  FrameSupportDef s;
  s.node = n / 2;
  s.spring[1] = ks;
  fm.supports.push_back(s);
  fm.integrator = FrameIntegrator::newmark;
  Frame f(fm);
  const double P = 21 * Pc;  // the spring takes 20 P_c: the centre deflects ~20 times the collapse deflection
  f.add_nodal_load(n / 2, Vec3(0, -P, 0));
  f.solve_static(400);
  return (P + ks * f.displacement()(3 * (n / 2) + 1)) / Pc;
}

TEST(FibreBeam, FixedEndBeamCollapseLoadAtEveryRefinement) {
  for (int n : {2, 4, 8, 16}) EXPECT_NEAR(fixed_beam_resistance(n), 1.0, 2e-3) << n << " elements";
}

}  // namespace
}  // namespace dmi

namespace dmi {
namespace {

// Fixed-base portal frame (Neal 1977, ch. 3): columns h = 4 m, beam L = 4 m, sway load lambda P at the left beam end and
// lambda 2P at midspan; mechanisms: beam lambda P = M_p, sway lambda P = M_p, combined lambda P (h + L) = 6 M_p, which
// governs: lambda_c P = 0.75 M_p / m. Sections 0.1 x 0.2 rectangles (the column's axial force, 4 % of its squash
// load, lowers M_p by 0.14 %). Equilibrium is found at 0.99 lambda_c with the sway below 20 times the elastic
// sway there; at 1.01 lambda_c there is none (the static solution fails or runs away).
double portal_sway(double lambda_ratio, double* elastic_sway) {
  const double h = 4, L = 4, E = 200e9, fy = 355e6;
  FrameModel fm;
  fm.nodes = {Vec2(0, 0), Vec2(0, h / 2), Vec2(0, h), Vec2(L / 2, h), Vec2(L, h), Vec2(L, h / 2), Vec2(L, 0)};
  for (int k = 0; k + 1 < 7; ++k) {
    FrameElementDef e;
    e.i = k, e.j = k + 1, e.section = Section::rectangle(0.1, 0.2), e.E = E, e.nu = 0.3, e.rho = 7850;
    e.steel = SteelLaw{E, fy, 0.0};
    e.member = k / 2;
    fm.elements.push_back(e);
  }
  fm.members = {{"left", 0, 2}, {"beam", 2, 2}, {"right", 4, 2}};
  test::support(fm, 0, true, true, true);
  test::support(fm, 6, true, true, true);
  const double Mp = fy * 0.1 * 0.04 / 4, P = 0.75 * Mp * lambda_ratio;
  Frame f(fm);
  f.add_nodal_load(2, Vec3(P, 0, 0));
  f.add_nodal_load(3, Vec3(0, -2 * P, 0));
  f.solve_static(200);
  if (elastic_sway) {  // the same frame elastic, same loads
    for (auto& e : fm.elements) e.steel = SteelLaw{};
    Frame g(fm);
    g.add_nodal_load(2, Vec3(P, 0, 0));
    g.add_nodal_load(3, Vec3(0, -2 * P, 0));
    g.solve_static(1);
    *elastic_sway = g.displacement()(6);
  }
  return f.displacement()(6);
}

TEST(FibreBeam, PortalFrameCollapsesByTheCombinedMechanism) {
  double elastic = 0;
  const double below = portal_sway(0.99, &elastic);
  std::printf("portal sway at 0.99 lambda_c: %.4g m, elastic %.4g m\n", below, elastic);
  EXPECT_GT(below, elastic);
  EXPECT_LT(below, 20 * elastic);
  bool collapsed = false;
  try {
    collapsed = !(portal_sway(1.01, nullptr) < 1e3 * elastic);
  } catch (const std::runtime_error&) {
    collapsed = true;
  }
  EXPECT_TRUE(collapsed);
}

}  // namespace
}  // namespace dmi

namespace dmi {
namespace {

// A space cantilever pipe (D 0.3 m, t 10 mm, L 2 m) under a tip load at 45 degrees between its section axes: the root
// hinge forms under the resultant moment, P_c = M_p / L with M_p = f_y (D^3 - d^3) / 6 in any direction (a circle);
// springs at the tip (k = 3 EI / L^3 along y and z) carry it past collapse as in the fixed beam above.
TEST(FibreBeam, SpaceCantileverPipeYieldsUnderTheResultantMoment) {
  const double L = 2, D = 0.3, t = 0.01, d = D - 2 * t, E = 200e9, fy = 355e6;
  const double Mp = fy * (D * D * D - d * d * d) / 6, Pc = Mp / L;
  for (int n : {1, 4}) {
    SpaceFrameModel m;
    for (int k = 0; k <= n; ++k) m.nodes.push_back(Vec3(L * k / n, 0, 0));
    for (int k = 0; k < n; ++k) {
      SpaceElementDef e;
      e.i = k, e.j = k + 1, e.section = Section::pipe(D, t), e.E = E, e.nu = 0.3, e.rho = 7850, e.orientation = Vec3::UnitY();
      e.steel = SteelLaw{E, fy, 0.0};
      m.elements.push_back(e);
    }
    m.members = {{"cantilever", 0, n}};
    m.supports.push_back(SpaceSupportDef::fixed_support(0));
    const double ks = 3 * E * Section::pipe(D, t).inertia(0) / (L * L * L);
    SpaceSupportDef tip;
    tip.node = n;
    tip.spring[1] = tip.spring[2] = ks;
    m.supports.push_back(tip);
    SpaceFrame f(m);
    const double P = 11 * Pc;
    Vec6 load = Vec6::Zero();
    load(1) = load(2) = P / std::sqrt(2.0);
    f.add_nodal_load(n, load);
    f.solve_static(200);
    const Vec3 u = f.displacement().segment<3>(6 * n);
    const double resistance = P - ks * std::hypot(u(1), u(2));
    EXPECT_NEAR(resistance / Pc, 1.0, 2e-3) << n << " elements";
    EXPECT_NEAR(u(1), u(2), 1e-9 * std::abs(u(1)));
    EXPECT_GT(f.plastic_work(), 0);
  }
}

}  // namespace
}  // namespace dmi
