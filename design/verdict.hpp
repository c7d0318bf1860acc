// The verdict as a typed record: the checks of one run, or of the runs a design judges, summed per design level and
// situation with the governing check (the largest utilisation). Built by design (design.cpp, document.cpp), written to
// design.json by to_json and read back, validated, by from_json: the report, `check`'s summary and a sweep's table read
// this record, not the document's keys (docs/design-json.md "verdict").
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "design/checks.hpp"

namespace dmi::design {

// A check read back from design.json, its fields validated (`where` names the document and place in errors).
Check check_from_json(const nlohmann::json& j, const std::string& where);
// A run's checks (design.json runs[].checks).
std::vector<Check> checks_from_json(const nlohmann::json& run, const std::string& where);

struct LevelVerdict {
  int checks = 0, failed = 0;
  bool passed = true;
  std::optional<Check> governing;  // the check of the largest utilisation (none: no checks)
  double max_utilisation() const { return governing ? governing->utilisation : NAN; }
};

// A set of checks judged: over the levels the limits judge (`judged_levels`: both, serviceability or ultimate; the
// information level never), and each level's and situation's own verdict.
struct Verdict : LevelVerdict {
  std::string judged_levels = "both";
  std::map<std::string, LevelVerdict> levels;      // serviceability, ultimate (a run's: information too)
  std::map<std::string, LevelVerdict> situations;  // persistent, accidental
  // The design document's verdict over its judged runs: their names, the governing run's variant and results file,
  // and the status (pass, fail, no_checks).
  bool document = false;
  std::string status, runs_judged, governing_variant, governing_results_file;
  std::string note;  // why the verdict is not its checks' alone (a grid study judged on the conservative bound)
};

// The verdict of one run's checks under the judged levels.
Verdict run_verdict(const std::vector<Check>& checks, const std::string& judged_levels);

nlohmann::json to_json(const LevelVerdict& v);
nlohmann::json to_json(const Verdict& v);
// `document`: the design document's verdict (with status and runs judged), else a run's.
Verdict verdict_from_json(const nlohmann::json& j, bool document, const std::string& where);

}  // namespace dmi::design
