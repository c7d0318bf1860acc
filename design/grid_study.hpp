// The grid_study section of design.json: the governing numbers of one scenario run at three cell sizes, each with
// its observed order, Richardson value and grid convergence index (engine/convergence/grid_convergence.hpp).
#pragma once
#include <array>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "design/design_document.hpp"

namespace dmi::design {

// The "grid_study" section of design.json from the three design documents (fine, medium, coarse) of one scenario:
// for every run (variant) of the fine document, the peak contact force, base shear, base moment, the governing
// check's demand and the governing utilisation, with their convergence. Quantities missing or
// non-finite in any of the three documents are errors (a run whose checks differ between the grids is reported,
// not silently dropped). `folders` name the three runs' output folders.
GridStudyRecord grid_study_section(const std::array<DesignDocument, 3>& designs, const std::array<double, 3>& h,
                                   const std::array<std::string, 3>& folders);

// Adds the grid study's verdict: for every judged run, the governing utilisation u, its GCI and the bound
// u (1 + GCI), passed when the bound is <= 1. With judge_on "conservative_bound" the document's verdict follows it
// (a design that passes on the finest grid but not on the bound fails, and the verdict says why). Returns whether
// the design passes on the criterion asked for.
bool judge_grid_study(DesignDocument& design, const std::string& judge_on);

// With a grid study: each applicable estimate of a run gets the grid uncertainty of the simulated peak it is compared
// with (simulated_gci, simulated_extrapolated_N and the ratio band ratio_low .. ratio_high for the simulated value
// within +-GCI). Estimates whose quantity the study did not cover are left as they are.
void add_grid_uncertainty(DesignDocument& design);

// Simulates every variant of the scenario file into dir (level 0 the finest) and returns the results files.
using LevelSimulator = std::function<std::vector<std::string>(const std::string& scenario, const std::string& dir, int level)>;

struct GridStudyOutcome {
  DesignDocument design;        // the finest level's design.json with the grid_study section, as written
  bool passed = false;          // on the criterion of the limits file (grid_study.judge_on)
  std::array<double, 3> h{};    // cell sizes, finest first
  std::array<double, 3> wall{}; // seconds per level (simulation and checks)
};

// The grid study of `damimpact run --grid-study` and of sweep files with "grid_study": the scenario file `file`
// (JSON `source`, cell size h) at h, r h and r^2 h, coarsest first. The coarser levels run in
// out/grid_study/h_<cell>/ from a copy of the scenario with grid.cell_size set (beside presets or in the low-level
// grid), the finest in out itself from `file`; each level's design checks go to its design.json, and out/design.json
// receives the grid_study section and the judged verdict. on_level (optional) hears of each finished level. With
// overlap, the two coarser levels run in two more threads at the lowest CPU priority (nice 19) while the finest runs
// in this one: they take the cores the finest level leaves idle (its variants end at different times) and little
// else; simulate and on_level must then be safe to call from two threads at once.
// Adds the grid_study section of the three documents to `design` (the finest), the grid uncertainty of its
// governing numbers and the judged verdict (limits file grid_study.judge_on); returns whether the design passes.
bool attach_grid_study(DesignDocument& design, const std::array<DesignDocument, 3>& designs, const std::array<double, 3>& h,
                       const std::array<std::string, 3>& folders, const std::string& limits_file);

// `damimpact check` of a finished grid study: when out/grid_study/ holds the two coarser levels (h_<cell>/), each is
// checked again with the limits file and the study rebuilt on `design` (the finest level's new document; the finest
// cell is h1^2 / h2 of the two). Returns false, leaving design as it is, when out holds no such study.
bool restudy_grid(DesignDocument& design, const std::string& out, const std::string& limits_file, const std::string& software_version);

GridStudyOutcome run_grid_study(const std::string& file, const nlohmann::json& source, double h, double ratio, const std::string& out,
                                const std::string& limits_file, const LevelSimulator& simulate, bool quiet,
                                const std::string& software_version,
                                const std::function<void(int level, double h, double seconds)>& on_level = {}, bool overlap = false);

}  // namespace dmi::design
