// design.json's "grid_study" as a typed record (docs/design-json.md): the governing numbers of one scenario at three
// cell sizes with their convergence, and the verdict on the conservative bound. Built by grid_study, written by
// to_json, read back validated by grid_study_from_json for the report, the estimates' bands and a sweep's table.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace dmi::design {

struct GridQuantity {
  std::string variant, id, title, unit;
  std::array<double, 3> values{};                  // fine, medium, coarse
  std::optional<double> observed_order, extrapolated, asymptotic_ratio;  // none: not defined (written null)
  double gci = 0, safety_factor = 0, conservative_magnitude = 0;
  std::string behaviour, statement;
  bool converged = false;
};

struct GridStudyRecord {
  std::string method;
  std::array<double, 3> cell_sizes_m{};
  std::array<double, 2> refinement_ratios{};
  std::array<std::string, 3> folders;
  std::vector<GridQuantity> quantities;
  int not_converged = 0;
  // judge_grid_study's: per judged run the governing utilisation, its GCI and bound u (1 + GCI).
  struct RunBound {
    std::string variant;
    double utilisation = 0, gci = 0, utilisation_bound = 0;
    bool passed = false, converged = false;
  };
  struct Judged {
    std::string judge_on;
    std::vector<RunBound> runs;
    bool bound_passed = true;
  };
  std::optional<Judged> verdict;
};

nlohmann::json to_json(const GridQuantity& q);
nlohmann::json to_json(const GridStudyRecord& g);
// null reads as nullopt (no grid study); `where` names the place in errors.
std::optional<GridStudyRecord> grid_study_from_json(const nlohmann::json& j, const std::string& where);

}  // namespace dmi::design
