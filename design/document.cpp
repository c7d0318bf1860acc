// design.json as a whole: runs, the with/without-buffer comparison and the verdict (docs/design-json.md).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>

#include "core/variants.hpp"
#include "design/design.hpp"
#include "design/loads.hpp"
#include "design/verdict.hpp"

namespace dmi::design {

using nlohmann::json;
namespace fs = std::filesystem;

namespace {

double num(const json& j, std::initializer_list<const char*> path) {
  const json* p = &j;
  for (const char* k : path) {
    if (!p->is_object() || !p->contains(k) || (*p)[k].is_null()) return NAN;
    p = &(*p)[k];
  }
  return p->is_number() ? p->get<double>() : NAN;
}

// The largest value of a member peak over all members (sign: +1 max of value, -1 max of -value).
double member_max(const json& run, const char* peak, double sign) {
  double best = NAN;
  for (const auto& m : run["members"]) {
    const double v = sign * num(m, {"peaks", peak, "value"});
    if (!std::isnan(v) && (std::isnan(best) || v > best)) best = v;
  }
  return best;
}

// The output folder a run's variant sits in: OUT/results.h5 for the variant "", OUT/<variant>/results.h5 otherwise.
std::string root_folder(const json& r) {
  const fs::path p = fs::path(r["results_file"].get<std::string>()).parent_path();
  return (r["variant"].get<std::string>().empty() ? p : p.parent_path()).string();
}

// The plane model's governing numbers beside its 3D model's (compare_3d), one pair of runs.
PlaneAndSpace::Pair plane_and_space(const json& plane, const json& space) {
  struct Q { const char* id; const char* title; const char* unit; std::function<double(const json&)> get; };
  auto level = [](const char* l) { return [l](const json& r) { return num(r, {"verdict", "levels", l, "max_utilisation"}); }; };
  const std::vector<Q> qs = {
      {"base_shear", "peak base shear", "N", [](const json& r) { return num(r, {"base_total", shear_key(r.value("dimension", 2)), "abs_max", "value"}); }},
      {"base_moment", "peak base moment", "N m", [](const json& r) { return num(r, {"base_total", moment_key(r.value("dimension", 2)), "abs_max", "value"}); }},
      {"contact_force", "peak contact force", "N", [](const json& r) { return num(r, {"contact", "peak_force_N"}); }},
      {"contact_impulse", "contact impulse", "N s", [](const json& r) { return num(r, {"contact", "impulse_magnitude_N_s"}); }},
      {"serviceability", "governing utilisation, serviceability", "-", level("serviceability")},
      {"ultimate", "governing utilisation, ultimate", "-", level("ultimate")},
      {"sliding", "sliding under the impact", "m", [](const json& r) { return num(r, {"stability", "impact", "sliding_displacement_m"}); }},
      {"rocking", "rocking about the toe", "rad", [](const json& r) { return num(r, {"stability", "impact", "peak_rocking_rotation_rad"}); }},
  };
  PlaneAndSpace::Pair pair{plane["variant"], plane["verdict"]["passed"].get<bool>(), space["verdict"]["passed"].get<bool>(), {}};
  for (const Q& q : qs) {
    const double a = q.get(plane), b = q.get(space);
    if (std::isnan(a) || std::isnan(b)) continue;
    pair.quantities.push_back({q.id, q.title, q.unit, a, b, b != 0 ? std::optional<double>(a / b) : std::nullopt});
  }
  return pair;
}

}  // namespace

std::optional<PlaneAndSpace> plane_and_space_section(const std::vector<json>& runs) {
  PlaneAndSpace out;
  for (const json& s : runs) {
    const std::string v = s["variant"].get<std::string>();
    if (!is_space_variant(v)) continue;
    for (const json& p : runs)
      if (p["variant"] == plane_variant(v) && root_folder(p) == root_folder(s)) out.pairs.push_back(plane_and_space(p, s));
  }
  if (out.pairs.empty()) return std::nullopt;
  out.note = "ratio = plane / 3D. The plane model strikes a width of the dam with a cylinder of the boulder's mass; the 3D "
             "model strikes the whole crest with the sphere. Both are judged: the verdict is the worse of the two.";
  return out;
}

BufferComparison compare_runs(const json& with, const json& without) {
  struct Q { const char* id; const char* title; const char* unit; std::function<double(const json&)> get; };
  auto abs_m = [](const json& r) {
    const double a = member_max(r, "M_max", 1), b = member_max(r, "M_min", -1);
    return std::isnan(a) ? b : std::isnan(b) ? a : std::max(a, b);
  };
  const std::vector<Q> qs = {
      {"base_shear", "peak base shear (plane |sum Fx|, space |(sum Fx, sum Fy)|)", "N", [](const json& r) {
         return num(r, {"base_total", shear_key(r.value("dimension", 2)), "abs_max", "value"}); }},
      {"base_moment", "peak base moment (plane |sum M|, space the overturning |(Mx, My)|)", "N m", [](const json& r) {
         return num(r, {"base_total", moment_key(r.value("dimension", 2)), "abs_max", "value"}); }},
      {"contact_force", "peak contact force", "N", [](const json& r) { return num(r, {"contact", "peak_force_N"}); }},
      {"contact_impulse", "contact impulse", "N s", [](const json& r) { return num(r, {"contact", "impulse_magnitude_N_s"}); }},
      {"contact_duration", "contact pulse duration", "s", [](const json& r) { return num(r, {"contact", "pulse", "duration_s"}); }},
      {"member_moment", "peak member |M|", "N m", abs_m},
      {"member_shear", "peak member |V|", "N", [](const json& r) { return member_max(r, "V_abs_max", 1); }},
      {"flexural_tension", "peak fibre tension", "Pa", [](const json& r) { return member_max(r, "sigma_tension_max", 1); }},
      {"fibre_compression", "peak fibre compression", "Pa", [](const json& r) { return member_max(r, "sigma_compression_min", -1); }},
      {"member_von_mises", "peak member von Mises", "Pa", [](const json& r) { return member_max(r, "von_mises_max", 1); }},
      {"max_utilisation", "largest utilisation", "-", [](const json& r) { return num(r, {"verdict", "max_utilisation"}); }},
  };
  BufferComparison out;
  auto row = [&](const std::string& id, const std::string& title, const std::string& unit, double a, double b) {
    if (std::isnan(a) || std::isnan(b)) return;
    out.quantities.push_back({id, title, unit, a, b, b != 0 ? std::optional<double>(100 * (b - a) / b) : std::nullopt});
  };
  for (const auto& q : qs) row(q.id, q.title, q.unit, q.get(with), q.get(without));
  if (with["solid"].is_object() && without["solid"].is_object())
    for (const auto& cw : with["solid"]["cases"])
      for (const auto& cb : without["solid"]["cases"])
        if (cw["name"] == cb["name"]) {
          const std::string n = cw["name"];
          row("solid_von_mises:" + n, "solid FE von Mises (" + n + ")", "Pa", num(cw, {"von_mises", "value_Pa"}), num(cb, {"von_mises", "value_Pa"}));
          row("solid_max_principal:" + n, "solid FE max principal (" + n + ")", "Pa", num(cw, {"max_principal", "value_Pa"}),
              num(cb, {"max_principal", "value_Pa"}));
        }
  out.note = "reduction_percent = 100 (without - with) / without; a negative value is an increase (the buffer lengthens the contact pulse)";
  return out;
}

namespace {

// The document's verdict: the judged runs' checks summed, the governing check the largest utilisation of any; each level
// and each design situation likewise.
Verdict document_verdict(const std::vector<json>& runs, const std::vector<bool>& reference, const Limits& limits) {
  Verdict d;
  d.document = true, d.judged_levels = limits.verdict_level;
  for (const char* level : {"serviceability", "ultimate"}) d.levels[level] = {};
  for (const char* situation : {"persistent", "accidental"}) d.situations[situation] = {};
  const auto add = [](LevelVerdict& into, const LevelVerdict& v) {
    into.checks += v.checks, into.failed += v.failed, into.passed = into.failed == 0;
    if (v.governing && (!into.governing || v.governing->utilisation > into.governing->utilisation)) into.governing = v.governing;
  };
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (reference[i]) continue;
    const json& r = runs[i];
    const Verdict v = verdict_from_json(r["verdict"], false, "runs[" + std::to_string(i) + "].verdict");
    const double before = d.governing ? d.governing->utilisation : -INFINITY;
    add(d, v);
    if (v.governing && v.governing->utilisation > before)
      d.governing_variant = r["variant"], d.governing_results_file = r["results_file"];
    for (auto& [name, l] : d.levels) add(l, v.levels.at(name));
    for (auto& [name, l] : d.situations) add(l, v.situations.at(name));
    const std::string variant = r["variant"];
    d.runs_judged += (d.runs_judged.empty() ? "" : ", ") + (variant.empty() ? r["results_file"].get<std::string>() : variant);
  }
  d.status = d.checks == 0 ? "no_checks" : d.failed == 0 ? "pass" : "fail";
  return d;
}

}  // namespace

json design_document(const std::vector<json>& runs, const Limits& limits, const std::string& software_version) {
  json doc{{"format", "damimpact-design"}, {"format_version", kDesignFormatVersion}, {"software_version", software_version},
           {"limits", limits.to_json()}, {"runs", runs}, {"comparison", nullptr}};
  // Pair the variants of one comparison folder (OUT/with_buffer, OUT/without_buffer): the bare run of a pair is the
  // reference; every other run is judged.
  // Pairs within one model (plane, or the 3D one of compare_3d).
  std::vector<bool> reference(runs.size(), false);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const std::string v = runs[i]["variant"].get<std::string>();
    if (plane_variant(v) != "without_buffer") continue;
    const std::string with = is_space_variant(v) ? space_variant("with_buffer") : "with_buffer";
    for (std::size_t j = 0; j < runs.size(); ++j)
      if (runs[j]["variant"] == with && root_folder(runs[j]) == root_folder(runs[i])) {
        reference[i] = true;
        if (doc["comparison"].is_null() && !is_space_variant(v)) doc["comparison"] = to_json(compare_runs(runs[j], runs[i]));
      }
  }
  for (std::size_t i = 0; i < runs.size(); ++i) doc["runs"][i]["reference"] = static_cast<bool>(reference[i]);
  const std::optional<PlaneAndSpace> ps = plane_and_space_section(runs);
  doc["plane_and_space"] = ps ? to_json(*ps) : json(nullptr);
  doc["verdict"] = to_json(document_verdict(runs, reference, limits));
  return doc;
}

}  // namespace dmi::design
