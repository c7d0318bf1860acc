// `damimpact check` end to end: a static cantilever simulated, then checked from its results.h5 alone.
// The envelope peak must be the largest value in the stored history, the base reactions must balance the
// self-weight, and bad input must exit 2 with one clear message.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "engine/io/results_writer.hpp"

#include <hdf5.h>

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

struct Cli {
  int status;
  std::string out, err;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

Cli cli(const std::string& args) {
  const fs::path base = fs::temp_directory_path() / ("dmi_check_cli_" + std::to_string(::getpid()));
  const std::string cmd = std::string(DMI_BINARY) + " " + args + " > " + base.string() + ".out 2> " + base.string() + ".err";
  const int rc = std::system(cmd.c_str());
  Cli c{WIFEXITED(rc) ? WEXITSTATUS(rc) : -1, slurp(base.string() + ".out"), slurp(base.string() + ".err")};
  fs::remove(base.string() + ".out"), fs::remove(base.string() + ".err");
  return c;
}

class CheckCli : public ::testing::Test {
 protected:
  static fs::path dir;
  static void SetUpTestSuite() {
    dir = fs::temp_directory_path() / ("dmi_check_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    const Cli r = cli("simulate " + std::string(DMI_SOURCE_DIR) + "/tests/data/design/cantilever_self_weight.json -o " + dir.string() + " -q");
    ASSERT_EQ(r.status, 0) << r.err;
  }
  static void TearDownTestSuite() { fs::remove_all(dir); }
  static fs::path write(const std::string& name, const std::string& text) {
    const fs::path p = dir / name;
    std::ofstream(p) << text;
    return p;
  }
};
fs::path CheckCli::dir;

}  // namespace

TEST_F(CheckCli, StaticCantileverReactionsBalanceTheSelfWeightAndPeaksMatchTheHistory) {
  const Cli c = cli("check " + dir.string() + " --json");
  ASSERT_EQ(c.status, 0) << c.err;
  const json d = json::parse(c.out);
  EXPECT_EQ(d, json::parse(slurp(dir / "design.json")));  // the same document is written beside the results
  ASSERT_EQ(d["runs"].size(), 1u);
  const json& run = d["runs"][0];
  // w = rho g A = 2500 x 9.81 x 0.06 = 1471.5 N/m over L = 2 m: the fixed end carries w L = 2943 N up and w L^2 / 2 = 2943 N m
  // (counter-clockwise on the frame, the beam running +x).
  const double W = 2500 * 9.81 * 0.2 * 0.3 * 2.0, M = W * 1.0;
  const json& b = run["base_total"];
  EXPECT_NEAR(b["Fy_N"]["max"]["value"].get<double>(), W, 1e-6 * W);
  EXPECT_NEAR(b["Fy_N"]["min"]["value"].get<double>(), W, 1e-6 * W);
  EXPECT_NEAR(b["M_Nm"]["max"]["value"].get<double>(), M, 1e-6 * M);
  EXPECT_NEAR(b["Fx_N"]["abs_max"]["value"].get<double>(), 0.0, 1e-6 * W);
  // The member's envelope peak equals the largest value in the stored history (element 0, end i).
  const dmi::Results r = dmi::read_results((dir / "results.h5").string(), false);
  const dmi::Series* ef = r.find("frame/end_forces");
  ASSERT_NE(ef, nullptr);
  double mmax = -1e300, mmin = 1e300, vmax = 0;
  for (std::size_t k = 0; k < r.time.size(); ++k) {
    const double* row = &ef->data[k * ef->components.size()];
    for (int e = 0; e < 4; ++e) {
      mmax = std::max({mmax, row[6 * e + 2], row[6 * e + 5]}), mmin = std::min({mmin, row[6 * e + 2], row[6 * e + 5]});
      vmax = std::max({vmax, std::abs(row[6 * e + 1]), std::abs(row[6 * e + 4])});
    }
  }
  const json& pk = run["members"][0]["peaks"];
  EXPECT_EQ(pk["M_max"]["value"].get<double>(), mmax);
  EXPECT_EQ(pk["M_min"]["value"].get<double>(), mmin);
  EXPECT_EQ(pk["V_abs_max"]["value"].get<double>(), vmax);
  // Hogging at the fixed end: |M| = w L^2 / 2; fibre stress M c / I = 2943 x 0.15 / 4.5e-4 = 981 kPa (tension on top).
  EXPECT_NEAR(std::max(std::abs(mmax), std::abs(mmin)), M, 1e-6 * M);
  EXPECT_DOUBLE_EQ(pk[std::abs(mmin) > std::abs(mmax) ? "M_min" : "M_max"]["s_m"].get<double>(), 0.0);
  EXPECT_NEAR(pk["sigma_tension_max"]["value"].get<double>(), M * 0.15 / 4.5e-4, 1e-3);
  EXPECT_TRUE(d["verdict"]["passed"].get<bool>());
  EXPECT_EQ(d["verdict"]["status"], "pass");
}

TEST_F(CheckCli, ExitOneWhenACheckFailsUnderOtherLimitsWithoutResimulating) {
  // f_t = 1 MPa, phi 0.6: 981 kPa / 600 kPa = 1.635 -> fail; at rest with the persistent factor 1.35 (the self-weight is
  // the whole load; no axial force): 2.207, which governs.
  const fs::path limits = write("low.json", R"({"concrete": {"tensile_strength_Pa": 1e6}})");
  const Cli c = cli("check " + (dir / "results.h5").string() + " --limits " + limits.string() + " -o " + (dir / "low_design.json").string());
  EXPECT_EQ(c.status, 1) << c.err;
  EXPECT_NE(c.out.find("FAIL"), std::string::npos) << c.out;
  const json d = json::parse(slurp(dir / "low_design.json"));
  EXPECT_NEAR(d["verdict"]["governing"]["utilisation"].get<double>(), 1.35 * 2943 * 0.15 / 4.5e-4 / 0.6e6, 1e-5);
  EXPECT_EQ(d["verdict"]["governing"]["id"], "concrete_flexural_tension_persistent");
  EXPECT_NEAR(d["verdict"]["situations"]["accidental"]["max_utilisation"].get<double>(), 2943 * 0.15 / 4.5e-4 / 0.6e6, 1e-5);
}

// The same failing serviceability check (flexural tension) under a limits file that judges the ultimate level only:
// the cantilever's ultimate checks (its one-way shear resistance) pass, so it exits 0; the serviceability level still
// fails in design.json and the -q output keeps the verdict lines.
TEST_F(CheckCli, TheLimitsFileChoosesTheLevelThatSetsTheExitCode) {
  const fs::path limits = write("low_ult.json", R"({"concrete": {"tensile_strength_Pa": 1e6}, "verdict": {"level": "ultimate"}})");
  const Cli c = cli("check " + (dir / "results.h5").string() + " --limits " + limits.string() + " -q -o " + (dir / "ult_design.json").string());
  EXPECT_EQ(c.status, 0) << c.err;
  EXPECT_NE(c.out.find("serviceability: fail"), std::string::npos) << c.out;
  EXPECT_NE(c.out.find("the verdict judges: ultimate"), std::string::npos) << c.out;
  const json d = json::parse(slurp(dir / "ult_design.json"));
  EXPECT_TRUE(d["verdict"]["passed"].get<bool>());
  EXPECT_FALSE(d["verdict"]["levels"]["serviceability"]["passed"].get<bool>());
  EXPECT_EQ(d["runs"][0]["checks"][0]["level"], "serviceability");
  EXPECT_GT(d["verdict"]["levels"]["ultimate"]["checks"].get<int>(), 0);
  // Strengths in MPa instead of Pa are refused with the conversion.
  const fs::path mpa = write("mpa.json", R"({"concrete": {"compressive_strength_Pa": 28}})");
  const Cli m = cli("check " + (dir / "results.h5").string() + " --limits " + mpa.string());
  EXPECT_EQ(m.status, 2);
  EXPECT_NE(m.err.find("/concrete/compressive_strength_Pa = 28: expected a concrete f'c in Pa between 5e6 and 2e8 (28 MPa is 28e6 Pa)"),
            std::string::npos) << m.err;
  const fs::path bad = write("bad_level.json", R"({"verdict": {"level": "all"}})");
  const Cli b = cli("check " + (dir / "results.h5").string() + " --limits " + bad.string());
  EXPECT_EQ(b.status, 2);
  EXPECT_NE(b.err.find("/verdict/level = \"all\": expected \"both\", \"ultimate\" or \"serviceability\""), std::string::npos) << b.err;
}

TEST_F(CheckCli, BadInputExitsTwoWithOneClearMessage) {
  Cli c = cli("check " + (dir / "nothing.h5").string());
  EXPECT_EQ(c.status, 2);
  EXPECT_NE(c.err.find("nothing.h5: no such results file"), std::string::npos) << c.err;
  const fs::path junk = write("junk.h5", "not an HDF5 file");
  c = cli("check " + junk.string());
  EXPECT_EQ(c.status, 2);
  EXPECT_NE(c.err.find("junk.h5: cannot open as HDF5"), std::string::npos) << c.err;
  // A truncated results file in a run folder: check, render and report all refuse it the same way.
  const fs::path trunc = dir / "trunc";
  fs::create_directories(trunc);
  {
    std::ifstream in(dir / "results.h5", std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(trunc / "results.h5", std::ios::binary) << bytes.substr(0, bytes.size() / 3);
  }
  for (const char* cmd : {"check", "render", "report"}) {
    c = cli(std::string(cmd) + " " + trunc.string());
    EXPECT_EQ(c.status, 2) << cmd;
    EXPECT_NE(c.err.find("results.h5: cannot open as HDF5 (not an HDF5 file, or truncated or corrupt)"), std::string::npos) << cmd << ": " << c.err;
  }
  EXPECT_FALSE(fs::exists(trunc / "report.html"));
  const fs::path bad = write("bad_limits.json", R"({"concrete": {"fc": 28e6}})");
  c = cli("check " + dir.string() + " --limits " + bad.string());
  EXPECT_EQ(c.status, 2);
  EXPECT_NE(c.err.find("bad_limits.json: /concrete/fc = 28000000.0: expected a known key"), std::string::npos) << c.err;
  const fs::path broken = write("broken.json", "{\"concrete\": ");
  c = cli("check " + dir.string() + " --limits " + broken.string());
  EXPECT_EQ(c.status, 2);
  EXPECT_NE(c.err.find("broken.json: invalid JSON"), std::string::npos) << c.err;
  const fs::path partial = dir / "partial";
  fs::create_directories(partial);
  write("partial/results.h5.partial", "");
  c = cli("check " + partial.string());
  EXPECT_EQ(c.status, 2);
  EXPECT_NE(c.err.find("the run did not finish"), std::string::npos) << c.err;
  EXPECT_FALSE(fs::exists(partial / "design.json"));
  // Exactly one line.
  EXPECT_EQ(std::count(c.err.begin(), c.err.end(), '\n'), 1) << c.err;
}

// Damaged results never become a verdict: a NaN in a history (the member end forces the checks read), a NaN in the
// particle positions of a snapshot, or the structure document cut from a file whose scenario has members: check,
// render and report all exit 2 naming the dataset, and no design.json or report is left behind.
TEST_F(CheckCli, DamagedResultsAreRefusedNeverChecked) {
  auto damaged = [&](const std::string& name, const std::function<void(hid_t)>& edit) {
    const fs::path d = dir / name;
    fs::create_directories(d);
    fs::copy_file(dir / "results.h5", d / "results.h5", fs::copy_options::overwrite_existing);
    const hid_t f = H5Fopen((d / "results.h5").c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    EXPECT_GE(f, 0);
    edit(f);
    H5Fclose(f);
    return d;
  };
  auto set_nan = [](hid_t f, const char* path, hsize_t row, hsize_t col) {
    const hid_t ds = H5Dopen2(f, path, H5P_DEFAULT);
    ASSERT_GE(ds, 0) << path;
    const hid_t space = H5Dget_space(ds);
    const hsize_t start[2] = {row, col}, count[2] = {1, 1};
    H5Sselect_hyperslab(space, H5S_SELECT_SET, start, nullptr, count, nullptr);
    const hsize_t one = 1;
    const hid_t mem = H5Screate_simple(1, &one, nullptr);
    const double nan = std::nan("");
    EXPECT_GE(H5Dwrite(ds, H5T_NATIVE_DOUBLE, mem, space, H5P_DEFAULT, &nan), 0);
    H5Sclose(mem), H5Sclose(space), H5Dclose(ds);
  };
  const fs::path forces = damaged("nan_forces", [&](hid_t f) { set_nan(f, "/history/frame/end_forces", 5, 3); });
  for (const char* cmd : {"check", "render", "report"}) {
    const Cli c = cli(std::string(cmd) + " " + forces.string());
    EXPECT_EQ(c.status, 2) << cmd << ": " << c.err;
    EXPECT_NE(c.err.find("/history/frame/end_forces holds a non-finite value (nan) at entry 123"), std::string::npos) << cmd << ": " << c.err;
    EXPECT_EQ(std::count(c.err.begin(), c.err.end(), '\n'), 1) << c.err;
  }
  EXPECT_FALSE(fs::exists(forces / "design.json"));
  EXPECT_FALSE(fs::exists(forces / "report.html"));
  const fs::path positions = damaged("nan_positions", [&](hid_t f) { set_nan(f, "/snapshots/0000/position", 0, 1); });
  Cli c = cli("render " + positions.string());
  EXPECT_EQ(c.status, 2) << c.err;
  EXPECT_NE(c.err.find("/snapshots/0000/position holds a non-finite value (nan) at entry 1"), std::string::npos) << c.err;
  const fs::path cut = damaged("no_structure", [&](hid_t f) { EXPECT_GE(H5Ldelete(f, "/documents/structure", H5P_DEFAULT), 0); });
  c = cli("check " + cut.string());
  EXPECT_EQ(c.status, 2) << c.out << c.err;
  EXPECT_NE(c.err.find("/documents/structure is missing although the scenario has 1 member(s)"), std::string::npos) << c.err;
  EXPECT_FALSE(fs::exists(cut / "design.json"));
}

TEST_F(CheckCli, RunSimulatesThenChecksAndExitsByTheVerdict) {
  const fs::path out = dir / "run";
  const fs::path limits = write("run_low.json", R"({"concrete": {"tensile_strength_Pa": 1e6}})");
  const Cli c = cli("run " + std::string(DMI_SOURCE_DIR) + "/tests/data/design/cantilever_self_weight.json -o " + out.string() +
                    " -q --limits " + limits.string());
  EXPECT_EQ(c.status, 1) << c.err;
  ASSERT_TRUE(fs::exists(out / "design.json"));
  EXPECT_FALSE(fs::exists(out / "design.json.tmp"));
  const json d = json::parse(slurp(out / "design.json"));
  EXPECT_EQ(d["verdict"]["status"], "fail");
  EXPECT_EQ(d["runs"][0]["results_file"], (out / "results.h5").string());
}

// `run --grid-study` end to end: the static cantilever's reactions do not depend on the grid, so every quantity of
// the study is converged with a zero index; the three runs are kept, the coarser ones under grid_study/.
TEST_F(CheckCli, GridStudyOfAGridIndependentRunIsConvergedWithZeroIndex) {
  const fs::path out = dir / "grid";
  const Cli c = cli("run " + std::string(DMI_SOURCE_DIR) + "/tests/data/design/cantilever_self_weight.json -o " + out.string() +
                    " --grid-study --grid-ratio 2 --no-report -q");
  ASSERT_EQ(c.status, 0) << c.err;
  const json d = json::parse(slurp(out / "design.json"));
  ASSERT_TRUE(d.contains("grid_study"));
  const json& g = d["grid_study"];
  const double h = g["cell_sizes_m"][0].get<double>();
  EXPECT_NEAR(g["cell_sizes_m"][1].get<double>(), 2 * h, 1e-12);
  EXPECT_NEAR(g["cell_sizes_m"][2].get<double>(), 4 * h, 1e-12);
  ASSERT_GE(g["quantities"].size(), 3u);
  for (const auto& q : g["quantities"]) {
    EXPECT_EQ(q["behaviour"], "converged") << q.dump();
    EXPECT_EQ(q["gci"].get<double>(), 0.0);
  }
  EXPECT_EQ(g["not_converged"], 0);
  for (int k = 1; k <= 2; ++k) EXPECT_TRUE(fs::exists(fs::path(g["folders"][k].get<std::string>()) / "design.json"));
}

// On two cores the coarser levels run beside the finest (at low priority): the study reads the same numbers as
// with the levels one after another (-t 1).
TEST_F(CheckCli, GridStudyWithLevelsSideBySideReadsTheSameNumbers) {
  const std::string scen = std::string(DMI_SOURCE_DIR) + "/tests/data/design/cantilever_self_weight.json";
  const fs::path a = dir / "grid_serial", b = dir / "grid_overlap";
  const Cli ca = cli("run " + scen + " -o " + a.string() + " -t 1 --grid-study --grid-ratio 2 --no-report -q");
  const Cli cb = cli("run " + scen + " -o " + b.string() + " -t 2 --grid-study --grid-ratio 2 --no-report -q");
  ASSERT_EQ(ca.status, 0) << ca.err;
  ASSERT_EQ(cb.status, 0) << cb.err;
  json ga = json::parse(slurp(a / "design.json"))["grid_study"], gb = json::parse(slurp(b / "design.json"))["grid_study"];
  ga.erase("folders"), gb.erase("folders");
  EXPECT_EQ(ga, gb);
}

TEST_F(CheckCli, GridStudyRefusesARatioBelowSqrtTwo) {
  const Cli c = cli("run " + std::string(DMI_SOURCE_DIR) + "/tests/data/design/cantilever_self_weight.json -o " + (dir / "g2").string() +
                    " --grid-study --grid-ratio 1.2 --no-report -q");
  EXPECT_EQ(c.status, 2);
  EXPECT_NE(c.err.find("--grid-ratio = 1.2"), std::string::npos) << c.err;
  EXPECT_NE(c.err.find("sqrt(2)"), std::string::npos) << c.err;
}
