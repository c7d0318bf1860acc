// Member contact in 3D against the plane analysis it must reproduce: a block on a fixed-fixed beam extruded along z
// between slip walls (plane strain), the space frame's beam as wide as the grid's reach, so every node layer along z
// is a scaled copy of the plane grid. The contact force, the beam's deflection and the block's motion must then be
// the plane results per metre of thickness, to round-off; a block resting on the beam loads it with its weight.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "engine/mpm/solver.hpp"
#include "engine/scenario/scenario.hpp"
#include "engine/sim/build_scene.hpp"
#include "verify/validate.hpp"

namespace dmi {
namespace {

using J = nlohmann::json;

// The plane frame along z = zc as a space frame (fixed supports stay fixed in all six DOFs).
SpaceFrameModel extrude(const FrameModel& p, double zc) {
  SpaceFrameModel m;
  for (const Vec2& x : p.nodes) m.nodes.push_back(Vec3(x.x(), x.y(), zc));
  for (const FrameElementDef& e : p.elements) {
    SpaceElementDef g;
    g.i = e.i, g.j = e.j, g.section = e.section, g.s0 = e.s0, g.s1 = e.s1, g.E = e.E, g.nu = e.nu, g.rho = e.rho;
    g.release_i = e.release_i, g.release_j = e.release_j, g.member = e.member;
    g.orientation = Vec3::UnitZ().cross(m.nodes[e.j] - m.nodes[e.i]);  // the plane frame's e2
    m.elements.push_back(g);
  }
  m.members = p.members;
  for (const FrameSupportDef& s : p.supports) {
    EXPECT_TRUE(s.fixed[0] && s.fixed[1] && s.fixed[2]);
    m.supports.push_back(SpaceSupportDef::fixed_support(s.node));
  }
  m.theory = p.theory, m.transform = p.transform, m.mass = p.mass, m.integrator = p.integrator;
  m.rayleigh_mass = p.rayleigh_mass, m.rayleigh_stiffness = p.rayleigh_stiffness, m.hht_alpha = p.hht_alpha;
  return m;
}

// A fixed-fixed steel beam along x at y = 0.1 (depth 0.2, width 1.4 m) and a soft 0.5 x 0.25 m block above it.
J plane_scene(double vy, double end_time, const char* detection = "surface", double nu = 0.3) {
  return J{{"schema_version", 1},
           {"name", "block on a beam"},
           {"analysis", {{"dimension", 2}, {"plane", "strain"}, {"end_time", end_time}, {"gravity", {0, -9.81}}}},
           {"grid", {{"origin", {-0.5, -1.0}}, {"size", {5.0, 2.5}}, {"cell_size", 0.1}}},
           {"materials", {{{"name", "soft"}, {"density", 1000}, {"youngs_modulus", 1e6}, {"poisson_ratio", nu}},
                          {{"name", "steel"}, {"density", 7850}, {"youngs_modulus", 2e11}, {"poisson_ratio", 0.3}}}},
           {"bodies", {{{"name", "block"}, {"material", "soft"}, {"shape", {{"type", "box"}, {"min", {1.0, 0.2}}, {"max", {1.5, 0.45}}}},
                        {"velocity", {0, vy}}}}},
           {"structure", {{"integrator", "newmark"}, {"self_weight", false},
                          {"nodes", {{{"name", "A"}, {"position", {0, 0.1}}}, {{"name", "B"}, {"position", {4, 0.1}}}}},
                          {"members", {{{"name", "beam"}, {"start", "A"}, {"end", "B"}, {"material", "steel"}, {"elements", 8},
                                        {"section", {{"type", "rectangle"}, {"width", 1.4}, {"depth", 0.2}}}}}},
                          {"supports", {{{"node", "A"}, {"type", "fixed"}}, {{"node", "B"}, {"type", "fixed"}}}}}},
           {"member_contact", {{"mode", "separable"}, {"distance", "node"}, {"detection", detection}}}};
}

// The same block, 1 m thick, between slip walls at z = 0 and 1 in a grid reaching from z = -0.2 to 1.2.
J space_scene(double vy, double end_time, double nu) {
  J j = plane_scene(vy, end_time, "surface", nu);
  j.erase("structure");
  j.erase("member_contact");
  j["analysis"] = {{"dimension", 3}, {"end_time", end_time}, {"gravity", {0, -9.81, 0}}};
  j["grid"] = {{"origin", {-0.5, -1.0, -0.2}}, {"size", {5.0, 2.5, 1.4}}, {"cell_size", 0.1}};
  j["bodies"][0]["shape"] = {{"type", "box"}, {"min", {1.0, 0.2, 0.0}}, {"max", {1.5, 0.45, 1.0}}};
  j["bodies"][0]["velocity"] = {0, vy, 0};
  j["walls"] = {{{"name", "front"}, {"type", "plane"}, {"point", {0, 0, 0}}, {"normal", {0, 0, 1}}, {"condition", "slip"}},
                {{"name", "back"}, {"type", "plane"}, {"point", {0, 0, 1}}, {"normal", {0, 0, -1}}, {"condition", "slip"}}};
  return j;
}

struct History {
  std::vector<double> t, force, deflection;
};

template <int D> History run(Solver<D>& s, double end_time) {
  History h;
  while (s.time() < end_time * (1 - 1e-12)) {
    s.step(s.stable_time_step(end_time - s.time()));
    h.t.push_back(s.time());
    h.force.push_back(s.member_contact()->force()[1]);
    h.deflection.push_back(s.scene().frame->displacement()(4 * (D == 2 ? 3 : 6) + 1));  // mid-span node
  }
  return h;
}

Solver<3> space_solver(double vy, double end_time, const Scene<2>& plane, double nu = 0.3) {
  Scene<3> sc = build_scene<3>(parse_scenario(space_scene(vy, end_time, nu), "space.json"));
  sc.frame = std::make_unique<SpaceFrame>(extrude(plane.frame->model(), 0.5));
  sc.coupling = plane.coupling;
  return Solver<3>(std::move(sc));
}

// Exact only where nothing breaks the extrusion: node detection holds the kernel's overhang layers behind the slip
// walls as the plane analysis holds its (surface detection leaves them free: the material's edges along a member,
// 2 % here), and Poisson's ratio 0 keeps the slip walls' boundary layer out (with nu > 0 the nodes a cell inside a
// slip wall feel the unbalanced sigma_zz of the truncated stencil: 1e-3 here).
TEST(MemberContact3D, ExtrudedImpactReproducesThePlaneAnalysis) {
  const double T = 0.08;
  const char* detection = std::getenv("DMI_DETECTION") ? std::getenv("DMI_DETECTION") : "node";  // the studies of docs/verification.md
  const double nu = std::getenv("DMI_NU") ? std::atof(std::getenv("DMI_NU")) : 0.0;
  Solver<2> p(build_scene<2>(parse_scenario(plane_scene(-2.0, T, detection, nu), "plane.json")));
  Solver<3> s = space_solver(-2.0, T, p.scene(), nu);
  const History a = run(p, T), b = run(s, T);
  ASSERT_EQ(a.t.size(), b.t.size());
  double fmax = 0, dmax = 0, ferr = 0, derr = 0;
  for (std::size_t k = 0; k < a.t.size(); ++k) {
    fmax = std::max(fmax, std::abs(a.force[k])), dmax = std::max(dmax, std::abs(a.deflection[k]));
    ferr = std::max(ferr, std::abs(a.force[k] - b.force[k])), derr = std::max(derr, std::abs(a.deflection[k] - b.deflection[k]));
  }
  std::printf("extruded impact: peak contact %.1f N, peak deflection %.3e m; 3D against 2D: %.2e, %.2e relative\n", fmax, dmax,
              ferr / fmax, derr / dmax);
  EXPECT_GT(fmax, 1e3);
  EXPECT_LT(ferr, 1e-6 * fmax);
  EXPECT_LT(derr, 1e-6 * dmax);
}

TEST(MemberContact3D, BlockRestingOnABeamLoadsItWithItsWeight) {
  const double T = 0.6;
  Solver<2> p(build_scene<2>(parse_scenario(plane_scene(0.0, T), "plane.json")));
  Solver<3> s = space_solver(0.0, T, p.scene());
  const History h = run(s, T);
  double sum = 0, dt = 0;
  for (std::size_t k = 1; k < h.t.size(); ++k)
    if (h.t[k] > 0.2) sum += h.force[k] * (h.t[k] - h.t[k - 1]), dt += h.t[k] - h.t[k - 1];
  EXPECT_NEAR(-sum / dt / (125 * 9.81), 1.0, 0.02);
}

// The same beam read from the scenario in 3D (nodes with three coordinates, a rectangle whose width lies along z):
// the supports' reactions (six components each) carry the resting block's weight, nothing acts across the plane.
TEST(MemberContact3D, ScenarioWithASpaceFrameRecordsItsHistories) {
  J j = space_scene(0.0, 0.5, 0.3);
  J st = plane_scene(0.0, 0.5)["structure"];
  st["nodes"] = {{{"name", "A"}, {"position", {0, 0.1, 0.5}}}, {{"name", "B"}, {"position", {4, 0.1, 0.5}}}};
  st["members"][0]["orientation"] = {0, 1, 0};  // this test's y is up
  j["structure"] = st;
  j["member_contact"] = {{"mode", "separable"}};
  const RunOutput out = run_quiet(parse_scenario(j.dump(), "space.json"));
  const auto& t = out.results.time;
  const auto& ra = series(out.results, "supports/A/reaction");
  const auto& rb = series(out.results, "supports/B/reaction");
  ASSERT_EQ(ra.components.size(), 6u);
  EXPECT_EQ(series(out.results, "frame/end_forces").components.size(), 8u * 12u);
  const double weight = 125 * 9.81;
  EXPECT_NEAR((time_mean(t, ra, 1, 0.2, 0.5) + time_mean(t, rb, 1, 0.2, 0.5)) / weight, 1.0, 0.02);
  EXPECT_NEAR(-time_mean(t, series(out.results, "frame/contact_force"), 1, 0.2, 0.5) / weight, 1.0, 0.02);
  for (int c : {2, 3, 4}) EXPECT_LT(std::abs(time_mean(t, ra, c, 0.2, 0.5)), 1e-6 * weight) << "component " << c;  // Fz, Mx, My
}

}  // namespace
}  // namespace dmi
