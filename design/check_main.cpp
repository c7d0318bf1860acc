// `damimpact check`: results.h5 -> design.json and a readable summary.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <utility>
#include <vector>
#include <stdexcept>
#include <unistd.h>

#include "core/variants.hpp"
#include "design/design.hpp"
#include "design/plastic_record.hpp"
#include "design/verdict.hpp"
#include "design/estimates.hpp"
#include "design/grid_study.hpp"
#include "design/health_record.hpp"
#include "engine/common/error.hpp"
#include "engine/io/results_writer.hpp"

namespace dmi::design {

using nlohmann::json;
namespace fs = std::filesystem;

namespace {

// Value in engineering units: Pa -> MPa, N -> kN, N m -> kN m, N s -> kN s, s -> ms.
std::string eng(double v, const std::string& unit) {
  char b[64];
  if (unit == "Pa") std::snprintf(b, sizeof b, "%.3g MPa", v / 1e6);
  else if (unit == "N") std::snprintf(b, sizeof b, "%.4g kN", v / 1e3);
  else if (unit == "N m") std::snprintf(b, sizeof b, "%.4g kN m", v / 1e3);
  else if (unit == "N s") std::snprintf(b, sizeof b, "%.4g kN s", v / 1e3);
  else if (unit == "s") std::snprintf(b, sizeof b, "%.4g ms", v * 1e3);
  else if (unit == "m" && std::abs(v) < 0.1) std::snprintf(b, sizeof b, "%.3g mm", v * 1e3);
  else if (!unit.empty() && unit != "-") std::snprintf(b, sizeof b, "%.3g %s", v, unit.c_str());
  else std::snprintf(b, sizeof b, "%.3g", v);
  return b;
}

std::string where_when(const Check& c) {
  std::ostringstream o;
  if (c.s_m >= 0) o << "s = " << eng(c.s_m, "") << " m";
  else if (c.member.empty() || c.member.rfind("solid", 0) == 0)
    o << "(" << eng(c.x_m, "") << ", " << eng(c.y_m, "") << (c.space ? ", " + eng(c.z_m, "") : std::string()) << ") m";
  if (c.time_s >= 0) o << (o.tellp() > 0 ? ", " : "") << "t = " << eng(c.time_s, "s");
  return o.str();
}

void run_summary(std::ostringstream& o, const RunDesign& r) {
  char line[512];
  o << "\n" << (r.variant.empty() ? "" : "[" + r.variant + "] ") << r.results_file << "  (" << r.scenario_name << ")\n";
  if (r.base_total) {
    const ReactionPeaks& b = r.base_total->peaks;
    if (r.dim() == 3)  // z up: the horizontal shear and overturning moment, and the vertical force
      o << "  base: |H| " << eng(b.at("H_N").abs.value, "N") << ", |M_overturning| " << eng(b.at("M_overturning_Nm").abs.value, "N m")
        << ", Fz " << eng(b.at("Fz_N").min.value, "N") << " .. " << eng(b.at("Fz_N").max.value, "N") << "\n";
    else
      o << "  base: |Fx| " << eng(b.at("Fx_N").abs.value, "N") << ", |M| " << eng(b.at("M_Nm").abs.value, "N m") << ", Fy "
        << eng(b.at("Fy_N").min.value, "N") << " .. " << eng(b.at("Fy_N").max.value, "N") << "\n";
  }
  if (r.contact.present && r.contact.peak_N > 0) {
    const Contact& c = r.contact;
    o << "  contact: peak " << eng(c.peak_N, "N") << " at " << eng(c.peak_time_s, "s") << ", impulse " << eng(c.impulse_magnitude(), "N s") << ", pulse "
      << eng(c.pulse_end_s - c.pulse_start_s, "s") << "\n";
  }
  for (const Estimate& e : r.estimates) {
    if (e.applicable)
      std::snprintf(line, sizeof line, "  estimate %-41s %12s  (simulated %s: ratio %.2f)\n", e.title.c_str(), eng(e.value, "N").c_str(),
                    eng(e.simulated, "N").c_str(), e.ratio);
    else
      std::snprintf(line, sizeof line, "  estimate %-41s %12s  (%s)\n", e.title.c_str(), "n/a", e.note.c_str());
    o << line;
  }
  for (const VolumeHealthRecord& v : r.volume_health)
    if (v.flagged)
      o << "  warning: body probe '" << v.probe << "' fills " << eng(100 * (v.largest_ratio - 1), "") << " % more than its particles did when created (at "
        << eng(v.largest_time_s, "s") << "): a non-dilatant body should keep its volume; its loads are suspect (docs/design-checks.md, numerical health)\n";
  if (r.checks.empty()) {
    o << "  no checks (no members and no solid check in this run)\n";
    return;
  }
  std::snprintf(line, sizeof line, "  %-50s %-12s %-5s %13s %13s %6s %-5s %s\n", "check", "member", "level", "demand", "capacity", "util", "",
                "where / when");
  o << line;
  for (const Check& c : r.checks) {
    const std::string& u = c.unit;
    std::string title = c.title, member = c.member;
    if (member.rfind("solid: ", 0) == 0) {  // the solid-FE load case in brackets, without the common prefix
      std::string load = member.substr(7);
      if (load.rfind("simulated contact, ", 0) == 0) load = load.substr(19);
      title += " [" + load + "]", member = "solid FE";
    }
    if (title.size() > 50) title = title.substr(0, 47) + "...";
    if (member.size() > 12) member = member.substr(0, 11) + ".";
    const std::string& level = c.level;
    const bool info = level == "information";
    std::snprintf(line, sizeof line, "  %-50s %-12s %-5s %13s %13s %6.2f %-5s %s\n", title.c_str(), member.c_str(),
                  level == "ultimate" ? "ULS" : level == "serviceability" ? "SLS" : "info", eng(c.demand, u).c_str(), eng(c.capacity, u).c_str(),
                  c.utilisation, info ? "" : c.passed ? "ok" : "FAIL", where_when(c).c_str());
    o << line;
  }
}

}  // namespace

// The verdict lines: the runs judged, pass or fail, the governing check, each level's verdict (also under -q).
std::string verdict_text(const DesignDocument& d) {
  std::ostringstream o;
  const Verdict& v = d.verdict;
  o << "verdict (" << v.runs_judged << "): ";
  if (v.status == "no_checks") o << "NO CHECKS (nothing to check in these results)\n";
  else {
    const Check& g = *v.governing;
    o << (v.passed ? "PASS" : "FAIL") << ", " << v.failed << " of " << v.checks << " checks failed";
    o << "; governing: " << g.title << (g.member.empty() ? "" : ", " + g.member) << ", utilisation " << eng(g.utilisation, "") << " ("
      << where_when(g) << ")\n";
  }
  for (const auto& [group, name] : std::vector<std::pair<const std::map<std::string, LevelVerdict>*, const char*>>{
           {&v.levels, "serviceability"}, {&v.levels, "ultimate"}, {&v.situations, "persistent"}, {&v.situations, "accidental"}}) {
    const auto l = group->find(name);
    if (l == group->end() || l->second.checks == 0) continue;
    o << "  " << name << (group == &v.situations ? " situation" : "") << ": " << (l->second.passed ? "pass" : "fail") << ", " << l->second.failed
      << " of " << l->second.checks << " failed, largest utilisation " << eng(l->second.max_utilisation(), "") << " (" << l->second.governing->title
      << ")\n";
  }
  o << "  the verdict judges: " << v.judged_levels << " (limits file: verdict.level)\n";
  // The member model the verdict rests on (elastic members cannot yield; plastic ones are judged by strain and drift).
  for (const RunDesign& r : d.runs)
    if (r.plastic) {
      o << "  members: " << r.plastic->member_model << ", f_y " << eng(r.steel_yield_strength_Pa, "Pa") << " ("
        << (r.variant.empty() ? std::string("the run") : r.variant) << ")\n";
      break;
    }
  return o.str();
}

std::string summary_text(const DesignDocument& d) {
  std::ostringstream o;
  for (const RunDesign& r : d.runs) run_summary(o, r);
  if (const auto& ps = d.plane_and_space) {
    char line[256];
    o << "\nplane model against its 3D model (compare_3d)\n";
    for (const auto& pair : ps->pairs) {
      const std::string& v = pair.variant;
      std::snprintf(line, sizeof line, "  [%s] %-44s %14s %14s %8s\n", v.empty() ? "scenario" : v.c_str(), "quantity", "plane (2D)", "3D", "2D / 3D");
      o << line;
      for (const auto& q : pair.quantities) {
        std::snprintf(line, sizeof line, "  %-*s %-44s %14s %14s %8s\n", static_cast<int>(v.empty() ? 10 : v.size() + 2), "", q.title.c_str(),
                      eng(q.plane, q.unit).c_str(), eng(q.space, q.unit).c_str(), q.ratio ? eng(*q.ratio, "").c_str() : "-");
        o << line;
      }
    }
  }
  if (const auto& comparison = d.comparison) {
    char line[256];
    o << "\nwith vs without buffer\n";
    std::snprintf(line, sizeof line, "  %-60s %14s %14s %10s\n", "peak", "with buffer", "without", "reduction");
    o << line;
    for (const auto& q : comparison->quantities) {
      const std::string& u = q.unit;
      std::string title = q.title;
      if (title.size() > 60) title = title.substr(0, 57) + "...";
      const double red = q.reduction_percent.value_or(0.0);
      char reduction[32];  // more than doubled (the buffer lengthens the pulse): the factor, not a percentage of thousands
      if (red < -100) std::snprintf(reduction, sizeof reduction, "x%.3g larger", 1 - red / 100);
      else std::snprintf(reduction, sizeof reduction, "%9.0f %%", red);
      std::snprintf(line, sizeof line, "  %-60s %14s %14s %11s\n", title.c_str(), eng(q.with_buffer, u).c_str(), eng(q.without_buffer, u).c_str(),
                    reduction);
      o << line;
    }
  }
  o << "\n" << verdict_text(d);
  return o.str();
}

namespace {

std::vector<std::string> resolve(const std::string& p) {
  std::error_code ec;
  if (fs::is_directory(p, ec)) {
    const fs::path d(p);
    std::vector<std::string> files;
    for (const auto& [variant, f] : variant_results(d)) files.push_back(f.string());
    if (!files.empty()) return files;
    if (fs::exists(d / "results.h5.partial")) throw InputError(p + ": holds only results.h5.partial: the run did not finish; nothing to check");
    throw InputError(p + ": no results.h5 in this folder (nor with_buffer/ and without_buffer/ holding one)");
  }
  if (!fs::exists(p, ec)) throw InputError(p + ": no such results file");
  return {p};
}

}  // namespace

void write_design_json(const std::string& path, const DesignDocument& doc) {
  const fs::path target = path, tmp = path + "." + std::to_string(::getpid()) + ".tmp";
  const std::string text = to_json(doc).dump(1) + "\n";  // before the file exists: a failure leaves nothing behind
  {
    std::ofstream o(tmp);
    if (!o) throw InputError(target.string() + ": cannot write design.json here");
    o << text;
    o.flush();
    if (!o) {
      std::error_code ec;
      fs::remove(tmp, ec);
      throw InputError(target.string() + ": writing design.json failed");
    }
  }
  fs::rename(tmp, target);
}

DesignDocument check_document(const std::vector<std::string>& paths, const std::string& limits_file, const std::string& version) {
  const Limits limits = limits_file.empty() ? Limits{} : read_limits(limits_file);
  std::vector<std::string> files;
  for (const auto& p : paths)
    for (const auto& f : resolve(p)) files.push_back(f);
  std::vector<RunDesign> runs;
  for (const auto& f : files) {
    Results r;
    try {
      r = read_results(f, false);
    } catch (const std::exception& e) {
      throw InputError(e.what());
    }
    try {
      runs.push_back(design_run(r, limits, f));
    } catch (const std::runtime_error& e) {  // design/ names the file itself
      throw InputError(e.what());
    } catch (const std::exception& e) {
      throw InputError(f + ": " + e.what());
    }
  }
  return design_document(std::move(runs), limits, version);
}

int check_main(const std::vector<std::string>& paths, const std::string& limits_file, bool print_json, const std::string& out, bool quiet,
               const std::string& version, bool with_grid_study) {
  DesignDocument doc = check_document(paths, limits_file, version);
  // Beside the results (a comparison folder: in the folder), atomically.
  fs::path target = out;
  if (target.empty()) {
    std::error_code ec;
    target = fs::is_directory(paths.front(), ec) ? fs::path(paths.front()) / "design.json" : fs::path(paths.front()).parent_path() / "design.json";
  }
  // A grid study's folder keeps its study: the coarser levels are judged again with the same limits.
  if (with_grid_study) restudy_grid(doc, target.parent_path().string(), limits_file, version);
  write_design_json(target.string(), doc);
  if (print_json) std::cout << to_json(doc).dump(1) << "\n";
  else if (!quiet) std::cout << summary_text(doc) << "wrote " << target.string() << "\n";
  else std::cout << verdict_text(doc);
  return doc.verdict.passed ? 0 : 1;
}

}  // namespace dmi::design
