#include "sweep/summary_record.hpp"

namespace dmi::sweep {

using json = nlohmann::json;

namespace {

template <class T> json or_null(const std::optional<T>& v) { return v ? json(*v) : json(nullptr); }
template <class T> std::optional<T> opt(const json& j, const char* key) {
  return j.contains(key) && !j[key].is_null() ? std::optional<T>(j[key].get<T>()) : std::nullopt;
}

}  // namespace

json to_json(const SweepRow& r) {
  json vars = json::object();
  for (const auto& [label, v] : r.variants)
    vars[label] = {{"max_utilisation", or_null(v.max_utilisation)}, {"passed", v.passed}, {"contact_peak_N", or_null(v.contact_peak_N)},
                   {"base_shear_N", or_null(v.base_shear_N)}, {"base_moment_Nm", or_null(v.base_moment_Nm)}};
  json params = json::object();
  for (const auto& [ptr, value] : r.parameters) params[ptr] = value;
  json j = {{"case", r.case_name}, {"index", r.index}, {"status", r.status}, {"error", or_null(r.error)}, {"wall_seconds", r.wall_seconds},
            {"simulated_seconds", r.simulated_seconds}, {"verdict", or_null(r.verdict)}, {"max_utilisation", or_null(r.max_utilisation)},
            {"governing", r.governing ? json{{"id", r.governing->id}, {"member", r.governing->member}, {"variant", r.governing->variant}}
                                      : json(nullptr)},
            {"variants", vars}, {"parameters", params}};
  if (r.report) j["report"] = *r.report;
  if (r.utilisation_bound) j["utilisation_bound"] = *r.utilisation_bound;
  if (r.grid_study_passed) j["grid_study_passed"] = *r.grid_study_passed;
  return j;
}

SweepRow row_from_json(const json& j) {
  SweepRow r;
  r.case_name = j.at("case").get<std::string>(), r.index = j.at("index").get<std::size_t>(), r.status = j.at("status").get<std::string>();
  r.error = opt<std::string>(j, "error"), r.verdict = opt<std::string>(j, "verdict"), r.report = opt<std::string>(j, "report");
  r.max_utilisation = opt<double>(j, "max_utilisation");
  if (const json& g = j.at("governing"); !g.is_null())
    r.governing = Governing{g.at("id").get<std::string>(), g.at("member").get<std::string>(), g.at("variant").get<std::string>()};
  for (const auto& [label, v] : j.at("variants").items())
    r.variants[label] = {opt<double>(v, "max_utilisation"), v.at("passed").get<bool>(), opt<double>(v, "contact_peak_N"),
                         opt<double>(v, "base_shear_N"), opt<double>(v, "base_moment_Nm")};
  for (const auto& [ptr, value] : j.at("parameters").items()) r.parameters[ptr] = value;
  r.wall_seconds = j.at("wall_seconds").get<double>(), r.simulated_seconds = j.at("simulated_seconds").get<double>();
  r.utilisation_bound = opt<double>(j, "utilisation_bound"), r.grid_study_passed = opt<bool>(j, "grid_study_passed");
  return r;
}

json to_json(const SweepSummary& s) {
  json cases = json::array();
  for (const SweepRow& r : s.cases) cases.push_back(to_json(r));
  return {{"format", "damimpact-sweep"}, {"format_version", 1}, {"software_version", s.software_version}, {"name", s.name},
          {"sweep_file", s.sweep_file}, {"base_file", s.base_file}, {"parameters", s.parameters}, {"ranks", s.ranks},
          {"threads_per_rank", s.threads_per_rank}, {"wall_seconds", s.wall_seconds}, {"cases_per_hour", s.cases_per_hour},
          {"counts", {{"cases", s.cases.size()}, {"passed", s.passed}, {"failed_runs", s.failed_runs}, {"reused", s.reused}}},
          {"cases", cases}};
}

}  // namespace dmi::sweep
