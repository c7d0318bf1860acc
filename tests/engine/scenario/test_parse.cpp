// Scenario parsing: the bundled examples parse, docs/scenario.md carries the generated key reference, defaults are
// applied, and frames parse with their member contact and probes (malformed input: test_parse_errors.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/common/error.hpp"
#include "engine/scenario/scenario.hpp"
#include "tests/engine/scenario/scenario_fixtures.hpp"

namespace dmi {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

using test::frame_2d;
using test::minimal_2d;
using test::minimal_3d;
using test::parse;

// ---------------------------------------------------------------------------------------------
// (a) every bundled example parses

TEST(ScenarioExamples, EveryExampleParses) {
  const fs::path dir = fs::path(DMI_SOURCE_DIR) / "examples";
  ASSERT_TRUE(fs::is_directory(dir)) << dir;
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file() && e.path().extension() == ".json") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  ASSERT_FALSE(files.empty()) << "no examples/*.json found in " << dir;
  for (const auto& f : files) {
    SCOPED_TRACE(f.string());
    try {
      const Scenario s = load_scenario(f.string());
      EXPECT_FALSE(s.name.empty());
      EXPECT_EQ(s.source_file, f.string());
      EXPECT_EQ(s.source_text, read_text(f));
      if (s.bodies.empty()) {  // a solid-FE check on its own
        EXPECT_TRUE(s.solid_check.present);
        continue;
      }
      EXPECT_EQ(static_cast<int>(s.analysis.gravity.size()), s.analysis.dimension);
    } catch (const std::exception& e) {
      ADD_FAILURE() << "example does not parse: " << e.what();
    }
  }
}

// ---------------------------------------------------------------------------------------------
// (b) docs/scenario.md carries exactly the generated reference

TEST(ScenarioDocs, GeneratedReferenceIsUpToDate) {
  const fs::path doc = fs::path(DMI_SOURCE_DIR) / "docs" / "scenario.md";
  const std::string text = read_text(doc);
  ASSERT_FALSE(text.empty()) << doc << " is missing or empty";
  const std::string begin = "<!-- BEGIN GENERATED: damimpact schema -->\n", end = "<!-- END GENERATED -->";
  const auto b = text.find(begin);
  ASSERT_NE(b, std::string::npos) << doc << " lacks the line " << begin;
  EXPECT_EQ(text.find(begin, b + 1), std::string::npos) << "two begin markers in " << doc;
  const auto e = text.find("\n" + end, b);
  ASSERT_NE(e, std::string::npos) << doc << " lacks the line " << end << " after the begin marker";
  const std::string in_doc = text.substr(b + begin.size(), e + 1 - (b + begin.size()));
  const std::string generated = scenario_reference_markdown();
  if (in_doc != generated) {
    // Point at the first differing line rather than dumping both texts.
    std::istringstream a(in_doc), g(generated);
    std::string la, lg;
    int line = 0;
    while (true) {
      ++line;
      const bool ha = static_cast<bool>(std::getline(a, la)), hg = static_cast<bool>(std::getline(g, lg));
      if (!ha && !hg) break;
      if (ha != hg || la != lg) {
        ADD_FAILURE() << "docs/scenario.md's generated key reference is out of date: run scripts/gen-docs\n"
                      << "first difference at line " << line << " of the generated section:\n  doc:       "
                      << (ha ? la : "<end>") << "\n  generated: " << (hg ? lg : "<end>");
        return;
      }
    }
    ADD_FAILURE() << "docs/scenario.md's generated key reference is out of date (whitespace): run scripts/gen-docs";
  }
}

TEST(ScenarioDocs, ReferenceCoversEveryKey) {
  const std::string md = scenario_reference_markdown();
  for (const char* key : {"`/schema_version`", "`/analysis/end_time`", "`/analysis/gravity`", "`/mpm/stress_update`",
                          "`/grid/cell_size`", "`/materials[]/poisson_ratio`", "`/bodies[]/shape/radius`",
                          "`/bodies[]/velocity_sine/wavevector`", "`/contact/friction`", "`/walls[]/normal`",
                          "`/walls[]/condition`", "`/prescribed_velocity[]/end`", "`/output/probes[]/quantities`",
                          "`/structure/integrator`", "`/structure/rayleigh_damping/stiffness`", "`/structure/members[]/section/depth_end`",
                          "`/structure/supports[]/stiffness`", "`/structure/masses[]/rotary_inertia`", "`/member_contact/decay_scale`",
                          "`/output/probes[]/member`", "`/output/probes[]/position`"})
    EXPECT_NE(md.find(key), std::string::npos) << key;
  // One section per top-level object or array, each headed once.
  for (const char* section : {"### `(top level)`", "### `analysis`", "### `mpm`", "### `grid`", "### `materials`", "### `bodies`",
                              "### `contact`", "### `walls`", "### `prescribed_velocity`", "### `structure`", "### `member_contact`",
                              "### `output`"}) {
    const auto at = md.find(section);
    EXPECT_NE(at, std::string::npos) << section;
    if (at != std::string::npos) {
      EXPECT_EQ(md.find(section, at + 1), std::string::npos) << section << " appears twice";
    }
  }
}

TEST(ScenarioDocs, ExampleInTheDocsParses) {
  const std::string text = read_text(fs::path(DMI_SOURCE_DIR) / "docs" / "scenario.md");
  const auto b = text.find("```json\n");
  ASSERT_NE(b, std::string::npos) << "docs/scenario.md has no ```json example";
  const auto e = text.find("```", b + 8);
  ASSERT_NE(e, std::string::npos);
  const Scenario s = parse_scenario(text.substr(b + 8, e - (b + 8)), "docs/scenario.md");
  EXPECT_EQ(s.bodies.size(), 1u);
}

// The second ```json block of docs/scenario.md: the frame example of its "Structures" section.
TEST(ScenarioDocs, StructureExampleInTheDocsParses) {
  const std::string text = read_text(fs::path(DMI_SOURCE_DIR) / "docs" / "scenario.md");
  const auto first = text.find("```json\n");
  ASSERT_NE(first, std::string::npos);
  const auto b = text.find("```json\n", first + 8);
  ASSERT_NE(b, std::string::npos) << "docs/scenario.md has no second ```json example (the frame)";
  const auto e = text.find("```", b + 8);
  ASSERT_NE(e, std::string::npos);
  const Scenario s = parse_scenario(text.substr(b + 8, e - (b + 8)), "docs/scenario.md");
  EXPECT_TRUE(s.structure.present);
  EXPECT_FALSE(s.structure.members.empty());
}

// ---------------------------------------------------------------------------------------------
// (c) defaults

TEST(ScenarioDefaults, Minimal2D) {
  const Scenario s = parse(minimal_2d());
  EXPECT_EQ(s.schema_version, 1);
  EXPECT_EQ(s.description, "");
  EXPECT_EQ(s.analysis.dimension, 2);
  EXPECT_EQ(s.analysis.plane, Plane::strain);
  EXPECT_DOUBLE_EQ(s.analysis.thickness, 1.0);
  EXPECT_DOUBLE_EQ(s.analysis.end_time, 0.1);
  EXPECT_DOUBLE_EQ(s.analysis.dt_max, 0.0);
  EXPECT_DOUBLE_EQ(s.analysis.cfl, 0.5);
  EXPECT_EQ(s.analysis.gravity, (DVec{0.0, -9.81}));
  EXPECT_EQ(s.mpm.shape, ShapeKind::bspline2);
  EXPECT_EQ(s.mpm.transfer, TransferKind::flip);
  EXPECT_DOUBLE_EQ(s.mpm.flip_blend, 1.0);
  EXPECT_EQ(s.mpm.update, StressUpdate::usl);
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].model, "linear_elastic");
  ASSERT_EQ(s.bodies.size(), 1u);
  EXPECT_EQ(s.bodies[0].particles_per_cell, 2);
  EXPECT_EQ(s.bodies[0].velocity, (DVec{0.0, 0.0}));
  EXPECT_TRUE(s.bodies[0].sine_amplitude.empty());
  EXPECT_EQ(s.contact.method, ContactMethod::multi_field);
  EXPECT_DOUBLE_EQ(s.contact.friction, 0.0);
  EXPECT_TRUE(s.walls.empty());
  EXPECT_TRUE(s.prescribed_velocity.empty());
  EXPECT_DOUBLE_EQ(s.output.snapshot_interval, 0.0);
  EXPECT_DOUBLE_EQ(s.output.history_interval, 0.0);
  EXPECT_TRUE(s.output.vtk);
  EXPECT_TRUE(s.output.probes.empty());
  EXPECT_EQ(s.source_file, "good.json");
}

TEST(ScenarioDefaults, Minimal3D) {
  const Scenario s = parse(minimal_3d());
  EXPECT_EQ(s.analysis.dimension, 3);
  EXPECT_EQ(s.analysis.gravity, (DVec{0.0, 0.0, -9.81}));
  EXPECT_EQ(s.analysis.plane, Plane::none);
  EXPECT_DOUBLE_EQ(s.analysis.cfl, 0.5);
  EXPECT_EQ(s.mpm.shape, ShapeKind::bspline2);
  EXPECT_EQ(s.mpm.update, StressUpdate::usl);
  EXPECT_EQ(s.bodies[0].velocity, (DVec{0.0, 0.0, 0.0}));
}

TEST(ScenarioDefaults, StressUpdateFollowsShapeFunction) {
  json j = minimal_2d();
  j["mpm"] = {{"shape_function", "linear"}};
  EXPECT_EQ(parse(j).mpm.update, StressUpdate::musl);
  j["mpm"] = {{"shape_function", "linear"}, {"stress_update", "usl"}};  // explicit choice wins
  EXPECT_EQ(parse(j).mpm.update, StressUpdate::usl);
  j["mpm"] = {{"shape_function", "gimp"}};
  EXPECT_EQ(parse(j).mpm.update, StressUpdate::usl);
  j["mpm"] = {{"stress_update", "musl"}};
  EXPECT_EQ(parse(j).mpm.shape, ShapeKind::bspline2);
  EXPECT_EQ(parse(j).mpm.update, StressUpdate::musl);
}

TEST(ScenarioDefaults, NestedDefaults) {
  json j = minimal_2d();
  j["walls"] = json::array({{{"name", "floor"}, {"type", "plane"}, {"point", {0, 0.2}}, {"normal", {0, 1}}}});
  j["prescribed_velocity"] = json::array({{{"name", "piston"}, {"min", {0.3, 0.2}}, {"max", {0.4, 0.6}}, {"velocity", {1, 0}}}});
  j["bodies"][0]["velocity_sine"] = {{"amplitude", {0.1, 0}}, {"wavevector", {3.14, 0}}};
  j["output"]["probes"] = json::array({{{"name", "b"}, {"type", "body"}, {"body", "block"}},
                                       {{"name", "p"}, {"type", "particle"}, {"body", "block"}, {"point", {0.7, 0.4}}}});
  const Scenario s = parse(j);
  ASSERT_EQ(s.walls.size(), 1u);
  EXPECT_EQ(s.walls[0].condition, WallCondition::slip);
  EXPECT_DOUBLE_EQ(s.walls[0].friction, 0.0);
  ASSERT_EQ(s.prescribed_velocity.size(), 1u);
  EXPECT_DOUBLE_EQ(s.prescribed_velocity[0].start, 0.0);
  EXPECT_TRUE(std::isinf(s.prescribed_velocity[0].end));
  EXPECT_EQ(s.bodies[0].sine_origin, (DVec{0.0, 0.0}));
  ASSERT_EQ(s.output.probes.size(), 2u);
  EXPECT_EQ(s.output.probes[0].quantities, body_probe_quantities());
  EXPECT_EQ(s.output.probes[1].quantities, particle_probe_quantities());
}

TEST(ScenarioDefaults, GivenValuesOverrideDefaults) {
  json j = minimal_2d();
  j["analysis"] = {{"plane", "stress"}, {"thickness", 0.2}, {"end_time", 1}, {"cfl", 0.3}, {"gravity", {0, 0}}, {"dt_max", 1e-4}};
  j["mpm"] = {{"shape_function", "gimp"}, {"transfer", "apic"}};
  const Scenario s = parse(j);
  EXPECT_EQ(s.analysis.plane, Plane::stress);
  EXPECT_DOUBLE_EQ(s.analysis.thickness, 0.2);
  EXPECT_DOUBLE_EQ(s.analysis.cfl, 0.3);
  EXPECT_DOUBLE_EQ(s.analysis.dt_max, 1e-4);
  EXPECT_EQ(s.analysis.gravity, (DVec{0.0, 0.0}));
  EXPECT_EQ(s.mpm.shape, ShapeKind::gimp);
  EXPECT_EQ(s.mpm.transfer, TransferKind::apic);
}

// ---------------------------------------------------------------------------------------------
// (c2) beam-column frames (Lin & Yang 2024), member contact (Lin & Yang 2024, eqs. 15–22) and member probes

TEST(ScenarioStructure, AbsentMeansNoFrame) {
  const Scenario s = parse(minimal_2d());
  EXPECT_FALSE(s.structure.present);
  EXPECT_TRUE(s.structure.nodes.empty());
  EXPECT_TRUE(s.structure.members.empty());
  EXPECT_EQ(s.member_contact.mode, MemberContactMode::separable);
  EXPECT_TRUE(s.member_contact.bodies.empty());
}

TEST(ScenarioStructure, Defaults) {
  json j = frame_2d();
  j["member_contact"] = json::object();
  j["output"]["probes"] = json::array({{{"name", "mid"}, {"type", "member"}, {"member", "beam"}}});
  const Scenario s = parse(j);
  const StructureConfig& st = s.structure;
  EXPECT_TRUE(st.present);
  EXPECT_EQ(st.theory, BeamTheoryKind::euler_bernoulli);
  EXPECT_EQ(st.transformation, FrameTransformKind::linear);
  EXPECT_EQ(st.mass, FrameMassKind::lumped);
  EXPECT_EQ(st.integrator, FrameIntegratorKind::explicit_euler);
  EXPECT_TRUE(st.self_weight);
  EXPECT_DOUBLE_EQ(st.rayleigh_mass, 0.0);
  EXPECT_DOUBLE_EQ(st.rayleigh_stiffness, 0.0);
  ASSERT_EQ(st.nodes.size(), 2u);
  EXPECT_EQ(st.nodes[1].name, "B");
  EXPECT_EQ(st.nodes[1].position, (DVec{1.8, 0.1}));
  ASSERT_EQ(st.members.size(), 1u);
  const MemberConfig& m = st.members[0];
  EXPECT_EQ(m.name, "beam");
  EXPECT_EQ(m.start, "A");
  EXPECT_EQ(m.end, "B");
  EXPECT_EQ(m.material, "steel");
  EXPECT_EQ(m.section.type, "rectangle");
  EXPECT_DOUBLE_EQ(m.section.width, 0.05);
  EXPECT_DOUBLE_EQ(m.section.depth, 0.1);
  EXPECT_EQ(m.elements, 1);
  EXPECT_FALSE(m.release_start);
  EXPECT_FALSE(m.release_end);
  ASSERT_EQ(st.supports.size(), 2u);
  EXPECT_EQ(st.supports[0].type, "pinned");
  EXPECT_EQ(st.supports[1].type, "roller");
  EXPECT_EQ(st.supports[1].restrained, "y");
  EXPECT_TRUE(st.supports[1].stiffness.empty());
  EXPECT_TRUE(st.masses.empty());
  const MemberContactConfig& mc = s.member_contact;
  EXPECT_EQ(mc.mode, MemberContactMode::separable);
  EXPECT_DOUBLE_EQ(mc.friction, 0.0);
  EXPECT_EQ(mc.decay, DecayKind::sharp);
  EXPECT_DOUBLE_EQ(mc.decay_scale, 1.0);
  EXPECT_TRUE(mc.bodies.empty());
  ASSERT_EQ(s.output.probes.size(), 1u);
  EXPECT_EQ(s.output.probes[0].type, "member");
  EXPECT_EQ(s.output.probes[0].target, "beam");
  EXPECT_DOUBLE_EQ(s.output.probes[0].position, 0.5);
  EXPECT_EQ(s.output.probes[0].quantities, member_probe_quantities());
  EXPECT_EQ(member_probe_quantities(),
            (std::vector<std::string>{"displacement", "top_displacement", "rotation", "section_forces", "fibre_stress"}));
}

TEST(ScenarioStructure, FullFrameParses) {
  // A portal over the block: two columns fixed at the base and a girder on top, every key given.
  json j = minimal_2d();
  j["grid"]["size"] = {2, 2};
  j["bodies"].push_back({{"name", "boulder"}, {"material", "rock"}, {"shape", {{"type", "ball"}, {"center", {1.0, 1.2}}, {"radius", 0.2}}}});
  j["materials"].push_back({{"name", "concrete"}, {"density", 2400}, {"youngs_modulus", 3e10}, {"poisson_ratio", 0.2}});
  j["structure"] = json::parse(R"({
    "theory": "timoshenko",
    "transformation": "linear",
    "mass": "consistent",
    "integrator": "newmark",
    "self_weight": false,
    "rayleigh_damping": {"mass": 0.5, "stiffness": 1e-4},
    "nodes": [{"name": "base_left", "position": [0.2, 0.1]}, {"name": "top_left", "position": [0.2, 1.6]},
              {"name": "top_right", "position": [1.8, 1.6]}, {"name": "base_right", "position": [1.8, 0.1]}],
    "members": [
      {"name": "left", "start": "base_left", "end": "top_left", "material": "concrete",
       "section": {"type": "tapered_rectangle", "width": 1.0, "depth_start": 0.3, "depth_end": 0.2}, "elements": 6},
      {"name": "girder", "start": "top_left", "end": "top_right", "material": "concrete",
       "section": {"type": "rectangle", "width": 1.0, "depth": 0.25}, "elements": 8, "release_start": true, "release_end": true},
      {"name": "right", "start": "base_right", "end": "top_right", "material": "concrete",
       "section": {"type": "pipe", "diameter": 0.3, "wall_thickness": 0.15}}
    ],
    "supports": [{"node": "base_left", "type": "fixed"},
                 {"node": "base_right", "type": "spring", "stiffness": [1e9, 2e9, 0]},
                 {"node": "top_right", "type": "roller", "restrained": "x"}],
    "masses": [{"node": "top_left", "mass": 120, "rotary_inertia": 3.5}, {"node": "top_right", "mass": 80}]
  })");
  j["member_contact"] = {{"mode", "friction"}, {"friction", 0.4}, {"decay", "cosine"}, {"decay_scale", 1.5}, {"bodies", {"boulder"}}};
  j["output"]["probes"] = json::array({{{"name", "girder_mid"}, {"type", "member"}, {"member", "girder"}, {"position", 0.25},
                                        {"quantities", {"fibre_stress", "section_forces"}}},
                                       {{"name", "b"}, {"type", "body"}, {"body", "boulder"}}});
  const Scenario s = parse(j);
  const StructureConfig& st = s.structure;
  EXPECT_TRUE(st.present);
  EXPECT_EQ(st.theory, BeamTheoryKind::timoshenko);
  EXPECT_EQ(st.transformation, FrameTransformKind::linear);
  EXPECT_EQ(st.mass, FrameMassKind::consistent);
  EXPECT_EQ(st.integrator, FrameIntegratorKind::newmark);
  EXPECT_FALSE(st.self_weight);
  EXPECT_DOUBLE_EQ(st.rayleigh_mass, 0.5);
  EXPECT_DOUBLE_EQ(st.rayleigh_stiffness, 1e-4);
  ASSERT_EQ(st.nodes.size(), 4u);
  EXPECT_EQ(st.nodes[2].name, "top_right");
  EXPECT_EQ(st.nodes[2].position, (DVec{1.8, 1.6}));
  ASSERT_EQ(st.members.size(), 3u);
  const SectionConfig& tapered = st.members[0].section;
  EXPECT_EQ(tapered.type, "tapered_rectangle");
  EXPECT_DOUBLE_EQ(tapered.width, 1.0);
  EXPECT_DOUBLE_EQ(tapered.depth_start, 0.3);
  EXPECT_DOUBLE_EQ(tapered.depth_end, 0.2);
  EXPECT_EQ(st.members[0].elements, 6);
  EXPECT_FALSE(st.members[0].release_start);
  const MemberConfig& girder = st.members[1];
  EXPECT_EQ(girder.name, "girder");
  EXPECT_EQ(girder.start, "top_left");
  EXPECT_EQ(girder.end, "top_right");
  EXPECT_EQ(girder.material, "concrete");
  EXPECT_EQ(girder.section.type, "rectangle");
  EXPECT_DOUBLE_EQ(girder.section.depth, 0.25);
  EXPECT_EQ(girder.elements, 8);
  EXPECT_TRUE(girder.release_start);
  EXPECT_TRUE(girder.release_end);
  const SectionConfig& pipe = st.members[2].section;
  EXPECT_EQ(pipe.type, "pipe");
  EXPECT_DOUBLE_EQ(pipe.diameter, 0.3);
  EXPECT_DOUBLE_EQ(pipe.wall_thickness, 0.15);  // = D/2: a solid circle is allowed
  EXPECT_EQ(st.members[2].elements, 1);
  ASSERT_EQ(st.supports.size(), 3u);
  EXPECT_EQ(st.supports[0].node, "base_left");
  EXPECT_EQ(st.supports[0].type, "fixed");
  EXPECT_EQ(st.supports[1].type, "spring");
  EXPECT_EQ(st.supports[1].stiffness, (DVec{1e9, 2e9, 0}));
  EXPECT_EQ(st.supports[2].type, "roller");
  EXPECT_EQ(st.supports[2].restrained, "x");
  ASSERT_EQ(st.masses.size(), 2u);
  EXPECT_EQ(st.masses[0].node, "top_left");
  EXPECT_DOUBLE_EQ(st.masses[0].mass, 120);
  EXPECT_DOUBLE_EQ(st.masses[0].rotary_inertia, 3.5);
  EXPECT_DOUBLE_EQ(st.masses[1].mass, 80);
  EXPECT_DOUBLE_EQ(st.masses[1].rotary_inertia, 0.0);
  const MemberContactConfig& mc = s.member_contact;
  EXPECT_EQ(mc.mode, MemberContactMode::friction);
  EXPECT_DOUBLE_EQ(mc.friction, 0.4);
  EXPECT_EQ(mc.decay, DecayKind::cosine);
  EXPECT_DOUBLE_EQ(mc.decay_scale, 1.5);
  EXPECT_EQ(mc.bodies, (std::vector<std::string>{"boulder"}));
  ASSERT_EQ(s.output.probes.size(), 2u);
  const ProbeConfig& p = s.output.probes[0];
  EXPECT_EQ(p.name, "girder_mid");
  EXPECT_EQ(p.type, "member");
  EXPECT_EQ(p.target, "girder");
  EXPECT_DOUBLE_EQ(p.position, 0.25);
  EXPECT_EQ(p.quantities, (std::vector<std::string>{"fibre_stress", "section_forces"}));
  EXPECT_EQ(s.output.probes[1].target, "boulder");
  EXPECT_EQ(s.output.probes[1].quantities, body_probe_quantities());
}

TEST(ScenarioStructure, MemberContactModesAndProbeEnds) {
  json j = frame_2d();
  j["member_contact"] = {{"mode", "stick"}};
  j["output"]["probes"] = json::array({{{"name", "s"}, {"type", "member"}, {"member", "beam"}, {"position", 0}},
                                       {{"name", "e"}, {"type", "member"}, {"member", "beam"}, {"position", 1}}});
  const Scenario s = parse(j);
  EXPECT_EQ(s.member_contact.mode, MemberContactMode::stick);
  EXPECT_DOUBLE_EQ(s.output.probes[0].position, 0.0);
  EXPECT_DOUBLE_EQ(s.output.probes[1].position, 1.0);
  // Frame nodes on the grid boundary are inside.
  j["structure"]["nodes"][0]["position"] = {0, 0};
  j["structure"]["nodes"][1]["position"] = {2, 1};
  EXPECT_NO_THROW(parse(j));
}

}  // namespace
}  // namespace dmi
