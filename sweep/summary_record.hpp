// A sweep's summary as typed records (docs/sweep.md "summary"): a row per case (its parameters, status, verdict,
// governing check and per variant the figures engineers size with) and the summary around them. Built by the case
// runner and the sweep, written to summary.json by to_json; a row travels between MPI ranks as its JSON (row_from_json).
#pragma once
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace dmi::sweep {

// A variant's figures ("run" for a scenario without variants): its governing utilisation and verdict, the peak
// contact force and base reactions.
struct VariantFigures {
  std::optional<double> max_utilisation;
  bool passed = false;
  std::optional<double> contact_peak_N, base_shear_N, base_moment_Nm;
};

struct Governing {
  std::string id, member, variant;
};

struct SweepRow {
  std::string case_name;  // "case_0003"
  std::size_t index = 0;  // 1-based
  std::map<std::string, nlohmann::json> parameters;  // JSON pointer -> the case's value, as the sweep file gives it
  std::string status = "ok";                         // ok | reused | failed
  std::optional<std::string> error, verdict, report;  // verdict: pass | fail | no_checks
  std::optional<double> max_utilisation;
  std::optional<Governing> governing;
  std::map<std::string, VariantFigures> variants;
  double wall_seconds = 0, simulated_seconds = 0;
  // With a grid study: the largest conservative bound u (1 + GCI) and whether the design passes on its criterion.
  std::optional<double> utilisation_bound;
  std::optional<bool> grid_study_passed;
};

struct SweepSummary {
  std::string software_version, name, sweep_file, base_file;
  std::vector<std::string> parameters;
  int ranks = 1, threads_per_rank = 1;
  double wall_seconds = 0, cases_per_hour = 0;
  int passed = 0, failed_runs = 0, reused = 0;
  std::vector<SweepRow> cases;
};

nlohmann::json to_json(const SweepRow& r);
SweepRow row_from_json(const nlohmann::json& j);
nlohmann::json to_json(const SweepSummary& s);

}  // namespace dmi::sweep
