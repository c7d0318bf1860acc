// The inflow boundary (engine/mpm/inflow.hpp): the hydrograph's interpolation and integrals by hand; its readers'
// errors; and runs of debris entering a frictionless horizontal channel, where the mass that entered is the
// hydrograph's int rho v h w dt within one slice, the momentum balances the created momentum and the impulses of
// gravity, walls and the driven zone to round-off, the energy balance closes within a fraction of one slice's
// kinetic energy, and the zone's thrust on a water-like stream is the hydrostatic force rho g h^2 w / 2.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "engine/common/error.hpp"
#include "engine/mpm/solver.hpp"
#include "engine/scenario/hydrograph_io.hpp"
#include "engine/scenario/scenario.hpp"
#include "engine/sim/build_scene.hpp"

namespace dmi {
namespace {

using json = nlohmann::json;

Hydrograph hand() {  // t 0 -> 1 s: depth 0 -> 1 m at 2 m/s; 1 -> 3 s: 1 m deep, 2 -> 4 m/s
  Hydrograph h;
  h.time = {0, 1, 3};
  h.depth = {0, 1, 1};
  h.velocity = {2, 2, 4};
  return h;
}

TEST(Hydrograph, InterpolatesAndIntegratesByHand) {
  const Hydrograph h = hand();
  EXPECT_DOUBLE_EQ(h.at(0.5, 2000).depth, 0.5);
  EXPECT_DOUBLE_EQ(h.at(2.0, 2000).velocity, 3.0);
  EXPECT_DOUBLE_EQ(h.at(2.0, 2000).density, 2000.0);
  EXPECT_EQ(h.at(3.5, 2000).depth, 0.0);  // no flow after the last row
  EXPECT_EQ(h.at(-0.1, 2000).velocity, 0.0);
  EXPECT_DOUBLE_EQ(h.advance(0, 3), 2.0 + 6.0);               // int v dt
  EXPECT_DOUBLE_EQ(h.advance(0.5, 2.0), 1.0 + 2.5);           // across a row
  EXPECT_DOUBLE_EQ(h.advance(-1, 10), 8.0);                   // clipped to the rows
  EXPECT_NEAR(h.volume_per_width(), 1.0 + 6.0, 1e-12);        // int_0^1 2t dt + int_1^3 (1 + t) dt
  EXPECT_NEAR(h.mass_per_width(2000), 14000.0, 1e-9);
  EXPECT_EQ(h.peak_flux_row(2000), 2u);
}

std::string write_csv(const std::string& name, const std::string& text) {
  const auto p = std::filesystem::temp_directory_path() / ("dmi_inflow_" + std::to_string(::getpid()) + "_" + name);
  std::ofstream(p) << text;
  return p.string();
}

std::string error_of(const json& v, const std::string& file = "scen.json") {
  try {
    read_hydrograph(v, file, "/debris_surge/hydrograph");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Hydrograph, ReadsACsvWithUnitsInTheHeaderAndOtherColumns) {
  const std::string f = write_csv("ok.csv", "# from a run-out model\ntime_s, depth_m, discharge, velocity_m_s, density_kg_m3\n"
                                            "0, 0, 0, 3, 1900\n0.5, 1.2, 4, 3.5, 2000\n\n2.0, 0.0, 0, 2, 2100\n");
  const Hydrograph h = read_hydrograph(json(f), "/somewhere/scen.json", "/x");
  ASSERT_EQ(h.time.size(), 3u);
  EXPECT_EQ(h.depth[1], 1.2);
  EXPECT_EQ(h.velocity[1], 3.5);
  EXPECT_EQ(h.density[2], 2100);
  std::filesystem::remove(f);
}

TEST(Hydrograph, BadInputNamesTheKeyTheFileTheLineAndTheColumn) {
  const std::string bad = write_csv("bad.csv", "time,depth,velocity\n0,0,3\n0.5,abc,3\n");
  std::string e = error_of(json(bad));
  EXPECT_NE(e.find("scen.json: /debris_surge/hydrograph"), std::string::npos) << e;
  EXPECT_NE(e.find("line 3"), std::string::npos) << e;
  EXPECT_NE(e.find("column 'depth'"), std::string::npos) << e;
  const std::string back = write_csv("back.csv", "time,depth,velocity\n0,0,3\n0.5,1,3\n0.4,1,3\n");
  e = error_of(json(back));
  EXPECT_NE(e.find("line 4"), std::string::npos) << e;
  EXPECT_NE(e.find("increasing"), std::string::npos) << e;
  const std::string nocol = write_csv("nocol.csv", "time,height,velocity\n0,0,3\n1,1,3\n");
  e = error_of(json(nocol));
  EXPECT_NE(e.find("'depth' is missing"), std::string::npos) << e;
  e = error_of(json("no_such_file.csv"));
  EXPECT_NE(e.find("a readable CSV file"), std::string::npos) << e;
  e = error_of(json{{"time", {0, 1}}, {"depth", {0, 1, 2}}, {"velocity", {1, 1}}});
  EXPECT_NE(e.find("/debris_surge/hydrograph/depth"), std::string::npos) << e;
  e = error_of(json{{"time", {0, 1}}, {"depth", {1, 1}}, {"velocity", {1, -2}}});
  EXPECT_NE(e.find("/debris_surge/hydrograph/velocity/1 = -2"), std::string::npos) << e;
  e = error_of(json{{"time", {0, 1}}, {"depth", {0, 0}}, {"velocity", {1, 1}}});
  EXPECT_NE(e.find("some flow"), std::string::npos) << e;
  e = error_of(json{{"time", {0, 1}}, {"depth", {1, 1}}, {"speed", {1, 1}}});
  EXPECT_NE(e.find("/debris_surge/hydrograph/speed"), std::string::npos) << e;
  for (const auto& f : {bad, back, nocol}) std::filesystem::remove(f);
}

// A scenario copied into another folder (a grid-study level, a sweep case) still finds its CSV.
TEST(Hydrograph, FileNamesResolveAgainstTheScenarioFolder) {
  json j = {{"debris_surge", {{"hydrograph", "flow.csv"}}},
            {"bodies", {{{"inflow", {{"hydrograph", "sub/in.csv"}}}}, {{"inflow", {{"hydrograph", "/abs/x.csv"}}}}, {{"shape", {}}}}}};
  resolve_file_references(j, "/data/case/scenario.json");
  EXPECT_EQ(j["debris_surge"]["hydrograph"], "/data/case/flow.csv");
  EXPECT_EQ(j["bodies"][0]["inflow"]["hydrograph"], "/data/case/sub/in.csv");
  EXPECT_EQ(j["bodies"][1]["inflow"]["hydrograph"], "/abs/x.csv");
  json inline_one = {{"debris_surge", {{"hydrograph", {{"time", {0, 1}}}}}}};
  resolve_file_references(inline_one, "/data/case/scenario.json");
  EXPECT_TRUE(inline_one["debris_surge"]["hydrograph"].is_object());
}

// A 0.4 m deep stream at 4 m/s entering a frictionless horizontal channel for 0.7 s (depth ramps of 0.1 s).
json channel(const json& material, double end_time) {
  return json{{"schema_version", 1},
              {"name", "inflow"},
              {"analysis", {{"dimension", 2}, {"plane", "strain"}, {"end_time", end_time}}},
              {"mpm", {{"stress_update", "musl"}}},
              {"grid", {{"origin", {0, -0.2}}, {"size", {6, 1.2}}, {"cell_size", 0.05}}},
              {"materials", {material}},
              {"bodies", {{{"name", "debris"}, {"material", "debris"},
                           {"inflow", {{"point", {0.5, 0}}, {"direction", {1, 0}},
                                       {"hydrograph", {{"time", {0, 0.1, 0.6, 0.7}}, {"depth", {0, 0.4, 0.4, 0}}, {"velocity", {4, 4, 4, 4}}}}}}}}},
              {"walls", {{{"name", "ground"}, {"type", "plane"}, {"point", {0, 0}}, {"normal", {0, 1}}, {"condition", "slip"}},
                         {{"name", "upstream_end"}, {"type", "plane"}, {"point", {0.1, 0}}, {"normal", {1, 0}}, {"condition", "slip"}}}}};
}

const json kDebris = {{"name", "debris"}, {"model", "drucker_prager"}, {"density", 2000}, {"youngs_modulus", 2e7}, {"poisson_ratio", 0.3},
                      {"friction_angle", 30}, {"cohesion", 0}};

TEST(Inflow, MassMomentumAndEnergyBalance) {
  Solver<2> s(build_scene<2>(parse_scenario(channel(kDebris, 0.8), "inflow.json")));
  const auto& sc = s.scene();
  ASSERT_EQ(sc.inflows.size(), 1u);
  const Inflow<2>& in = sc.inflows[0];
  Vec<2> impulse = Vec<2>::Zero();  // of gravity, walls and the zone on the debris since t = 0
  while (s.time() < 0.8 - 1e-12) {
    const double dt = s.stable_time_step(0.8 - s.time());
    s.step(dt);
    double m = 0;
    for (double pm : sc.particles.mass) m += pm;
    impulse += dt * m * sc.gravity;  // the step's particles: those created at its start
    for (const auto& w : sc.walls) impulse -= dt * w.force;
    impulse -= dt * in.force;
  }
  const Diagnostics<2> d = s.diagnostics();
  // Mass: every created particle is in the body, and the plug's Riemann sum is within one slice (rho h_max dx w).
  double m = 0;
  for (double pm : sc.particles.mass) m += pm;
  EXPECT_NEAR(m, in.mass, 1e-12 * in.mass);
  const double exact = in.hydrograph.mass_per_width(2000), slice = 2000 * 0.4 * in.spacing;
  EXPECT_NEAR(in.mass, exact, slice) << "hydrograph " << exact << " kg";
  EXPECT_EQ(sc.bodies[0].end, static_cast<Index>(sc.particles.size()));
  // Momentum: created + impulses, to round-off (the transfers conserve momentum; walls and zone record theirs).
  const Vec<2> residual = d.momentum - d.inflow_momentum - impulse;
  EXPECT_LT(residual.norm(), 1e-9 * d.inflow_momentum.norm()) << residual.transpose();
  // Energy: within a quarter of one slice's kinetic energy rho h dx w v^2 / 2 (a slice created twice, lost, or the
  // zone's work counted wrongly would show as a whole one).
  const double slice_energy = 0.5 * slice * 16;
  EXPECT_LT(std::abs(d.balance(0.0)), 0.25 * slice_energy) << "inflow energy " << d.inflow_energy;
  EXPECT_NEAR(d.inflow_energy, 0.5 * in.mass * 16, 1e-9 * d.inflow_energy);
}

// Supercritical water (Froude 2) on a frictionless horizontal bed stays h deep downstream of the section, so the
// zone holds the stream against its hydrostatic thrust rho g h^2 w / 2. Tolerance 10 %: the free surface is known to
// half a particle spacing (3 % of the depth, 6 % of the thrust) and the weakly compressible pressure lags ~1 %.
TEST(Inflow, ZoneThrustIsHydrostaticForWater) {
  const json water = {{"name", "debris"}, {"model", "newtonian"}, {"density", 1000}, {"bulk_modulus", 1000.0 * 40 * 40}, {"viscosity", 1e-3}};
  Solver<2> s(build_scene<2>(parse_scenario(channel(water, 0.55), "inflow.json")));
  const Inflow<2>& in = s.scene().inflows[0];
  double impulse = 0, span = 0;
  while (s.time() < 0.55 - 1e-12) {
    const double dt = s.stable_time_step(0.55 - s.time());
    s.step(dt);
    if (s.time() > 0.3) impulse -= dt * in.force[0], span += dt;  // the steady part: full depth since 0.1 s
  }
  const double thrust = 0.5 * 1000 * 9.81 * 0.4 * 0.4;
  EXPECT_NEAR(impulse / span, thrust, 0.10 * thrust);
}

// A section too close to the dam: the deposit backs up to it while debris still enters, and the run stops with a
// message naming the inflow and what to do, rather than pushing the deposit as a piston.
TEST(Inflow, DepositReachingTheSectionStopsTheRun) {
  const json j = json::parse(R"({"schema_version": 1, "name": "d",
    "dam": {"type": "concrete_gravity", "height": 4.0, "crest_thickness": 1.0, "base_thickness": 1.6},
    "debris_surge": {"hydrograph": {"time": [0, 0.4, 2.0], "depth": [0, 1.0, 1.0], "velocity": [6, 6, 6]}, "section_distance": 1.0,
                     "channel_slope": 0, "material": {"friction_angle": 32}}})");
  Solver<2> s(build_scene<2>(parse_scenario(j.dump(), "near.json")));
  try {
    while (s.time() < 2.0) s.step(s.stable_time_step(2.0 - s.time()));
    FAIL() << "the deposit pushed by the driven zone was not noticed";
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find("backed up to the inflow section of 'debris'"), std::string::npos) << e.what();
    EXPECT_LT(s.time(), 2.0);
  }
}

// Debris lighter than its material (a hydrograph density of 500 against 2000 kg/m^3) has a wave speed twice the
// material's, c ~ 1/sqrt(rho): the step halves (the empty channel's step is the wave speed's, the entering
// velocity 4 m/s added), and the created particles carry the hydrograph's density.
TEST(Inflow, LighterDebrisShortensTheStepAndCarriesItsDensity) {
  json light = channel(kDebris, 0.2), heavy = light;
  light["bodies"][0]["inflow"]["hydrograph"]["density"] = {500, 500, 500, 500};
  Solver<2> a(build_scene<2>(parse_scenario(heavy, "heavy.json"))), b(build_scene<2>(parse_scenario(light, "light.json")));
  const double c = a.scene().materials[0]->wave_speed(), h = 0.05, cfl = a.scene().options.cfl;
  EXPECT_NEAR(a.stable_time_step(1.0), cfl * h / (c + 4), 1e-12);
  EXPECT_NEAR(b.stable_time_step(1.0), cfl * h / (2 * c + 4), 1e-12);
  while (b.time() < 0.2 - 1e-12) b.step(b.stable_time_step(0.2 - b.time()));
  const auto& P = b.scene().particles;
  ASSERT_GT(P.size(), 0u);
  for (std::size_t i = 0; i < P.size(); ++i) ASSERT_NEAR(P.mass[i] / P.vol0[i], 500.0, 1e-9);
}

}  // namespace
}  // namespace dmi
