// Sweep files (docs/sweep.md): a base scenario plus the parameters to vary, as JSON pointers into the scenario.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace dmi::sweep {

struct SweepSpec {
  std::string file;                      // the sweep file as given
  std::string name;
  nlohmann::json base;                   // the base scenario (JSON)
  std::string base_file;                 // where it came from ("<inline>" when given in the sweep file)
  std::vector<std::string> parameters;   // JSON pointers, in column order
  std::vector<std::vector<nlohmann::json>> cases;  // one value per parameter
  double grid_ratio = 0;                 // "grid_study": every case also at r h and r^2 h (0: no grid study)
};

// Reads and checks a sweep file; throws InputError naming the file, the JSON path, the value and the expectation
// (a parameter path that does not lead into the base scenario is such an error).
SweepSpec load_sweep(const std::string& path);
SweepSpec parse_sweep(const nlohmann::ordered_json& j, const std::string& file, const std::string& dir);

// The scenario of case k: the base with the case's values set.
nlohmann::json case_scenario(const SweepSpec& s, std::size_t k);
// "case_0003"
std::string case_id(std::size_t k);

}  // namespace dmi::sweep
