// The three phases of a debris load read from a hand-made contact history (design/phases.hpp).
#include <gtest/gtest.h>

#include <cmath>

#include "design/phases.hpp"

using dmi::design::debris_phases;

namespace {
// Samples every 0.01 s over [0, t_end]: nothing until 0.10 s, 250 N over (0.10, 0.20], 80 N to 1.10 s, then 50 N,
// with one 999 N sample at 1.50 s (after the passage: it must not be taken as the surge's peak).
void history(double t_end, std::vector<double>& t, std::vector<double>& F) {
  for (int k = 0; k * 0.01 <= t_end + 1e-9; ++k) {
    const double s = k * 0.01;
    t.push_back(s);
    F.push_back(s <= 0.10 + 1e-9 ? 0.0 : s <= 0.20 + 1e-9 ? 250.0 : s <= 1.10 + 1e-9 ? 80.0 : std::abs(s - 1.5) < 1e-9 ? 999.0 : 50.0);
  }
}
}  // namespace

// F0 = 100 N, T = 1 s: arrival 0.10 s (the start of the first interval above 1 N), peak 250 N (alpha 2.5) at 0.11 s,
// dynamic mean over (0.35, 1.10] = 80 N, static mean over the last 10 % of 2 s, (1.8, 2.0], = 50 N.
TEST(DebrisPhases, HandMadeHistory) {
  std::vector<double> t, F;
  history(2.0, t, F);
  const auto p = debris_phases(t, F, 100.0, 1.0);
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->arrival_s, 0.10, 1e-12);
  EXPECT_DOUBLE_EQ(p->peak_N, 250.0);
  EXPECT_NEAR(p->peak_time_s, 0.11, 1e-12);
  EXPECT_NEAR(p->dynamic_N, 80.0, 1e-9);
  ASSERT_TRUE(p->static_N);
  EXPECT_NEAR(*p->static_N, 50.0, 1e-9);
  const auto j = p->to_json();
  EXPECT_NEAR(j["alpha_peak"].get<double>(), 2.5, 1e-12);
  EXPECT_NEAR(j["alpha_static"].get<double>(), 0.5, 1e-9);
}

// A run that ends within the passage has no static phase; a surge that never arrives has no phases at all.
TEST(DebrisPhases, ShortRunAndNoArrival) {
  std::vector<double> t, F;
  history(1.0, t, F);
  const auto p = debris_phases(t, F, 100.0, 1.0);
  ASSERT_TRUE(p);
  EXPECT_FALSE(p->static_N);
  EXPECT_TRUE(p->to_json()["static_N"].is_null());
  EXPECT_FALSE(debris_phases(t, std::vector<double>(t.size(), 0.5), 100.0, 1.0));
  EXPECT_FALSE(debris_phases(t, F, 0.0, 1.0));
}

namespace dmi::design {
namespace {

// Three face elements 1 m long, 2 m wide; over the last 10 % of a 10 s run (the sample at 10 s) they carry 1000, 500
// and 10 Pa: the deposit reaches the top of the second (10 Pa is below 5 % of 1000), h_d = 2 m, its hydrostatic load
// 2000 x 9.81 x 2^2 x 2 / 2 = 78 480 N; the face carries (1000 + 500 + 10) x 1 x 2 = 3 020 N.
TEST(DebrisPhases, DepositAgainstTheFaceByHand) {
  Results r;
  for (int k = 0; k <= 10; ++k) r.time.push_back(k);
  Series p{"face/pressure", "Pa", {"bin0", "bin1", "bin2"}, {}};
  for (int k = 0; k <= 10; ++k) p.data.insert(p.data.end(), {k == 10 ? 1000.0 : 0.0, k == 10 ? 500.0 : 0.0, k == 10 ? 10.0 : 99.0});
  r.series.push_back(p);
  r.info.face_profile = FaceProfileRecord{{"dam"}, {1, 0}, 2, {{"dam", 0, 0, 1, 0, 1}, {"dam", 1, 1, 2, 1, 2}, {"dam", 2, 2, 3, 2, 3}}};
  const std::optional<DepositLoad> d = deposit_load(r, 2000);
  ASSERT_TRUE(d.has_value());
  EXPECT_DOUBLE_EQ(d->height_m, 2.0);
  EXPECT_NEAR(d->hydrostatic_N, 78480.0, 1e-9);
  EXPECT_NEAR(d->face_resultant_N, 3020.0, 1e-9);
  r.info.face_profile.reset();
  EXPECT_FALSE(deposit_load(r, 2000).has_value());
}

// design.json's debris_phases reads back the same, with and without a static tail and a deposit.
TEST(DebrisPhases, RecordReadsBackTheSame) {
  DebrisLoad d;
  d.phases = DebrisPhases{1e5, 2.0, 0.3, 2.5e5, 0.4, 1.5e5, std::nullopt};
  d.froude = 3.1, d.cui = {0.97, 0.97e5, "Cui"}, d.cui_in_range = true, d.geo = {2.5, 2.5e5, "Kwan"};
  EXPECT_EQ(debris_load_from_json(d.to_json(), "test")->to_json(), d.to_json());
  d.phases.static_N = 4e4, d.deposit = DepositLoad{1.2, 3e4, 2.9e4};
  EXPECT_EQ(debris_load_from_json(d.to_json(), "test")->to_json(), d.to_json());
  nlohmann::json bad = d.to_json();
  bad["cui"].erase("in_range");
  EXPECT_THROW(debris_load_from_json(bad, "test"), std::runtime_error);
}

}  // namespace
}  // namespace dmi::design
