// design.json's grid_study section from three design documents: the quantities are read per run, their
// convergence computed, and a missing or non-numeric value is an error naming the file.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <filesystem>
#include <stdexcept>
#include <thread>

#include <unistd.h>

#include "design/grid_study.hpp"
#include "design/grid_study_record.hpp"
#include "design/verdict.hpp"

using namespace dmi::design;

TEST(GridStudy, SectionReadsTheThreeDesignsAndRefusesANonFiniteQuantity) {
  auto doc = [](double shear, double util) {
    Check check;
    check.id = "shear", check.member = "dam", check.demand = shear, check.utilisation = util, check.title = "one-way shear", check.unit = "N";
    // An information check (never judged) with a larger utilisation: the governing utilisation is the verdict's.
    Check info;
    info.id = "solid_principal_tension", info.member = "solid: x", info.demand = 1, info.utilisation = 3 * util, info.level = "information";
    RunDesign run;
    const auto peak = [](const char* key, double v) { return dmi::design::ReactionComponent{key, {}, {}, {v, 0.1, true}, 0.0}; };
    run.base_total = BaseTotal{{"base total", {peak("Fx_N", shear), peak("M_Nm", 2 * shear)}}, {0, 0}};
    run.checks = {check, info};
    run.verdict.governing = check;
    DesignDocument d;
    d.runs = {run};
    return d;
  };
  const std::array<double, 3> h{0.01, 0.02, 0.04};
  const GridStudyRecord s = grid_study_section({doc(101, 0.5), doc(104, 0.52), doc(116, 0.6)}, h, {"a", "b", "c"});
  ASSERT_EQ(s.quantities.size(), 4u);  // base shear, base moment, governing demand, governing utilisation
  EXPECT_EQ(s.quantities[0].id, "base_shear");
  EXPECT_NEAR(*s.quantities[0].observed_order, 2.0, 1e-9);
  EXPECT_NEAR(*s.quantities[0].extrapolated, 100.0, 1e-9);
  EXPECT_EQ(s.quantities[3].id, "governing_utilisation");
  EXPECT_NEAR(s.quantities[3].values[0], 0.5, 1e-12);
  DesignDocument bad = doc(104, 0.52);
  bad.runs[0].base_total->peaks.components[0].abs.value = NAN;
  EXPECT_THROW(grid_study_section({doc(101, 0.5), bad, doc(116, 0.6)}, h, {"a", "b", "c"}), std::runtime_error);
}

// Judging on the conservative bound: a design that passes on the finest grid (u 0.9) fails when its grid
// uncertainty (GCI 20 %) lifts u (1 + GCI) above 1, and the verdict says why; judged on the finest grid it passes.
TEST(GridStudy, ConservativeBoundCanFailADesignThatPassesOnTheFinestGrid) {
  using nlohmann::json;
  auto design = [] {
    GridStudyRecord gs;  // the study as design writes it, of the governing utilisation alone
    GridQuantity q;
    q.id = "governing_utilisation", q.variant = "", q.values = {0.9, 0.8, 0.7}, q.gci = 0.2, q.converged = true;
    gs.quantities = {q};
    Verdict v = run_verdict({}, "both");  // a document's verdict as design writes it: one passing check, u 0.9
    v.document = true, v.status = "pass", v.checks = 1, v.governing = Check{};
    v.governing->utilisation = 0.9, v.governing->demand = 0.9, v.governing->capacity = 1;
    DesignDocument d;
    d.verdict = v, d.grid_study = gs;
    return d;
  };
  DesignDocument a = design(), b = design();
  EXPECT_TRUE(judge_grid_study(a, "finest"));
  EXPECT_TRUE(a.verdict.passed);
  EXPECT_NEAR(a.grid_study->verdict->runs.at(0).utilisation_bound, 1.08, 1e-12);
  EXPECT_FALSE(a.grid_study->verdict->bound_passed);
  EXPECT_FALSE(judge_grid_study(b, "conservative_bound"));
  EXPECT_EQ(b.verdict.status, "fail");
  EXPECT_NE(b.verdict.note.find("conservative bound"), std::string::npos);
}

// Levels side by side: an error of a coarser level (its own thread) reaches the caller, after the finest level has
// ended; an error of the finest level wins, and the coarser threads are joined first (no terminate).
TEST(GridStudy, SideBySideLevelsReportTheirErrors) {
  namespace fs = std::filesystem;
  const fs::path out = fs::temp_directory_path() / ("dmi_gs_overlap_" + std::to_string(::getpid()));
  const nlohmann::json source = {{"grid", {{"cell_size", 0.1}}}};
  bool fine_ended = false;
  const LevelSimulator coarse_fails = [&](const std::string&, const std::string&, int g) -> std::vector<std::string> {
    if (g > 0) throw std::runtime_error("level " + std::to_string(g) + " failed");
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    fine_ended = true;
    throw std::runtime_error("fine failed");
  };
  try {
    run_grid_study("s.json", source, 0.1, 2.0, out.string(), "", coarse_fails, true, "test", {}, true);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "fine failed");
  }
  EXPECT_TRUE(fine_ended);
  // The finest level ends well (the cantilever simulated by the command-line tool), a coarser one fails: its error.
  const LevelSimulator only_coarse_fails = [&](const std::string&, const std::string& dir, int g) -> std::vector<std::string> {
    if (g == 2) throw std::runtime_error("level 2 failed");
    if (g == 1) throw std::runtime_error("level 1 failed");  // both fail: the coarsest level's error is told
    const std::string cmd = std::string(DMI_BINARY) + " simulate " + DMI_SOURCE_DIR + "/tests/data/design/cantilever_self_weight.json -o " + dir + " -q";
    if (std::system(cmd.c_str()) != 0) throw std::logic_error("the finest level's simulation failed");
    return {dir + "/results.h5"};
  };
  try {
    run_grid_study("s.json", source, 0.1, 2.0, out.string(), "", only_coarse_fails, true, "test", {}, true);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "level 2 failed");
  }
  EXPECT_TRUE(fs::exists(out / "results.h5"));     // the finest level ran ...
  EXPECT_FALSE(fs::exists(out / "design.json"));  // ... but its checks alone are not the study: removed
  fs::remove_all(out);
}

// `damimpact check` on a grid study's folder keeps the study: the coarser levels are judged again and the section
// rebuilt, with the same numbers for the same limits.
TEST(GridStudy, CheckOfAStudyFolderKeepsItsStudy) {
  namespace fs = std::filesystem;
  const fs::path out = fs::temp_directory_path() / ("dmi_gs_check_" + std::to_string(::getpid()));
  fs::remove_all(out);
  const std::string file = std::string(DMI_SOURCE_DIR) + "/tests/data/design/cantilever_self_weight.json";
  std::ifstream in(file);
  const nlohmann::json source = nlohmann::json::parse(in);
  const LevelSimulator simulate = [&](const std::string& scen, const std::string& dir, int) -> std::vector<std::string> {
    const std::string cmd = std::string(DMI_BINARY) + " simulate " + scen + " -o " + dir + " -q";
    if (std::system(cmd.c_str()) != 0) throw std::logic_error("simulation failed: " + cmd);
    return {dir + "/results.h5"};
  };
  const double h = source["grid"]["cell_size"].get<double>();
  const GridStudyOutcome study = run_grid_study(file, source, h, 2.0, out.string(), "", simulate, true, "test");
  ASSERT_TRUE(study.design.grid_study.has_value());
  const std::string cmd = std::string(DMI_BINARY) + " check " + out.string() + " -q > /dev/null";
  ASSERT_LE(std::system(cmd.c_str()) >> 8, 1);
  std::ifstream d(out / "design.json");
  const nlohmann::json checked = nlohmann::json::parse(d);
  ASSERT_TRUE(checked.contains("grid_study"));
  EXPECT_EQ(checked["grid_study"]["quantities"], to_json(*study.design.grid_study)["quantities"]);
  EXPECT_NEAR(checked["grid_study"]["cell_sizes_m"][0].get<double>(), h, 1e-12 * h);
  fs::remove_all(out);
}
