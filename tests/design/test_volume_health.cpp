// The bodies' volume as numerical health (design/volume_health) by hand.
#include <gtest/gtest.h>

#include "design/volume_health.hpp"

using namespace dmi;
using namespace dmi::design;

// A body created with 9.04 m^3 that ends filling 10.39 m^3 has grown by 14.9 % (flagged, above 5 %); an inflow whose
// particles enter (created volume growing with them) and keep their volume is not flagged; a body not yet entered
// (nothing created) is skipped until it is.
TEST(VolumeHealth, GrowthAgainstTheVolumeAsCreated) {
  Results r;
  r.time = {0.0, 1.0, 2.0};
  r.series.push_back(Series{"probes/debris/volume", "m^3", {"current", "initial"}, {9.04, 9.04, 9.5, 9.04, 10.39, 9.04}});
  r.series.push_back(Series{"probes/inflow/volume", "m^3", {"current", "initial"}, {0.0, 0.0, 2.0, 2.0, 5.1, 5.0}});
  r.series.push_back(Series{"probes/debris/velocity", "m/s", {"x", "y"}, {0, 0, 1, 0, 2, 0}});
  const nlohmann::json v = to_json(volume_health(r));
  EXPECT_EQ(to_json(volume_health_from_json(v, "test")), v);  // the record reads back the same
  ASSERT_EQ(v.size(), 2u);
  EXPECT_EQ(v[0]["probe"], "debris");
  EXPECT_NEAR(v[0]["largest_ratio"].get<double>(), 10.39 / 9.04, 1e-12);
  EXPECT_NEAR(v[0]["largest_time_s"].get<double>(), 2.0, 0);
  EXPECT_TRUE(v[0]["flagged"].get<bool>());
  EXPECT_EQ(v[1]["probe"], "inflow");
  EXPECT_NEAR(v[1]["largest_ratio"].get<double>(), 1.02, 1e-12);
  EXPECT_FALSE(v[1]["flagged"].get<bool>());
}
