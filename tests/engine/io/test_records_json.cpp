// The run's typed records against their JSON in results.h5: a record reads back as written, and a damaged document
// is refused naming it rather than read as numbers.
#include <gtest/gtest.h>

#include <functional>
#include <stdexcept>
#include <string>

#include "engine/io/records_json.hpp"

namespace dmi {
namespace {

using json = nlohmann::json;

bool refused(const std::function<void()>& read) {
  try {
    read();
  } catch (const std::runtime_error& e) {
    return std::string(e.what()).find("/documents/x is malformed") != std::string::npos;
  }
  return false;
}

TEST(RecordsJson, PeakContactReadsBackAndRefusesDamage) {
  const PeakContact p{0.25, {3, 4}, {{"dam", 0.5, {0, 1.5}, {3, 4}}}};
  const PeakContact q = peak_contact_from_json(peak_contact_to_json(p), "/documents/x");
  EXPECT_EQ(q.time, 0.25);
  EXPECT_EQ(q.loads.at(0).point, p.loads[0].point);
  json bad = peak_contact_to_json(p);
  bad["loads"] = nullptr;
  EXPECT_TRUE(refused([&] { peak_contact_from_json(bad, "/documents/x"); }));
  bad = peak_contact_to_json(p);
  bad["loads"][0]["force"] = {1, 2, 3};  // a 3D force in a 2D record
  EXPECT_TRUE(refused([&] { peak_contact_from_json(bad, "/documents/x"); }));
}

TEST(RecordsJson, StructureRefusesIndicesOutsideTheFrame) {
  StructureRecord s;
  s.nodes_m = {{0, 0}, {0, 1}};
  s.node_names = {"A", "B"};
  ElementRecord e;
  e.i = 0, e.j = 1, e.section = {"rectangle", 0, 0, 1, 0.5, 0.5}, e.youngs_modulus_Pa = 25e9;
  s.elements = {e};
  s.members = {{"dam", "concrete", 0, 1}};
  s.supports = {{"A", "fixed", "supports/A/reaction", 0, {true, true, true}}};
  s.gravity_m_s2 = {0, -9.81};
  const json good = structure_to_json(s);
  EXPECT_EQ(structure_from_json(good, "/documents/x").members.at(0).name, "dam");
  json bad = good;
  bad["elements"][0]["member"] = 1;  // no second member
  EXPECT_TRUE(refused([&] { structure_from_json(bad, "/documents/x"); }));
  bad = good;
  bad["elements"][0]["j"] = 1.7;  // not a whole number
  EXPECT_TRUE(refused([&] { structure_from_json(bad, "/documents/x"); }));
  bad = good;
  bad["supports"][0]["fixed"] = {true};
  EXPECT_TRUE(refused([&] { structure_from_json(bad, "/documents/x"); }));
}

TEST(RecordsJson, FaceWithoutHeightsStandsVertical) {
  const json f = {{"members", {"dam"}}, {"direction", {1, 0}}, {"width", 2}, {"bins", {{{"member", "dam"}, {"element", 0}, {"from", 0.5}, {"to", 1.5}}}}};
  const FaceProfileRecord r = face_profile_from_json(f, "/documents/x");
  EXPECT_EQ(r.bins.at(0).height_from, 0.5);
  EXPECT_EQ(r.bins.at(0).height_to, 1.5);
  json bad = f;
  bad["direction"] = {1};
  EXPECT_TRUE(refused([&] { face_profile_from_json(bad, "/documents/x"); }));
}

TEST(RecordsJson, SolidCheckNeedsItsGaussPointPeaks) {
  SolidCheckRecord c;
  c.model.element = "quad4", c.model.cells = {4, 8};
  SolidCase k;
  k.name = "impact", k.type = "point", k.total_base_reaction_N = {1, 0};
  for (const char* m : {"von_mises", "max_principal", "min_principal"}) k.peaks[m]["gauss"] = {1e6, {0.1, 0.2}};
  c.cases = {k};
  const json good = solid_check_to_json(c);
  EXPECT_EQ(solid_check_from_json(good, "/documents/x").cases.at(0).peaks.at("max_principal").at("gauss").value_Pa, 1e6);
  json bad = good;
  bad["cases"][0]["peaks"].erase("min_principal");
  EXPECT_TRUE(refused([&] { solid_check_from_json(bad, "/documents/x"); }));
}

}  // namespace
}  // namespace dmi
