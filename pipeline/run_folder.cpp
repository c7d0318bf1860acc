#include "pipeline/run_folder.hpp"

#include "engine/io/results_writer.hpp"
#include "engine/scenario/identity.hpp"

namespace dmi::pipeline {
namespace fs = std::filesystem;

RunState run_state(const fs::path& dir) {
  if (fs::exists(dir / "checkpoint.dmi")) return RunState::interrupted;
  if (fs::exists(dir / "results.h5") && !fs::exists(dir / "results.h5.partial")) return RunState::complete;
  return RunState::absent;
}

bool holds_run_of(const fs::path& dir, const Scenario& s) {
  if (run_state(dir) != RunState::complete) return false;
  try {
    const RunInfo info = read_results((dir / "results.h5").string(), false).info;
    return scenario_identity(info.scenario_json, info.scenario_expanded_json, info.variant) == scenario_identity(s);
  } catch (const std::exception&) {  // a damaged file holds no run
    return false;
  }
}

}  // namespace dmi::pipeline
