// Malformed scenarios: every kind is rejected with one InputError naming the file, the JSON path and what was
// expected; the slurry materials' keys and the solid check's plausibility.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/common/error.hpp"
#include "engine/scenario/scenario.hpp"
#include "tests/engine/scenario/scenario_fixtures.hpp"

namespace dmi {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using test::frame_2d;
using test::minimal_2d;
using test::minimal_3d;
using test::parse;

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
  expect_error(with([](json& j) { j.erase("bodies"); }), "/bodies", {"at least one body"});
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
  expect_error(with([](json& j) { j["materials"][0]["model"] = "mohr_coulomb"; }), "/materials/0/model", {"linear_elastic, neo_hookean, drucker_prager, newtonian, bingham, mu_i or elastic_plastic", "mohr_coulomb"});
  expect_error(with([](json& j) { j["bodies"][0]["shape"]["type"] = "cylinder"; }), "/bodies/0/shape/type", {"box, ball or polygon", "cylinder"});
  // mu(I): the limiting friction must exceed the static one.
  auto mu_i = [](json& j) {
    j["analysis"]["plane"] = "strain";
    j["materials"][0] = json{{"name", j["materials"][0]["name"]}, {"model", "mu_i"}, {"density", 2000}, {"youngs_modulus", 1e7},
                             {"poisson_ratio", 0.3}, {"mu_s", 0.5}, {"mu_2", 0.4}, {"I0", 0.3}, {"grain_diameter", 0.01}};
  };
  expect_error(with(mu_i), "/materials/0/mu_2", {"= 0.4", "greater than mu_s"});
  expect_error(with([&](json& j) { mu_i(j), j["materials"][0].erase("grain_diameter"); }), "/materials/0/grain_diameter", {"required key"});
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

// frame_2d() with one change.
json frame_with(const std::function<void(json&)>& change) { return with(change, frame_2d()); }

// A 3D analysis takes a space frame: node positions with three coordinates, rollers along z, six spring stiffnesses.
TEST(ScenarioStructureErrors, ThreeDimensionsNeedSpaceFrameInputs) {
  json j = minimal_3d();
  j["structure"] = frame_2d()["structure"];
  j["materials"] = frame_2d()["materials"];
  expect_error(j, "/structure/nodes/0/position", {"an array of 3 numbers"});
  expect_error(frame_with([](json& k) { k["structure"]["supports"][0] = {{"node", k["structure"]["supports"][0]["node"]}, {"type", "roller"}, {"restrained", "z"}}; }),
               "/structure/supports/0/restrained", {"\"z\""});
  expect_error(frame_with([](json& k) { k["structure"]["members"][0]["orientation"] = {0, 0, 1}; }), "/structure/members/0/orientation",
               {"unknown key 'orientation'"});
}

TEST(ScenarioStructureErrors, UnknownAndMisplacedKeys) {
  expect_error(frame_with([](json& j) { j["structure"]["members"][0]["element"] = 4; }), "/structure/members/0/element",
               {"= 4", "unknown key 'element'", "elements"});
  expect_error(frame_with([](json& j) { j["structure"]["theroy"] = "timoshenko"; }), "/structure/theroy", {"unknown key 'theroy'", "theory"});
  expect_error(frame_with([](json& j) { j["structure"]["rayleigh_damping"]["alpha"] = 1; }), "/structure/rayleigh_damping/alpha",
               {"unknown key 'alpha'", "mass, stiffness"});
  // Keys of another variant: a rectangle has no diameter, a pinned support no stiffness, friction needs mode friction.
  expect_error(frame_with([](json& j) { j["structure"]["members"][0]["section"]["diameter"] = 0.1; }),
               "/structure/members/0/section/diameter", {"unknown key 'diameter'"});
  expect_error(frame_with([](json& j) { j["structure"]["supports"][0]["stiffness"] = {1, 1, 1}; }), "/structure/supports/0/stiffness",
               {"unknown key 'stiffness'"});
  expect_error(frame_with([](json& j) { j["structure"]["supports"][0]["restrained"] = "x"; }), "/structure/supports/0/restrained",
               {"unknown key 'restrained'"});
  expect_error(frame_with([](json& j) { j["member_contact"] = {{"friction", 0.3}}; }), "/member_contact/friction", {"unknown key 'friction'"});
  // A member probe names a member, not a body; a body probe still needs its body.
  expect_error(frame_with([](json& j) {
                 j["output"]["probes"] = json::array({{{"name", "m"}, {"type", "member"}, {"member", "beam"}, {"body", "block"}}});
               }),
               "/output/probes/0/body", {"unknown key 'body'"});
  expect_error(frame_with([](json& j) { j["output"]["probes"] = json::array({{{"name", "m"}, {"type", "member"}}}); }),
               "/output/probes/0/member", {"the required key 'member'"});
  expect_error(frame_with([](json& j) { j["output"]["probes"] = json::array({{{"name", "b"}, {"type", "body"}, {"member", "beam"}}}); }),
               "/output/probes/0/body", {"the required key 'body'"});
  expect_error(frame_with([](json& j) { j["output"]["probes"] = json::array({{{"name", "b"}, {"type", "body"}, {"position", 0.5}}}); }),
               "/output/probes/0/body", {"the required key 'body'"});
  expect_error(frame_with([](json& j) { j["output"]["probes"] = json::array({{{"name", "b"}, {"type", "beam"}, {"member", "beam"}}}); }),
               "/output/probes/0/type", {"particle, body or member", "beam"});
}

TEST(ScenarioStructureErrors, MissingRequiredKeys) {
  expect_error(frame_with([](json& j) { j["structure"].erase("nodes"); }), "/structure/nodes", {"the required key 'nodes'"});
  expect_error(frame_with([](json& j) { j["structure"].erase("members"); }), "/structure/members", {"the required key 'members'"});
  expect_error(frame_with([](json& j) { j["structure"].erase("supports"); }), "/structure/supports", {"the required key 'supports'"});
  expect_error(frame_with([](json& j) { j["structure"]["members"][0].erase("section"); }), "/structure/members/0/section/type",
               {"the required key 'type'"});
  expect_error(frame_with([](json& j) { j["structure"]["members"][0]["section"].erase("depth"); }), "/structure/members/0/section/depth",
               {"the required key 'depth'", "(number, m)"});
  expect_error(frame_with([](json& j) { j["structure"]["members"][0]["section"] = {{"type", "pipe"}, {"diameter", 0.2}}; }),
               "/structure/members/0/section/wall_thickness", {"the required key 'wall_thickness'"});
  expect_error(frame_with([](json& j) { j["structure"]["supports"][0] = {{"node", "A"}, {"type", "spring"}}; }),
               "/structure/supports/0/stiffness", {"the required key 'stiffness'"});
  expect_error(frame_with([](json& j) { j["structure"]["nodes"][0].erase("position"); }), "/structure/nodes/0/position",
               {"the required key 'position'"});
}

TEST(ScenarioStructureErrors, OutOfRangeAndWrongType) {
  expect_error(frame_with([](json& j) { j["structure"]["members"][0]["section"]["depth"] = -0.1; }), "/structure/members/0/section/depth",
               {"= -0.1", "a number > 0 (m)"});
  expect_error(frame_with([](json& j) { j["structure"]["members"][0]["elements"] = 0; }), "/structure/members/0/elements",
               {"= 0", ">= 1 and <= 10000"});
  expect_error(frame_with([](json& j) { j["structure"]["members"][0]["elements"] = 10001; }), "/structure/members/0/elements",
               {"<= 10000"});
  expect_error(frame_with([](json& j) { j["structure"]["members"][0]["section"]["type"] = "i_beam"; }), "/structure/members/0/section/type",
               {"rectangle, pipe, tapered_rectangle, box or i_section", "i_beam"});
  expect_error(frame_with([](json& j) { j["structure"]["supports"][0]["type"] = "clamped"; }), "/structure/supports/0/type",
               {"fixed, pinned, roller or spring", "clamped"});
  expect_error(frame_with([](json& j) { j["structure"]["supports"][1]["restrained"] = "z"; }), "/structure/supports/1/restrained",
               {"= \"z\"", "one of x | y"});
  expect_error(frame_with([](json& j) { j["structure"]["supports"][0] = {{"node", "A"}, {"type", "spring"}, {"stiffness", {1e6, 1e6}}}; }),
               "/structure/supports/0/stiffness", {"an array of 3 numbers >= 0"});
  expect_error(frame_with([](json& j) { j["structure"]["supports"][0] = {{"node", "A"}, {"type", "spring"}, {"stiffness", {1e6, -1, 0}}}; }),
               "/structure/supports/0/stiffness", {"an array of 3 numbers >= 0"});
  expect_error(frame_with([](json& j) { j["structure"]["nodes"][0]["position"] = {0.2, 0.1, 0}; }), "/structure/nodes/0/position",
               {"an array of 2 numbers"});
  expect_error(frame_with([](json& j) { j["structure"]["theory"] = "bernoulli"; }), "/structure/theory", {"one of euler_bernoulli | timoshenko"});
  expect_error(frame_with([](json& j) { j["structure"]["integrator"] = "central_difference"; }), "/structure/integrator",
               {"one of explicit | newmark"});
  expect_error(frame_with([](json& j) { j["structure"]["rayleigh_damping"] = {{"mass", -0.1}}; }), "/structure/rayleigh_damping/mass",
               {"a number >= 0 (1/s)"});
  expect_error(frame_with([](json& j) { j["structure"]["masses"] = json::array({{{"node", "A"}, {"mass", -1}}}); }),
               "/structure/masses/0/mass", {"a number >= 0 (kg)"});
  expect_error(frame_with([](json& j) { j["structure"]["self_weight"] = 1; }), "/structure/self_weight", {"true or false"});
  expect_error(frame_with([](json& j) { j["member_contact"] = {{"decay_scale", 0}}; }), "/member_contact/decay_scale", {"a number > 0"});
  expect_error(frame_with([](json& j) { j["member_contact"] = {{"mode", "glue"}}; }), "/member_contact/mode",
               {"one of stick | separable | friction"});
  expect_error(frame_with([](json& j) { j["member_contact"] = {{"mode", "friction"}, {"friction", -0.2}}; }), "/member_contact/friction",
               {"a number >= 0"});
  expect_error(frame_with([](json& j) { j["member_contact"] = {{"bodies", "block"}}; }), "/member_contact/bodies", {"an array of strings"});
  expect_error(frame_with([](json& j) {
                 j["output"]["probes"] = json::array({{{"name", "m"}, {"type", "member"}, {"member", "beam"}, {"position", 1.5}}});
               }),
               "/output/probes/0/position", {"= 1.5", ">= 0 and <= 1"});
  expect_error(frame_with([](json& j) {
                 j["output"]["probes"] = json::array({{{"name", "m"}, {"type", "member"}, {"member", "beam"}, {"quantities", {"velocity"}}}});
               }),
               "/output/probes/0/quantities", {"\"velocity\"", "section_forces"});
}

TEST(ScenarioStructureErrors, NodesAndMembers) {
  expect_error(frame_with([](json& j) {
                 j["structure"]["nodes"][1]["name"] = "A";
                 j["structure"]["members"][0]["end"] = "A";
               }),
               "/structure/nodes/1/name", {"= \"A\"", "a name not used before"});
  expect_error(frame_with([](json& j) { j["structure"]["members"][0]["end"] = "C"; }), "/structure/members/0/end",
               {"= \"C\"", "the name of one of the structure's nodes"});
  expect_error(frame_with([](json& j) { j["structure"]["members"][0]["start"] = "a"; }), "/structure/members/0/start",
               {"= \"a\"", "the name of one of the structure's nodes"});
  expect_error(frame_with([](json& j) { j["structure"]["members"][0]["end"] = "A"; }), "/structure/members/0/end",
               {"= \"A\"", "a node other than the start node"});
  expect_error(frame_with([](json& j) { j["structure"]["nodes"][1]["position"] = {0.2, 0.1}; }), "/structure/members/0/end",
               {"= \"B\"", "zero-length member", "[0.2,0.1]"});
  expect_error(frame_with([](json& j) { j["structure"]["nodes"].push_back({{"name", "C"}, {"position", {1, 0.8}}}); }),
               "/structure/nodes/2/name", {"= \"C\"", "node 'C' is not connected to any member"});
  expect_error(frame_with([](json& j) { j["structure"]["nodes"] = json::array({j["structure"]["nodes"][0]}); }), "/structure/nodes",
               {"at least two nodes (got 1)"});
  expect_error(frame_with([](json& j) { j["structure"]["members"] = json::array(); }), "/structure/members", {"at least one member"});
  expect_error(frame_with([](json& j) { j["structure"]["members"].push_back(j["structure"]["members"][0]); }), "/structure/members/1/name",
               {"= \"beam\"", "a name not used before"});
  expect_error(frame_with([](json& j) { j["structure"]["members"][0]["name"] = "block"; }), "/structure/members/0/name",
               {"= \"block\"", "a name that no body has"});
  // The frame acts on the grid: its nodes lie in [0, 2] x [0, 1].
  expect_error(frame_with([](json& j) { j["structure"]["nodes"][1]["position"] = {2.5, 0.1}; }), "/structure/nodes/1/position",
               {"= [2.5,0.1]", "a position inside the grid [0, 2] x [0, 1] m", "along axis 0"});
  expect_error(frame_with([](json& j) { j["structure"]["nodes"][0]["position"] = {0.2, -0.05}; }), "/structure/nodes/0/position",
               {"along axis 1"});
}

TEST(ScenarioStructureErrors, MaterialsAndSections) {
  expect_error(frame_with([](json& j) { j["structure"]["members"][0]["material"] = "timber"; }), "/structure/members/0/material",
               {"= \"timber\"", "the name of one of the materials"});
  expect_error(frame_with([](json& j) {
                 j["materials"][1]["model"] = "neo_hookean";
               }),
               "/structure/members/0/material", {"= \"steel\"", "a linear_elastic or elastic_plastic material", "'steel' is neo_hookean"});
  expect_error(frame_with([](json& j) {
                 j["structure"]["members"][0]["section"] = {{"type", "pipe"}, {"diameter", 0.2}, {"wall_thickness", 0.11}};
               }),
               "/structure/members/0/section/wall_thickness", {"= 0.11", "a wall thickness <= diameter / 2 = 0.1 m"});
}

TEST(ScenarioStructureErrors, SupportsAndMasses) {
  expect_error(frame_with([](json& j) { j["structure"]["supports"] = json::array(); }), "/structure/supports", {"at least one support"});
  expect_error(frame_with([](json& j) { j["structure"]["supports"][1]["node"] = "Z"; }), "/structure/supports/1/node",
               {"= \"Z\"", "the name of one of the structure's nodes"});
  expect_error(frame_with([](json& j) { j["structure"]["supports"][1]["node"] = "A"; }), "/structure/supports/1/node",
               {"= \"A\"", "a node without another support", "supports/0"});
  expect_error(frame_with([](json& j) { j["structure"]["supports"][0] = {{"node", "A"}, {"type", "spring"}, {"stiffness", {0, 0, 0}}}; }),
               "/structure/supports/0/stiffness", {"= [0.0,0.0,0.0]", "at least one stiffness > 0"});
  expect_error(frame_with([](json& j) { j["structure"]["masses"] = json::array({{{"node", "M"}, {"mass", 10}}}); }),
               "/structure/masses/0/node", {"= \"M\"", "the name of one of the structure's nodes"});
}

TEST(ScenarioStructureErrors, MemberContactAndProbes) {
  expect_error(with([](json& j) { j["member_contact"] = {{"mode", "stick"}}; }), "/member_contact",
               {"a \"structure\" section", "there is no structure"});
  expect_error(with([](json& j) { j["member_contact"] = json::object(); }), "/member_contact", {"a \"structure\" section"});
  expect_error(frame_with([](json& j) { j["member_contact"] = {{"bodies", {"block", "boulder"}}}; }), "/member_contact/bodies/1",
               {"= \"boulder\"", "the name of one of the bodies"});
  expect_error(frame_with([](json& j) { j["output"]["probes"] = json::array({{{"name", "m"}, {"type", "member"}, {"member", "girder"}}}); }),
               "/output/probes/0/member", {"= \"girder\"", "the name of one of the structure's members"});
  expect_error(with([](json& j) { j["output"]["probes"] = json::array({{{"name", "m"}, {"type", "member"}, {"member", "beam"}}}); }),
               "/output/probes/0/member", {"= \"beam\"", "there is no structure"});
  // A member probe cannot look at a body, nor a body probe at a member.
  expect_error(frame_with([](json& j) { j["output"]["probes"] = json::array({{{"name", "m"}, {"type", "member"}, {"member", "block"}}}); }),
               "/output/probes/0/member", {"= \"block\""});
  expect_error(frame_with([](json& j) { j["output"]["probes"] = json::array({{{"name", "b"}, {"type", "body"}, {"body", "beam"}}}); }),
               "/output/probes/0/body", {"= \"beam\"", "the name of one of the bodies"});
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

namespace dmi {
namespace {

// Slurry materials: a fluid takes bulk_modulus and viscosity (bingham also yield_stress) instead of the
// elastic constants, which stay required for the solids.
json with_fluid(const json& material) {
  json j = minimal_2d();
  j["materials"][0] = material;
  return j;
}
const json kNewtonian = {{"name", "rock"}, {"model", "newtonian"}, {"density", 1200}, {"bulk_modulus", 2e6}, {"viscosity", 0.5}};
const json kBingham = {{"name", "rock"}, {"model", "bingham"}, {"density", 2000}, {"bulk_modulus", 5e6}, {"viscosity", 20}, {"yield_stress", 300}};

TEST(ScenarioMaterials, FluidsParse) {
  const Scenario n = parse(with_fluid(kNewtonian));
  ASSERT_EQ(n.materials.size(), 1u);
  EXPECT_EQ(n.materials[0].model, "newtonian");
  EXPECT_DOUBLE_EQ(n.materials[0].bulk_modulus, 2e6);
  EXPECT_DOUBLE_EQ(n.materials[0].viscosity, 0.5);
  const Scenario b = parse(with_fluid(kBingham));
  EXPECT_DOUBLE_EQ(b.materials[0].yield_stress, 300);
  EXPECT_DOUBLE_EQ(b.materials[0].regularisation_rate, 0.01);  // default
  json r = kBingham;
  r["regularisation_rate"] = 0.1;
  EXPECT_DOUBLE_EQ(parse(with_fluid(r)).materials[0].regularisation_rate, 0.1);
  r["yield_stress"] = 0;  // a Bingham fluid without yield stress is Newtonian, and allowed
  EXPECT_NO_THROW(parse(with_fluid(r)));
  json j3 = minimal_3d();
  j3["materials"][0] = kBingham;
  EXPECT_EQ(parse(j3).materials[0].model, "bingham");
  // The reference documents the fluid keys, scoped to their models.
  const std::string md = scenario_reference_markdown();
  for (const char* key : {"`/materials[]/bulk_modulus`", "`/materials[]/viscosity`", "`/materials[]/yield_stress`", "`/materials[]/regularisation_rate`",
                          "when model = newtonian or bingham", "when model = linear_elastic or neo_hookean or drucker_prager"})
    EXPECT_NE(md.find(key), std::string::npos) << key;
}

TEST(ScenarioMaterials, FluidErrors) {
  auto fluid_without = [](json m, const char* key) { m.erase(key); return with_fluid(m); };
  auto fluid_with = [](json m, const char* key, const json& v) { m[key] = v; return with_fluid(m); };
  expect_error(fluid_without(kNewtonian, "viscosity"), "/materials/0/viscosity", {"the required key 'viscosity'"});
  expect_error(fluid_without(kBingham, "viscosity"), "/materials/0/viscosity", {"the required key 'viscosity'"});
  expect_error(fluid_without(kNewtonian, "bulk_modulus"), "/materials/0/bulk_modulus", {"the required key 'bulk_modulus'"});
  expect_error(fluid_without(kBingham, "yield_stress"), "/materials/0/yield_stress", {"the required key 'yield_stress'"});
  expect_error(fluid_with(kBingham, "yield_stress", -10), "/materials/0/yield_stress", {"-10", ">= 0 (Pa)"});
  expect_error(fluid_with(kNewtonian, "viscosity", 0), "/materials/0/viscosity", {"> 0 (Pa s)"});
  expect_error(fluid_with(kBingham, "regularisation_rate", 0), "/materials/0/regularisation_rate", {"> 0 (1/s)"});
  // Keys of another model are unknown here.
  expect_error(fluid_with(kNewtonian, "yield_stress", 100), "/materials/0/yield_stress", {"unknown key 'yield_stress'", "viscosity"});
  expect_error(fluid_with(kNewtonian, "youngs_modulus", 1e8), "/materials/0/youngs_modulus", {"unknown key 'youngs_modulus'"});
  expect_error(fluid_with(kBingham, "viscocity", 1), "/materials/0/viscocity", {"unknown key 'viscocity'"});
  expect_error(with([](json& j) { j["materials"][0]["viscosity"] = 1; }), "/materials/0/viscosity", {"unknown key 'viscosity'"});
  // The solids still need their elastic constants.
  expect_error(with([](json& j) { j["materials"][0].erase("youngs_modulus"); }), "/materials/0/youngs_modulus",
               {"the required key 'youngs_modulus'"});
  expect_error(with([](json& j) { j["materials"][0]["model"] = "drucker_prager"; j["materials"][0]["friction_angle"] = 30;
                                  j["materials"][0].erase("poisson_ratio"); }),
               "/materials/0/poisson_ratio", {"the required key 'poisson_ratio'"});
  // Plane stress: a fluid layer cannot be a thin plate.
  json ps = with_fluid(kBingham);
  ps["analysis"]["plane"] = "stress";
  expect_error(ps, "/bodies/0/material", {"a material other than bingham in plane stress", "plane strain or 3D"});
}

// A solid check's force in kN (980 meant as Lin, Cheng & Tuan's 980 kN) is refused naming the conversion; a laboratory
// model says accept_unusual.
TEST(ScenarioErrors, SolidCheckForceInKilonewtonsIsRefused) {
  const json j = json::parse(R"({"schema_version": 1, "name": "slip", "solid_check": {"height": 4, "crest_thickness": 1, "base_thickness": 1.6,
    "width": 2, "youngs_modulus": 25e9, "poisson_ratio": 0.2, "loads": [{"name": "p", "type": "point", "force": 980, "height": 3.6}]}})");
  expect_error(j, "/solid_check/loads/0/force", {"a force in N between 1e4 and 1e9", "980 kN is 980000 N"});
  json lab = j;
  lab["accept_unusual"] = true;
  EXPECT_NO_THROW(parse_scenario(lab.dump(), "lab.json"));
  json right = j;
  right["solid_check"]["loads"][0]["force"] = 980e3;
  EXPECT_NO_THROW(parse_scenario(right.dump(), "ok.json"));
}

}  // namespace
}  // namespace dmi
