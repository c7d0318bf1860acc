#include "design/verdict.hpp"

#include "design/record_reader.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

namespace dmi::design {

using nlohmann::json;

using namespace record;

namespace {

// A number or null (null: -1, "not on a member" / "not time-dependent").
double optional_number(const json& j, const char* key, const std::string& where) { return record::number_or(j, key, -1, where); }

LevelVerdict level_from_json(const json& j, const std::string& where) {
  LevelVerdict l;
  l.checks = count(j, "checks", where), l.failed = count(j, "failed", where), l.passed = flag(j, "passed", where);
  if (!field(j, "governing", where).is_null()) l.governing = check_from_json(j["governing"], where + ".governing");
  return l;
}

LevelVerdict level_of(const std::vector<Check>& checks, const std::function<bool(const Check&)>& counts) {
  LevelVerdict l;
  for (const auto& c : checks) {
    if (!counts(c)) continue;
    ++l.checks, l.failed += !c.passed;
    if (!l.governing || c.utilisation > l.governing->utilisation) l.governing = c;
  }
  l.passed = l.failed == 0;
  return l;
}

}  // namespace

Check check_from_json(const json& j, const std::string& where) {
  Check c;
  c.id = text(j, "id", where), c.title = text(j, "title", where), c.member = text(j, "member", where);
  c.material = text(j, "material", where), c.unit = text(j, "unit", where), c.formula = text(j, "formula", where);
  c.source = text(j, "source", where), c.level = text(j, "level", where), c.situation = text(j, "situation", where);
  c.demand = number(j, "demand", where), c.capacity = number(j, "capacity", where), c.utilisation = number(j, "utilisation", where);
  c.passed = flag(j, "passed", where);
  c.dynamic_factor = number(j, "dynamic_increase_factor", where), c.strain_rate = number(j, "strain_rate_per_s", where);
  c.position = optional_number(j, "position", where), c.s_m = optional_number(j, "s_m", where), c.time_s = optional_number(j, "time_s", where);
  const json& loc = field(j, "location_m", where);
  if (!loc.is_array() || loc.size() < 2 || loc.size() > 3 || !std::all_of(loc.begin(), loc.end(), [](const json& x) { return x.is_number(); }))
    throw std::runtime_error(where + ".location_m is not 2 or 3 numbers");
  c.x_m = loc[0], c.y_m = loc[1], c.space = loc.size() == 3, c.z_m = c.space ? loc[2].get<double>() : 0.0;
  return c;
}

std::vector<Check> checks_from_json(const json& run, const std::string& where) {
  return record::items<Check>(list(run, "checks", where), where + ".checks", check_from_json);
}

Verdict run_verdict(const std::vector<Check>& checks, const std::string& judged) {
  const auto counts = [&](const Check& c) { return c.level != "information" && (judged == "both" || c.level == judged); };
  Verdict v;
  static_cast<LevelVerdict&>(v) = level_of(checks, counts);
  v.judged_levels = judged;
  for (const char* level : {"serviceability", "ultimate", "information"})
    v.levels[level] = level_of(checks, [&](const Check& c) { return c.level == level; });
  // Each design situation's own verdict over the judged levels (EN 1990 3.2).
  for (const char* situation : {"persistent", "accidental"})
    v.situations[situation] = level_of(checks, [&](const Check& c) { return counts(c) && c.situation == situation; });
  return v;
}

json to_json(const LevelVerdict& v) {
  return json{{"checks", v.checks}, {"failed", v.failed}, {"passed", v.passed},
              {"max_utilisation", v.governing ? json(v.governing->utilisation) : json(nullptr)},
              {"governing", v.governing ? v.governing->to_json() : json(nullptr)}};
}

json to_json(const Verdict& v) {
  json j = to_json(static_cast<const LevelVerdict&>(v));
  if (v.document) {
    j.erase("max_utilisation");
    if (v.governing) j["governing"]["variant"] = v.governing_variant, j["governing"]["results_file"] = v.governing_results_file;
    j["runs_judged"] = v.runs_judged, j["status"] = v.status;
    if (!v.note.empty()) j["note"] = v.note;
  }
  j["judged_levels"] = v.judged_levels;
  for (const auto& [name, l] : v.levels) j["levels"][name] = to_json(l);
  for (const auto& [name, l] : v.situations) j["situations"][name] = to_json(l);
  return j;
}

Verdict verdict_from_json(const json& j, bool document, const std::string& where) {
  Verdict v;
  static_cast<LevelVerdict&>(v) = level_from_json(j, where);
  v.document = document;
  v.judged_levels = text(j, "judged_levels", where);
  for (const auto& [group, into] : {std::pair{"levels", &v.levels}, std::pair{"situations", &v.situations}}) {
    const json& g = field(j, group, where);
    if (!g.is_object()) throw std::runtime_error(where + "." + group + " is not an object");
    for (const auto& [name, l] : g.items()) (*into)[name] = level_from_json(l, where + "." + group + "." + name);
  }
  if (document) {
    v.status = text(j, "status", where), v.runs_judged = text(j, "runs_judged", where);
    if (j.contains("note")) v.note = text(j, "note", where);
    if (v.governing) {
      v.governing_variant = text(j["governing"], "variant", where + ".governing");
      v.governing_results_file = text(j["governing"], "results_file", where + ".governing");
    }
  }
  return v;
}

}  // namespace dmi::design
