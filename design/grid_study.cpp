#include "design/grid_study.hpp"
#include "design/grid_study_record.hpp"
#include "design/design_document.hpp"
#include "design/verdict.hpp"
#include "core/variants.hpp"
#include "engine/io/results_writer.hpp"
#include "design/loads.hpp"

#include "engine/convergence/grid_convergence.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <thread>

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include "design/design.hpp"
#include "design/estimates.hpp"
#include "design/limits.hpp"

namespace dmi::design {

using nlohmann::json;

namespace {

const Check* find_check(const RunDesign& run, const std::string& id, const std::string& member) {
  for (const Check& c : run.checks)
    if (c.id == id && c.member == member) return &c;
  return nullptr;
}

double finite(double v, const std::string& what, const std::string& folder) {
  if (!std::isfinite(v)) throw std::runtime_error("grid study: " + folder + "/design.json: " + what + " is not finite");
  return v;
}

// A governing number of a run, none where the run has no such quantity.
using Reading = std::function<std::optional<double>(const RunDesign&)>;

GridQuantity quantity(const std::string& variant, const std::string& id, const std::string& title, const std::string& unit,
                      const std::array<double, 3>& h, const std::array<double, 3>& f) {
  const GridConvergence c = grid_convergence(h, f);
  auto num = [](double v) { return std::isfinite(v) ? std::optional<double>(v) : std::nullopt; };
  GridQuantity q;
  q.variant = variant, q.id = id, q.title = title, q.unit = unit, q.values = f;
  q.observed_order = num(c.order), q.extrapolated = num(c.extrapolated), q.asymptotic_ratio = num(c.asymptotic_ratio);
  q.gci = c.gci, q.safety_factor = c.safety_factor, q.conservative_magnitude = std::abs(f[0]) * (1 + c.gci);
  q.behaviour = behaviour_name(c.behaviour), q.statement = describe(c), q.converged = c.converged();
  return q;
}

}  // namespace

GridStudyRecord grid_study_section(const std::array<DesignDocument, 3>& designs, const std::array<double, 3>& h,
                                   const std::array<std::string, 3>& folders) {
  std::vector<GridQuantity> qs;
  for (const RunDesign& run : designs[0].runs) {
    const std::string& variant = run.variant;
    std::array<const RunDesign*, 3> runs{};
    for (int g = 0; g < 3; ++g) {
      for (const RunDesign& r : designs[g].runs)
        if (r.variant == variant) runs[g] = &r;
      if (!runs[g]) throw std::runtime_error("grid study: " + folders[g] + "/design.json has no run '" + variant + "'");
    }
    auto add = [&](const std::string& id, const std::string& title, const std::string& unit, const Reading& read) {
      // Not in this kind of run (no frame, no contact), or none on one grid (a surge whose static tail that grid's run
      // does not reach): left out of the study.
      std::array<std::optional<double>, 3> v;
      for (int g = 0; g < 3; ++g)
        if (!(v[g] = read(*runs[g]))) return;
      std::array<double, 3> f{};
      for (int g = 0; g < 3; ++g) f[g] = std::abs(finite(*v[g], title + " of run '" + variant + "'", folders[g]));
      qs.push_back(quantity(variant, id, title, unit, h, f));
    };
    const int dim = run.dim();
    const auto face = [](double FaceProfileAtMoment::*q) {
      return [q](const RunDesign& r) { return r.face_profile ? std::optional<double>((*r.face_profile).*q) : std::nullopt; };
    };
    const auto debris = [](auto get) {
      return [get](const RunDesign& r) { return r.debris_phases ? get(r.debris_phases->phases) : std::optional<double>(); };
    };
    add("contact_force", "peak contact force", "N", [](const RunDesign& r) { return r.contact.present ? std::optional<double>(r.contact.peak_N) : std::nullopt; });
    add("base_shear", dim == 3 ? "peak base shear |(sum Fx, sum Fy)|" : "peak base shear |sum Fx|", "N",
        [dim](const RunDesign& r) { return r.base_abs_max(shear_key(dim)); });
    add("base_moment", dim == 3 ? "peak overturning moment |(sum Mx, sum My)|" : "peak base moment |sum M|", "N m",
        [dim](const RunDesign& r) { return r.base_abs_max(moment_key(dim)); });
    add("face_resultant", "face pressure resultant at its largest moment about the foot", "N", face(&FaceProfileAtMoment::resultant_N));
    add("face_height", "height of that resultant above the foot", "m", face(&FaceProfileAtMoment::height_m));
    add("debris_peak", "debris load: peak over the surge's passage", "N", debris([](const DebrisPhases& p) { return std::optional<double>(p.peak_N); }));
    add("debris_dynamic", "debris load: dynamic (the surge's body)", "N", debris([](const DebrisPhases& p) { return std::optional<double>(p.dynamic_N); }));
    add("debris_static", "debris load: static tail (the deposit)", "N", debris([](const DebrisPhases& p) { return p.static_N; }));
    if (run.verdict.governing) {
      const Check& gov = *run.verdict.governing;
      const std::string& id = gov.id, member = gov.member;
      std::array<double, 3> demand{}, util{};
      for (int g = 0; g < 3; ++g) {
        const Check* c = find_check(*runs[g], id, member);
        if (!c) throw std::runtime_error("grid study: " + folders[g] + "/design.json has no check '" + id + "' on '" + member + "' (run '" + variant + "')");
        demand[g] = std::abs(finite(c->demand, "demand of " + id, folders[g]));
        // The governing utilisation of each grid: its verdict's, whichever check governs there (information checks and
        // levels the limits do not judge left out).
        util[g] = finite(runs[g]->verdict.max_utilisation(), "governing utilisation", folders[g]);
      }
      qs.push_back(quantity(variant, "governing_demand", gov.title + " (" + member + ")", gov.unit, h, demand));
      qs.push_back(quantity(variant, "governing_utilisation", "governing utilisation", "-", h, util));
    }
  }
  GridStudyRecord out;
  out.method = "Roache 1994 grid convergence index, Celik et al. 2008 procedure (ASME V&V 20-2009); Fs 1.25, 3 outside the asymptotic "
               "range; order at most the method's, 2 (Oberkampf & Roy 2010)";
  out.cell_sizes_m = h, out.refinement_ratios = {h[1] / h[0], h[2] / h[1]}, out.folders = folders, out.quantities = qs;
  for (const auto& q : qs) out.not_converged += q.converged ? 0 : 1;
  return out;
}

void add_grid_uncertainty(DesignDocument& design) {
  if (!design.grid_study) return;
  for (RunDesign& run : design.runs)
    for (Estimate& e : run.estimates) {
      if (!e.applicable) continue;
      const std::string id = e.compare_to == "peak_base_shear" ? "base_shear" : "contact_force";
      for (const GridQuantity& q : design.grid_study->quantities) {
        if (q.variant != run.variant || q.id != id) continue;
        const double gci = q.gci, sim = e.simulated, val = e.value;
        if (!(sim > 0) || !std::isfinite(gci)) continue;
        e.grid = true, e.simulated_gci = gci;
        e.simulated_extrapolated = q.extrapolated;
        e.ratio_low = val / (sim * (1 + gci));
        e.ratio_high = gci < 1 ? std::optional<double>(val / (sim * (1 - gci))) : std::nullopt;
      }
    }
}

bool judge_grid_study(DesignDocument& design, const std::string& judge_on) {
  if (!design.grid_study) throw std::runtime_error("design.json has no grid study to judge");
  GridStudyRecord& gs = *design.grid_study;
  Verdict& v = design.verdict;
  const std::string judged = v.runs_judged;
  GridStudyRecord::Judged out{judge_on, {}, true};
  for (const GridQuantity& q : gs.quantities) {
    if (q.id != "governing_utilisation") continue;
    const std::string& var = q.variant;
    if (!judged.empty() && !var.empty() && judged.find(var) == std::string::npos) continue;  // a reference run
    const double u = q.values[0], gci = q.gci, bound = u * (1 + gci);
    out.runs.push_back({var, u, gci, bound, bound <= 1.0, q.converged});
    out.bound_passed = out.bound_passed && bound <= 1.0;
  }
  const bool bound_ok = out.bound_passed;
  gs.verdict = out;
  if (judge_on == "conservative_bound" && v.passed && !bound_ok) {
    v.passed = false;
    v.status = "fail";
    v.note = "passes on the finest grid but not on the conservative bound u (1 + GCI) of the grid study (limits: grid_study.judge_on)";
  }
  return v.passed;
}

GridStudyOutcome run_grid_study(const std::string& file, const nlohmann::json& source, double h, double ratio, const std::string& out,
                                const std::string& limits_file, const LevelSimulator& simulate, bool quiet,
                                const std::string& software_version, const std::function<void(int, double, double)>& on_level, bool overlap) {
  namespace fs = std::filesystem;
  GridStudyOutcome r;
  r.h = {h, h * ratio, h * ratio * ratio};
  std::array<std::string, 3> folders;
  std::array<DesignDocument, 3> designs;
  const auto t_start = std::chrono::steady_clock::now();
  auto level = [&](int g) {
    const auto t0 = overlap ? t_start : std::chrono::steady_clock::now();  // overlapping: seconds since the study began
    char name[64];
    std::snprintf(name, sizeof name, "h_%.6g", r.h[g]);
    const std::string dir = g == 0 ? out : (fs::path(out) / "grid_study" / name).string();
    fs::create_directories(dir);
    std::string scen = file;
    if (g > 0) {
      nlohmann::json j = source;
      j["grid"]["cell_size"] = r.h[g];
      scen = (fs::path(dir) / "scenario.json").string();
      std::ofstream(scen) << j.dump(1) << "\n";
    }
    const std::vector<std::string> written = simulate(scen, dir, g);
    const std::string design = (fs::path(dir) / "design.json").string();
    if (g == 0) {  // the finest level prints its checks (the coarser ones only feed the study)
      check_main(written, limits_file, false, design, quiet, software_version);
      designs[g] = read_design_json(design);
    } else {
      designs[g] = check_document(written, limits_file, software_version);
      write_design_json(design, designs[g]);
    }
    folders[g] = dir;
    r.wall[g] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (on_level) on_level(g, r.h[g], r.wall[g]);
  };
  if (!overlap) {
    for (int g = 2; g >= 0; --g) level(g);
  } else {
    // Each coarser level in its own thread: one level's two variants end at different times, and the other level's
    // runs fill the core that leaves.
    std::array<std::exception_ptr, 3> error;
    std::array<std::thread, 3> coarse;
    struct Join {  // also when the finest level (or starting a thread) throws: the coarser levels end first
      std::array<std::thread, 3>& t;
      void all() {
        for (auto& x : t)
          if (x.joinable()) x.join();
      }
      ~Join() { all(); }
    } join{coarse};
    for (int g = 1; g <= 2; ++g)
      coarse[g] = std::thread([&, g] {
        ::setpriority(PRIO_PROCESS, static_cast<id_t>(::syscall(SYS_gettid)), 19);  // this thread and those it starts
        try {
          level(g);
        } catch (...) {
          error[g] = std::current_exception();
        }
      });
    level(0);
    join.all();  // before their errors are read
    for (int g = 2; g >= 1; --g)
      if (error[g]) {  // the finest level's checks alone are not the study asked for (levels in turn leave none)
        std::error_code ec;
        fs::remove(fs::path(out) / "design.json", ec);
        std::rethrow_exception(error[g]);
      }
  }
  r.design = designs[0];
  r.passed = attach_grid_study(r.design, designs, r.h, folders, limits_file);
  write_design_json((fs::path(out) / "design.json").string(), r.design);
  return r;
}

bool attach_grid_study(DesignDocument& design, const std::array<DesignDocument, 3>& designs, const std::array<double, 3>& h,
                       const std::array<std::string, 3>& folders, const std::string& limits_file) {
  design.grid_study = grid_study_section(designs, h, folders);
  add_grid_uncertainty(design);
  const Limits limits = limits_file.empty() ? Limits{} : read_limits(limits_file);
  return judge_grid_study(design, limits.grid_judge_on);
}

bool restudy_grid(DesignDocument& design, const std::string& out, const std::string& limits_file, const std::string& software_version) {
  namespace fs = std::filesystem;
  const fs::path root = fs::path(out) / "grid_study";
  std::error_code ec;
  if (!fs::is_directory(root, ec)) return false;
  std::vector<std::pair<double, std::string>> levels;  // (h, folder) of the coarser levels
  for (const auto& e : fs::directory_iterator(root, ec)) {
    const std::string name = e.path().filename().string();
    char* end = nullptr;
    const double h = name.rfind("h_", 0) == 0 ? std::strtod(name.c_str() + 2, &end) : 0.0;
    if (e.is_directory() && h > 0 && end && *end == '\0') levels.emplace_back(h, e.path().string());
  }
  if (levels.size() != 2) return false;
  std::sort(levels.begin(), levels.end());
  std::array<DesignDocument, 3> designs{design, {}, {}};
  std::array<std::string, 3> folders{out, levels[0].second, levels[1].second};
  // Each level's cell as its run recorded it (the folder names round it to 6 digits).
  std::array<double, 3> h{};
  for (int g = 0; g < 3; ++g) {
    const auto files = variant_results(folders[g]);
    if (files.empty()) return false;
    const Results r = read_results(files.front().second.string(), false);
    const std::optional<double>& cell = r.info.stats.cell_size;
    if (!cell || !(*cell > 0)) return false;
    h[g] = *cell;
  }
  for (int g = 1; g <= 2; ++g) {
    designs[g] = check_document({folders[g]}, limits_file, software_version);
    write_design_json((fs::path(folders[g]) / "design.json").string(), designs[g]);
  }
  return attach_grid_study(design, designs, h, folders, limits_file);
}

}  // namespace dmi::design
