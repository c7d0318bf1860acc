#include "design/grid_study_record.hpp"

#include <cmath>

#include "design/record_reader.hpp"

namespace dmi::design {

using namespace record;

namespace {

json optional_json(const std::optional<double>& x) { return x ? json(*x) : json(nullptr); }

GridQuantity quantity_from(const json& q, const std::string& w) {
  GridQuantity g;
  g.variant = text(q, "variant", w), g.id = text(q, "id", w), g.title = text(q, "title", w), g.unit = text(q, "unit", w);
  const std::vector<double> v = numbers(q, "values", w);
  if (v.size() != 3) throw std::runtime_error(w + ".values is not three numbers");
  g.values = {v[0], v[1], v[2]};
  g.observed_order = number_or_none(q, "observed_order", w), g.extrapolated = number_or_none(q, "extrapolated", w);
  g.asymptotic_ratio = number_or_none(q, "asymptotic_ratio", w);
  g.gci = number_or(q, "gci", NAN, w), g.safety_factor = number(q, "safety_factor", w), g.conservative_magnitude = number(q, "conservative_magnitude", w);
  g.behaviour = text(q, "behaviour", w), g.statement = text(q, "statement", w), g.converged = flag(q, "converged", w);
  return g;
}

}  // namespace

json to_json(const GridQuantity& q) {
  return json{{"variant", q.variant}, {"id", q.id}, {"title", q.title}, {"unit", q.unit}, {"values", q.values},
              {"observed_order", optional_json(q.observed_order)}, {"extrapolated", optional_json(q.extrapolated)}, {"gci", q.gci},
              {"safety_factor", q.safety_factor}, {"asymptotic_ratio", optional_json(q.asymptotic_ratio)},
              {"behaviour", q.behaviour}, {"converged", q.converged}, {"conservative_magnitude", q.conservative_magnitude},
              {"statement", q.statement}};
}

json to_json(const GridStudyRecord& g) {
  json qs = json::array();
  for (const auto& q : g.quantities) qs.push_back(to_json(q));
  json out{{"method", g.method}, {"cell_sizes_m", g.cell_sizes_m}, {"refinement_ratios", g.refinement_ratios}, {"folders", g.folders},
           {"quantities", qs}, {"not_converged", g.not_converged}};
  if (g.verdict) {
    json runs = json::array();
    for (const auto& r : g.verdict->runs)
      runs.push_back({{"variant", r.variant}, {"utilisation", r.utilisation}, {"gci", r.gci}, {"utilisation_bound", r.utilisation_bound},
                      {"passed", r.passed}, {"converged", r.converged}});
    out["verdict"] = {{"judge_on", g.verdict->judge_on}, {"runs", runs}, {"bound_passed", g.verdict->bound_passed}};
  }
  return out;
}

std::optional<GridStudyRecord> grid_study_from_json(const json& j, const std::string& w) {
  if (j.is_null()) return std::nullopt;
  GridStudyRecord g;
  g.method = text(j, "method", w);
  const std::vector<double> h = numbers(j, "cell_sizes_m", w), r = numbers(j, "refinement_ratios", w);
  if (h.size() != 3 || r.size() != 2) throw std::runtime_error(w + ": three cell sizes and two ratios expected");
  g.cell_sizes_m = {h[0], h[1], h[2]}, g.refinement_ratios = {r[0], r[1]};
  const json& f = list(j, "folders", w);
  if (f.size() != 3 || !f[0].is_string() || !f[1].is_string() || !f[2].is_string()) throw std::runtime_error(w + ".folders is not three names");
  g.folders = {f[0].get<std::string>(), f[1].get<std::string>(), f[2].get<std::string>()};
  const json& qs = list(j, "quantities", w);
  g.quantities = record::items<GridQuantity>(qs, w + ".quantities", quantity_from);
  g.not_converged = count(j, "not_converged", w);
  if (j.contains("verdict")) {
    const json& v = j["verdict"];
    const std::string wv = w + ".verdict";
    GridStudyRecord::Judged judged{text(v, "judge_on", wv), {}, flag(v, "bound_passed", wv)};
    const json& runs = list(v, "runs", wv);
    for (std::size_t k = 0; k < runs.size(); ++k) {
      const std::string at = wv + ".runs[" + std::to_string(k) + "]";
      judged.runs.push_back({text(runs[k], "variant", at), number(runs[k], "utilisation", at), number(runs[k], "gci", at),
                             number(runs[k], "utilisation_bound", at), flag(runs[k], "passed", at), flag(runs[k], "converged", at)});
    }
    g.verdict = judged;
  }
  return g;
}

}  // namespace dmi::design
