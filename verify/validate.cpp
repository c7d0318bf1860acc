#include "verify/validate.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>

#include "engine/common/error.hpp"
#include "engine/scenario/scenario.hpp"

namespace dmi {

CaseResult metric(const std::string& c, const std::string& m, const std::string& unit, double value, double ref, double tol,
                  bool relative) {
  CaseResult r;
  r.case_name = c;
  r.metric = m;
  r.unit = unit;
  r.value = value;
  r.reference = ref;
  r.error = relative ? std::abs(value - ref) / std::abs(ref) : std::abs(value - ref);
  r.tolerance = tol;
  r.passed = std::isfinite(r.error) && r.error <= tol;
  return r;
}

CaseResult bound_metric(const std::string& c, const std::string& m, const std::string& unit, double value, double limit,
                        bool must_exceed) {
  CaseResult r = metric(c, m, unit, value, limit, 0.0, false);
  r.error = std::max(0.0, must_exceed ? limit - value : value - limit);
  r.passed = std::isfinite(value) && (must_exceed ? value > limit : value < limit);
  return r;
}

std::vector<CaseResult> stamp(std::vector<CaseResult> r, double wall) {
  for (auto& x : r) x.wall_seconds = wall;
  return r;
}


Scenario example_scenario(const std::string& file, const std::vector<std::pair<std::string, nlohmann::json>>& overrides) {
  const auto& ex = embedded_examples();
  auto it = ex.find(file);
  if (it == ex.end()) throw InputError("no bundled example named '" + file + "'");
  nlohmann::json j = nlohmann::json::parse(it->second);
  for (const auto& [ptr, value] : overrides) j[nlohmann::json::json_pointer(ptr)] = value;
  Scenario s = parse_scenario(j, "examples/" + file);
  s.source_text = j.dump(2);
  return s;
}

RunOutput run_quiet(const Scenario& s) {
  RunOptions o;
  o.progress = ProgressMode::quiet;
  return run_scenario(s, o);
}

const Series& series(const Results& r, const std::string& path) {
  const Series* s = r.find(path);
  if (!s) throw std::runtime_error("validation: no series '" + path + "'");
  return *s;
}

double column_max(const Series& s, std::size_t comp, bool absolute) {
  double m = -std::numeric_limits<double>::infinity();
  const std::size_t nc = s.components.size();
  for (std::size_t i = 0; i < s.samples(); ++i) m = std::max(m, absolute ? std::abs(s.data[i * nc + comp]) : s.data[i * nc + comp]);
  return m;
}

std::vector<double> zero_crossings(const std::vector<double>& t, const Series& s, std::size_t comp) {
  std::vector<double> z;
  const std::size_t nc = s.components.size();
  for (std::size_t i = 1; i < s.samples(); ++i) {
    const double a = s.data[(i - 1) * nc + comp], b = s.data[i * nc + comp];
    if ((a < 0 && b >= 0) || (a > 0 && b <= 0)) z.push_back(t[i - 1] + (t[i] - t[i - 1]) * a / (a - b));
  }
  return z;
}

double slope(const std::vector<double>& t, const Series& s, std::size_t comp, double t0, double t1) {
  double n = 0, st = 0, sy = 0, stt = 0, sty = 0;
  const std::size_t nc = s.components.size();
  for (std::size_t i = 0; i < s.samples(); ++i) {
    if (t[i] < t0 || t[i] > t1) continue;
    const double y = s.data[i * nc + comp];
    n += 1; st += t[i]; sy += y; stt += t[i] * t[i]; sty += t[i] * y;
  }
  return (n * sty - st * sy) / (n * stt - st * st);
}

double time_mean(const std::vector<double>& t, const Series& s, std::size_t comp, double t0, double t1) {
  double area = 0, span = 0;
  const std::size_t nc = s.components.size();
  for (std::size_t i = 1; i < s.samples(); ++i) {
    if (t[i - 1] < t0 || t[i] > t1) continue;
    const double dt = t[i] - t[i - 1];
    area += 0.5 * dt * (s.data[(i - 1) * nc + comp] + s.data[i * nc + comp]);
    span += dt;
  }
  return area / span;
}

bool& validate_verbose() {
  static bool verbose = false;
  return verbose;
}

int validate_main(const std::vector<std::string>& names, bool json, bool list, int threads, bool stress) {
  static const std::vector<ValidationCase> stress_list = stress_cases();
  const auto& all = stress ? stress_list : validation_cases();
  const char* suite = stress ? "damimpact validate --stress --list" : "damimpact validate --list";
  if (list) {
    for (const auto& c : all)
      std::printf("%-20s %s%s\n", c.name.c_str(), c.description.c_str(), c.by_default ? "" : " [run only when named]");
    return 0;
  }
  for (const auto& n : names) {
    bool known = false;
    for (const auto& c : all) known = known || c.name == n;
    if (!known) throw InputError("validate: unknown case '" + n + "' (see " + suite + ")");
  }
  if (threads > 0) omp_set_num_threads(threads);
  validate_verbose() = !json;
  std::vector<CaseResult> results;
  for (const auto& c : all) {
    if (names.empty() ? !c.by_default : std::find(names.begin(), names.end(), c.name) == names.end()) continue;
    if (!json) std::fprintf(stderr, "running %s ...\n", c.name.c_str());
    if (!stress) {
      for (auto& r : c.run()) results.push_back(r);
      continue;
    }
    // A stress case that throws (a run error the case did not expect) fails with the message; the suite goes on.
    const CaseTimer timer;
    try {
      for (auto& r : c.run()) results.push_back(r);
    } catch (const std::exception& e) {
      CaseResult r = metric(c.name, std::string("case completes: ") + e.what(), "-", std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0, false);
      r.passed = false;
      r.wall_seconds = timer.seconds();
      results.push_back(r);
    }
  }
  validate_verbose() = false;
  bool ok = true;
  nlohmann::json out = nlohmann::json::array();
  for (const auto& r : results) {
    ok = ok && r.passed;
    out.push_back({{"case", r.case_name}, {"metric", r.metric}, {"unit", r.unit}, {"value", r.value}, {"reference", r.reference},
                   {"error", r.error}, {"tolerance", r.tolerance}, {"passed", r.passed}, {"wall_seconds", r.wall_seconds}});
  }
  if (json) {
    std::cout << out.dump(2) << "\n";
  } else {
    std::printf("%-18s %-26s %14s %14s %10s %10s %6s %8s\n", "case", "metric", "value", "reference", "error", "tolerance", "pass", "wall s");
    for (const auto& r : results)
      std::printf("%-18s %-26s %14.6g %14.6g %10.3g %10.3g %6s %8.2f\n", r.case_name.c_str(), (r.metric + (r.unit.empty() ? "" : " [" + r.unit + "]")).c_str(),
                  r.value, r.reference, r.error, r.tolerance, r.passed ? "yes" : "NO", r.wall_seconds);
    std::printf("%s\n", ok ? "all cases passed" : "SOME CASES FAILED");
  }
  return ok ? 0 : 1;
}

}  // namespace dmi
