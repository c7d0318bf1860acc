// damimpact command line: a thin shell over the engine and the design layer. Exit 0 ok, 1 a validation case or a
// design check failed, 2 bad input or failed run.
#include <CLI/CLI.hpp>
#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <new>
#include <sstream>
#include <thread>

#include "design/design.hpp"
#include "design/grid_study.hpp"
#include "engine/scenario/hydrograph_io.hpp"
#ifndef DMI_LEAN
#include "render/field.hpp"
#include "render/render_main.hpp"
#include "render/picture_helper.hpp"
#include "render/charts.hpp"
#include "render/report.hpp"
#endif
#include "engine/common/error.hpp"
#include "engine/io/results_writer.hpp"
#include "engine/scenario/scenario.hpp"
#include "engine/sim/run.hpp"
#include "engine/sim/solid_check.hpp"
#include "verify/bench.hpp"
#include "engine/sim/build_scene.hpp"
#include "verify/validate.hpp"
#include "sweep/sweep_main.hpp"

#ifndef DMI_VERSION
#define DMI_VERSION "0.0.0"
#endif

namespace {

// The file this process runs, as /proc/self/exe names it; empty when that cannot be read or is not an absolute path.
std::filesystem::path own_file() {
  std::error_code ec;
  std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  return !ec && self.is_absolute() ? self : std::filesystem::path();
}

dmi::ProgressMode progress_mode(bool quiet, const std::string& p) {
  if (quiet) return dmi::ProgressMode::quiet;
  if (p == "lines") return dmi::ProgressMode::lines;
  if (p == "terminal") return dmi::ProgressMode::terminal;
  return dmi::ProgressMode::automatic;
}

// --dry-run: validate every variant and print a one-line summary of each (stdout). With --expand,
// print the low-level scenario the presets expand to instead (stdout, runnable as a scenario file;
// the summaries go to stderr).
int dry_run_report(const std::string& file, const std::vector<dmi::ScenarioVariant>& variants, bool expand) {
  // The parser kept each variant's expansion (or, without presets, the file as given): printed first, so that a
  // scene that cannot be built can be read at the paths its error names.
  auto low_level = [](const dmi::Scenario& s) { return nlohmann::json::parse(s.expanded_text.empty() ? s.source_text : s.expanded_text); };
  if (expand) {
    if (variants.size() == 1) {
      std::cout << low_level(variants[0].scenario).dump(1) << "\n";
    } else {
      nlohmann::json all = nlohmann::json::object();
      for (const auto& v : variants) all[v.label] = low_level(v.scenario);
      std::cout << all.dump(1) << "\n";
    }
    std::cout.flush();
  }
  for (const auto& v : variants) {
    const dmi::Scenario& s = v.scenario;
    const dmi::RunEstimate e = dmi::preflight(s);
    char cost[160] = "";
    if (e.steps > 0) std::snprintf(cost, sizeof cost, "; about %.3g steps, a first guess of %.3g s on one core", e.steps, e.wall_s);
    std::fprintf(expand ? stderr : stdout, "%s%s%s: valid scenario '%s' (%dD, %zu bodies, %zu materials, %zu walls, %zu members%s)\n", file.c_str(),
                 v.label.empty() ? "" : " / ", v.label.c_str(), s.name.c_str(), s.analysis.dimension, s.bodies.size(), s.materials.size(),
                 s.walls.size(), s.structure.members.size(), cost);
  }
  return 0;
}

// Checkpoint and restart options of simulate/run (docs/reliability.md).
struct RestartFlags {
  double checkpoint_every = 600;  // wall seconds
  long stop_after = 0;
  bool restart = false;
};

// With --restart, a variant that has a checkpoint continues from it; one whose results.h5 is complete (and has no
// checkpoint) is kept as it is; any other starts afresh.
enum class Resume { fresh, from_checkpoint, done };
Resume resume_mode(const RestartFlags& rf, const std::string& dir) {
  namespace fs = std::filesystem;
  if (!rf.restart) return Resume::fresh;
  if (fs::exists(fs::path(dir) / "checkpoint.dmi")) return Resume::from_checkpoint;
  if (fs::exists(fs::path(dir) / "results.h5") && !fs::exists(fs::path(dir) / "results.h5.partial")) return Resume::done;
  return Resume::fresh;
}

// Simulates every variant; `written` receives the results files. With two or more threads the variants run side by
// side, the threads shared among them: a scene below 4 096 particles steps serially whatever -t says, so in turn they
// left cores idle (docs/performance.md). Results do not depend on this (each run is deterministic across thread
// counts); messages come in variant order after all have ended, and the first variant's error is the one reported.
int simulate(const std::string& file, const std::string& out, int threads, bool quiet, const std::string& progress, bool dry_run,
             bool expand, const RestartFlags& rf, std::vector<std::string>* written = nullptr) {
  const std::vector<dmi::ScenarioVariant> variants = dmi::load_scenario_variants(file);
  if (dry_run || expand) return dry_run_report(file, variants, expand);
  const int nv = static_cast<int>(variants.size());
  const int cores = threads > 0 ? threads : omp_get_max_threads();
  const bool side_by_side = nv > 1 && cores >= 2;
  struct Job {
    dmi::RunOptions o;
    Resume mode = Resume::fresh;
    dmi::RunOutput r;
    std::exception_ptr error;
  };
  std::vector<Job> jobs(variants.size());
  for (int k = 0; k < nv; ++k) {
    const auto& v = variants[k];
    dmi::RunOptions& o = jobs[k].o;
    o.out_dir = v.label.empty() ? out : (std::filesystem::path(out) / v.label).string();
    o.threads = side_by_side ? std::max(1, cores / nv) : threads;
    o.progress = progress_mode(quiet, progress);
    if (side_by_side && o.progress != dmi::ProgressMode::quiet) o.progress = dmi::ProgressMode::lines;  // no two live bars
    o.software_version = DMI_VERSION;
    o.checkpoint_every = rf.checkpoint_every;
    o.stop_after_steps = rf.stop_after;
    jobs[k].mode = resume_mode(rf, o.out_dir);
    o.restart = jobs[k].mode == Resume::from_checkpoint;
    // A complete result is kept only if it was computed from this scenario (a checkpoint is checked by its fingerprint
    // when it is read): a file edited since would otherwise leave a stale result, or mix scenarios in a grid study.
    if (jobs[k].mode == Resume::done) {
      const std::string kept = (std::filesystem::path(o.out_dir) / "results.h5").string();
      const dmi::RunInfo info = dmi::read_results(kept, false).info;
      if (info.scenario_json != v.scenario.source_text || info.variant != v.scenario.variant)
        throw dmi::InputError(kept + ": --restart keeps a complete result only when it was computed from this scenario, and this one "
                              "was computed from a different scenario text (edited since?): run without --restart to compute it afresh");
    }
  }
  // --restart continues an interrupted run: with no checkpoint in any variant's folder (and not every variant done)
  // there is none, and starting afresh silently would hide a wrong folder.
  if (rf.restart && std::none_of(jobs.begin(), jobs.end(), [](const Job& j) { return j.mode != Resume::fresh; }))
    throw dmi::InputError(out + ": --restart: no checkpoint.dmi to continue from (the run finished or was never started here); run without "
                          "--restart to start afresh");
  auto run_one = [&](int k) {
    if (jobs[k].mode == Resume::done) return;
    try {
      jobs[k].r = dmi::run_scenario(variants[k].scenario, jobs[k].o);
    } catch (...) {
      jobs[k].error = std::current_exception();
    }
  };
  auto report = [&](int k) {
    const auto& v = variants[k];
    const Job& j = jobs[k];
    if (!quiet && !v.label.empty()) std::printf("variant %s -> %s\n", v.label.c_str(), j.o.out_dir.c_str());
    if (j.mode == Resume::done) {  // finished before the interruption
      if (!quiet) std::printf("kept %s/results.h5 (complete; nothing to restart)\n", j.o.out_dir.c_str());
      if (written) written->push_back((std::filesystem::path(j.o.out_dir) / "results.h5").string());
      return;
    }
    if (!quiet && j.o.restart) std::printf("restarting from %s/checkpoint.dmi\n", j.o.out_dir.c_str());
    if (j.error) std::rethrow_exception(j.error);
    if (written) written->push_back(j.r.results_path);
    if (!quiet) std::printf("wrote %s (%.0f steps, %.2f s wall)\n", j.r.results_path.c_str(), j.r.results.info.numbers.at("steps"),
                            j.r.results.info.numbers.at("wall_seconds"));
  };
  if (side_by_side) {
    const dmi::InterruptScope signals;  // a signal stops every variant, also one still building its scene
    std::vector<std::thread> pool;
    for (int k = 0; k < nv; ++k) pool.emplace_back(run_one, k);
    // The variants check one dam body: its factorisation (most of a solid check's time) runs beside them instead of
    // after the first to finish.
    const dmi::SolidCheckConfig& sc = variants.front().scenario.solid_check;
    if (sc.present && std::any_of(jobs.begin(), jobs.end(), [](const Job& j) { return j.mode != Resume::done; }))
      pool.emplace_back([&sc] { dmi::prepare_solid_check(sc); });
    for (auto& t : pool) t.join();
    for (int k = 0; k < nv; ++k) report(k);
  } else {
    for (int k = 0; k < nv; ++k) run_one(k), report(k);
  }
  return 0;
}

#ifndef DMI_LEAN
// `run --grid-study`: the scenario at its cell size h and at r h and r^2 h (coarsest first), each simulated and
// checked in OUT/grid_study/h_<cell>/ (the finest in OUT/ itself), then the grid uncertainty of every governing
// quantity (design/grid_study.hpp) written into OUT/design.json. Returns the verdict of the finest run.
int grid_study_run(const std::string& file, const std::string& out, int threads, bool quiet, const std::string& progress, double ratio,
                   const std::string& limits_file, const RestartFlags& rf) {
  namespace fs = std::filesystem;
  if (!(ratio >= std::sqrt(2.0) - 1e-12)) throw dmi::InputError("--grid-ratio = " + std::to_string(ratio) + ": expected a ratio >= sqrt(2) (1.41421)");
  const std::vector<dmi::ScenarioVariant> variants = dmi::load_scenario_variants(file);
  const double h1 = dmi::common_cell_size(variants, file);
  const int dim = variants.front().scenario.analysis.dimension;
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::json source = nlohmann::json::parse(text.str());
  dmi::resolve_file_references(source, file);  // the coarser levels are written into OUT/grid_study/
  const std::array<double, 3> h{h1, h1 * ratio, h1 * ratio * ratio};
  const double c1 = std::pow(ratio, -(dim + 1)), c2 = c1 * c1;
  // Two or more cores: the coarser levels run beside the finest at the lowest priority (design/grid_study.hpp).
  const bool overlap = (threads > 0 ? threads : omp_get_max_threads()) >= 2;
  if (!quiet) std::printf("grid study: cell sizes %.4g, %.4g, %.4g m (ratio %.3g); estimated cost %.2f times the single run at %.4g m "
              "(particles ~ h^-%d, steps ~ h^-1: the coarser runs cost %.2f and %.2f of it)%s\n",
              h[0], h[1], h[2], ratio, 1 + c1 + c2, h[0], dim, c1, c2,
              overlap ? "; the coarser two run beside it at low priority, on the cores it leaves idle" : "");
  double wall_coarse = 0;
  // Restarted, every level continues from its own checkpoints (or keeps its complete results), variant by variant as
  // simulate() decides (resume_mode); a level with nothing to resume (it never started: the levels run in turn on one
  // core, coarsest first) starts afresh. Only a study with nothing to resume at any level is refused, as a run is.
  // --stop-after counts the finest level's steps only.
  const auto resumable = [&](const std::string& dir) {
    return std::any_of(variants.begin(), variants.end(), [&](const dmi::ScenarioVariant& v) {
      return resume_mode(rf, v.label.empty() ? dir : (fs::path(dir) / v.label).string()) != Resume::fresh;
    });
  };
  if (rf.restart) {
    bool any = resumable(out);
    if (const fs::path levels = fs::path(out) / "grid_study"; fs::is_directory(levels))
      for (const auto& e : fs::directory_iterator(levels)) any = any || (e.is_directory() && resumable(e.path().string()));
    if (!any)
      throw dmi::InputError(out + ": --restart: no checkpoint.dmi to continue from at any level of the grid study (it finished or was never "
                            "started here); run without --restart to start afresh");
  }
  const auto level_run = [&](const std::string& scen, const std::string& dir, int g) {
    std::vector<std::string> written;
    RestartFlags lf = rf;
    lf.restart = rf.restart && resumable(dir);
    if (g > 0) lf.stop_after = 0;
    simulate(scen, dir, threads, quiet || g > 0, progress, false, false, lf, &written);
    return written;
  };
  const auto on_level = [&](int g, double hg, double wall) {
    if (g == 2) wall_coarse = wall;
    if (quiet) return;
    if (overlap) {
      std::printf("grid study: h = %.4g m done, %.1f s after the study began\n", hg, wall);
      return;
    }
    std::printf("grid study: h = %.4g m done in %.1f s", hg, wall);
    if (g == 2) std::printf("; the remaining runs should take about %.0f s", wall_coarse * (1 / c1 + 1 / c2));
    std::printf("\n");
  };
  const dmi::design::GridStudyOutcome r = [&] {
    const dmi::InterruptScope signals;  // a signal stops every level, also one that starts after it
    return dmi::design::run_grid_study(file, source, h1, ratio, out, limits_file, level_run, quiet, DMI_VERSION, on_level, overlap);
  }();
  const nlohmann::json& fine = r.design;
  const int verdict = r.passed ? 0 : 1;
  if (!quiet) {
    std::printf("\ngrid uncertainty of the governing numbers (%s):\n", fine["grid_study"]["method"].get<std::string>().c_str());
    for (const auto& q : fine["grid_study"]["quantities"]) {
      const std::string var = q["variant"].get<std::string>();
      std::printf("  %s%-40s %12.5g %-4s +- %5.1f %%  %s\n", var.empty() ? "" : ("[" + var + "] ").c_str(), q["title"].get<std::string>().c_str(),
                  q["values"][0].get<double>(), q["unit"].get<std::string>().c_str(), 100 * q["gci"].get<double>(),
                  q["statement"].get<std::string>().c_str());
    }
    for (const auto& r : fine["grid_study"]["verdict"]["runs"])
      std::printf("  %sgoverning utilisation %.3f, conservative bound u (1 + GCI) = %.3f: %s\n",
                  r["variant"].get<std::string>().empty() ? "" : ("[" + r["variant"].get<std::string>() + "] ").c_str(), r["utilisation"].get<double>(),
                  r["utilisation_bound"].get<double>(), r["passed"].get<bool>() ? "within 1" : "above 1");
    std::printf("  judged on: %s%s\n", fine["grid_study"]["verdict"]["judge_on"].get<std::string>().c_str(), fine["verdict"].contains("note") ? (" (" + fine["verdict"]["note"].get<std::string>() + ")").c_str() : "");
  }
  return verdict;
}

// `bench`, plus with --out the JSON and the Pareto chart of Lin & Yang verification 1 (error against wall time, the front joined).
int bench_command(const std::vector<std::string>& cases, bool as_json, bool quick, const dmi::BenchOptions& o, const std::string& out) {
  if (out.empty()) return dmi::bench_main(cases, as_json, quick, o);
  std::stringstream captured;
  std::streambuf* old = std::cout.rdbuf(captured.rdbuf());
  int rc = 0;
  try {
    rc = dmi::bench_main(cases, true, quick, o);
  } catch (...) {
    std::cout.rdbuf(old);
    throw;
  }
  std::cout.rdbuf(old);
  const nlohmann::json j = nlohmann::json::parse(captured.str());
  std::filesystem::create_directories(out);
  std::ofstream(std::filesystem::path(out) / "bench.json") << j.dump(1) << "\n";
  for (const char* cs : {"bar", "disks", "dam"}) {  // Pareto charts of the MPM studies: one point set per variant group
    if (!j.contains(cs)) continue;
    dmi::render::ChartSpec c;
    c.title = std::string(cs) + ": error against run time";
    c.log_x = c.log_y = true;
    c.x_label = "wall time [s]";
    c.y_label = std::string(cs) == "bar" ? "period error [-]" : std::string(cs) == "disks" ? "|E(3 s) / E0 - 1| [-]" : "base shear error vs Richardson [-]";
    std::vector<std::string> groups;
    for (const auto& p : j[cs]["points"])
      if (std::find(groups.begin(), groups.end(), p["group"].get<std::string>()) == groups.end()) groups.push_back(p["group"]);
    static const std::array<unsigned char, 3> pal[] = {{31, 119, 180}, {255, 127, 14}, {44, 160, 44}, {214, 39, 40}, {148, 103, 189}, {140, 86, 75}, {227, 119, 194}, {127, 127, 127}};
    for (std::size_t g = 0; g < groups.size(); ++g) {
      dmi::render::Curve pts;
      pts.label = groups[g], pts.points = true, pts.color = pal[g % 8];
      for (const auto& p : j[cs]["points"])
        if (p["group"] == groups[g] && !p.contains("failed") && p.contains("error") && p["error"].is_number())
          pts.x.push_back(p["wall_seconds"]), pts.y.push_back(p["error"]);
      if (pts.x.size() >= 2) c.curves.push_back(pts);  // a group whose error is unknown (not converged) has no curve
    }
    std::vector<std::pair<double, double>> front;
    for (const auto& p : j[cs]["points"])
      if (p["front"].get<bool>()) front.push_back({p["wall_seconds"], p["error"]});
    std::sort(front.begin(), front.end());
    dmi::render::Curve f;
    f.label = "Pareto front", f.color = {60, 60, 60};
    for (const auto& [x, y] : front) f.x.push_back(x), f.y.push_back(y);
    if (f.x.size() >= 2) c.curves.push_back(f);
    if (c.curves.empty()) {
      std::fprintf(stderr, "bench: no chart for %s: fewer than two points with a known error\n", cs);
      continue;
    }
    dmi::render::render_chart(c, (std::filesystem::path(out) / ("pareto_" + std::string(cs) + ".png")).string());
  }
  if (j.contains("a5")) {
    dmi::render::ChartSpec c;
    c.title = "Lin & Yang verification 1: error against run time";
    c.log_x = true;
    c.x_label = "wall time [s]", c.y_label = "NRMS error vs converged FE [-]";
    for (const char* integ : {"explicit", "newmark"}) {
      dmi::render::Curve pts;
      pts.label = std::string(integ) + " frame";
      pts.points = true;
      pts.color = std::string(integ) == "explicit" ? std::array<unsigned char, 3>{31, 119, 180} : std::array<unsigned char, 3>{255, 127, 14};
      for (const auto& p : j["a5"]["points"])
        if (p["integrator"] == integ) pts.x.push_back(p["wall_seconds"]), pts.y.push_back(p["error"]);
      c.curves.push_back(pts);
    }
    std::vector<std::pair<double, double>> front;
    for (const auto& p : j["a5"]["points"])
      if (p["front"].get<bool>()) front.push_back({p["wall_seconds"], p["error"]});
    std::sort(front.begin(), front.end());
    dmi::render::Curve f;
    f.label = "Pareto front";
    f.color = {60, 60, 60};
    for (const auto& [x, y] : front) f.x.push_back(x), f.y.push_back(y);
    c.curves.push_back(f);
    dmi::render::render_chart(c, (std::filesystem::path(out) / "pareto_a5.png").string());
  }
  if (!as_json) std::printf("wrote %s/bench.json and the Pareto charts of its studies\n", out.c_str());
  else std::cout << j.dump(1) << "\n";
  return rc;
}
#else
// The commands that draw (VTK) or spread cases over MPI ranks run in damimpact-full, built beside this binary: linked
// with VTK and MPI (125 shared libraries) it takes ~0.09 s to start, this one without them ~0.02 s. The arguments
// were checked here already; the environment (OMP_WAIT_POLICY) goes with them.
int hand_over(char** argv) {
  const std::filesystem::path self = own_file();
  if (self.empty()) {  // never a path relative to the working directory
    std::fprintf(stderr, "damimpact: error: /proc/self/exe: cannot read it as an absolute path, so damimpact-full beside this binary "
                 "cannot be found; run damimpact-full directly\n");
    return 2;
  }
  const std::filesystem::path full = self.parent_path() / "damimpact-full";
  execv(full.c_str(), argv);
  std::fprintf(stderr, "damimpact: error: %s: cannot start it (%s); run, render, report, sweep and bench --out need it beside damimpact\n",
               full.c_str(), std::strerror(errno));
  return 2;
}
#endif

}  // namespace

constexpr long kMaxThreads = 1024;

// A whole number in [lo, hi], named with readable bounds (CLI11's own checks print doubles: 1.797...e308 in full).
CLI::Validator whole_in(long lo, long hi) {
  const std::string want = "a whole number from " + std::to_string(lo) + " to " + std::to_string(hi);
  return CLI::Validator(
      [lo, hi, want](std::string& s) -> std::string {
        long v = 0;
        std::size_t used = 0;
        try {
          v = std::stol(s, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used != s.size() || s.empty() || v < lo || v > hi) return "value " + s + ": expected " + want;
        return {};
      },
      "INT in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
}

int main(int argc, char** argv) {
  // OpenMP threads that spin while waiting stall badly when the cores are shared (a second run, a
  // parallel test job): ~100x slower on 2 cores. libgomp reads OMP_WAIT_POLICY when it loads, so set
  // a passive default and re-execute once; a user's own setting is respected.
  if (!std::getenv("OMP_WAIT_POLICY")) {
    setenv("OMP_WAIT_POLICY", "passive", 1);
    // Through the file /proc/self/exe names, so that the process keeps its name (exec'd as /proc/self/exe it was
    // called "exe" in ps, top and pgrep).
    if (const std::filesystem::path self = own_file(); !self.empty()) execv(self.c_str(), argv);
    execv("/proc/self/exe", argv);  // returns only on failure (both): then go on as we are
  }
  CLI::App app{"damimpact " DMI_VERSION " - check dams hit by boulders and debris flows: MPM simulation, design checks, reports"};
  app.set_version_flag("--version", DMI_VERSION);
  app.require_subcommand(1);

  std::string file, out = "out", progress = "auto";
  bool grid_study = false;
  double grid_ratio = std::sqrt(2.0);
  int threads = 0;
  bool quiet = false, dry_run = false, expand = false, json = false, list = false, markdown = false;
  RestartFlags restart;
  auto add_run_options = [&](CLI::App* c) {
    c->add_option("scenario", file, "scenario JSON file (docs/scenario.md)")->required();
    c->add_option("-o,--out", out, "output folder (results.h5, fields/)")->capture_default_str();
    c->add_option("-t,--threads", threads, "OpenMP threads (0 = all cores)")->capture_default_str()->check(whole_in(0, kMaxThreads));
    c->add_flag("-q,--quiet", quiet, "no progress output");
    c->add_option("--progress", progress, "progress display: auto | terminal | lines")->check(CLI::IsMember({"auto", "terminal", "lines"}));
    c->add_flag("--restart", restart.restart, "continue an interrupted run from OUT/checkpoint.dmi (bit for bit; same scenario file)");
    c->add_option("--checkpoint-every", restart.checkpoint_every, "wall seconds between checkpoints (0 = only when interrupted)")
        ->capture_default_str()->check(CLI::NonNegativeNumber);
    c->add_option("--stop-after", restart.stop_after, "stop after this many steps with a checkpoint (exit 3; continue with --restart)")
        ->check(whole_in(1, 1000000000000L));
  };
  CLI::App* run = app.add_subcommand("run", "simulate a scenario and write results (the whole chain)");
  add_run_options(run);
  CLI::App* sim = app.add_subcommand("simulate", "simulate a scenario: OUT/results.h5 and ParaView files OUT/fields/");
  add_run_options(sim);
  sim->add_flag("--dry-run", dry_run, "only read and validate the scenario (every variant of a comparison)");
  sim->add_flag("--expand", expand, "with --dry-run: print the low-level scenario the presets expand to (JSON; a runnable scenario file)");
  std::vector<std::string> cases;
  CLI::App* val = app.add_subcommand("validate", "run the verification cases against closed forms; exit 0 when all pass");
  val->add_option("cases", cases, "case names (default: all; see --list)");
  val->add_flag("--json", json, "print a JSON array of {case, metric, value, reference, error, tolerance, passed, wall_seconds}");
  val->add_flag("--list", list, "list the cases and exit");
  bool stress = false;
  val->add_flag("--stress", stress, "run the stability stress suite instead (docs/reliability.md)");
  val->add_option("-t,--threads", threads, "OpenMP threads (0 = all cores)")->check(whole_in(0, kMaxThreads));
  std::vector<std::string> check_paths;
  std::string limits_file, design_out;
  CLI::App* chk = app.add_subcommand("check", "design checks of finished runs: envelopes, reactions, strength checks -> design.json; "
                                              "exit 0 all pass, 1 a check fails, 2 bad input");
  chk->add_option("results", check_paths, "results.h5 files or run folders (a comparison folder holds with_buffer/ and without_buffer/)")->required();
  chk->add_option("--limits", limits_file, "limits JSON (docs/design-checks.md): strengths, factors, member materials");
  chk->add_flag("--json", json, "print design.json to stdout instead of the summary");
  chk->add_option("-o,--out", design_out, "where to write design.json (default: beside the results)");
  chk->add_flag("-q,--quiet", quiet, "no summary");
  run->add_option("--limits", limits_file, "limits JSON for the design checks (docs/design-checks.md)");
  std::string render_dir, quantity = "von_mises";
  CLI::App* ren = app.add_subcommand("render", "stress-field pictures and charts of a finished run -> OUT/images/ (off-screen, no display needed)");
  ren->add_option("out", render_dir, "run folder (results.h5, or with_buffer/ and without_buffer/)")->required();
  ren->add_option("--quantity", quantity, "particle colouring: von_mises | sigma_xx | sigma_yy | pressure")
      ->check(CLI::IsMember({"von_mises", "sigma_xx", "sigma_yy", "pressure"}))->capture_default_str();
  ren->add_flag("-q,--quiet", quiet, "no progress output");
  long helper_of = 0;  // the second picture process of a render, run or report (render/picture_helper.hpp)
  std::string claims;
  ren->add_option("--helper-of", helper_of, "internal: the second picture process of process PID (run, render and report start it)")
      ->check(CLI::PositiveNumber);
  ren->add_option("--claims", claims, "internal: with --helper-of, the folder of the pictures' claims")->check(CLI::ExistingDirectory);
  std::string report_dir;
  bool no_pdf = false;
  CLI::App* rep = app.add_subcommand("report", "pictures and the HTML + PDF design report of a finished run: OUT/report.html, OUT/report.pdf");
  rep->add_option("out", report_dir, "run folder (results.h5, or with_buffer/ and without_buffer/; design.json when checked)")->required();
  rep->add_option("--quantity", quantity, "particle colouring: von_mises | sigma_xx | sigma_yy | pressure")
      ->check(CLI::IsMember({"von_mises", "sigma_xx", "sigma_yy", "pressure"}))->capture_default_str();
  rep->add_flag("--no-pdf", no_pdf, "HTML only");
  rep->add_flag("-q,--quiet", quiet, "no progress output");
  run->add_flag("--grid-study", grid_study,
                "also run the scenario at r h and r^2 h and state the grid uncertainty (observed order, Richardson value, GCI) of "
                "every governing number in design.json and the report");
  run->add_option("--grid-ratio", grid_ratio, "refinement ratio r of --grid-study (>= sqrt 2)")->capture_default_str();
  run->add_flag("--no-report", no_pdf, "skip the pictures and the report (simulation and checks only)");
  std::vector<std::string> bench_cases;
  bool quick = false;
  CLI::App* bch = app.add_subcommand("bench", "performance figures (printed, not asserted): kernel throughput; docs/performance.md");
  bch->add_option("cases", bench_cases, "cases (default: all): kernel | a5 (run time vs error) | a6 (cost vs depth) | bar | disks | skip | dam (the main job: run time vs error) | small (the demo per particle-step against the kernel)");
  bch->add_flag("--json", json, "print JSON instead of tables");
  bch->add_flag("--quick", quick, "small problems (100 k particles), for a smoke test");
  dmi::BenchOptions bo;
  bo.particles = 0, bo.shapes.clear(), bo.transfers.clear(), bo.threads.clear();
  bch->add_option("--particles", bo.particles, "particles of the kernel block (default 1 M; --quick 100 k)");
  bch->add_option("--shape", bo.shapes, "shape functions (default linear gimp bspline2)")->check(CLI::IsMember({"linear", "gimp", "bspline2"}));
  bch->add_option("--transfer", bo.transfers, "transfers (default flip apic)")->check(CLI::IsMember({"flip", "apic"}));
  bch->add_option("--threads", bo.threads, "thread counts (default 1 2)");
  bch->add_option("--dim", bo.dimension, "the kernel block's dimension: 2 (a square, the default) or 3 (a cube)")->check(CLI::IsMember({2, 3}));
  std::string bench_out;
  bch->add_option("-o,--out", bench_out, "also write DIR/bench.json and the Pareto charts DIR/pareto_<case>.png (VTK charts)");
  std::string sweep_file;
  dmi::sweep::SweepOptions so;
  so.out_dir = "out/sweep";
  bool no_case_reports = false;
  CLI::App* swp = app.add_subcommand("sweep", "parametric study: every case of a sweep file (over MPI ranks under mpirun) -> "
                                              "OUT/cases/*, summary.csv/.json/.html/.pdf (docs/sweep.md)");
  swp->add_option("study", sweep_file, "sweep JSON file")->required();
  swp->add_option("-o,--out", so.out_dir, "output folder")->capture_default_str();
  swp->add_option("-t,--threads", so.threads, "OpenMP threads per case (per MPI rank; 0 = all cores)")->check(whole_in(0, kMaxThreads));
  swp->add_option("--limits", so.limits_file, "design limits file (docs/design-checks.md)");
  swp->add_flag("--no-case-reports", no_case_reports, "no HTML report per case (faster; the summary report is still written)");
  swp->add_flag("--no-pdf", no_pdf, "HTML only (no weasyprint)");
  swp->add_flag("-q,--quiet", so.quiet, "no progress output");
  CLI::App* sch = app.add_subcommand("schema", "print the scenario key reference (Markdown, as in docs/scenario.md)");
  sch->add_flag("--markdown", markdown, "Markdown tables (default)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    // One line on stderr, like every other input error.
    std::fprintf(stderr, "damimpact: error: %s (run with --help for the options)\n", e.what());
    return 2;
  }
  try {
    for (const auto& [cmd, folder] : {std::pair{sim, &out}, std::pair{run, &out}, std::pair{swp, &so.out_dir}})
      if (*cmd && folder->empty()) throw dmi::InputError("-o/--out = \"\": expected an output folder");
    if (*sim) return simulate(file, out, threads, quiet, progress, dry_run, expand, restart);
#ifdef DMI_LEAN
    if (*run || *ren || *rep || *swp || (*bch && !bench_out.empty())) return hand_over(argv);
#else
    dmi::render::set_picture_program(own_file().string());  // the second picture process runs this program
    if (*run) {  // the whole chain: simulation, then the design checks of what it wrote
      if (!limits_file.empty()) dmi::design::read_limits(limits_file);  // a bad limits file fails before the simulation
      int verdict = 0;
      if (grid_study) {
        verdict = grid_study_run(file, out, threads, quiet, progress, grid_ratio, limits_file, restart);
      } else {
        std::vector<std::string> written;
        simulate(file, out, threads, quiet, progress, false, false, restart, &written);
        std::error_code ec;  // a grid study left in the folder belonged to the results just replaced
        std::filesystem::remove_all(std::filesystem::path(out) / "grid_study", ec);
        const std::string design = (std::filesystem::path(out) / "design.json").string();
        verdict = dmi::design::check_main(written, limits_file, false, design, quiet, DMI_VERSION);
      }
      if (!no_pdf) dmi::render::report_main(out, {quantity, quiet, true, DMI_VERSION, threads == 1 ? 1 : 2});
      return verdict;
    }
    if (*ren) {
      if (helper_of > 0 || !claims.empty()) {  // the second picture process: whole files; it ends without tearing VTK down
        if (helper_of <= 0 || claims.empty()) throw dmi::InputError("render: --helper-of and --claims go together (internal options)");
        dmi::render::render_main(render_dir, {quantity, true, 1, helper_of, claims});
        std::fflush(nullptr);
        std::_Exit(0);
      }
      dmi::render::render_main(render_dir, {quantity, quiet, 2, 0, ""});
      return 0;
    }
    if (*rep) {
      dmi::render::report_main(report_dir, {quantity, quiet, !no_pdf, DMI_VERSION, 2});
      return 0;
    }
#endif
    if (*chk) return dmi::design::check_main(check_paths, limits_file, json, design_out, quiet, DMI_VERSION, true);
#ifdef DMI_LEAN
    if (*bch) return dmi::bench_main(bench_cases, json, quick, bo);
#else
    if (*bch) return bench_command(bench_cases, json, quick, bo, bench_out);
    if (*swp) {
      so.case_reports = !no_case_reports;
      so.pdf = !no_pdf;
      so.software_version = DMI_VERSION;
      return dmi::sweep::sweep_main(sweep_file, so);
    }
#endif
    if (*val) return dmi::validate_main(cases, json, list, threads, stress);
    if (*sch) {
      std::cout << dmi::scenario_reference_markdown();
      return 0;
    }
  } catch (const dmi::InputError& e) {
    std::fprintf(stderr, "damimpact: error: %s\n", e.what());
    return 2;
  } catch (const dmi::Interrupted& e) {
    std::fprintf(stderr, "damimpact: %s\n", e.what());
    return e.signal() == 0 ? 3 : 128 + e.signal();  // 3: stopped on request (--stop-after)
  } catch (const dmi::RunError& e) {
    std::fprintf(stderr, "damimpact: run failed: %s\n", e.what());
    return 2;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "damimpact: error: out of memory (the scenario's own estimate passed: other processes hold memory, or a "
                         "structure beyond the estimate; set DMI_MEMORY_LIMIT to what this run may use, or use larger cells)\n");
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "damimpact: error: %s\n", e.what());
    return 2;
  }
  return 0;
}
