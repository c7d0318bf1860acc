// design.json's grid_study section from three design documents: the quantities are read per run, their
// convergence computed, and a missing or non-numeric value is an error naming the file.
#include <gtest/gtest.h>

#include "design/grid_study.hpp"

using namespace dmi::design;

TEST(GridStudy, SectionReadsTheThreeDesignsAndRefusesAMissingQuantity) {
  using nlohmann::json;
  auto doc = [](double shear, double util) {
    json check = {{"id", "shear"}, {"member", "dam"}, {"demand", shear}, {"utilisation", util}, {"title", "one-way shear"}, {"unit", "N"}};
    json run = {{"variant", ""}, {"base_total", {{"Fx_N", {{"abs_max", {{"value", shear}}}}}, {"M_Nm", {{"abs_max", {{"value", 2 * shear}}}}}}},
                {"contact", nullptr}, {"checks", {check}}, {"verdict", {{"governing", check}}}};
    return json{{"runs", {run}}};
  };
  const std::array<double, 3> h{0.01, 0.02, 0.04};
  const json s = grid_study_section({doc(101, 0.5), doc(104, 0.52), doc(116, 0.6)}, h, {"a", "b", "c"});
  ASSERT_EQ(s["quantities"].size(), 4u);  // base shear, base moment, governing demand, governing utilisation
  EXPECT_EQ(s["quantities"][0]["id"], "base_shear");
  EXPECT_NEAR(s["quantities"][0]["observed_order"].get<double>(), 2.0, 1e-9);
  EXPECT_NEAR(s["quantities"][0]["extrapolated"].get<double>(), 100.0, 1e-9);
  json bad = doc(104, 0.52);
  bad["runs"][0]["base_total"]["Fx_N"]["abs_max"]["value"] = "n/a";
  EXPECT_THROW(grid_study_section({doc(101, 0.5), bad, doc(116, 0.6)}, h, {"a", "b", "c"}), std::runtime_error);
}
