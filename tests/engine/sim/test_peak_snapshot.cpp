// The state at the peak member contact force is written whatever the snapshot interval: a cylinder striking a member
// with snapshots only every half of the run still has one at the instant of its largest contact force (the
// peak_contact document's), in time order with the periodic ones.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "engine/io/results_writer.hpp"
#include "engine/sim/run.hpp"
#include "verify/validate.hpp"

namespace dmi {
namespace {

TEST(PeakSnapshot, TheContactPeakHasASnapshot) {
  namespace fs = std::filesystem;
  Scenario s = example_scenario("cylinder_on_member.json", {{"/output/snapshot_interval", 0.0025}});
  RunOptions o;
  o.out_dir = (fs::temp_directory_path() / ("dmi_peak_snap_" + std::to_string(::getpid()))).string();
  o.progress = ProgressMode::quiet;
  run_scenario(s, o);
  const Results r = read_results(o.out_dir + "/results.h5", true);
  ASSERT_TRUE(r.info.peak_contact);
  const double t_peak = r.info.peak_contact->time;
  ASSERT_GE(r.snapshots.size(), 3u);  // t = 0, the end, and at least the peak
  bool at_peak = false;
  for (const Snapshot& sn : r.snapshots) at_peak = at_peak || std::abs(sn.time - t_peak) < 1e-12;
  EXPECT_TRUE(at_peak) << "no snapshot at the peak contact instant " << t_peak << " s";
  EXPECT_TRUE(std::is_sorted(r.snapshots.begin(), r.snapshots.end(), [](const Snapshot& a, const Snapshot& b) { return a.time < b.time; }));
  fs::remove_all(o.out_dir);
}

}  // namespace
}  // namespace dmi
