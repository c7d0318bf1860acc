// SIGINT / SIGTERM during a run: the run stops after the step in hand, keeps its histories in
// results.h5.partial (complete = 0), exits 128 + signal, and never replaces an older complete results.h5.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <map>
#include <thread>
#include <vector>

#include "engine/io/results_writer.hpp"

namespace fs = std::filesystem;

namespace {

// Starts damimpact with args (stdout/stderr to files in dir) and returns its pid.
pid_t spawn(const std::vector<std::string>& args, const fs::path& dir) {
  const pid_t pid = fork();
  if (pid == 0) {
    const std::string out = (dir / "stdout.txt").string(), err = (dir / "stderr.txt").string();
    if (!freopen(out.c_str(), "w", stdout) || !freopen(err.c_str(), "w", stderr)) _exit(99);
    std::vector<char*> argv;
    std::string bin = DMI_BINARY;
    argv.push_back(bin.data());
    std::vector<std::string> copy = args;
    for (auto& a : copy) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(DMI_BINARY, argv.data());
    _exit(98);
  }
  return pid;
}

// A fresh folder for one test under the temporary directory.
fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / (name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// The small cantilever scenario these tests run (0.01 s as given).
nlohmann::json cantilever() {
  return nlohmann::json::parse(std::ifstream(std::string(DMI_SOURCE_DIR) + "/tests/data/design/cantilever_self_weight.json"));
}

// What the spawned process wrote to its standard error.
std::string stderr_of(const fs::path& dir) {
  std::ifstream err(dir / "stderr.txt");
  return std::string((std::istreambuf_iterator<char>(err)), std::istreambuf_iterator<char>());
}

}  // namespace

TEST(Interrupt, SigtermKeepsPartialHistoriesAndTheOlderCompleteResult) {
  const fs::path dir = fresh_dir("dmi_interrupt");
  const std::string source = std::string(DMI_SOURCE_DIR) + "/tests/data/design/cantilever_self_weight.json";
  // A complete result first (0.01 s).
  pid_t pid = spawn({"simulate", source, "-o", dir.string(), "-q"}, dir);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  const dmi::Results before = dmi::read_results((dir / "results.h5").string(), false);
  ASSERT_TRUE(before.complete);
  // The same scene for 100 s, stopped after half a second.
  nlohmann::json j = cantilever();
  j["analysis"]["end_time"] = 100.0;
  const fs::path long_run = dir / "long.json";
  std::ofstream(long_run) << j.dump();
  ASSERT_FALSE(fs::exists(dir / "results.h5.partial"));
  pid = spawn({"simulate", long_run.string(), "-o", dir.string(), "-q"}, dir);
  // Once the partial file exists the run handles the signal (its handlers come first); then let it step a while.
  // Waiting for the file, not a fixed time: a program start takes seconds under a sanitizer on a loaded machine.
  for (int k = 0; k < 1200 && !fs::exists(dir / "results.h5.partial"); ++k) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  ASSERT_TRUE(fs::exists(dir / "results.h5.partial"));
  std::this_thread::sleep_for(std::chrono::milliseconds(700));
  kill(pid, SIGTERM);
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGTERM);
  const std::string msg = stderr_of(dir);
  EXPECT_NE(msg.find("run interrupted by SIGTERM at step"), std::string::npos) << msg;
  // The older complete file is untouched; the partial one holds the histories so far and says it is incomplete.
  const dmi::Results after = dmi::read_results((dir / "results.h5").string(), false);
  EXPECT_TRUE(after.complete);
  EXPECT_EQ(after.time.size(), before.time.size());
  EXPECT_DOUBLE_EQ(after.info.stats.end_time.value(), 0.01);
  const dmi::Results partial = dmi::read_results((dir / "results.h5.partial").string(), false);
  EXPECT_FALSE(partial.complete);
  ASSERT_GT(partial.time.size(), 2u);
  EXPECT_LT(partial.time.back(), 100.0);
  for (const auto& s : partial.series) EXPECT_EQ(s.samples(), partial.time.size()) << s.path;
  EXPECT_EQ(partial.info.stats.status.value(), "interrupted (SIGTERM)");
  fs::remove_all(dir);
}

// A grid study runs its levels side by side (the coarse ones beside the finest; -t 2 makes it so on any machine): one
// SIGINT stops every level, each keeping its partial histories and a checkpoint, and nothing is checked or written as
// if complete (no design.json, no results.h5); the same command with --restart goes on from the checkpoints. The
// restarted study is stopped sooner than the first (each level's partial rewritten, then 0.3 s against 1.5 s), so a
// level that continued has at least its earlier steps and one started afresh has fewer.
TEST(Interrupt, GridStudyLevelsAllStopAndRestartFromTheirCheckpoints) {
  const fs::path dir = fresh_dir("dmi_interrupt_grid");
  nlohmann::json j = cantilever();
  j["analysis"]["end_time"] = 100.0;  // ~40 s a level: a signal always arrives while they step
  const fs::path scenario = dir / "long.json", out = dir / "out";
  std::ofstream(scenario) << j.dump();
  const std::vector<fs::path> levels{out / "results.h5.partial", out / "grid_study" / "h_0.2" / "results.h5.partial",
                                     out / "grid_study" / "h_0.141421" / "results.h5.partial"};
  // Starts the study, waits until every level's partial file is written by it (its signal handlers are in place
  // then), lets it step, and stops it with SIGINT.
  auto run_and_interrupt = [&](std::vector<std::string> args, int ms) {
    const auto started = fs::file_time_type::clock::now();
    const pid_t pid = spawn(args, dir);
    auto written = [&](const fs::path& p) { return fs::exists(p) && fs::last_write_time(p) > started; };
    for (int k = 0; k < 1200 && !std::all_of(levels.begin(), levels.end(), written); ++k)
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    EXPECT_TRUE(std::all_of(levels.begin(), levels.end(), written));
    std::this_thread::sleep_for(std::chrono::milliseconds(ms));
    kill(pid, SIGINT);
    int status = 0;
    waitpid(pid, &status, 0);
    return status;
  };
  const std::vector<std::string> cmd{"run", scenario.string(), "-o", out.string(), "-t", "2", "--grid-study", "--no-report", "-q"};
  int status = run_and_interrupt(cmd, 1500);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGINT);
  std::vector<double> steps;
  for (const fs::path& p : levels) {
    const dmi::Results r = dmi::read_results(p.string(), false);
    EXPECT_FALSE(r.complete) << p;
    EXPECT_EQ(r.info.stats.status.value(), "interrupted (SIGINT)") << p;
    EXPECT_TRUE(fs::exists(p.parent_path() / "checkpoint.dmi")) << p;
    steps.push_back(r.info.stats.steps.value());
  }
  for (const auto& e : fs::recursive_directory_iterator(out)) {
    EXPECT_NE(e.path().filename(), "results.h5") << e.path();
    EXPECT_NE(e.path().filename(), "design.json") << e.path();
  }
  std::vector<std::string> again = cmd;
  again.push_back("--restart");
  status = run_and_interrupt(again, 300);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGINT);
  for (std::size_t k = 0; k < levels.size(); ++k)
    EXPECT_GE(dmi::read_results(levels[k].string(), false).info.stats.steps.value(), steps[k]) << levels[k] << ": started afresh";
  EXPECT_FALSE(fs::exists(out / "design.json"));
  fs::remove_all(dir);
}

// --restart keeps a complete result only when it was computed from the scenario given: the same file keeps it (exit
// 0), an edited one is refused with exit 2 naming the result, which is left as it was.
TEST(Interrupt, RestartKeepsACompleteResultOnlyForItsOwnScenario) {
  const fs::path dir = fresh_dir("dmi_restart_kept");
  nlohmann::json j = cantilever();
  const fs::path scenario = dir / "s.json", out = dir / "out";
  std::ofstream(scenario) << j.dump();
  auto run = [&](const std::vector<std::string>& args) {
    int status = 0;
    waitpid(spawn(args, dir), &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  };
  ASSERT_EQ(run({"simulate", scenario.string(), "-o", out.string(), "-q"}), 0);
  const auto written = fs::last_write_time(out / "results.h5");
  EXPECT_EQ(run({"simulate", scenario.string(), "-o", out.string(), "-q", "--restart"}), 0);
  j["analysis"]["end_time"] = 2 * j["analysis"]["end_time"].get<double>();
  std::ofstream(scenario, std::ios::trunc) << j.dump();
  EXPECT_EQ(run({"simulate", scenario.string(), "-o", out.string(), "-q", "--restart"}), 2);
  const std::string msg = stderr_of(dir);
  EXPECT_NE(msg.find((out / "results.h5").string() + ": --restart keeps a complete result only when"), std::string::npos) << msg;
  EXPECT_EQ(fs::last_write_time(out / "results.h5"), written);
  fs::remove_all(dir);
}
