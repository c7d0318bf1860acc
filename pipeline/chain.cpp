#include "pipeline/chain.hpp"

#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "design/design.hpp"
#include "design/grid_study.hpp"
#include "engine/common/error.hpp"
#include "engine/scenario/hydrograph_io.hpp"
#include "engine/scenario/scenario.hpp"
#include "engine/sim/run.hpp"
#include "render/report.hpp"

namespace dmi::pipeline {
namespace fs = std::filesystem;
namespace {

// The grid uncertainty of the governing numbers, and the verdict on their conservative bound (stdout).
void print_grid_study(const design::DesignDocument& fine) {
  if (!fine.grid_study) return;
  const design::GridStudyRecord& g = *fine.grid_study;
  std::printf("\ngrid uncertainty of the governing numbers (%s):\n", g.method.c_str());
  auto tag = [](const std::string& v) { return v.empty() ? std::string() : "[" + v + "] "; };
  for (const design::GridQuantity& q : g.quantities)
    std::printf("  %s%-40s %12.5g %-4s +- %5.1f %%  %s\n", tag(q.variant).c_str(), q.title.c_str(), q.values[0], q.unit.c_str(), 100 * q.gci,
                q.statement.c_str());
  if (!g.verdict) return;
  for (const auto& r : g.verdict->runs)
    std::printf("  %sgoverning utilisation %.3f, conservative bound u (1 + GCI) = %.3f: %s\n", tag(r.variant).c_str(), r.utilisation,
                r.utilisation_bound, r.passed ? "within 1" : "above 1");
  const std::string note = fine.verdict.note.empty() ? "" : " (" + fine.verdict.note + ")";
  std::printf("  judged on: %s%s\n", g.verdict->judge_on.c_str(), note.c_str());
}

// Restarted, every level continues from its own checkpoints (or keeps its complete results), variant by variant as
// simulate() decides; a level with nothing to resume (it never started: the levels run in turn on one core, coarsest
// first) starts afresh. Only a study with nothing to resume at any level is refused, as a run is.
void check_study_resumable(const SimulateRequest& r, const std::vector<ScenarioVariant>& variants) {
  bool any = resumable(variants, r.out);
  if (const fs::path levels = fs::path(r.out) / "grid_study"; fs::is_directory(levels))
    for (const auto& e : fs::directory_iterator(levels)) any = any || (e.is_directory() && resumable(variants, e.path().string()));
  if (!any)
    throw InputError(r.out + ": --restart: no checkpoint.dmi to continue from at any level of the grid study (it finished or was never "
                     "started here); run without --restart to start afresh");
}

// `run --grid-study`: the scenario at its cell size h and at r h and r^2 h (coarsest first), each simulated and
// checked in OUT/grid_study/h_<cell>/ (the finest in OUT/ itself), then the grid uncertainty of every governing
// quantity (design/grid_study.hpp) written into OUT/design.json. Returns the verdict of the finest run.
int grid_study_chain(const ChainRequest& c) {
  const SimulateRequest& rq = c.simulate;
  const double ratio = c.grid_ratio;
  if (!(ratio >= std::sqrt(2.0) - 1e-12)) throw InputError("--grid-ratio = " + std::to_string(ratio) + ": expected a ratio >= sqrt(2) (1.41421)");
  const std::vector<ScenarioVariant> variants = load_scenario_variants(rq.file);
  const double h1 = common_cell_size(variants, rq.file);
  const int dim = variants.front().scenario.analysis.dimension;
  std::ifstream in(rq.file);
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::json source = nlohmann::json::parse(text.str());
  resolve_file_references(source, rq.file);  // the coarser levels are written into OUT/grid_study/
  const std::array<double, 3> h{h1, h1 * ratio, h1 * ratio * ratio};
  const double c1 = std::pow(ratio, -(dim + 1)), c2 = c1 * c1;
  // Two or more cores: the coarser levels run beside the finest at the lowest priority (design/grid_study.hpp).
  const bool overlap = (rq.threads > 0 ? rq.threads : omp_get_max_threads()) >= 2;
  if (!rq.quiet)
    std::printf("grid study: cell sizes %.4g, %.4g, %.4g m (ratio %.3g); estimated cost %.2f times the single run at %.4g m "
                "(particles ~ h^-%d, steps ~ h^-1: the coarser runs cost %.2f and %.2f of it)%s\n",
                h[0], h[1], h[2], ratio, 1 + c1 + c2, h[0], dim, c1, c2,
                overlap ? "; the coarser two run beside it at low priority, on the cores it leaves idle" : "");
  if (rq.restart.restart) check_study_resumable(rq, variants);
  // --stop-after counts the finest level's steps only.
  const auto level_run = [&](const std::string& scen, const std::string& dir, int g) {
    std::vector<std::string> written;
    SimulateRequest lr = rq;
    lr.file = scen, lr.out = dir, lr.quiet = rq.quiet || g > 0;
    lr.restart.restart = rq.restart.restart && resumable(variants, dir);  // every level has the same variants
    if (g > 0) lr.restart.stop_after = 0;
    simulate(lr, &written);
    return written;
  };
  double wall_coarse = 0;
  const auto on_level = [&](int g, double hg, double wall) {
    if (g == 2) wall_coarse = wall;
    if (rq.quiet) return;
    if (overlap) {
      std::printf("grid study: h = %.4g m done, %.1f s after the study began\n", hg, wall);
      return;
    }
    std::printf("grid study: h = %.4g m done in %.1f s", hg, wall);
    if (g == 2) std::printf("; the remaining runs should take about %.0f s", wall_coarse * (1 / c1 + 1 / c2));
    std::printf("\n");
  };
  const design::GridStudyOutcome r = [&] {
    const InterruptScope signals;  // a signal stops every level, also one that starts after it
    return design::run_grid_study(rq.file, source, h1, ratio, rq.out, c.limits_file, level_run, rq.quiet, rq.software_version, on_level, overlap);
  }();
  if (!rq.quiet) print_grid_study(r.design);
  return r.passed ? 0 : 1;
}

}  // namespace

int run_chain(const ChainRequest& c) {
  const SimulateRequest& rq = c.simulate;
  if (!c.limits_file.empty()) design::read_limits(c.limits_file);  // a bad limits file fails before the simulation
  int verdict = 0;
  if (c.grid_study) {
    verdict = grid_study_chain(c);
  } else {
    std::vector<std::string> written;
    simulate(rq, &written);
    std::error_code ec;  // a grid study left in the folder belonged to the results just replaced
    fs::remove_all(fs::path(rq.out) / "grid_study", ec);
    verdict = design::check_main(written, c.limits_file, false, (fs::path(rq.out) / "design.json").string(), rq.quiet, rq.software_version);
  }
  if (c.report) render::report_main(rq.out, {c.quantity, rq.quiet, true, rq.software_version, rq.threads == 1 ? 1 : 2});
  return verdict;
}

}  // namespace dmi::pipeline
