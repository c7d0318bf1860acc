#include "sweep/case_runner.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "design/design.hpp"
#include "design/grid_study.hpp"
#include "design/grid_study_record.hpp"
#include "design/verdict.hpp"
#include "design/loads.hpp"
#include "engine/common/error.hpp"
#include "engine/io/results_writer.hpp"
#include "engine/scenario/identity.hpp"
#include "engine/scenario/scenario.hpp"
#include "engine/sim/run.hpp"
#include "pipeline/run_folder.hpp"
#include "render/report.hpp"

namespace dmi::sweep {
namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return in ? ss.str() : std::string();
}

// The design's figures for the summary: per variant, the largest utilisation and the peaks engineers size with.
void fill_from_design(SweepRow& row, const design::DesignDocument& design) {
  const design::Verdict& v = design.verdict;
  row.verdict = v.status;
  row.max_utilisation = v.governing ? std::optional<double>(v.governing->utilisation) : std::nullopt;
  if (v.governing) row.governing = Governing{v.governing->id, v.governing->member, v.governing_variant};
  else row.governing.reset();
  row.variants.clear();
  for (const design::RunDesign& r : design.runs) {
    const design::Verdict& rv = r.verdict;
    row.variants[r.variant.empty() ? "run" : r.variant] = {
        rv.governing ? std::optional<double>(rv.governing->utilisation) : std::nullopt, rv.passed,
        r.contact.present ? std::optional<double>(r.contact.peak_N) : std::nullopt, r.base_abs_max(design::shear_key(r.dim())),
        r.base_abs_max(design::moment_key(r.dim()))};
  }
}

// Hard links (copies where links fail) of every file under from into to, directories created.
void link_tree(const fs::path& from, const fs::path& to) {
  for (const auto& e : fs::recursive_directory_iterator(from)) {
    const fs::path target = to / fs::relative(e.path(), from);
    if (e.is_directory()) {
      fs::create_directories(target);
      continue;
    }
    fs::create_directories(target.parent_path());
    fs::remove(target);
    std::error_code ec;
    fs::create_hard_link(e.path(), target, ec);
    if (ec) fs::copy_file(e.path(), target, fs::copy_options::overwrite_existing);
  }
}

// Simulates every variant into dir (dir/<label>/ for labelled ones); adds their run wall times to sim_wall and
// returns the results files. Variants of one identity (engine/scenario/identity.hpp) are simulated once per sweep:
// the first run is kept under OUT/runs/<identity>/ and later cases link its files (the without-buffer run of every
// buffer thickness at one boulder speed).
std::vector<std::string> run_variants(const std::vector<ScenarioVariant>& variants, const fs::path& dir, const SweepOptions& o,
                                      double& sim_wall) {
  std::vector<std::string> written;
  for (const auto& v : variants) {
    const fs::path vd = v.label.empty() ? dir : dir / v.label;
    const fs::path shared = fs::path(o.out_dir) / "runs" / scenario_identity(v.scenario).substr(0, 20);
    if (pipeline::run_state(shared) == pipeline::RunState::complete) {
      fs::remove_all(vd);
      link_tree(shared, vd);
      sim_wall += read_results((vd / "results.h5").string(), false).info.stats.wall_seconds.value();
      written.push_back((vd / "results.h5").string());
      continue;
    }
    RunOptions ro;
    ro.out_dir = vd.string();
    ro.threads = o.threads;
    ro.progress = ProgressMode::quiet;
    ro.software_version = o.software_version;
    const RunOutput r = run_scenario(v.scenario, ro);
    sim_wall += r.results.info.stats.wall_seconds.value();
    written.push_back(r.results_path);
    // Kept for the other cases: linked into a fresh folder, which is then renamed into place (another rank that
    // simulated the same run first keeps its own; both are the same run).
    const fs::path tmp = shared.string() + ".tmp" + std::to_string(std::hash<std::string>{}(vd.string()));
    fs::remove_all(tmp);
    link_tree(vd, tmp);
    std::error_code ec;
    fs::rename(tmp, shared, ec);
    if (ec) fs::remove_all(tmp);
  }
  return written;
}

}  // namespace

SweepRow run_case(const SweepSpec& spec, std::size_t k, const SweepOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  const fs::path dir = fs::path(o.out_dir) / "cases" / case_id(k);
  SweepRow row;
  row.case_name = case_id(k), row.index = k + 1;
  for (std::size_t p = 0; p < spec.parameters.size(); ++p) row.parameters[spec.parameters[p]] = spec.cases[k][p];
  try {
    fs::create_directories(dir);
    const std::string text = case_scenario(spec, k).dump(1) + "\n";
    const fs::path scen = dir / "scenario.json";
    if (read_text(scen) != text) render::write_text_atomic(scen.string(), text);
    const auto variants = parse_scenario_variants(text, scen.string());
    double sim_wall = 0;
    if (spec.grid_ratio > 0) {  // the case at three cell sizes: grid uncertainty of its governing numbers
      const double h = common_cell_size(variants, scen.string());
      const auto level_run = [&](const std::string& file, const std::string& d, int) {
        return run_variants(parse_scenario_variants(read_text(file), file), d, o, sim_wall);
      };
      const design::GridStudyOutcome g = design::run_grid_study(scen.string(), json::parse(text), h, spec.grid_ratio, dir.string(),
                                                                o.limits_file, level_run, true, o.software_version);
      row.simulated_seconds = sim_wall;
      fill_from_design(row, g.design);
      double bound = 0;
      if (g.design.grid_study && g.design.grid_study->verdict)
        for (const auto& r : g.design.grid_study->verdict->runs) bound = std::max(bound, r.utilisation_bound);
      row.utilisation_bound = bound;
      row.grid_study_passed = g.passed;
      if (o.case_reports) row.report = fs::relative(render::report_main(dir.string(), {"von_mises", true, o.pdf, o.software_version}).html, o.out_dir).string();
      row.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      return row;
    }
    std::vector<std::string> written;
    bool reused = true;
    for (const auto& v : variants) {
      const fs::path vd = v.label.empty() ? dir : dir / v.label;
      reused = reused && pipeline::holds_run_of(vd, v.scenario);
      written.push_back((vd / "results.h5").string());
    }
    if (reused) {  // resumable: a finished case is kept (its scenario unchanged)
      for (const auto& w : written) sim_wall += read_results(w, false).info.stats.wall_seconds.value();
      row.status = "reused";
    } else {
      run_variants(variants, dir, o, sim_wall);
    }
    row.simulated_seconds = sim_wall;
    design::check_main(written, o.limits_file, false, (dir / "design.json").string(), true, o.software_version);
    fill_from_design(row, design::read_design_json((dir / "design.json").string()));
    if (o.case_reports && (!reused || !fs::exists(dir / "report.html"))) {
      const auto rf = render::report_main(dir.string(), {"von_mises", true, o.pdf, o.software_version});
      row.report = fs::relative(rf.html, o.out_dir).string();
    } else if (fs::exists(dir / "report.html")) {
      row.report = fs::relative(dir / "report.html", o.out_dir).string();
    }
  } catch (const Interrupted&) {
    throw;
  } catch (const std::exception& e) {
    row.status = "failed";
    row.error = e.what();
  }
  row.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return row;
}

}  // namespace dmi::sweep
