// Sweeps (docs/sweep.md): the case table of a sweep file (product, zip, ranges, explicit cases), bad parameter paths
// named, a bad case that fails alone, resumable reruns, and the same summary from `mpirun -np 2` as from one process.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "engine/common/error.hpp"
#include "sweep/spec.hpp"
#include "sweep/summary.hpp"
#include "sweep/sweep_main.hpp"

namespace fs = std::filesystem;
using json = nlohmann::json;
using ojson = nlohmann::ordered_json;

namespace {

const std::string kDir = std::string(DMI_SOURCE_DIR) + "/examples/sweeps";

dmi::sweep::SweepSpec parse(const std::string& text) { return dmi::sweep::parse_sweep(ojson::parse(text), "study.json", kDir); }

std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const dmi::InputError& e) {
    return e.what();
  }
  return "";
}

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("dmi_sweep_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  return d;
}

json read_json(const fs::path& p) { return json::parse(std::ifstream(p)); }

// The rows without the timings (which differ from run to run).
json without_times(json rows) {
  for (json& r : rows) r.erase("wall_seconds"), r.erase("simulated_seconds");
  return rows;
}

}  // namespace

TEST(SweepSpec, ProductZipRangesAndTables) {
  const auto p = parse(R"({"base": "../free_fall.json", "parameters": {"/analysis/end_time": [0.1, 0.2, 0.3],
                           "/grid/cell_size": {"from": 0.1, "to": 0.2, "count": 2}}})");
  ASSERT_EQ(p.cases.size(), 6u);  // 3 x 2, the last parameter fastest
  EXPECT_EQ(p.parameters[0], "/analysis/end_time");  // the order given
  EXPECT_DOUBLE_EQ(p.cases[1][0].get<double>(), 0.1);
  EXPECT_DOUBLE_EQ(p.cases[1][1].get<double>(), 0.2);
  EXPECT_DOUBLE_EQ(p.cases[5][0].get<double>(), 0.3);
  EXPECT_DOUBLE_EQ(dmi::sweep::case_scenario(p, 5)["grid"]["cell_size"].get<double>(), 0.2);
  const auto z = parse(R"({"base": "../free_fall.json", "combine": "zip", "parameters": {"/analysis/end_time": [0.1, 0.2],
                           "/grid/cell_size": {"from": 0.1, "to": 0.15, "step": 0.05}}})");
  ASSERT_EQ(z.cases.size(), 2u);
  EXPECT_DOUBLE_EQ(z.cases[1][1].get<double>(), 0.15);
  const auto t = parse(R"({"base": "../free_fall.json", "cases": [{"/analysis/end_time": 0.1}, {"/analysis/end_time": 0.4}]})");
  ASSERT_EQ(t.cases.size(), 2u);
  EXPECT_DOUBLE_EQ(t.cases[1][0].get<double>(), 0.4);
}

TEST(SweepSpec, BadParameterPathsAndKeysAreNamed) {
  std::string e = error_of(R"({"base": "../free_fall.json", "parameters": {"/analysis/end_tme": [0.1]}})");
  EXPECT_NE(e.find("/analysis/end_tme"), std::string::npos) << e;  // a key the scenario format does not know
  EXPECT_NE(e.find("study.json"), std::string::npos) << e;
  e = error_of(R"({"base": "../free_fall.json", "parameters": {"/nowhere/x": [1]}})");
  EXPECT_NE(e.find("/parameters/~1nowhere~1x"), std::string::npos) << e;  // the sweep file's own JSON path
  EXPECT_NE(e.find("/nowhere is not in it"), std::string::npos) << e;
  e = error_of(R"({"base": "../free_fall.json", "combine": "zip", "parameters": {"/analysis/end_time": [0.1, 0.2], "/grid/cell_size": [0.1]}})");
  EXPECT_NE(e.find("as many as the first parameter"), std::string::npos) << e;
  e = error_of(R"({"base": "../free_fall.json", "parameter": {}})");
  EXPECT_NE(e.find("/parameter"), std::string::npos) << e;
  e = error_of(R"({"base": "../free_fall.json", "cases": [{"/analysis/end_time": 0.1}, {"/grid/cell_size": 0.1}]})");
  EXPECT_NE(e.find("every case gives every parameter"), std::string::npos) << e;
  e = error_of(R"({"base": "missing.json", "parameters": {"/a": [1]}})");
  EXPECT_NE(e.find("/base"), std::string::npos) << e;
  e = error_of(R"({"base": "../free_fall.json", "grid_study": {"ratio": 1.2}, "parameters": {"/analysis/end_time": [0.1]}})");
  EXPECT_NE(e.find("/grid_study/ratio"), std::string::npos) << e;
  EXPECT_NE(e.find("1.41421"), std::string::npos) << e;
  e = error_of(R"({"base": "../free_fall.json", "grid_study": "yes", "parameters": {"/analysis/end_time": [0.1]}})");
  EXPECT_NE(e.find("/grid_study"), std::string::npos) << e;
  EXPECT_EQ(parse(R"({"base": "../free_fall.json", "grid_study": true, "parameters": {"/analysis/end_time": [0.1]}})").grid_ratio,
            std::sqrt(2.0));
}

// "grid_study": each case runs at h, r h and r^2 h; its design.json carries the grid_study section with the three
// folders, and the summary row the conservative bound u (1 + GCI) of the governing utilisation, which is the
// utilisation times 1 + the GCI the section gives for it.
TEST(Sweep, GridStudyCasesCarryTheirUncertainty) {
  const fs::path dir = fresh_dir("grid"), study = dir / "study.json";
  fs::create_directories(dir);
  std::ofstream(study) << R"({"name": "grid", "base": ")" << DMI_SOURCE_DIR
                       << R"(/examples/sdof_boulder_on_column.json", "grid_study": {"ratio": 2}, "parameters": {"/analysis/end_time": [0.02]}})";
  dmi::sweep::SweepOptions o;
  o.out_dir = (dir / "out").string();
  o.case_reports = false, o.pdf = false, o.quiet = true, o.threads = 1;
  dmi::sweep::sweep_main(study.string(), o);
  const json s = read_json(dir / "out" / "summary.json");
  ASSERT_EQ(s["cases"].size(), 1u);
  const json& row = s["cases"][0];
  ASSERT_EQ(row["status"], "ok") << row["error"];
  const json d = read_json(dir / "out" / "cases" / "case_0001" / "design.json");
  ASSERT_TRUE(d.contains("grid_study"));
  for (const json& f : d["grid_study"]["folders"]) EXPECT_TRUE(fs::exists(fs::path(f.get<std::string>()) / "design.json")) << f;
  double u = 0, gci = -1;
  for (const json& r : d["grid_study"]["verdict"]["runs"]) u = r["utilisation"].get<double>(), gci = r["gci"].get<double>();
  EXPECT_GT(u, 0);
  EXPECT_GE(gci, 0);
  EXPECT_NEAR(row["utilisation_bound"].get<double>(), u * (1 + gci), 1e-12 * u);
  std::ifstream csv(dir / "out" / "summary.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_NE(header.find(",max_utilisation,utilisation_bound,"), std::string::npos) << header;
  fs::remove_all(dir);
}

// Three cases of the free-fall example, the second with a negative cell size: it fails with its error in the
// summary, the others complete; a second run reuses the complete cases and retries the failed one.
TEST(Sweep, ABadCaseFailsAloneAndARerunReusesTheRest) {
  const fs::path dir = fresh_dir("bad"), study = dir / "study.json";
  fs::create_directories(dir);
  std::ofstream(study) << R"({"name": "free fall", "base": ")" << DMI_SOURCE_DIR
                       << R"(/examples/free_fall.json", "parameters": {"/grid/cell_size": [0.25, -0.25, 0.125]}})";
  dmi::sweep::SweepOptions o;
  o.out_dir = (dir / "out").string();
  o.case_reports = false, o.pdf = false, o.quiet = true, o.threads = 1;
  EXPECT_EQ(dmi::sweep::sweep_main(study.string(), o), 1);  // a case could not run
  const json s = read_json(dir / "out" / "summary.json");
  ASSERT_EQ(s["cases"].size(), 3u);
  EXPECT_EQ(s["cases"][0]["status"], "ok");
  EXPECT_EQ(s["cases"][1]["status"], "failed");
  EXPECT_NE(s["cases"][1]["error"].get<std::string>().find("/grid/cell_size"), std::string::npos) << s["cases"][1]["error"];
  EXPECT_EQ(s["cases"][2]["status"], "ok");
  EXPECT_TRUE(fs::exists(dir / "out" / "cases" / "case_0003" / "results.h5"));
  EXPECT_EQ(s["counts"]["failed_runs"], 1);
  // The CSV: a header and one line per case, parameters first.
  std::ifstream csv(dir / "out" / "summary.csv");
  std::string header, line;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("case,/grid/cell_size,status,", 0), 0u) << header;
  int lines = 0;
  while (std::getline(csv, line)) ++lines;
  EXPECT_EQ(lines, 3);
  EXPECT_EQ(dmi::sweep::sweep_main(study.string(), o), 1);
  const json again = read_json(dir / "out" / "summary.json");
  EXPECT_EQ(again["cases"][0]["status"], "reused");
  EXPECT_EQ(again["cases"][1]["status"], "failed");
  EXPECT_EQ(again["cases"][2]["status"], "reused");
  EXPECT_EQ(again["counts"]["reused"], 2);
  fs::remove_all(dir);
}

// The quick example sweep under `mpirun -np 2` (loopback) gives the summary of one process, case for case.
TEST(Sweep, MpirunTwoRanksGivesTheSerialSummary) {
  if (std::system("command -v mpirun > /dev/null 2>&1") != 0) GTEST_SKIP() << "mpirun not installed";
  const fs::path dir = fresh_dir("mpi");
  const std::string study = kDir + "/column_speed.json";
  const std::string args = " sweep " + study + " --no-case-reports --no-pdf -q -t 1 -o ";
  const std::string serial = std::string(DMI_BINARY) + args + (dir / "serial").string() + " > /dev/null 2>&1";
  const std::string mpi = "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1 mpirun -np 2 " +
                          std::string(DMI_BINARY) + args + (dir / "mpi").string() + " > " + (dir / "mpi.log").string() + " 2>&1";
  fs::create_directories(dir);
  EXPECT_EQ(WEXITSTATUS(std::system(serial.c_str())), 1);  // every case fails its checks (an unbuffered column)
  std::system(mpi.c_str());
  const json a = read_json(dir / "serial" / "summary.json"), b = read_json(dir / "mpi" / "summary.json");
  EXPECT_EQ(a["ranks"], 1);
  EXPECT_EQ(b["ranks"], 2);
  EXPECT_EQ(without_times(a["cases"]), without_times(b["cases"]));
  fs::remove_all(dir);
}

// Two buffer thicknesses share the run without the buffer, which is identical after expansion: it is simulated once
// (the second case's files are links to the first's) and both cases report it alike.
TEST(Sweep, IdenticalVariantsAreSimulatedOnce) {
  const fs::path dir = fresh_dir("shared"), study = dir / "study.json";
  fs::create_directories(dir);
  json base = read_json(fs::path(DMI_SOURCE_DIR) / "examples" / "concrete_dam_boulder_buffer.json");
  base["grid"] = {{"cell_size", 0.08}};
  base.erase("solid_check");
  std::ofstream(dir / "base.json") << base.dump();
  std::ofstream(study) << R"({"name": "buffer", "base": "base.json", "parameters": {"/tyre_buffer/thickness": [0.2, 0.3]}})";
  dmi::sweep::SweepOptions o;
  o.out_dir = (dir / "out").string();
  o.case_reports = false, o.pdf = false, o.quiet = true, o.threads = 1;
  ASSERT_EQ(dmi::sweep::sweep_main(study.string(), o), 0);
  const fs::path a = dir / "out" / "cases" / "case_0001", b = dir / "out" / "cases" / "case_0002";
  EXPECT_TRUE(fs::equivalent(a / "without_buffer" / "results.h5", b / "without_buffer" / "results.h5"));
  EXPECT_FALSE(fs::equivalent(a / "with_buffer" / "results.h5", b / "with_buffer" / "results.h5"));
  const json s = read_json(dir / "out" / "summary.json");
  ASSERT_EQ(s["cases"].size(), 2u);
  EXPECT_EQ(s["cases"][0]["variants"]["without_buffer"], s["cases"][1]["variants"]["without_buffer"]);
  EXPECT_NE(s["cases"][0]["variants"]["with_buffer"], s["cases"][1]["variants"]["with_buffer"]);
  fs::remove_all(dir);
}
