// The report's member checks by member group (render/report_groups.cpp), by hand.
#include <gtest/gtest.h>

#include "design/checks.hpp"
#include "render/report_rows.hpp"

namespace dmi::render {
namespace {

using nlohmann::json;

// A check as design builds it.
design::Check check(const std::string& id, const std::string& member, double u, const std::string& level = "ultimate") {
  design::Check c;
  c.id = id, c.title = id + " title", c.member = member, c.unit = "N", c.level = level, c.demand = 100 * u, c.capacity = 100;
  c.finish();
  return c;
}

design::RunDesign run_of(std::vector<design::Check> checks) {
  design::RunDesign r;
  r.checks = std::move(checks);
  return r;
}

// Two columns and a beam: the shear row of the columns counts 2 members, 1 failing, column_1_1 governing at 1.20; the
// beam's own row counts 1. The solid-FE and information checks stay out.
TEST(ReportGroups, GovernsPerCheckAndGroup) {
  const json rows = check_group_rows(run_of({check("shear", "column_0_1", 0.5), check("shear", "column_1_1", 1.2), check("shear", "beam_0_1", 0.3),
                                             check("stress", "column_0_1", 0.7, "serviceability"), check("principal", "solid: x", 9.0, "information")}));
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0]["group"], "columns");
  EXPECT_EQ(rows[0]["members"], 2);
  EXPECT_EQ(rows[0]["failed"], 1);
  EXPECT_EQ(rows[0]["member"], "column_1_1");
  EXPECT_EQ(rows[0]["util"], "1.20");
  EXPECT_EQ(rows[0]["level"], "ULS");
  EXPECT_EQ(rows[1]["group"], "beams");
  EXPECT_EQ(rows[2]["level"], "SLS");
  // One member per group (a concrete dam): no summary.
  EXPECT_TRUE(check_group_rows(run_of({check("shear", "dam", 0.5), check("stress", "dam", 0.7)})).empty());
}

}  // namespace
}  // namespace dmi::render
