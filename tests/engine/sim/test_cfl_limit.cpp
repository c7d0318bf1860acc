// A CFL factor above the stability limit measured for the scheme (validate --stress cfl_sweep) is reduced to it,
// with a note in /run and on stderr; the Courant number actually used never exceeds the limit.
#include <gtest/gtest.h>

#include "engine/sim/run.hpp"
#include "verify/validate.hpp"

TEST(CflLimit, AFactorAboveTheSchemeLimitIsReducedWithANote) {
  struct Case { const char *shape, *transfer; double limit; };
  for (const Case& c : {Case{"bspline2", "flip", 0.8}, Case{"bspline2", "apic", 0.9}, Case{"gimp", "flip", 0.5}}) {
    const dmi::Scenario s = dmi::example_scenario("bar_free_free.json", {{"/analysis/cfl", 1.0}, {"/analysis/end_time", 1.0},
                                                                          {"/mpm/shape_function", c.shape}, {"/mpm/transfer", c.transfer}});
    const dmi::RunOutput out = dmi::run_quiet(s);
    const auto& info = out.results.info;
    ASSERT_TRUE(info.stats.notes.has_value()) << c.shape << " " << c.transfer;
    EXPECT_NE(info.stats.notes.value().find("/analysis/cfl = 1"), std::string::npos) << info.stats.notes.value();
    EXPECT_DOUBLE_EQ(info.stats.cfl_used.value(), c.limit);
    EXPECT_LE(info.stats.courant_max.value(), c.limit * (1 + 1e-12));
  }
  // At or below the limit nothing changes.
  const dmi::RunOutput ok = dmi::run_quiet(dmi::example_scenario("bar_free_free.json", {{"/analysis/end_time", 1.0}}));
  EXPECT_FALSE(ok.results.info.stats.notes.has_value());
}
