// Checkpoint and restart: a run stopped after step N (checkpoint + partial results) and continued with restart
// gives results.h5 bit-identical to an uninterrupted run (histories and every snapshot), with either frame
// integrator and another thread count after the restart; a bad checkpoint is refused with a clear InputError.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <omp.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "engine/common/error.hpp"
#include "engine/io/results_writer.hpp"
#include "engine/mpm/solver.hpp"
#include "engine/sim/build_scene.hpp"
#include "engine/sim/run.hpp"
#include "engine/scenario/scenario.hpp"
#include "verify/validate.hpp"

namespace fs = std::filesystem;

namespace {

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("dmi_restart_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  return d;
}

dmi::RunOptions options(const fs::path& dir) {
  dmi::RunOptions o;
  o.out_dir = dir.string();
  o.progress = dmi::ProgressMode::quiet;
  return o;
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

// Runs s uninterrupted, then stopped after `stop` steps and restarted (with `threads_after` threads); compares.
void expect_bit_identical_restart(const dmi::Scenario& s, const std::string& name, long stop, int threads_after) {
  const fs::path full = fresh_dir(name + "_full"), part = fresh_dir(name + "_part");
  const int threads = omp_get_max_threads();
  dmi::run_scenario(s, options(full));
  dmi::RunOptions o = options(part);
  o.stop_after_steps = stop;
  try {
    dmi::run_scenario(s, o);
    FAIL() << "the run was not stopped";
  } catch (const dmi::Interrupted& e) {
    EXPECT_EQ(e.signal(), 0);
  }
  ASSERT_TRUE(fs::exists(part / "checkpoint.dmi"));
  ASSERT_TRUE(fs::exists(part / "results.h5.partial"));
  ASSERT_FALSE(fs::exists(part / "results.h5"));
  o.stop_after_steps = 0;
  o.restart = true;
  o.threads = threads_after;
  dmi::run_scenario(s, o);
  omp_set_num_threads(threads);
  EXPECT_FALSE(fs::exists(part / "checkpoint.dmi"));  // removed once the run is complete
  const dmi::Results a = dmi::read_results((full / "results.h5").string()), b = dmi::read_results((part / "results.h5").string());
  ASSERT_TRUE(b.complete);
  EXPECT_EQ(a.info.stats.steps.value(), b.info.stats.steps.value());
  EXPECT_TRUE(same_bits(a.time, b.time));
  ASSERT_EQ(a.series.size(), b.series.size());
  for (std::size_t k = 0; k < a.series.size(); ++k) EXPECT_TRUE(same_bits(a.series[k].data, b.series[k].data)) << a.series[k].path;
  ASSERT_EQ(a.snapshots.size(), b.snapshots.size());
  for (std::size_t k = 0; k < a.snapshots.size(); ++k) {
    EXPECT_EQ(a.snapshots[k].step, b.snapshots[k].step);
    EXPECT_TRUE(same_bits(a.snapshots[k].position, b.snapshots[k].position)) << "snapshot " << k;
    EXPECT_TRUE(same_bits(a.snapshots[k].stress, b.snapshots[k].stress)) << "snapshot " << k;
    EXPECT_TRUE(same_bits(a.snapshots[k].velocity, b.snapshots[k].velocity)) << "snapshot " << k;
  }
  fs::remove_all(full);
  fs::remove_all(part);
}

}  // namespace

// Boulder on a column: Newmark frame, member contact; stopped mid-impact after step 1009, so the next step sorts the
// particles by the restored order of the last binning (1009 % 16 == 1, Solver::kSortInterval).
TEST(Restart, NewmarkFrameWithContactIsBitIdentical) {
  expect_bit_identical_restart(dmi::example_scenario("sdof_boulder_on_column.json"), "newmark", 1009, 1);
}

// A steel column that yields under the boulder, its fibres following Menegotto-Pinto: stopped while it yields, the
// restart carries every fibre's branch (reversal point, asymptote, curvature) and repeats the run exactly.
TEST(Restart, MenegottoPintoFibresAreBitIdentical) {
  const nlohmann::json steel = {{"name", "concrete"}, {"model", "elastic_plastic"}, {"density", 7850}, {"youngs_modulus", 2e11},
                                {"poisson_ratio", 0.3}, {"yield_strength", 1e8}, {"steel_curve", "menegotto_pinto"}};
  const dmi::Scenario s = dmi::example_scenario("sdof_boulder_on_column.json", {{"/materials/1", steel}, {"/structure/members/0/section/width", 0.05},
                                                                                {"/analysis/end_time", 0.016}});
  expect_bit_identical_restart(s, "menegotto_pinto", 2501, 1);
}

// The same with the explicit frame (eqs. 27-29), stopped between sorts, restarted on 2 threads.
TEST(Restart, ExplicitFrameIsBitIdentical) {
  const dmi::Scenario s = dmi::example_scenario("sdof_boulder_on_column.json", {{"/structure/integrator", "explicit"},
                                                                                {"/analysis/end_time", 0.02}});
  expect_bit_identical_restart(s, "explicit", 777, 2);
}

// The buffered dam: the tyres' damping integrated implicitly (Chebyshev sub-steps, held components and contact ties);
// stopped inside the impact (the boulder meets the buffer near 17 ms), the restart repeats the run exactly.
TEST(Restart, ImplicitlyDampedBufferIsBitIdentical) {
  const std::string file = std::string(DMI_SOURCE_DIR) + "/examples/concrete_dam_boulder_buffer.json";
  nlohmann::json j = nlohmann::json::parse(std::ifstream(file));
  j["grid"] = {{"cell_size", 0.04}};  // coarser than the preset's: the test is about the restart
  const auto variants = dmi::parse_scenario_variants(j.dump(), file);
  dmi::Scenario s = variants.at(0).scenario;
  ASSERT_EQ(s.variant, "with_buffer");
  s.analysis.end_time = 0.04;
  s.solid_check.present = false;
  expect_bit_identical_restart(s, "damped", 200, 1);  // step 200: t = 29 ms
}

// A rigid_when_free disc (tests/engine/mpm/test_rigid.cpp's wall strike): stopped while elastic on the wall and while
// rigid after the rebound, the restart restores which bodies are rigid, their rigid states and reference offsets, and
// the energy given up, and continues bit for bit.
TEST(Restart, RigidWhenFreeIsBitIdentical) {
  const std::string file = std::string(DMI_SOURCE_DIR) + "/examples/wall_impact.json";
  nlohmann::json j = nlohmann::json::parse(std::ifstream(file));
  j["analysis"]["end_time"] = 0.2;
  j["grid"] = {{"origin", {-0.1, -0.3}}, {"size", {0.8, 0.6}}, {"cell_size", 0.02}};
  j["materials"][0]["youngs_modulus"] = 1e9;
  j["bodies"] = {{{"name", "disc"}, {"material", "elastic"}, {"particles_per_cell", 2}, {"rigid_when_free", true},
                  {"shape", {{"type", "ball"}, {"center", {0.3, 0.0}}, {"radius", 0.1}}}, {"velocity", {-2, 0}}}};
  j["output"].erase("probes");
  const dmi::Scenario s = dmi::parse_scenario(j.dump(), file);
  // The stops: elastic near the wall (rigid from the start, then elastic: 2 switches) and rigid after the rebound (3).
  long elastic_from = -1, rigid_from = -1, steps = 0;
  {
    dmi::Solver<2> probe(dmi::build_scene<2>(s));
    while (probe.time() < s.analysis.end_time - 1e-12) {
      probe.step(probe.stable_time_step(s.analysis.end_time - probe.time()));
      if (probe.free_switches() == 2 && elastic_from < 0) elastic_from = probe.steps();
      if (probe.free_switches() == 3 && rigid_from < 0) rigid_from = probe.steps();
    }
    steps = probe.steps();
    ASSERT_EQ(probe.free_switches(), 3);
  }
  ASSERT_GT(rigid_from, elastic_from + 2);
  ASSERT_GT(steps, rigid_from + 2);
  expect_bit_identical_restart(s, "free_elastic", (elastic_from + rigid_from) / 2, 2);
  expect_bit_identical_restart(s, "free_rigid", (rigid_from + steps) / 2, 1);
}

// Debris entering from a CSV hydrograph: the particle count grows; stopped while it enters, the restart restores the
// body's range, the plug length and the totals, and continues bit for bit.
TEST(Restart, InflowIsBitIdentical) {
  const auto variants = dmi::load_scenario_variants(std::string(DMI_SOURCE_DIR) + "/examples/concrete_dam_debris_hydrograph.json");
  dmi::Scenario s = variants.at(0).scenario;
  s.analysis.end_time = 1.3;
  expect_bit_identical_restart(s, "inflow", 1601, 2);
}

TEST(Restart, RefusesAMissingCorruptOrForeignCheckpoint) {
  const dmi::Scenario s = dmi::example_scenario("free_fall.json");
  const fs::path dir = fresh_dir("bad");
  dmi::RunOptions o = options(dir);
  o.restart = true;
  EXPECT_THROW(dmi::run_scenario(s, o), dmi::InputError);  // nothing to restart from
  o.restart = false;
  o.stop_after_steps = 10;
  EXPECT_THROW(dmi::run_scenario(s, o), dmi::Interrupted);
  const fs::path ck = dir / "checkpoint.dmi";
  const auto size = fs::file_size(ck);
  o.stop_after_steps = 0;
  o.restart = true;
  dmi::Scenario other = dmi::example_scenario("free_fall.json", {{"/analysis/end_time", 0.123}});
  try {
    dmi::run_scenario(other, o);
    FAIL() << "a checkpoint of another scenario was accepted";
  } catch (const dmi::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("another scenario"), std::string::npos) << e.what();
  }
  fs::resize_file(ck, size / 2);
  try {
    dmi::run_scenario(s, o);
    FAIL() << "a truncated checkpoint was accepted";
  } catch (const dmi::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("truncated"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("checkpoint.dmi"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

// Disk full: a run whose snapshots cannot fit in the output folder's free space is refused before it starts,
// naming the folder and the estimate; an output folder that cannot be created fails before the run too.
TEST(Restart, RefusesARunWhoseOutputCannotFit) {
  const dmi::Scenario s = dmi::example_scenario("free_fall.json", {{"/output/snapshot_interval", 1e-12}});
  const fs::path dir = fresh_dir("space");
  try {
    dmi::run_scenario(s, options(dir));
    FAIL() << "a run needing more than the free disk space was started";
  } catch (const dmi::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not enough disk space"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(dir.string()), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir / "results.h5.partial"));
  EXPECT_THROW(dmi::run_scenario(dmi::example_scenario("free_fall.json"), options("/proc/dmi_no_such_folder")), std::exception);
  fs::remove_all(dir);
}
