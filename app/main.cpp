// damimpact command line: parses the arguments and hands each command to its layer (pipeline/ for simulate and run,
// design/ for check, render/ for render and report, sweep/, verify/). Exit 0 ok, 1 a validation case or a design check
// failed, 2 bad input or failed run, 3 stopped on request (--stop-after), 128 + signal when interrupted.
#include <CLI/CLI.hpp>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <new>
#include <sstream>

#include "design/design.hpp"
#ifndef DMI_LEAN
#include "pipeline/chain.hpp"
#include "render/bench_charts.hpp"
#include "render/render_main.hpp"
#include "render/picture_helper.hpp"
#include "render/report.hpp"
#endif
#include "engine/common/error.hpp"
#include "engine/scenario/scenario.hpp"
#include "engine/sim/run.hpp"
#include "pipeline/simulate.hpp"
#include "sweep/sweep_main.hpp"
#include "verify/bench.hpp"
#include "verify/validate.hpp"

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

#ifndef DMI_LEAN
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
  dmi::render::write_bench_charts(j, out);
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

// Every subcommand and the options the parser fills.
struct CommandLine {
  CLI::App app{"damimpact " DMI_VERSION " - check dams hit by boulders and debris flows: MPM simulation, design checks, reports"};
  CLI::App *run = nullptr, *sim = nullptr, *val = nullptr, *chk = nullptr, *ren = nullptr, *rep = nullptr, *bch = nullptr,
           *swp = nullptr, *sch = nullptr;
  dmi::pipeline::SimulateRequest simulate;  // run and simulate
  bool dry_run = false, expand = false, grid_study = false, no_pdf = false;
  double grid_ratio = std::sqrt(2.0);
  std::string limits_file, quantity = "von_mises";
  bool json = false, quiet = false;
  std::vector<std::string> cases;  // validate
  bool list = false, stress = false;
  int threads = 0;                        // validate
  std::vector<std::string> check_paths;   // check
  std::string design_out;
  std::string render_dir, claims, report_dir;  // render, report
  long helper_of = 0;  // the second picture process of a render, run or report (render/picture_helper.hpp)
  std::vector<std::string> bench_cases;  // bench
  bool quick = false;
  dmi::BenchOptions bench;
  std::string bench_out;
  std::string sweep_file;  // sweep
  dmi::sweep::SweepOptions sweep;
  bool no_case_reports = false;
  bool markdown = false;  // schema
};

void add_run_options(CommandLine& c, CLI::App* s) {
  dmi::pipeline::SimulateRequest& r = c.simulate;
  s->add_option("scenario", r.file, "scenario JSON file (docs/scenario.md)")->required();
  s->add_option("-o,--out", r.out, "output folder (results.h5, fields/)")->capture_default_str();
  s->add_option("-t,--threads", r.threads, "OpenMP threads (0 = all cores)")->capture_default_str()->check(whole_in(0, kMaxThreads));
  s->add_flag("-q,--quiet", r.quiet, "no progress output");
  s->add_option("--progress", r.progress, "progress display: auto | terminal | lines")->check(CLI::IsMember({"auto", "terminal", "lines"}));
  s->add_flag("--restart", r.restart.restart, "continue an interrupted run from OUT/checkpoint.dmi (bit for bit; same scenario file)");
  s->add_option("--checkpoint-every", r.restart.checkpoint_every, "wall seconds between checkpoints (0 = only when interrupted)")
      ->capture_default_str()->check(CLI::NonNegativeNumber);
  s->add_option("--stop-after", r.restart.stop_after, "stop after this many steps with a checkpoint (exit 3; continue with --restart)")
      ->check(whole_in(1, 1000000000000L));
}

// run, simulate, validate, check.
void add_analysis_commands(CommandLine& c) {
  c.run = c.app.add_subcommand("run", "simulate a scenario and write results (the whole chain)");
  add_run_options(c, c.run);
  c.sim = c.app.add_subcommand("simulate", "simulate a scenario: OUT/results.h5 and ParaView files OUT/fields/");
  add_run_options(c, c.sim);
  c.sim->add_flag("--dry-run", c.dry_run, "only read and validate the scenario (every variant of a comparison)");
  c.sim->add_flag("--expand", c.expand, "with --dry-run: print the low-level scenario the presets expand to (JSON; a runnable scenario file)");
  c.val = c.app.add_subcommand("validate", "run the verification cases against closed forms; exit 0 when all pass");
  c.val->add_option("cases", c.cases, "case names (default: all; see --list)");
  c.val->add_flag("--json", c.json, "print a JSON array of {case, metric, value, reference, error, tolerance, passed, wall_seconds}");
  c.val->add_flag("--list", c.list, "list the cases and exit");
  c.val->add_flag("--stress", c.stress, "run the stability stress suite instead (docs/reliability.md)");
  c.val->add_option("-t,--threads", c.threads, "OpenMP threads (0 = all cores)")->check(whole_in(0, kMaxThreads));
  c.chk = c.app.add_subcommand("check", "design checks of finished runs: envelopes, reactions, strength checks -> design.json; "
                                        "exit 0 all pass, 1 a check fails, 2 bad input");
  c.chk->add_option("results", c.check_paths, "results.h5 files or run folders (a comparison folder holds with_buffer/ and without_buffer/)")->required();
  c.chk->add_option("--limits", c.limits_file, "limits JSON (docs/design-checks.md): strengths, factors, member materials");
  c.chk->add_flag("--json", c.json, "print design.json to stdout instead of the summary");
  c.chk->add_option("-o,--out", c.design_out, "where to write design.json (default: beside the results)");
  c.chk->add_flag("-q,--quiet", c.quiet, "no summary");
  c.run->add_option("--limits", c.limits_file, "limits JSON for the design checks (docs/design-checks.md)");
}

// render, report, and the rest of run's options.
void add_picture_commands(CommandLine& c) {
  const auto quantity = [&c](CLI::App* s) {
    s->add_option("--quantity", c.quantity, "particle colouring: von_mises | sigma_xx | sigma_yy | pressure")
        ->check(CLI::IsMember({"von_mises", "sigma_xx", "sigma_yy", "pressure"}))->capture_default_str();
  };
  c.ren = c.app.add_subcommand("render", "stress-field pictures and charts of a finished run -> OUT/images/ (off-screen, no display needed)");
  c.ren->add_option("out", c.render_dir, "run folder (results.h5, or with_buffer/ and without_buffer/)")->required();
  quantity(c.ren);
  c.ren->add_flag("-q,--quiet", c.quiet, "no progress output");
  c.ren->add_option("--helper-of", c.helper_of, "internal: the second picture process of process PID (run, render and report start it)")
      ->check(CLI::PositiveNumber);
  c.ren->add_option("--claims", c.claims, "internal: with --helper-of, the folder of the pictures' claims")->check(CLI::ExistingDirectory);
  c.rep = c.app.add_subcommand("report", "pictures and the HTML + PDF design report of a finished run: OUT/report.html, OUT/report.pdf");
  c.rep->add_option("out", c.report_dir, "run folder (results.h5, or with_buffer/ and without_buffer/; design.json when checked)")->required();
  quantity(c.rep);
  c.rep->add_flag("--no-pdf", c.no_pdf, "HTML only");
  c.rep->add_flag("-q,--quiet", c.quiet, "no progress output");
  c.run->add_flag("--grid-study", c.grid_study,
                  "also run the scenario at r h and r^2 h and state the grid uncertainty (observed order, Richardson value, GCI) of "
                  "every governing number in design.json and the report");
  c.run->add_option("--grid-ratio", c.grid_ratio, "refinement ratio r of --grid-study (>= sqrt 2)")->capture_default_str();
  c.run->add_flag("--no-report", c.no_pdf, "skip the pictures and the report (simulation and checks only)");
}

// bench, sweep, schema.
void add_study_commands(CommandLine& c) {
  c.bch = c.app.add_subcommand("bench", "performance figures (printed, not asserted): kernel throughput; docs/performance.md");
  c.bch->add_option("cases", c.bench_cases, "cases (default: all): kernel | a5 (run time vs error) | a6 (cost vs depth) | bar | disks | skip | dam (the main job: run time vs error) | small (the demo per particle-step against the kernel)");
  c.bch->add_flag("--json", c.json, "print JSON instead of tables");
  c.bch->add_flag("--quick", c.quick, "small problems (100 k particles), for a smoke test");
  dmi::BenchOptions& bo = c.bench;
  bo.particles = 0, bo.shapes.clear(), bo.transfers.clear(), bo.threads.clear();
  c.bch->add_option("--particles", bo.particles, "particles of the kernel block (default 1 M; --quick 100 k)");
  c.bch->add_option("--shape", bo.shapes, "shape functions (default linear gimp bspline2)")->check(CLI::IsMember({"linear", "gimp", "bspline2"}));
  c.bch->add_option("--transfer", bo.transfers, "transfers (default flip apic)")->check(CLI::IsMember({"flip", "apic"}));
  c.bch->add_option("--threads", bo.threads, "thread counts (default 1 2)");
  c.bch->add_option("--dim", bo.dimension, "the kernel block's dimension: 2 (a square, the default) or 3 (a cube)")->check(CLI::IsMember({2, 3}));
  c.bch->add_option("-o,--out", c.bench_out, "also write DIR/bench.json and the Pareto charts DIR/pareto_<case>.png (VTK charts)");
  dmi::sweep::SweepOptions& so = c.sweep;
  so.out_dir = "out/sweep";
  c.swp = c.app.add_subcommand("sweep", "parametric study: every case of a sweep file (over MPI ranks under mpirun) -> "
                                        "OUT/cases/*, summary.csv/.json/.html/.pdf (docs/sweep.md)");
  c.swp->add_option("study", c.sweep_file, "sweep JSON file")->required();
  c.swp->add_option("-o,--out", so.out_dir, "output folder")->capture_default_str();
  c.swp->add_option("-t,--threads", so.threads, "OpenMP threads per case (per MPI rank; 0 = all cores)")->check(whole_in(0, kMaxThreads));
  c.swp->add_option("--limits", so.limits_file, "design limits file (docs/design-checks.md)");
  c.swp->add_flag("--no-case-reports", c.no_case_reports, "no HTML report per case (faster; the summary report is still written)");
  c.swp->add_flag("--no-pdf", c.no_pdf, "HTML only (no weasyprint)");
  c.swp->add_flag("-q,--quiet", so.quiet, "no progress output");
  c.sch = c.app.add_subcommand("schema", "print the scenario key reference (Markdown, as in docs/scenario.md)");
  c.sch->add_flag("--markdown", c.markdown, "Markdown tables (default)");
}

#ifndef DMI_LEAN
// The commands that draw: run's chain, render (or its second picture process), report.
int picture_command(CommandLine& c) {
  if (*c.run) {
    dmi::pipeline::ChainRequest r;
    r.simulate = c.simulate;
    r.limits_file = c.limits_file, r.report = !c.no_pdf, r.grid_study = c.grid_study, r.grid_ratio = c.grid_ratio, r.quantity = c.quantity;
    return dmi::pipeline::run_chain(r);
  }
  if (*c.ren) {
    if (c.helper_of > 0 || !c.claims.empty()) {  // the second picture process: whole files; it ends without tearing VTK down
      if (c.helper_of <= 0 || c.claims.empty()) throw dmi::InputError("render: --helper-of and --claims go together (internal options)");
      dmi::render::render_main(c.render_dir, {c.quantity, true, 1, c.helper_of, c.claims});
      std::fflush(nullptr);
      std::_Exit(0);
    }
    dmi::render::render_main(c.render_dir, {c.quantity, c.quiet, 2, 0, ""});
    return 0;
  }
  dmi::render::report_main(c.report_dir, {c.quantity, c.quiet, !c.no_pdf, DMI_VERSION, 2});
  return 0;
}
#endif

int dispatch(CommandLine& c, char** argv) {
  for (const auto& [cmd, folder] : {std::pair{c.sim, &c.simulate.out}, std::pair{c.run, &c.simulate.out}, std::pair{c.swp, &c.sweep.out_dir}})
    if (*cmd && folder->empty()) throw dmi::InputError("-o/--out = \"\": expected an output folder");
  if (*c.sim) {
    if (c.dry_run || c.expand) return dry_run_report(c.simulate.file, dmi::load_scenario_variants(c.simulate.file), c.expand);
    dmi::pipeline::simulate(c.simulate);
    return 0;
  }
#ifdef DMI_LEAN
  if (*c.run || *c.ren || *c.rep || *c.swp || (*c.bch && !c.bench_out.empty())) return hand_over(argv);
  if (*c.bch) return dmi::bench_main(c.bench_cases, c.json, c.quick, c.bench);
#else
  (void)argv;
  dmi::render::set_picture_program(own_file().string());  // the second picture process runs this program
  if (*c.run || *c.ren || *c.rep) return picture_command(c);
  if (*c.bch) return bench_command(c.bench_cases, c.json, c.quick, c.bench, c.bench_out);
  if (*c.swp) {
    c.sweep.case_reports = !c.no_case_reports;
    c.sweep.pdf = !c.no_pdf;
    c.sweep.software_version = DMI_VERSION;
    return dmi::sweep::sweep_main(c.sweep_file, c.sweep);
  }
#endif
  if (*c.chk) return dmi::design::check_main(c.check_paths, c.limits_file, c.json, c.design_out, c.quiet, DMI_VERSION, true);
  if (*c.val) return dmi::validate_main(c.cases, c.json, c.list, c.threads, c.stress);
  if (*c.sch) std::cout << dmi::scenario_reference_markdown();
  return 0;
}

}  // namespace

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
  CommandLine c;
  c.app.set_version_flag("--version", DMI_VERSION);
  c.app.require_subcommand(1);
  c.simulate.out = "out";
  c.simulate.software_version = DMI_VERSION;
  add_analysis_commands(c);
  add_picture_commands(c);
  add_study_commands(c);
  try {
    c.app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return c.app.exit(e);  // --help, --version
    // One line on stderr, like every other input error.
    std::fprintf(stderr, "damimpact: error: %s (run with --help for the options)\n", e.what());
    return 2;
  }
  try {
    return dispatch(c, argv);
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
