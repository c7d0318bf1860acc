// Runs a scenario: builds the scene, steps the solver to end_time, records histories, probes and
// snapshots, and writes OUT/results.h5 (+ OUT/fields/*.vtu, particles.pvd).
#pragma once
#include <string>

#include "engine/io/results.hpp"
#include "engine/scenario/config.hpp"
#include "engine/sim/progress.hpp"

namespace dmi {

struct RunOptions {
  std::string out_dir;          // empty: nothing is written (validation runs)
  ProgressMode progress = ProgressMode::automatic;
  int threads = 0;              // 0: OpenMP default
  std::string software_version;
  // Checkpoints (OUT/checkpoint.dmi): every `checkpoint_every` wall seconds (0: never), and always when a signal or
  // stop_after_steps stops the run. restart: continue from OUT/checkpoint.dmi, bit for bit.
  double checkpoint_every = 0;
  long stop_after_steps = 0;    // > 0: stop (checkpoint + partial results, Interrupted with signal 0) after this step
  bool restart = false;
  // Wall time per phase of the step loop into the run info (profile_<phase>_seconds; the small-scene bench).
  bool profile = false;
};

struct RunOutput {
  Results results;              // histories and run info, as written to results.h5 (no snapshots)
  std::string results_path;     // empty when nothing was written
};

// SIGINT / SIGTERM handling shared by runs (run_scenario holds one scope per run). Hold one around runs that belong
// together (variants side by side, a grid study's levels) so that a signal stops all of them, also those that start
// after it; a signal no run acted on is raised again when the outermost scope ends without an exception.
class InterruptScope {
 public:
  InterruptScope();
  ~InterruptScope();
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;
};

// Throws InputError for a scenario that cannot be built, RunError when the run fails, and
// std::runtime_error for file errors.
RunOutput run_scenario(const Scenario& s, const RunOptions& o);
struct RunEstimate {
  double steps = 0;   // end_time over the first step (a lower bound)
  double wall_s = 0;  // on one core at the particle kernel's speed (a lower bound)
};
// What a run checks before it writes anything (the scene builds; the estimated step count and wall time are within
// /analysis/max_steps and /analysis/max_wall_hours): --dry-run. Returns the estimate (zero without bodies). Throws
// InputError.
RunEstimate preflight(const Scenario& s);

}  // namespace dmi
