#include "pipeline/simulate.hpp"

#include <omp.h>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <thread>

#include "engine/common/error.hpp"
#include "engine/scenario/scenario.hpp"
#include "engine/sim/run.hpp"
#include "engine/sim/solid_check.hpp"
#include "pipeline/run_folder.hpp"

namespace dmi::pipeline {
namespace fs = std::filesystem;
namespace {

std::string variant_dir(const std::string& out, const ScenarioVariant& v) { return v.label.empty() ? out : (fs::path(out) / v.label).string(); }

// With --restart, a variant that has a checkpoint continues from it; one whose results.h5 is complete (and has no
// checkpoint) is kept as it is -- provided it was computed for this scenario; any other starts afresh.
RunState resume_state(const RestartFlags& rf, const std::string& dir, const ScenarioVariant& v) {
  if (!rf.restart) return RunState::absent;
  const RunState st = run_state(dir);
  // A complete result is kept only if it was computed from this scenario (a checkpoint is checked by its fingerprint
  // when it is read): a file edited since would otherwise leave a stale result, or mix scenarios in a grid study.
  if (st == RunState::complete && !holds_run_of(dir, v.scenario))
    throw InputError((fs::path(dir) / "results.h5").string() +
                     ": --restart keeps a complete result only when it was computed from this scenario, and this one "
                     "was computed from a different scenario (edited since?): run without --restart to compute it afresh");
  return st;
}

struct Job {
  RunOptions o;
  RunState mode = RunState::absent;
  RunOutput r;
  std::exception_ptr error;
};

// Messages come in variant order after all have ended; the first variant's error is the one reported.
void report(const SimulateRequest& rq, const ScenarioVariant& v, const Job& j, std::vector<std::string>* written) {
  if (!rq.quiet && !v.label.empty()) std::printf("variant %s -> %s\n", v.label.c_str(), j.o.out_dir.c_str());
  if (j.mode == RunState::complete) {  // finished before the interruption
    if (!rq.quiet) std::printf("kept %s/results.h5 (complete; nothing to restart)\n", j.o.out_dir.c_str());
    if (written) written->push_back((fs::path(j.o.out_dir) / "results.h5").string());
    return;
  }
  if (!rq.quiet && j.o.restart) std::printf("restarting from %s/checkpoint.dmi\n", j.o.out_dir.c_str());
  if (j.error) std::rethrow_exception(j.error);
  if (written) written->push_back(j.r.results_path);
  if (!rq.quiet)
    std::printf("wrote %s (%.0f steps, %.2f s wall)\n", j.r.results_path.c_str(), j.r.results.info.stats.steps.value(),
                j.r.results.info.stats.wall_seconds.value());
}

}  // namespace

ProgressMode progress_mode(bool quiet, const std::string& p) {
  if (quiet) return ProgressMode::quiet;
  if (p == "lines") return ProgressMode::lines;
  if (p == "terminal") return ProgressMode::terminal;
  return ProgressMode::automatic;
}

bool resumable(const std::vector<ScenarioVariant>& variants, const std::string& dir) {
  return std::any_of(variants.begin(), variants.end(), [&](const ScenarioVariant& v) { return run_state(variant_dir(dir, v)) != RunState::absent; });
}

// With two or more threads the variants run side by side, the threads shared among them: a scene below 4 096
// particles steps serially whatever -t says, so in turn they left cores idle (docs/performance.md). Results do not
// depend on this (each run is deterministic across thread counts).
void simulate(const SimulateRequest& rq, std::vector<std::string>* written) {
  const std::vector<ScenarioVariant> variants = load_scenario_variants(rq.file);
  const int nv = static_cast<int>(variants.size());
  const int cores = rq.threads > 0 ? rq.threads : omp_get_max_threads();
  const bool side_by_side = nv > 1 && cores >= 2;
  std::vector<Job> jobs(variants.size());
  for (int k = 0; k < nv; ++k) {
    RunOptions& o = jobs[k].o;
    o.out_dir = variant_dir(rq.out, variants[k]);
    o.threads = side_by_side ? std::max(1, cores / nv) : rq.threads;
    o.progress = progress_mode(rq.quiet, rq.progress);
    if (side_by_side && o.progress != ProgressMode::quiet) o.progress = ProgressMode::lines;  // no two live bars
    o.software_version = rq.software_version;
    o.checkpoint_every = rq.restart.checkpoint_every;
    o.stop_after_steps = rq.restart.stop_after;
    jobs[k].mode = resume_state(rq.restart, o.out_dir, variants[k]);
    o.restart = jobs[k].mode == RunState::interrupted;
  }
  // --restart continues an interrupted run: with no checkpoint in any variant's folder (and not every variant done)
  // there is none, and starting afresh silently would hide a wrong folder.
  if (rq.restart.restart && std::none_of(jobs.begin(), jobs.end(), [](const Job& j) { return j.mode != RunState::absent; }))
    throw InputError(rq.out + ": --restart: no checkpoint.dmi to continue from (the run finished or was never started here); run without "
                     "--restart to start afresh");
  auto run_one = [&](int k) {
    if (jobs[k].mode == RunState::complete) return;
    try {
      jobs[k].r = run_scenario(variants[k].scenario, jobs[k].o);
    } catch (...) {
      jobs[k].error = std::current_exception();
    }
  };
  if (!side_by_side) {
    for (int k = 0; k < nv; ++k) run_one(k), report(rq, variants[k], jobs[k], written);
    return;
  }
  // A signal stops every variant, also one still building its scene; the scope ends after the reports so that an
  // interrupted variant's error, rethrown, is what the user sees.
  const InterruptScope signals;
  std::vector<std::thread> pool;
  for (int k = 0; k < nv; ++k) pool.emplace_back(run_one, k);
  // The variants check one dam body: its factorisation (most of a solid check's time) runs beside them instead of
  // after the first to finish.
  const SolidCheckConfig& sc = variants.front().scenario.solid_check;
  if (sc.present && std::any_of(jobs.begin(), jobs.end(), [](const Job& j) { return j.mode != RunState::complete; }))
    pool.emplace_back([&sc] { prepare_solid_check(sc); });
  for (auto& t : pool) t.join();
  for (int k = 0; k < nv; ++k) report(rq, variants[k], jobs[k], written);
}

}  // namespace dmi::pipeline
