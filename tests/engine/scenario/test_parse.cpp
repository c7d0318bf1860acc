// Scenario parsing: the bundled examples parse, docs/scenario.md carries the generated key reference,
// defaults are applied, and every kind of malformed input is rejected with an InputError naming the
// file, the JSON path and what was expected.
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

// A small valid 2D scenario that the error cases below break one key at a time.
json minimal_2d() {
  return json::parse(R"({
    "schema_version": 1,
    "name": "Block on a floor",
    "analysis": {"end_time": 0.1},
    "grid": {"origin": [0, 0], "size": [2, 1], "cell_size": 0.1},
    "materials": [{"name": "rock", "density": 2500, "youngs_modulus": 1e8, "poisson_ratio": 0.25}],
    "bodies": [{"name": "block", "material": "rock", "shape": {"type": "box", "min": [0.5, 0.2], "max": [1.0, 0.6]}}]
  })");
}

json minimal_3d() {
  return json::parse(R"({
    "schema_version": 1,
    "name": "Ball in a box",
    "analysis": {"dimension": 3, "end_time": 0.1},
    "grid": {"origin": [0, 0, 0], "size": [1, 1, 1], "cell_size": 0.1},
    "materials": [{"name": "rock", "density": 2500, "youngs_modulus": 1e8, "poisson_ratio": 0.25}],
    "bodies": [{"name": "ball", "material": "rock", "shape": {"type": "ball", "center": [0.5, 0.5, 0.5], "radius": 0.2}}]
  })");
}

Scenario parse(const json& j) { return parse_scenario(j.dump(2), "good.json"); }

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
      EXPECT_FALSE(s.bodies.empty());
      EXPECT_EQ(s.source_file, f.string());
      EXPECT_EQ(s.source_text, read_text(f));
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
                          "`/walls[]/condition`", "`/prescribed_velocity[]/end`", "`/output/probes[]/quantities`"})
    EXPECT_NE(md.find(key), std::string::npos) << key;
  // One section per top-level object or array, each headed once.
  for (const char* section : {"### `(top level)`", "### `analysis`", "### `mpm`", "### `grid`", "### `materials`", "### `bodies`",
                              "### `contact`", "### `walls`", "### `prescribed_velocity`", "### `output`"}) {
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
// (d) malformed input: InputError naming file, path and expectation

// Parses text as "bad.json" and checks the error. path: the JSON path the message must name, as
// "bad.json: PATH = value: expected ..." or "bad.json: PATH: expected ..."; empty = do not check.
void expect_text_error(const std::string& text, const std::string& path, std::initializer_list<std::string> fragments) {
  try {
    parse_scenario(text, "bad.json");
    ADD_FAILURE() << "accepted, but expected an error at " << path << "\n" << text;
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("bad.json"), std::string::npos) << "no file name in: " << m;
    if (!path.empty()) {
      EXPECT_TRUE(m.find("bad.json: " + path + " = ") != std::string::npos ||
                  m.find("bad.json: " + path + ": expected ") != std::string::npos)
          << "path " << path << " not named in: " << m;
      EXPECT_NE(m.find(": expected "), std::string::npos) << "no expectation in: " << m;
    }
    for (const auto& f : fragments) EXPECT_NE(m.find(f), std::string::npos) << "'" << f << "' not in: " << m;
  } catch (const std::exception& e) {
    ADD_FAILURE() << "threw something other than InputError: " << e.what();
  }
}

void expect_error(const json& j, const std::string& path, std::initializer_list<std::string> fragments) {
  expect_text_error(j.dump(2), path, fragments);
}

// minimal_2d() with one change.
json with(const std::function<void(json&)>& change, json j = minimal_2d()) {
  change(j);
  return j;
}

TEST(ScenarioErrors, SyntaxErrorHasLineAndColumn) {
  // Trailing comma: the parser stops at the '}' on line 4, column 1.
  expect_text_error("{\n  \"schema_version\": 1,\n  \"name\": \"x\",\n}\n", "", {"bad.json:4:1: invalid JSON", "syntax error"});
  // Missing comma: stops at the next key on line 3 ("grid" spans columns 3-8).
  expect_text_error("{\n  \"schema_version\": 1\n  \"grid\": {}\n}\n", "", {"bad.json:3:", "invalid JSON", "syntax error"});
  expect_text_error("", "", {"bad.json:1:1: invalid JSON"});
  expect_text_error("{\"schema_version\": 1, \"name\": 'x'}", "", {"bad.json:1:", "invalid JSON"});
}

TEST(ScenarioErrors, NumberTooLarge) {
  expect_text_error("{\"schema_version\": 1, \"analysis\": {\"end_time\": 1e400}}", "", {"bad.json: invalid JSON", "1e400"});
}

TEST(ScenarioErrors, NotAnObject) {
  expect_text_error("[1, 2]", "/", {"a JSON object"});
  expect_error(with([](json& j) { j["analysis"] = 5; }), "/analysis", {"an object"});
  expect_error(with([](json& j) { j["bodies"] = {{"name", "x"}}; }), "/bodies", {"an array of objects"});
  expect_error(with([](json& j) { j["bodies"][0] = "block"; }), "/bodies/0", {"an object"});
}

TEST(ScenarioErrors, WrongType) {
  expect_error(with([](json& j) { j["analysis"]["end_time"] = "0.1"; }), "/analysis/end_time", {"\"0.1\"", "a number > 0 (s)"});
  expect_error(with([](json& j) { j["schema_version"] = "1"; }), "/schema_version", {"an integer"});
  expect_error(with([](json& j) { j["bodies"][0]["particles_per_cell"] = 2.5; }), "/bodies/0/particles_per_cell", {"an integer >= 1 and <= 8"});
  expect_error(with([](json& j) { j["output"]["vtk"] = "yes"; }), "/output/vtk", {"true or false"});
  expect_error(with([](json& j) { j["name"] = 3; }), "/name", {"a string"});
  expect_error(with([](json& j) { j["mpm"]["shape_function"] = "quadratic"; }), "/mpm/shape_function", {"one of linear | gimp | bspline2"});
  expect_error(with([](json& j) { j["analysis"]["gravity"] = {0, "down"}; }), "/analysis/gravity", {"an array of 2 numbers"});
}

TEST(ScenarioErrors, UnknownKeys) {
  expect_error(with([](json& j) { j["outputs"] = json::object(); }), "/outputs", {"unknown key 'outputs'", "known keys:"});
  expect_error(with([](json& j) { j["bodies"][0]["materal"] = "rock"; }), "/bodies/0/materal", {"unknown key 'materal'", "material"});
  expect_error(with([](json& j) { j["bodies"][0]["shape"]["radius"] = 0.1; }), "/bodies/0/shape/radius", {"unknown key 'radius'"});
  expect_error(with([](json& j) { j["analysis"]["end"] = 1; }), "/analysis/end", {"unknown key 'end'"});
  // A key of the other variant (plane walls have no min/max).
  expect_error(with([](json& j) {
                 j["walls"] = json::array({{{"name", "w"}, {"type", "plane"}, {"point", {0, 0.2}}, {"normal", {0, 1}}, {"min", {0, 0}}}});
               }),
               "/walls/0/min", {"unknown key 'min'"});
}

TEST(ScenarioErrors, MissingRequiredKey) {
  expect_error(with([](json& j) { j["analysis"].erase("end_time"); }), "/analysis/end_time", {"the required key 'end_time'"});
  expect_error(with([](json& j) { j.erase("analysis"); }), "/analysis/end_time", {"the required key 'end_time'"});
  expect_error(with([](json& j) { j.erase("schema_version"); }), "/schema_version", {"the required key 'schema_version'"});
  expect_error(with([](json& j) { j.erase("grid"); }), "/grid/origin", {"the required key 'origin'"});
  expect_error(with([](json& j) { j.erase("bodies"); }), "/bodies", {"the required key 'bodies'"});
  expect_error(with([](json& j) { j["bodies"][0].erase("material"); }), "/bodies/0/material", {"the required key 'material'"});
  expect_error(with([](json& j) { j["bodies"][0]["shape"].erase("max"); }), "/bodies/0/shape/max", {"the required key 'max'"});
  expect_error(with([](json& j) { j["bodies"][0]["name"] = ""; }), "/bodies/0/name", {"a non-empty string"});
}

TEST(ScenarioErrors, OutOfRange) {
  expect_error(with([](json& j) { j["bodies"][0]["shape"] = {{"type", "ball"}, {"center", {1, 0.5}}, {"radius", -0.2}}; }),
               "/bodies/0/shape/radius", {"-0.2", "a number > 0 (m)"});
  expect_error(with([](json& j) { j["grid"]["cell_size"] = 0; }), "/grid/cell_size", {"= 0", "a number > 0 (m)"});
  expect_error(with([](json& j) { j["grid"]["size"] = {2, 0}; }), "/grid/size", {"numbers > 0"});
  expect_error(with([](json& j) { j["materials"][0]["poisson_ratio"] = 0.5; }), "/materials/0/poisson_ratio", {"= 0.5", "> -1 and < 0.5"});
  expect_error(with([](json& j) { j["materials"][0]["density"] = -1; }), "/materials/0/density", {"> 0 (kg/m^3)"});
  expect_error(with([](json& j) { j["analysis"]["cfl"] = 1.5; }), "/analysis/cfl", {"> 0 and <= 1"});
  expect_error(with([](json& j) { j["analysis"]["dimension"] = 4; }), "/analysis/dimension", {">= 2 and <= 3"});
  expect_error(with([](json& j) { j["bodies"][0]["particles_per_cell"] = 0; }), "/bodies/0/particles_per_cell", {">= 1 and <= 8"});
  expect_error(with([](json& j) { j["materials"][0]["model"] = "mohr_coulomb"; }), "/materials/0/model", {"linear_elastic or neo_hookean", "mohr_coulomb"});
  expect_error(with([](json& j) { j["bodies"][0]["shape"]["type"] = "cylinder"; }), "/bodies/0/shape/type", {"box or ball", "cylinder"});
}

TEST(ScenarioErrors, VectorOfWrongLength) {
  expect_error(with([](json& j) { j["analysis"]["gravity"] = {0, 0, -9.81}; }), "/analysis/gravity", {"[0,0,-9.81]", "an array of 2 numbers"});
  expect_error(with([](json& j) { j["bodies"][0]["velocity"] = {1}; }), "/bodies/0/velocity", {"an array of 2 numbers"});
  // A 2D grid in a 3D analysis.
  expect_error(with([](json& j) { j["grid"]["origin"] = {0, 0}; }, minimal_3d()), "/grid/origin", {"an array of 3 numbers"});
}

TEST(ScenarioErrors, UnknownMaterialReference) {
  expect_error(with([](json& j) { j["bodies"][0]["material"] = "granite"; }), "/bodies/0/material",
               {"\"granite\"", "the name of one of the materials"});
}

TEST(ScenarioErrors, BodyOutsideGridInterior) {
  // The grid spans x in [0, 2] with 0.1 m cells: the interior is [0.05, 1.95].
  expect_error(with([](json& j) { j["bodies"][0]["shape"]["max"] = {1.97, 0.6}; }), "/bodies/0/shape",
               {"grid interior [0.05, 1.95]", "along axis 0"});
  expect_error(with([](json& j) { j["bodies"][0]["shape"] = {{"type", "ball"}, {"center", {1, 0.1}}, {"radius", 0.2}}; }),
               "/bodies/0/shape", {"grid interior", "along axis 1"});
  // Entirely outside.
  expect_error(with([](json& j) { j["bodies"][0]["shape"]["min"] = {-3, 0.2}; j["bodies"][0]["shape"]["max"] = {-2, 0.6}; }),
               "/bodies/0/shape", {"grid interior"});
}

TEST(ScenarioErrors, DuplicateNames) {
  expect_error(with([](json& j) { j["bodies"].push_back(j["bodies"][0]); }), "/bodies/1/name", {"\"block\"", "a name not used before"});
  expect_error(with([](json& j) { j["materials"].push_back(j["materials"][0]); }), "/materials/1/name", {"\"rock\"", "a name not used before"});
  expect_error(with([](json& j) {
                 j["walls"] = json::array({{{"name", "w"}, {"type", "plane"}, {"point", {0, 0.2}}, {"normal", {0, 1}}}});
                 j["prescribed_velocity"] = json::array({{{"name", "w"}, {"min", {0, 0}}, {"max", {0.2, 0.2}}, {"velocity", {0, 0}}}});
               }),
               "/prescribed_velocity/0/name", {"a name not used before"});
  expect_error(with([](json& j) {
                 j["output"]["probes"] = json::array({{{"name", "p"}, {"type", "body"}, {"body", "block"}},
                                                      {{"name", "p"}, {"type", "body"}, {"body", "block"}}});
               }),
               "/output/probes/1/name", {"a name not used before"});
}

TEST(ScenarioErrors, BoxesNeedMaxAboveMin) {
  expect_error(with([](json& j) {
                 j["walls"] = json::array({{{"name", "dam"}, {"type", "box"}, {"min", {1.5, 0}}, {"max", {1.2, 0.8}}}});
               }),
               "/walls/0/max", {"max > min along every axis", "[1.2,0.8]"});
  // Equal is not enough either.
  expect_error(with([](json& j) {
                 j["walls"] = json::array({{{"name", "dam"}, {"type", "box"}, {"min", {1.5, 0}}, {"max", {1.8, 0}}}});
               }),
               "/walls/0/max", {"max > min along every axis"});
  expect_error(with([](json& j) { j["bodies"][0]["shape"]["max"] = {1.0, 0.2}; }), "/bodies/0/shape/max", {"max > min along every axis"});
  expect_error(with([](json& j) {
                 j["prescribed_velocity"] = json::array({{{"name", "piston"}, {"min", {0.4, 0.6}}, {"max", {0.3, 0.2}}, {"velocity", {1, 0}}}});
               }),
               "/prescribed_velocity/0/max", {"max > min along every axis"});
  expect_error(with([](json& j) {
                 j["prescribed_velocity"] = json::array(
                     {{{"name", "piston"}, {"min", {0.3, 0.2}}, {"max", {0.4, 0.6}}, {"velocity", {1, 0}}, {"start", 0.5}, {"end", 0.2}}});
               }),
               "/prescribed_velocity/0/end", {"end > start"});
}

TEST(ScenarioErrors, ZeroWallNormal) {
  expect_error(with([](json& j) {
                 j["walls"] = json::array({{{"name", "floor"}, {"type", "plane"}, {"point", {0, 0.2}}, {"normal", {0, 0}}}});
               }),
               "/walls/0/normal", {"a non-zero normal vector"});
  expect_error(with([](json& j) {
                 j["walls"] = json::array({{{"name", "floor"}, {"type", "cylinder"}}});
               }),
               "/walls/0/type", {"plane or box", "cylinder"});
}

TEST(ScenarioErrors, SchemaVersion) {
  expect_error(with([](json& j) { j["schema_version"] = 2; }), "/schema_version", {"= 2", "expected an integer >= 1 and <= 1"});
  expect_error(with([](json& j) { j["schema_version"] = 0; }), "/schema_version", {"= 0"});
}

TEST(ScenarioErrors, ProbeOnUnknownBody) {
  expect_error(with([](json& j) { j["output"]["probes"] = json::array({{{"name", "c"}, {"type", "body"}, {"body", "boulder"}}}); }),
               "/output/probes/0/body", {"\"boulder\"", "the name of one of the bodies"});
  // Quantities must suit the probe type.
  expect_error(with([](json& j) {
                 j["output"]["probes"] = json::array({{{"name", "c"}, {"type", "body"}, {"body", "block"}, {"quantities", {"stress"}}}});
               }),
               "/output/probes/0/quantities", {"\"stress\"", "kinetic_energy"});
  expect_error(with([](json& j) { j["output"]["probes"] = json::array({{{"name", "c"}, {"type", "particle"}, {"body", "block"}}}); }),
               "/output/probes/0/point", {"the required key 'point'"});
}

TEST(ScenarioErrors, HugeParticleCount) {
  // 1.8 m x 0.9 m at 0.5 mm cells (6.5e6 cells) with 8 x 8 particles per cell: 4.1e8 particles.
  expect_error(with([](json& j) {
                 j["grid"]["cell_size"] = 0.0005;
                 j["bodies"][0]["particles_per_cell"] = 8;
                 j["bodies"][0]["shape"]["min"] = {0.1, 0.05};
                 j["bodies"][0]["shape"]["max"] = {1.9, 0.95};
               }),
               "/bodies", {"at most 2e8 particles", "use larger cells"});
  // 3D: a 0.4 m ball (bounding box 80^3 cells of 5 mm) with 8^3 particles per cell: 2.6e8.
  expect_error(with([](json& j) {
                 j["grid"]["cell_size"] = 0.005;
                 j["bodies"][0]["particles_per_cell"] = 8;
               }, minimal_3d()),
               "/bodies", {"at most 2e8 particles"});
}

TEST(ScenarioErrors, GridTooLargeOrCellsTooBig) {
  expect_error(with([](json& j) { j["grid"]["size"] = {1000, 1000}; j["grid"]["cell_size"] = 0.01; j["bodies"][0]["particles_per_cell"] = 1; }),
               "/grid/cell_size", {"at most 4e8 cells"});
  expect_error(with([](json& j) { j["grid"]["cell_size"] = 2; }), "/grid/cell_size", {"smaller than the grid size"});
}

TEST(ScenarioErrors, NoBodies) {
  expect_error(with([](json& j) { j["bodies"] = json::array(); }), "/bodies", {"= []", "at least one body"});
}

TEST(ScenarioErrors, LoadScenarioFileProblems) {
  const std::string missing = (fs::temp_directory_path() / "dmi_no_such_scenario_8127.json").string();
  try {
    load_scenario(missing);
    ADD_FAILURE() << "a missing file was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("cannot open"), std::string::npos) << e.what();
  }
  const std::string dir = (fs::path(DMI_SOURCE_DIR) / "examples").string();
  try {
    load_scenario(dir);
    ADD_FAILURE() << "a directory was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("directory"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace dmi
