// The face profile at its largest moment and the sensors' peaks, from hand-made histories (design/pressures.hpp).
#include <gtest/gtest.h>

#include "design/pressures.hpp"

namespace dmi::design {
namespace {

// Resultants 0, 10, 8 N at heights 0, 1, 2 m: moments 0, 10, 16 N m, so the profile is taken at t = 2 s (the largest
// moment) although the largest resultant comes at t = 1 s.
TEST(Pressures, FaceProfileAtTheLargestMomentByHand) {
  Results r;
  r.time = {0, 1, 2};
  r.series.push_back(Series{"face/pressure", "Pa", {"bin0", "bin1"}, {0, 0, 4, 6, 1, 7}});
  r.series.push_back(Series{"face/resultant", "N", {"value"}, {0, 10, 8}});
  r.series.push_back(Series{"face/height", "m", {"value"}, {0, 1, 2}});
  r.series.push_back(Series{"sensors/a/pressure", "Pa", {"value"}, {1, 5, 2}});
  r.info.face_profile = FaceProfileRecord{{"dam"}, {1, 0}, 2, {{"dam", 0, 0, 1.5, 0, 1.5}, {"dam", 1, 1.5, 3, 1.5, 3}}};
  const nlohmann::json f = to_json(*face_profile(r, "hand.h5"));
  EXPECT_EQ(to_json(*face_profile_from_json(f, "test")), f);  // the record reads back the same
  EXPECT_DOUBLE_EQ(f["time_s"].get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(f["moment_N_m"].get<double>(), 16.0);
  EXPECT_DOUBLE_EQ(f["peak_resultant_N"].get<double>(), 10.0);
  EXPECT_DOUBLE_EQ(f["peak_resultant_time_s"].get<double>(), 1.0);
  EXPECT_EQ(f["pressure_Pa"], nlohmann::json({1.0, 7.0}));
  EXPECT_EQ(f["positions_m"], nlohmann::json({0.75, 2.25}));
  const nlohmann::json s = to_json(sensor_peaks(r));
  EXPECT_EQ(to_json(sensors_from_json(s, "test")), s);
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0]["name"], "a");
  EXPECT_DOUBLE_EQ(s[0]["peak_pressure_Pa"].get<double>(), 5.0);
  EXPECT_DOUBLE_EQ(s[0]["peak_time_s"].get<double>(), 1.0);
  EXPECT_NEAR(s[0]["mean_pressure_Pa"].get<double>(), 8.0 / 3.0, 1e-12);
  r.info.face_profile->bins.clear();
  EXPECT_THROW(face_profile(r, "hand.h5"), std::runtime_error);  // the record does not match the history
}

}  // namespace
}  // namespace dmi::design
