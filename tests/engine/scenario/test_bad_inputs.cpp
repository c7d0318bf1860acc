// The malformed-scenario corpus tests/data/bad/*.json, run through the real command line:
// `damimpact simulate --dry-run FILE` must exit 2 with exactly one stderr line
// "damimpact: error: FILE: /json/path ...: expected ..." matching tests/data/bad/expected.json,
// and a real run of a bad file must not leave a results.h5 behind.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/sim/build_scene.hpp"
#include "engine/common/error.hpp"
#include "engine/scenario/scenario.hpp"

namespace dmi {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

const fs::path kBadDir = fs::path(DMI_SOURCE_DIR) / "tests" / "data" / "bad";

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string quote(const std::string& s) {
  std::string r = "'";
  for (char c : s) r += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return r + "'";
}

// A scratch directory per test, removed at the end.
struct TempDir {
  fs::path path;
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path = fs::temp_directory_path() /
           ("dmi_badinput_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

struct CliResult {
  int status = -1;  // exit status, -1 if not exited normally
  std::string out, err;
};

// Runs the damimpact binary with args (already quoted), capturing stdout and stderr.
CliResult run_cli(const std::string& args, const TempDir& tmp) {
  const fs::path out = tmp.path / "stdout.txt", err = tmp.path / "stderr.txt";
  const std::string cmd = quote(DMI_BINARY) + " " + args + " >" + quote(out.string()) + " 2>" + quote(err.string());
  const int rc = std::system(cmd.c_str());
  CliResult r;
  if (rc != -1 && WIFEXITED(rc)) r.status = WEXITSTATUS(rc);
  r.out = read_text(out);
  r.err = read_text(err);
  return r;
}

json expectations() {
  const std::string text = read_text(kBadDir / "expected.json");
  if (text.empty()) throw std::runtime_error("cannot read " + (kBadDir / "expected.json").string());
  return json::parse(text);
}

std::vector<fs::path> corpus() {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(kBadDir))
    if (e.is_regular_file() && e.path().extension() == ".json" && e.path().filename() != "expected.json") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

// The message (without the "damimpact: error: " prefix) names the file, the path and the fragments.
void check_message(const std::string& msg, const std::string& file, const json& expect) {
  EXPECT_NE(msg.find(file), std::string::npos) << "file name " << file << " not in: " << msg;
  if (!expect.at("path").is_null()) {
    const std::string path = expect.at("path").get<std::string>();
    EXPECT_TRUE(msg.find(file + ": " + path + " = ") != std::string::npos || msg.find(file + ": " + path + ": expected ") != std::string::npos)
        << "path " << path << " not named in: " << msg;
    EXPECT_NE(msg.find(": expected "), std::string::npos) << "no expectation in: " << msg;
  }
  for (const auto& f : expect.at("contains")) {
    const std::string frag = f.get<std::string>();
    EXPECT_NE(msg.find(frag), std::string::npos) << "'" << frag << "' not in: " << msg;
  }
}

TEST(BadInputCorpus, EveryFileHasAnExpectation) {
  const json exp = expectations();
  std::set<std::string> files, listed;
  for (const auto& f : corpus()) files.insert(f.filename().string());
  for (auto it = exp.begin(); it != exp.end(); ++it) {
    listed.insert(it.key());
    EXPECT_TRUE(it.value().contains("path") && (it.value()["path"].is_string() || it.value()["path"].is_null())) << it.key();
    EXPECT_TRUE(it.value().contains("contains") && it.value()["contains"].is_array()) << it.key();
  }
  EXPECT_GE(files.size(), 12u);
  EXPECT_EQ(files, listed) << "tests/data/bad/*.json and tests/data/bad/expected.json disagree";
}

// In-process first: a failure here points at the parser (or the scene checks) rather than at the command line.
TEST(BadInputCorpus, LoadScenarioRejectsEachFile) {
  const json exp = expectations();
  for (const auto& f : corpus()) {
    SCOPED_TRACE(f.filename().string());
    const std::string name = f.filename().string();
    if (!exp.contains(name)) continue;  // reported by EveryFileHasAnExpectation
    try {
      check_scene(load_scenario(f.string()));  // some checks need the built scene (overlaps)
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      check_message(e.what(), f.string(), exp[name]);
    }
  }
}

TEST(BadInputCli, DryRunExitsTwoWithOneLine) {
  const json exp = expectations();
  TempDir tmp;
  const std::string prefix = "damimpact: error: ";
  for (const auto& f : corpus()) {
    SCOPED_TRACE(f.filename().string());
    const std::string name = f.filename().string();
    if (!exp.contains(name)) continue;
    const CliResult r = run_cli("simulate --dry-run " + quote(f.string()), tmp);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(r.out, "") << "nothing on stdout for a bad file";
    ASSERT_FALSE(r.err.empty());
    EXPECT_EQ(r.err.back(), '\n') << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "not exactly one line:\n" << r.err;
    ASSERT_EQ(r.err.rfind(prefix, 0), 0u) << r.err;
    check_message(r.err.substr(prefix.size()), f.string(), exp[name]);
  }
}

// Every JSON reader bounds nesting and size: the limits and sweep files nested 100 000 deep (a stack overflow before),
// and /dev/zero as a scenario, exit 2 with one line.
TEST(BadInputCli, DeepAndEndlessInputsAreRefusedByEveryReader) {
  TempDir tmp;
  const fs::path deep = tmp.path / "deep.json";
  std::ofstream(deep) << std::string(100000, '[') << std::string(100000, ']');
  const std::pair<std::string, std::string> cases[] = {
      {"simulate --dry-run " + quote(deep.string()), "deep.json:1:65: invalid JSON (nested deeper than 64 levels)"},
      {"check " + quote(tmp.path.string()) + " --limits " + quote(deep.string()), "deep.json:1:65: invalid JSON (nested deeper than 64 levels)"},
      {"sweep " + quote(deep.string()) + " -o " + quote((tmp.path / "sw").string()), "deep.json:1:65: invalid JSON (nested deeper than 64 levels)"},
      {"simulate --dry-run /dev/zero", "/dev/zero: larger than 64 MiB: expected a scenario file"},
  };
  for (const auto& [args, msg] : cases) {
    const CliResult r = run_cli(args, tmp);
    EXPECT_EQ(r.status, 2) << args << ": " << r.err;
    EXPECT_NE(r.err.find(msg), std::string::npos) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

// A grid inside the cell cap that does not fit in memory is refused with the estimate, before anything is allocated
// (it ended in std::bad_alloc). The limit is set by DMI_MEMORY_LIMIT here (100 MB), so the case is the same on every
// machine: 2 000 x 2 000 cells need about 0.39 GiB (4 M nodes x 104 B); the same grid fits under 1 GB.
TEST(BadInputCli, GridBeyondMemoryIsRefusedWithTheEstimate) {
  TempDir tmp;
  json j = json::parse(std::ifstream(fs::path(DMI_SOURCE_DIR) / "examples" / "wall_impact.json"));
  j["grid"] = {{"origin", {-500, -500}}, {"size", {1000, 1000}}, {"cell_size", 0.5}};
  const fs::path f = tmp.path / "big_grid.json";
  std::ofstream(f) << j.dump(1);
  const fs::path out = tmp.path / "o.txt", err = tmp.path / "e.txt";
  auto run_with = [&](const std::string& limit) {
    const std::string c = "DMI_MEMORY_LIMIT=" + limit + " " + quote(DMI_BINARY) + " simulate --dry-run " + quote(f.string()) + " >" +
                          quote(out.string()) + " 2>" + quote(err.string());
    const int rc = std::system(c.c_str());
    return std::make_pair(WIFEXITED(rc) ? WEXITSTATUS(rc) : -1, read_text(err));
  };
  const auto [refused, msg] = run_with("1e8");
  EXPECT_EQ(refused, 2) << msg;
  EXPECT_NE(msg.find("/grid/cell_size = 0.5: expected a grid and bodies that fit in memory: about 0.388 GiB"), std::string::npos) << msg;
  EXPECT_NE(msg.find("available (DMI_MEMORY_LIMIT)"), std::string::npos) << msg;
  const auto [fits, msg2] = run_with("1e9");
  EXPECT_EQ(fits, 0) << msg2;
}

TEST(BadInputCli, GoodFileDryRunExitsZero) {
  TempDir tmp;
  const fs::path good = fs::path(DMI_SOURCE_DIR) / "examples" / "free_fall.json";
  ASSERT_TRUE(fs::exists(good));
  const CliResult r = run_cli("simulate --dry-run " + quote(good.string()), tmp);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("valid scenario"), std::string::npos) << r.out;
  EXPECT_EQ(r.err, "");
}

TEST(BadInputCli, NonexistentFileExitsTwo) {
  TempDir tmp;
  const std::string missing = (tmp.path / "no_such_scenario.json").string();
  for (const std::string& args : {"simulate --dry-run " + quote(missing), "simulate " + quote(missing) + " -o " + quote((tmp.path / "out").string())}) {
    SCOPED_TRACE(args);
    const CliResult r = run_cli(args, tmp);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find(missing), std::string::npos) << r.err;
  }
  EXPECT_FALSE(fs::exists(tmp.path / "out" / "results.h5"));
}

TEST(BadInputCli, BadFileWritesNoResults) {
  TempDir tmp;
  for (const auto& f : corpus()) {
    SCOPED_TRACE(f.filename().string());
    const fs::path out = tmp.path / ("out_" + f.stem().string());
    const CliResult r = run_cli("simulate -q " + quote(f.string()) + " -o " + quote(out.string()), tmp);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(r.err.rfind("damimpact: error: ", 0), 0u) << r.err;
    EXPECT_FALSE(fs::exists(out / "results.h5")) << "a bad scenario produced " << (out / "results.h5");
    EXPECT_FALSE(fs::exists(out / "results.h5.partial")) << "a bad scenario produced " << (out / "results.h5.partial");
  }
}

}  // namespace
}  // namespace dmi
