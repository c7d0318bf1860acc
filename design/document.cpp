// design.json as a whole: runs, the with/without-buffer comparison and the verdict (docs/design-json.md).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>

#include "design/design.hpp"
#include "design/loads.hpp"

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

}  // namespace

json compare_runs(const json& with, const json& without) {
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
  json rows = json::array();
  auto row = [&](const std::string& id, const std::string& title, const std::string& unit, double a, double b) {
    if (std::isnan(a) || std::isnan(b)) return;
    rows.push_back({{"id", id}, {"title", title}, {"unit", unit}, {"with_buffer", a}, {"without_buffer", b},
                    {"reduction_percent", b != 0 ? json(100 * (b - a) / b) : json(nullptr)}});
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
  return json{{"quantities", rows}, {"note", "reduction_percent = 100 (without - with) / without; a negative value is an increase "
                                             "(the buffer lengthens the contact pulse)"}};
}

json design_document(const std::vector<json>& runs, const Limits& limits, const std::string& software_version) {
  json doc{{"format", "damimpact-design"}, {"format_version", kDesignFormatVersion}, {"software_version", software_version},
           {"limits", limits.to_json()}, {"runs", runs}, {"comparison", nullptr}};
  // Pair the variants of one comparison folder (OUT/with_buffer, OUT/without_buffer): the bare run of a pair is the
  // reference; every other run is judged.
  auto folder = [](const json& r) { return fs::path(r["results_file"].get<std::string>()).parent_path().parent_path().string(); };
  std::vector<bool> reference(runs.size(), false);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (runs[i]["variant"] != "without_buffer") continue;
    for (std::size_t j = 0; j < runs.size(); ++j)
      if (runs[j]["variant"] == "with_buffer" && folder(runs[j]) == folder(runs[i])) {
        reference[i] = true;
        if (doc["comparison"].is_null()) doc["comparison"] = compare_runs(runs[j], runs[i]);
      }
  }
  json gov = nullptr;
  int checks = 0, failed = 0;
  std::string basis;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (reference[i]) continue;
    const json& r = runs[i];
    const json& v = r["verdict"];
    checks += v["checks"].get<int>(), failed += v["failed"].get<int>();
    if (!v["governing"].is_null() && (gov.is_null() || v["governing"]["utilisation"] > gov["utilisation"])) {
      gov = v["governing"];
      gov["variant"] = r["variant"];
      gov["results_file"] = r["results_file"];
    }
    basis += (basis.empty() ? "" : ", ") + (r["variant"].get<std::string>().empty() ? r["results_file"].get<std::string>() : r["variant"].get<std::string>());
  }
  doc["verdict"] = {{"passed", failed == 0}, {"checks", checks}, {"failed", failed}, {"governing", gov}, {"runs_judged", basis},
                    {"status", checks == 0 ? "no_checks" : failed == 0 ? "pass" : "fail"}, {"judged_levels", limits.verdict_level}};
  // Each level over the judged runs: its checks, failures and governing check.
  for (const char* level : {"serviceability", "ultimate"}) {
    json l{{"checks", 0}, {"failed", 0}, {"passed", true}, {"max_utilisation", nullptr}, {"governing", nullptr}};
    for (std::size_t i = 0; i < runs.size(); ++i) {
      if (reference[i] || !runs[i]["verdict"].contains("levels")) continue;
      const json& v = runs[i]["verdict"]["levels"][level];
      l["checks"] = l["checks"].get<int>() + v["checks"].get<int>(), l["failed"] = l["failed"].get<int>() + v["failed"].get<int>();
      l["passed"] = l["failed"].get<int>() == 0;
      if (!v["governing"].is_null() && (l["governing"].is_null() || v["governing"]["utilisation"] > l["governing"]["utilisation"]))
        l["governing"] = v["governing"], l["max_utilisation"] = v["max_utilisation"];
    }
    doc["verdict"]["levels"][level] = l;
  }
  return doc;
}

}  // namespace dmi::design
