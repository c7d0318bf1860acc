// The grid_study section of design.json: the governing numbers of one scenario run at three cell sizes, each with
// its observed order, Richardson value and grid convergence index (engine/convergence/grid_convergence.hpp).
#pragma once
#include <array>
#include <string>

#include <nlohmann/json.hpp>

namespace dmi::design {

// The "grid_study" section of design.json from the three design documents (fine, medium, coarse) of one scenario:
// for every run (variant) of the fine document, the peak contact force, base shear, base moment, the governing
// check's demand and the governing utilisation, with their convergence. Quantities missing or
// non-finite in any of the three documents are errors (a run whose checks differ between the grids is reported,
// not silently dropped). `folders` name the three runs' output folders.
nlohmann::json grid_study_section(const std::array<nlohmann::json, 3>& designs, const std::array<double, 3>& h,
                                  const std::array<std::string, 3>& folders);

// Adds design["grid_study"]["verdict"]: for every judged run, the governing utilisation u, its GCI and the bound
// u (1 + GCI), passed when the bound is <= 1. With judge_on "conservative_bound" the document's verdict follows it
// (a design that passes on the finest grid but not on the bound fails, and the verdict says why). Returns whether
// the design passes on the criterion asked for.
bool judge_grid_study(nlohmann::json& design, const std::string& judge_on);

}  // namespace dmi::design
