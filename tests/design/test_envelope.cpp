// Envelopes, reactions, contact and checks of design_run on small hand-made histories, worked by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "design/design.hpp"
#include "design/loads.hpp"
#include "design/members.hpp"
#include "engine/io/records_json.hpp"

using namespace dmi::design;
using nlohmann::json;

namespace {

// One vertical member 'dam' from (0,0) to (0,2) in two elements; rectangle b = 2 m, h = 1 m (A = 2 m^2,
// I = 1/6 m^4, c = 0.5 m); support 'base' at node 0 and, with two_supports, 'top' at node 2.
json structure(const json& section, const std::string& material, bool two_supports = false) {
  json els = json::array();
  els.push_back({{"member", 0}, {"i", 0}, {"j", 1}, {"s0", 0.0}, {"s1", 0.5}, {"section", section}, {"youngs_modulus_Pa", 25e9},
                 {"poisson_ratio", 0.2}, {"density_kg_m3", 2400}});
  els.push_back({{"member", 0}, {"i", 1}, {"j", 2}, {"s0", 0.5}, {"s1", 1.0}, {"section", section}, {"youngs_modulus_Pa", 25e9},
                 {"poisson_ratio", 0.2}, {"density_kg_m3", 2400}});
  json sup = json::array({{{"node", "base"}, {"node_index", 0}, {"type", "fixed"}, {"fixed", {true, true, true}}, {"series", "supports/base/reaction"}}});
  if (two_supports)
    sup.push_back({{"node", "top"}, {"node_index", 2}, {"type", "pinned"}, {"fixed", {true, true, false}}, {"series", "supports/top/reaction"}});
  return json{{"nodes_m", {{0.0, 0.0}, {0.0, 1.0}, {0.0, 2.0}}}, {"node_names", {"base", "", "top"}}, {"elements", els},
              {"members", {{{"name", "dam"}, {"material", material}, {"first_element", 0}, {"elements", 2}}}}, {"supports", sup}};
}

dmi::Series series(const std::string& path, std::vector<std::string> comps, std::vector<double> data) {
  dmi::Series s;
  s.path = path, s.unit = "N", s.components = std::move(comps), s.data = std::move(data);
  return s;
}

// Three samples, t = 0, 0.1, 0.2 s. End forces per element: N_i V_i M_i N_j V_j M_j.
dmi::Results results(const json& st) {
  dmi::Results r;
  r.complete = true;
  r.info.scenario_name = "hand";
  r.info.scenario_json = json{{"name", "hand"}, {"structure", {{"members", json::array({json::object()})}}}}.dump();  // what the file says it ran
  r.info.structure = dmi::structure_from_json(st, "hand.h5");
  r.time = {0.0, 0.1, 0.2};
  std::vector<std::string> c;
  for (int e = 0; e < 2; ++e)
    for (const char* q : {"N_i", "V_i", "M_i", "N_j", "V_j", "M_j"}) c.push_back("e" + std::to_string(e) + "_" + q);
  r.series.push_back(series("frame/end_forces", c,
                            {-200e3, 0, 0, -150e3, 0, 0, -150e3, 0, 0, -100e3, 0, 0,                  // t = 0: self-weight only
                             -200e3, 100e3, 300e3, -150e3, 100e3, 200e3, -150e3, 50e3, 200e3, -100e3, 50e3, 0,   // t = 0.1
                             -200e3, -400e3, -250e3, -150e3, -500e3, 150e3, -150e3, -20e3, 150e3, -100e3, -20e3, 0}));  // t = 0.2
  r.series.push_back(series("supports/base/reaction", {"Fx", "Fy", "M"}, {0, 200e3, 0, -100e3, 200e3, -300e3, 400e3, 200e3, 250e3}));
  r.series.push_back(series("supports/top/reaction", {"Fx", "Fy", "M"}, {0, 0, 0, 10e3, -5e3, 0, -20e3, 0, 0}));
  // Contact: interval means; 0 at t = 0, 100 kN over (0, 0.1], 40 kN over (0.1, 0.2].
  r.series.push_back(series("frame/contact_force", {"x", "y"}, {0, 0, 100e3, 0, 24e3, 32e3}));  // |F| = 40 kN at t = 0.2
  return r;
}

const json kRect{{"kind", "rectangle"}, {"width_m", 2.0}, {"depth_start_m", 1.0}, {"depth_end_m", 1.0}};

const Check& find(const std::vector<Check>& v, const std::string& id) {
  for (const auto& c : v)
    if (c.id == id) return c;
  throw std::runtime_error("no check " + id);
}

}  // namespace

TEST(DesignEnvelope, ConcreteMemberStationsAndChecksByHand) {
  Limits L;
  L.concrete.strain_rate_effects = false;  // the static envelope by hand (the strain-rate factors: test_strain_rate.cpp)
  const dmi::Results r = results(structure(kRect, "concrete"));
  const FrameInfo f = frame_info(*r.info.structure, "hand.h5", L);
  ASSERT_EQ(f.members.size(), 1u);
  EXPECT_EQ(f.members[0].cls, "concrete");
  EXPECT_DOUBLE_EQ(f.members[0].length, 2.0);
  const auto env = member_envelopes(r, f, L, "hand.h5");
  ASSERT_EQ(env.size(), 1u);
  const auto& st = env[0].stations;
  ASSERT_EQ(st.size(), 3u);
  EXPECT_DOUBLE_EQ(st[1].position, 0.5);
  EXPECT_DOUBLE_EQ(st[1].s_m, 1.0);
  // Station 0 (base): M = 300 kN m at 0.1 s with N = -200 kN: sigma_t = -200e3/2 + 300e3 x 0.5 / (1/6) = -1e5 + 9e5 = 8e5 Pa;
  // sigma_c = -1e5 - 9e5 = -1e6 Pa.
  EXPECT_NEAR(st[0].M_max.value, 300e3, 1e-9);
  EXPECT_DOUBLE_EQ(st[0].M_max.time, 0.1);
  EXPECT_NEAR(st[0].M_min.value, -250e3, 1e-9);
  EXPECT_DOUBLE_EQ(st[0].M_min.time, 0.2);
  EXPECT_NEAR(st[0].sigma_tension.value, 8e5, 1e-6);
  EXPECT_NEAR(st[0].sigma_compression.value, -1e6, 1e-6);
  // Station 1 joins element 0's end j and element 1's end i: |V| max = 500 kN (e0, t = 0.2), M max 200 kN m (both, t = 0.1).
  EXPECT_NEAR(st[1].V_abs.value, 500e3, 1e-9);
  EXPECT_DOUBLE_EQ(st[1].V_abs.time, 0.2);
  EXPECT_NEAR(st[1].M_max.value, 200e3, 1e-9);
  // tau = 1.5 V / A = 1.5 x 500e3 / 2 = 375 kPa.
  EXPECT_NEAR(st[1].tau.value, 375e3, 1e-6);
  const auto& ch = env[0].checks;
  // Tension: 8e5 / (0.6 x 3.28e6) = 0.406504 at the base, t = 0.1.
  const Check& t = find(ch, "concrete_flexural_tension");
  EXPECT_NEAR(t.utilisation, 8e5 / 1.968e6, 1e-9);
  EXPECT_DOUBLE_EQ(t.time_s, 0.1);
  EXPECT_DOUBLE_EQ(t.s_m, 0.0);
  EXPECT_TRUE(t.passed);
  // Compression: 1e6 / (0.6 x 0.85 x 28e6) = 1e6 / 14.28e6 = 0.070028.
  EXPECT_NEAR(find(ch, "concrete_compression").utilisation, 1e6 / 14.28e6, 1e-9);
  // Shear: 500 kN / 698.478 kN (b 2 m, h 1 m, f'c 28 MPa, phi 0.6) = 0.715845, at s = 1 m, t = 0.2.
  const Check& v = find(ch, "concrete_shear");
  EXPECT_NEAR(v.utilisation, 500e3 / 698478.346, 1e-6);
  EXPECT_DOUBLE_EQ(v.s_m, 1.0);
  EXPECT_DOUBLE_EQ(v.time_s, 0.2);
  // A lower tensile strength fails the tension check: 8e5 / (0.6 x 0.5e6) = 2.667.
  Limits low;
  low.concrete.tensile_strength = 0.5e6;
  low.concrete.strain_rate_effects = false;
  const auto env2 = member_envelopes(r, f, low, "hand.h5");
  const Check& t2 = find(env2[0].checks, "concrete_flexural_tension");
  EXPECT_NEAR(t2.utilisation, 8e5 / 3e5, 1e-9);
  EXPECT_FALSE(t2.passed);
}

TEST(DesignEnvelope, SteelPipeChecksByHand) {
  // CHS 500 x 20, S355 by the limits; station 0 at 0.1 s: N = -200 kN, M = 300 kN m.
  // Elastic: 200e3 / 0.0301593 + 300e3 / 3.480382e-3 = 6.6314 + 86.1975 = 92.829 MPa; / 355 MPa = 0.261490.
  // Interaction (class 1, W_pl): 200e3 / (0.0301593 x 355e6) + 300e3 / (4.610667e-3 x 355e6) = 0.018680 + 0.183286 = 0.201966.
  Limits L;
  L.steel.yield_strength = 355e6;
  const json pipe{{"kind", "pipe"}, {"diameter_m", 0.5}, {"wall_thickness_m", 0.02}};
  const dmi::Results r = results(structure(pipe, "steel"));
  const FrameInfo f = frame_info(*r.info.structure, "hand.h5", L);
  EXPECT_EQ(f.members[0].cls, "steel");
  const auto env = member_envelopes(r, f, L, "hand.h5");
  const auto& ch = env[0].checks;
  EXPECT_NEAR(find(ch, "steel_elastic_stress").demand, 200e3 / 0.030159289 + 300e3 / 3.48038201e-3, 1.0);
  EXPECT_NEAR(find(ch, "steel_elastic_stress").utilisation, (200e3 / 0.030159289 + 300e3 / 3.48038201e-3) / 355e6, 1e-7);
  EXPECT_NEAR(find(ch, "steel_interaction").utilisation, 200e3 / (0.030159289 * 355e6) + 300e3 / (4.6106667e-3 * 355e6), 1e-6);
  // Shear 500 kN / 3.935219 MN = 0.127057.
  EXPECT_NEAR(find(ch, "steel_shear").utilisation, 500e3 / 3.9352194e6, 1e-6);
  const Check& cls = find(ch, "steel_section_class");
  EXPECT_DOUBLE_EQ(cls.demand, 25.0);
  EXPECT_NEAR(cls.capacity, 90 * 235.0 / 355.0, 1e-9);
  EXPECT_TRUE(cls.passed);
  // The limits may call it concrete instead (e.g. a concrete-filled pipe checked as plain concrete).
  L.member_material["dam"] = "concrete";
  EXPECT_EQ(frame_info(*r.info.structure, "hand.h5", L).members[0].cls, "concrete");
}

TEST(DesignEnvelope, ReactionTotalsAboutTheSupportCentroidAndContactPulse) {
  const dmi::Results r = results(structure(kRect, "concrete", true));
  const FrameInfo f = frame_info(*r.info.structure, "hand.h5", Limits{});
  const Reactions re = reactions(r, f, "hand.h5");
  ASSERT_EQ(re.supports.size(), 2u);
  EXPECT_DOUBLE_EQ(re.about[1], 1.0);  // centroid of (0,0) and (0,2)
  // t = 0.2: sum Fx = 400 - 20 = 380 kN; M about (0, 1): base 250 - (0 - 1) 400 = 650 kN m, top 0 - (2 - 1)(-20) = 20 -> 670 kN m.
  EXPECT_NEAR(re.total.at("Fx_N").abs.value, 380e3, 1e-6);
  EXPECT_DOUBLE_EQ(re.total.at("Fx_N").abs.time, 0.2);
  EXPECT_NEAR(re.total.at("M_Nm").max.value, 670e3, 1e-6);
  // t = 0.1: M = -300 + (1)(-100) ... base: -300 - (0 - 1)(-100) = -400; top: 0 - (1)(10) = -10 -> -410 kN m.
  EXPECT_NEAR(re.total.at("M_Nm").min.value, -410e3, 1e-6);
  EXPECT_NEAR(re.supports[0].at("Fy_N").max.value, 200e3, 1e-9);
  EXPECT_NEAR(re.total.at("Fy_N").final, 200e3, 1e-9);
  // Contact: impulse = 100 kN x 0.1 s + (24, 32) kN x 0.1 s = (12.4, 3.2) kN s; peak 100 kN at 0.1 s; the pulse (>= 5 kN)
  // runs from 0 to 0.2 s.
  const Contact c = contact(r);
  EXPECT_NEAR(c.peak_N, 100e3, 1e-9);
  EXPECT_DOUBLE_EQ(c.peak_time_s, 0.1);
  EXPECT_NEAR(c.impulse_N_s[0], 12.4e3, 1e-9);
  EXPECT_NEAR(c.impulse_N_s[1], 3.2e3, 1e-9);
  EXPECT_DOUBLE_EQ(c.pulse_start_s, 0.0);
  EXPECT_DOUBLE_EQ(c.pulse_end_s, 0.2);
  EXPECT_NEAR(c.pulse_impulse_N_s, 100e3 * 0.1 + 40e3 * 0.1, 1e-9);
}

TEST(DesignEnvelope, DesignRunJsonCarriesPeaksChecksAndVerdict) {
  const dmi::Results r = results(structure(kRect, "concrete"));
  const json run = to_json(design_run(r, Limits{}, "hand.h5"));
  const json& m = run["members"][0];
  EXPECT_EQ(m["name"], "dam");
  EXPECT_NEAR(m["peaks"]["sigma_tension_max"]["value"].get<double>(), 8e5, 1e-6);
  EXPECT_DOUBLE_EQ(m["peaks"]["sigma_tension_max"]["s_m"].get<double>(), 0.0);
  EXPECT_NEAR(m["peaks"]["V_abs_max"]["value"].get<double>(), 500e3, 1e-6);
  // Tension, compression and shear through the run (accidental) and at rest with the persistent factors.
  ASSERT_EQ(run["checks"].size(), 6u);
  int persistent = 0;
  for (const auto& c : run["checks"]) persistent += c["situation"] == "persistent";
  EXPECT_EQ(persistent, 3);
  EXPECT_EQ(run["verdict"]["situations"]["persistent"]["checks"].get<int>(), 3);
  EXPECT_TRUE(run["verdict"]["passed"].get<bool>());
  EXPECT_EQ(run["verdict"]["governing"]["id"], "concrete_shear");
  // Punching around a 0.4 x 0.4 m patch when asked for (the peak contact load on the member, at mid-height).
  dmi::Results r2 = r;
  r2.info.peak_contact = dmi::PeakContact{0.1, {2e5, 0}, {{"dam", 0.4, {0, 0.8}, {1e5, 0}}, {"dam", 0.6, {0, 1.2}, {1e5, 0}}}};
  Limits L;
  L.concrete.punching_patch_width = 0.4, L.concrete.punching_patch_height = 0.4;
  const json run2 = to_json(design_run(r2, L, "hand.h5"));
  bool found = false;
  for (const auto& c : run2["checks"])
    if (c["id"] == "concrete_punching") {
      found = true;
      EXPECT_NEAR(c["capacity"].get<double>(), 3.911479e6, 5.0);  // h = 1 m: test_checks' hand value
      EXPECT_NEAR(c["demand"].get<double>(), 200e3, 1e-6);  // the total contact force, at the loads' mean position
      EXPECT_NEAR(c["s_m"].get<double>(), 1.0, 1e-12);
      EXPECT_DOUBLE_EQ(c["time_s"].get<double>(), 0.1);
    }
  EXPECT_TRUE(found);
  // An unfinished run is refused.
  dmi::Results partial = r;
  partial.complete = false;
  EXPECT_THROW(design_run(partial, Limits{}, "hand.h5"), std::runtime_error);
}

// compare_3d: the plane and 3D runs of one folder side by side (ratio plane / 3D), both buffered runs judged, the bare
// 3D run the reference of its own buffered one.
TEST(DesignEnvelope, PlaneAndSpaceRunsSideBySide) {
  const dmi::Results r = results(structure(kRect, "concrete"));
  RunDesign with = design_run(r, Limits{}, "out/with_buffer/results.h5");
  RunDesign without = with, with3 = with, without3 = with;
  with.variant = "with_buffer", without.variant = "without_buffer";
  with3.variant = "with_buffer_3d", without3.variant = "without_buffer_3d";
  without.results_file = "out/without_buffer/results.h5";
  with3.results_file = "out/with_buffer_3d/results.h5";
  without3.results_file = "out/without_buffer_3d/results.h5";
  with.contact.peak_N = 300e3, with3.contact.peak_N = 200e3;
  const json doc = to_json(design_document({with, without, with3, without3}, Limits{}, "test"));
  ASSERT_TRUE(doc["plane_and_space"].is_object());
  ASSERT_EQ(doc["plane_and_space"]["pairs"].size(), 2u);
  const json& pair = doc["plane_and_space"]["pairs"][0];
  EXPECT_EQ(pair["variant"], "with_buffer");
  bool found = false;
  for (const auto& q : pair["quantities"])
    if (q["id"] == "contact_force") {
      found = true;
      EXPECT_NEAR(q["ratio"].get<double>(), 1.5, 1e-12);
    }
  EXPECT_TRUE(found);
  EXPECT_EQ(doc["verdict"]["runs_judged"], "with_buffer, with_buffer_3d");
  EXPECT_FALSE(design_document({with, without}, Limits{}, "test").plane_and_space.has_value());
}

TEST(DesignEnvelope, ComparisonReductionsInPercent) {
  const dmi::Results r = results(structure(kRect, "concrete"));
  RunDesign with = design_run(r, Limits{}, "a.h5"), without = with;
  with.variant = "with_buffer", without.variant = "without_buffer";
  without.contact.peak_N = 400e3;  // with: 100 kN -> 75 % less
  const json doc = to_json(design_document({with, without}, Limits{}, "test"));
  ASSERT_TRUE(doc["comparison"].is_object());
  bool found = false;
  for (const auto& q : doc["comparison"]["quantities"])
    if (q["id"] == "contact_force") {
      found = true;
      EXPECT_NEAR(q["reduction_percent"].get<double>(), 75.0, 1e-12);
    }
  EXPECT_TRUE(found);
  EXPECT_EQ(doc["verdict"]["runs_judged"], "with_buffer");
  // A failing bare run is the reference only beside its own buffered run: a run from elsewhere is judged.
  RunDesign bare = without;
  bare.verdict.failed = 1, bare.verdict.passed = false;
  EXPECT_TRUE(design_document({with, bare}, Limits{}, "test").verdict.passed);
  RunDesign other = bare;
  other.results_file = "elsewhere/without_buffer/results.h5";
  with.results_file = "out/with_buffer/results.h5";
  const DesignDocument d2 = design_document({with, other}, Limits{}, "test");
  EXPECT_FALSE(d2.verdict.passed);
  EXPECT_FALSE(d2.comparison.has_value());
  RunDesign plain = bare;
  plain.variant = "";
  EXPECT_FALSE(design_document({with, plain}, Limits{}, "test").verdict.passed);
  EXPECT_EQ(doc["format"], "damimpact-design");
  EXPECT_EQ(doc["format_version"], kDesignFormatVersion);
}

// design.json's runs and document are typed records: what design builds survives its file (written, read back
// validated, written again: the same text), and a damaged value is refused naming its place.
TEST(DesignEnvelope, RunAndDocumentSurviveTheirFile) {
  dmi::Results r = results(structure(kRect, "concrete"));
  r.info.peak_contact = dmi::PeakContact{0.1, {2e5, 0}, {{"dam", 0.4, {0, 0.8}, {1e5, 0}}, {"dam", 0.6, {0, 1.2}, {1e5, 0}}}};
  Limits L;
  L.concrete.punching_patch_width = 0.4, L.concrete.punching_patch_height = 0.4;
  RunDesign with = design_run(r, L, "out/with_buffer/results.h5"), without = with;
  with.variant = "with_buffer", without.variant = "without_buffer", without.results_file = "out/without_buffer/results.h5";
  const json run = to_json(with);
  EXPECT_EQ(to_json(run_design_from_json(run, "design.json run")), run);
  const json doc = to_json(design_document({with, without}, L, "test"));
  ASSERT_TRUE(doc["comparison"].is_object());
  EXPECT_EQ(to_json(design_document_from_json(doc, "design.json")), doc);
  EXPECT_TRUE(design_document_from_json(doc, "design.json").runs[1].reference);
  json bad = doc;
  bad["runs"][0]["base_total"]["Fx_N"]["abs_max"]["value"] = "n/a";
  try {
    design_document_from_json(bad, "design.json");
    ADD_FAILURE() << "a damaged base total was read";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("design.json run out/with_buffer/results.h5.base_total.Fx_N"), std::string::npos) << e.what();
  }
  bad = doc;
  bad["format_version"] = 99;
  EXPECT_THROW(design_document_from_json(bad, "design.json"), std::runtime_error);
}
