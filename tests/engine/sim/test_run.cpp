// The run driver end to end through the CLI: files written, readable and consistent; a failed run
// exits 2 with one message and leaves no complete-looking results.
#include <gtest/gtest.h>

#include <algorithm>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <nlohmann/json.hpp>
#include <string>

#include "engine/io/results_writer.hpp"
#include "engine/scenario/scenario.hpp"
#include "engine/sim/run.hpp"

namespace fs = std::filesystem;

namespace {

struct Cli {
  int status;
  std::string err;
};

Cli run_cli(const std::string& args, const std::string& binary = DMI_BINARY) {
  const fs::path err = fs::temp_directory_path() / ("dmi_run_err_" + std::to_string(::getpid()));
  const std::string cmd = binary + " " + args + " > /dev/null 2> " + err.string();
  const int rc = std::system(cmd.c_str());
  std::ifstream in(err);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  fs::remove(err);
  return {WIFEXITED(rc) ? WEXITSTATUS(rc) : -1, text};
}

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("dmi_run_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  return d;
}

TEST(RunCli, WritesResultsSnapshotsAndParaViewFiles) {
  const fs::path out = fresh_dir("ok");
  const Cli r = run_cli("simulate " + std::string(DMI_SOURCE_DIR) + "/examples/wall_impact.json -o " + out.string() + " -q");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;  // --quiet
  EXPECT_FALSE(fs::exists(out / "results.h5.partial"));
  const dmi::Results res = dmi::read_results((out / "results.h5").string());
  EXPECT_TRUE(res.complete);
  // wall_impact: end 0.03 s, snapshots every 0.005 s -> initial + 5 + final = 7 (the one at 0.03 is the final).
  EXPECT_GE(res.snapshots.size(), 6u);
  EXPECT_LE(res.snapshots.size(), 7u);
  EXPECT_EQ(res.snapshots.front().count, 2000u);
  EXPECT_DOUBLE_EQ(res.snapshots.front().time, 0.0);
  EXPECT_NEAR(res.snapshots.back().time, 0.03, 1e-12);
  EXPECT_NEAR(res.time.back(), 0.03, 1e-12);
  // One history row per step (history_interval 0) plus the initial state.
  EXPECT_EQ(res.time.size(), static_cast<std::size_t>(res.info.stats.steps.value()) + 1);
  for (const auto& s : res.series) EXPECT_EQ(s.samples(), res.time.size()) << s.path;
  EXPECT_EQ(nlohmann::json::parse(res.info.scenario_json)["name"], "Elastic bar hitting a rigid wall");
  for (std::size_t i = 0; i < res.snapshots.size(); ++i) {
    char name[64];
    std::snprintf(name, sizeof name, "particles_%04zu.vtu", i);
    EXPECT_TRUE(fs::exists(out / "fields" / name)) << name;
  }
  std::ifstream pvd(out / "fields" / "particles.pvd");
  std::string text((std::istreambuf_iterator<char>(pvd)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("particles_0000.vtu"), std::string::npos);
  fs::remove_all(out);
}

TEST(RunCli, FailedRunExitsTwoAndLeavesNoCompleteResults) {
  const fs::path out = fresh_dir("fail");
  nlohmann::json j = nlohmann::json::parse(std::ifstream(std::string(DMI_SOURCE_DIR) + "/examples/wall_impact.json"));
  j["walls"] = nlohmann::json::array();
  j["bodies"][0]["velocity"] = {-50, 0};  // flies off the grid within a few steps
  fs::create_directories(out);
  std::ofstream(out / "flyaway.json") << j.dump(2);
  const Cli r = run_cli("run " + (out / "flyaway.json").string() + " -o " + out.string() + " -q");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.rfind("damimpact: run failed: run stopped at step", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("body 'bar'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("left the grid"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(out / "results.h5"));
  fs::remove_all(out);
}

// The variants of a scenario run side by side with two threads (app/main.cpp): every history is bit for bit the one
// of the same variant run alone on one thread, and a failing variant still fails the command (exit 2, its message).
TEST(RunCli, VariantsSideBySideGiveTheResultsOfOneByOne) {
  const fs::path out = fresh_dir("side_by_side");
  nlohmann::json j = nlohmann::json::parse(std::ifstream(std::string(DMI_SOURCE_DIR) + "/examples/concrete_dam_boulder_buffer.json"));
  j["grid"] = {{"cell_size", 0.08}};
  j.erase("solid_check");
  fs::create_directories(out);
  std::ofstream(out / "dam.json") << j.dump(2);
  for (const char* t : {"1", "2"}) {
    const Cli r = run_cli("simulate " + (out / "dam.json").string() + " -o " + (out / t).string() + " -q -t " + t);
    ASSERT_EQ(r.status, 0) << r.err;
  }
  for (const char* v : {"with_buffer", "without_buffer"}) {
    const dmi::Results a = dmi::read_results((out / "1" / v / "results.h5").string(), false);
    const dmi::Results b = dmi::read_results((out / "2" / v / "results.h5").string(), false);
    ASSERT_EQ(a.series.size(), b.series.size()) << v;
    ASSERT_GT(a.time.size(), 10u) << v;
    EXPECT_EQ(a.time, b.time) << v;
    for (std::size_t k = 0; k < a.series.size(); ++k) EXPECT_EQ(a.series[k].data, b.series[k].data) << v << " " << a.series[k].path;
  }
  j["boulder"]["velocity"] = {900, 0};  // through the dam and off the grid: both variants fail
  std::ofstream(out / "bad.json") << j.dump(2);
  const Cli r = run_cli("simulate " + (out / "bad.json").string() + " -o " + (out / "bad").string() + " -q -t 2");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("run failed"), std::string::npos) << r.err;
  fs::remove_all(out);
}

// Command-line numbers and folders: out-of-range or malformed threads and step counts, an empty output folder and a
// --restart with nothing to restart are refused (exit 2, the bound named), and nothing is written.
TEST(RunCli, NumbersAndFoldersAreRangeChecked) {
  const std::string ex = std::string(DMI_SOURCE_DIR) + "/examples/wall_impact.json";
  const fs::path out = fresh_dir("ranges");
  const std::pair<std::string, std::string> cases[] = {
      {"-t -1", "--threads: value -1: expected a whole number from 0 to 1024"},
      {"-t 2x", "--threads: value 2x: expected a whole number from 0 to 1024"},
      {"--stop-after 0", "--stop-after: value 0: expected a whole number from 1 to 1000000000000"},
  };
  for (const auto& [args, msg] : cases) {
    const Cli r = run_cli("simulate " + ex + " -q -o " + out.string() + " " + args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_NE(r.err.find(msg), std::string::npos) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
  }
  // An option the command does not have is named, on one line.
  Cli u = run_cli("simulate " + ex + " --bogus");
  EXPECT_EQ(u.status, 2);
  EXPECT_NE(u.err.find("damimpact: error: The following argument was not expected: --bogus"), std::string::npos) << u.err;
  EXPECT_EQ(std::count(u.err.begin(), u.err.end(), '\n'), 1) << u.err;
  Cli r = run_cli("simulate " + ex + " -q -o ''");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("-o/--out = \"\": expected an output folder"), std::string::npos) << r.err;
  r = run_cli("simulate " + ex + " -q --restart -o " + out.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--restart: no checkpoint.dmi to continue from"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out / "results.h5"));
  fs::remove_all(out);
}

// A recorded quantity that overflows (the kinetic energy of a body of density 1e307 at 100 m/s) stops the run: exit 2
// naming the series, and no complete results.h5 holding inf. A body at 1e200 m/s is refused before it starts (its
// first step is 0 s), and an end time of 1e12 s as needing more steps than /analysis/max_steps; nothing is written.
TEST(RunCli, OverflowedRecordStopsTheRun) {
  const fs::path out = fresh_dir("overflow");
  nlohmann::json j = nlohmann::json::parse(std::ifstream(std::string(DMI_SOURCE_DIR) + "/examples/wall_impact.json"));
  const nlohmann::json j0 = j;
  j["bodies"][0]["velocity"] = {-1e200, 0};
  fs::create_directories(out);
  std::ofstream(out / "v.json") << j.dump(2);
  Cli r = run_cli("simulate " + (out / "v.json").string() + " -o " + (out / "v").string() + " -q");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("/analysis/end_time = 0.03: expected a run with a first step above 0 s"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out / "v"));
  j = j0;
  j["analysis"]["end_time"] = 1e12;
  std::ofstream(out / "long.json") << j.dump(2);
  r = run_cli("simulate " + (out / "long.json").string() + " --dry-run");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("expected a run of at most /analysis/max_steps = 1e+07 steps"), std::string::npos) << r.err;
  // The dry run states the estimate; a wall-time limit below it refuses the run with the estimate.
  r = run_cli("simulate " + std::string(DMI_SOURCE_DIR) + "/examples/wall_impact.json --dry-run --expand");  // the summary on stderr
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find(" steps, a first guess of "), std::string::npos) << r.err;
  j = j0;
  j["analysis"]["max_wall_hours"] = 1e-9;
  std::ofstream(out / "slow.json") << j.dump(2);
  r = run_cli("simulate " + (out / "slow.json").string() + " --dry-run");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("expected a run of at most /analysis/max_wall_hours = 1e-09 h: about"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("raise /analysis/max_wall_hours"), std::string::npos) << r.err;
  j = j0;
  j["materials"][0]["density"] = 1e307;
  j["bodies"][0]["velocity"] = {-100, 0};
  std::ofstream(out / "fast.json") << j.dump(2);
  r = run_cli("simulate " + (out / "fast.json").string() + " -o " + (out / "run").string() + " -q");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("the recorded energy/kinetic is infinite"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out / "run" / "results.h5"));
  fs::remove_all(out);
}

TEST(RunCli, MissingScenarioFileIsOneClearError) {
  const Cli r = run_cli("simulate /nonexistent/dam.json -o /tmp/never");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.rfind("damimpact: error: /nonexistent/dam.json: cannot open", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

// The binary users call links neither VTK nor MPI and hands the commands that draw to damimpact-full beside the real
// file (found through /proc/self/exe, so a symlink elsewhere works); alone, it says what is missing, in one line.
TEST(RunCli, DrawingCommandsAreHandedToTheFullBinaryBesideIt) {
  const fs::path d = fresh_dir("handover");
  fs::create_directories(d);
  fs::create_symlink(DMI_BINARY, d / "linked");
  fs::copy_file(DMI_BINARY, d / "alone");
  auto call = [](const fs::path& bin, const std::string& args) { return run_cli(args, bin.string()); };
  const Cli linked = call(d / "linked", "render /nonexistent/run");
  EXPECT_EQ(linked.status, 2);
  EXPECT_NE(linked.err.find("/nonexistent/run: no results.h5"), std::string::npos) << linked.err;  // the full binary's own message
  const Cli alone = call(d / "alone", "render /nonexistent/run");
  EXPECT_EQ(alone.status, 2);
  EXPECT_NE(alone.err.find((d / "damimpact-full").string() + ": cannot start it"), std::string::npos) << alone.err;
  EXPECT_EQ(std::count(alone.err.begin(), alone.err.end(), '\n'), 1) << alone.err;
  const Cli checked = call(d / "alone", "render");  // arguments are checked before the hand-over
  EXPECT_EQ(checked.status, 2);
  EXPECT_NE(checked.err.find("out is required"), std::string::npos) << checked.err;
  EXPECT_EQ(call(d / "alone", "schema").status, 0);  // what needs no pictures runs alone
  fs::remove_all(d);
}

// OpenMP waits passively unless the user set OMP_WAIT_POLICY: libgomp reads the variable when it loads and prints
// what it took (a passive policy spins 0 times before sleeping; unset, it would display PASSIVE but spin 300 000).
TEST(RunCli, OpenMPWaitsPassivelyUnlessTheUserSaysOtherwise) {
  auto spin = [](const std::string& env) {
    const fs::path err = fs::temp_directory_path() / ("dmi_omp_env_" + std::to_string(::getpid()));
    const std::string cmd = "env -u OMP_WAIT_POLICY OMP_DISPLAY_ENV=verbose " + env + " " + DMI_BINARY + " --version > /dev/null 2> " + err.string();
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
    std::ifstream in(err);
    std::string line, found;
    while (std::getline(in, line))
      if (line.find("GOMP_SPINCOUNT") != std::string::npos) found = line;
    fs::remove(err);
    return found;
  };
  EXPECT_NE(spin("").find("'0'"), std::string::npos) << spin("");
  EXPECT_EQ(spin("OMP_WAIT_POLICY=active").find("'0'"), std::string::npos) << spin("OMP_WAIT_POLICY=active");
}

}  // namespace

// Numerical health in /run: the Courant number never exceeds the cfl factor (the automatic step), and the smallest
// particle J stays positive (the disks compress where they meet, then recover).
TEST(RunHealth, CourantAndJacobianAreRecorded) {
  dmi::Scenario s = dmi::load_scenario(std::string(DMI_SOURCE_DIR) + "/examples/colliding_disks.json");
  dmi::RunOptions o;
  o.progress = dmi::ProgressMode::quiet;
  const dmi::RunOutput r = dmi::run_scenario(s, o);
  const double c = r.results.info.stats.courant_max.value(), j = r.results.info.stats.jacobian_min.value();
  EXPECT_GT(c, 0.9 * s.analysis.cfl);
  EXPECT_LE(c, s.analysis.cfl + 1e-12);
  EXPECT_GT(j, 0.3);
  EXPECT_LT(j, 1.0);
}

// A preset scenario's scene-building and run-budget errors name the expansion's paths and say so, and --dry-run
// --expand prints that expansion even when the scene cannot be built.
TEST(RunCli, PresetBuildErrorsPointToTheExpansion) {
  const fs::path out = fresh_dir("preset_budget");
  fs::create_directories(out);
  nlohmann::json j = nlohmann::json::parse(std::ifstream(std::string(DMI_SOURCE_DIR) + "/examples/concrete_dam_boulder_buffer.json"));
  j["analysis"] = {{"end_time", 1e12}};
  std::ofstream(out / "long.json") << j.dump(2);
  Cli r = run_cli("simulate " + (out / "long.json").string() + " --dry-run");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("long.json (expanded presets; see --dry-run --expand): /analysis/end_time = 1e+12"), std::string::npos) << r.err;
  const std::string cmd = std::string(DMI_BINARY) + " simulate " + (out / "long.json").string() + " --dry-run --expand > " + (out / "x.json").string() +
                          " 2> /dev/null";
  const int rc = std::system(cmd.c_str());
  EXPECT_EQ(WIFEXITED(rc) ? WEXITSTATUS(rc) : -1, 2);
  const nlohmann::json x = nlohmann::json::parse(std::ifstream(out / "x.json"));
  EXPECT_EQ(x["with_buffer"]["analysis"]["end_time"], 1e12);  // the expansion, readable at the error's path
  fs::remove_all(out);
}

// A 3D run with a space frame goes through the whole chain: design.json with the space frame's checks (3-component
// locations, the horizontal base shear), the oblique and section pictures, and the report.
TEST(RunCli, SpaceFrameRunsThroughChecksPicturesAndReport) {
  const fs::path out = fresh_dir("space_frame");
  fs::create_directories(out);
  nlohmann::json j = nlohmann::json::parse(std::ifstream(fs::path(DMI_SOURCE_DIR) / "examples" / "sdof_sphere_on_column_3d.json"));
  j["grid"]["cell_size"] = 0.15;
  j["analysis"]["end_time"] = 0.016;
  j["output"]["snapshot_interval"] = 0.004;
  j["output"]["vtk"] = true;
  std::ofstream(out / "s.json") << j.dump();
  const Cli run = run_cli("run " + (out / "s.json").string() + " -o " + (out / "r").string() + " -q");
  ASSERT_LE(run.status, 1) << run.err;  // 0 pass, 1 a check fails: both are finished runs
  const auto d = nlohmann::json::parse(std::ifstream(out / "r" / "design.json"));
  const auto& r = d["runs"][0];
  EXPECT_EQ(r["dimension"], 3);
  ASSERT_FALSE(r["checks"].empty());
  EXPECT_EQ(r["checks"][0]["location_m"].size(), 3u);
  EXPECT_GT(r["contact"]["peak_force_N"].get<double>(), 0.0);
  // The column stands alone: its base's horizontal reaction is the base shear, and the vertical axis carries nothing.
  EXPECT_DOUBLE_EQ(r["base_total"]["H_N"]["abs_max"]["value"].get<double>(), r["supports"][0]["H_N"]["abs_max"]["value"].get<double>());
  const auto images = nlohmann::json::parse(std::ifstream(out / "r" / "images" / "images.json"));
  bool section = false;
  for (const auto& i : images["images"]) section = section || i["kind"] == "field_section";
  EXPECT_TRUE(section);
  std::stringstream html;
  html << std::ifstream(out / "r" / "report.html").rdbuf();
  EXPECT_NE(html.str().find("three dimensions"), std::string::npos);
  // ParaView: the members beside the particles, with the space frame's section forces.
  std::stringstream vtu;
  vtu << std::ifstream(out / "r" / "fields" / "members_0000.vtu").rdbuf();
  EXPECT_NE(vtu.str().find("Name=\"T (N m)\""), std::string::npos);
  EXPECT_TRUE(fs::exists(out / "r" / "fields" / "members.pvd"));
  fs::remove_all(out);
}
