// Simulation of a scenario file's variants into an output folder: side by side on two or more cores, resumed from
// checkpoints or kept when complete under --restart (pipeline/run_folder.hpp).
#pragma once
#include <string>
#include <vector>

#include "engine/scenario/scenario.hpp"
#include "engine/sim/progress.hpp"

namespace dmi::pipeline {

// Checkpoint and restart options of simulate/run (docs/reliability.md).
struct RestartFlags {
  double checkpoint_every = 600;  // wall seconds
  long stop_after = 0;
  bool restart = false;
};

struct SimulateRequest {
  std::string file, out;
  int threads = 0;  // 0: all cores
  bool quiet = false;
  std::string progress = "auto";  // auto | terminal | lines
  RestartFlags restart;
  std::string software_version;
};

ProgressMode progress_mode(bool quiet, const std::string& progress);

// Simulates every variant of r.file into r.out (r.out/<label>/ for labelled ones); `written` receives the results
// files. Throws InputError (bad scenario, --restart with nothing to resume, a kept result of another scenario).
void simulate(const SimulateRequest& r, std::vector<std::string>* written = nullptr);

// Whether --restart finds anything to resume for these variants in dir.
bool resumable(const std::vector<ScenarioVariant>& variants, const std::string& dir);

}  // namespace dmi::pipeline
