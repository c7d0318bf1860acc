// Verification suite: named cases, each a scenario from examples/ (compiled in) run against a
// closed form. `damimpact validate` prints a table or a JSON array; exit 0 only when all pass.
#pragma once
#include <chrono>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/scenario/config.hpp"
#include "engine/sim/run.hpp"

namespace dmi {

struct CaseResult {
  std::string case_name, metric, unit;
  double value = 0, reference = 0, error = 0, tolerance = 0;  // error: relative unless unit says otherwise
  bool passed = false;
  double wall_seconds = 0;
};

struct ValidationCase {
  std::string name, description;
  std::function<std::vector<CaseResult>()> run;
  bool by_default = true;  // false: run only when named (a stress case that fails for a known solver defect)
};

const std::map<std::string, std::string>& embedded_examples();  // file name -> JSON text
// An embedded example with JSON-pointer overrides applied (e.g. {"/grid/cell_size", 0.25}).
Scenario example_scenario(const std::string& file, const std::vector<std::pair<std::string, nlohmann::json>>& overrides = {});
// Runs a scenario in memory (no files, quiet); returns histories.
RunOutput run_quiet(const Scenario& s);

// One metric: error relative to |ref| (absolute if !relative); passes when finite and <= tol.
CaseResult metric(const std::string& case_name, const std::string& metric, const std::string& unit, double value, double ref,
                  double tol, bool relative = true);
// A one-sided check: passes when value > limit (must_exceed) or value < limit (otherwise); the error is by
// how much the value falls on the wrong side of the limit (0 when it passes).
CaseResult bound_metric(const std::string& case_name, const std::string& metric, const std::string& unit, double value,
                        double limit, bool must_exceed);
struct CaseTimer {
  std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();
  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); }
};
// Sets every result's wall time to `wall` (s).
std::vector<CaseResult> stamp(std::vector<CaseResult> r, double wall);

const std::vector<ValidationCase>& validation_cases();
std::vector<ValidationCase> member_validation_cases();  // cases_members.cpp (Lin & Yang 2024)
std::vector<ValidationCase> debris_validation_cases();  // cases_debris.cpp (granular collapse)
std::vector<ValidationCase> dam_validation_cases();     // cases_dam.cpp (the dam members against a solid model)
std::vector<ValidationCase> plastic_validation_cases(); // cases_plastic.cpp (elasto-plastic members against closed forms)
std::vector<ValidationCase> experiment_validation_cases();  // cases_experiments.cpp (measured pressures, bodies at rest)

// Bar vibration at one resolution (used by the case, tests and benchmarks).
struct BarResult {
  double period = 0, period_exact = 0, amplitude = 0, amplitude_exact = 0, wall = 0;
};
BarResult bar_vibration_run(double h, ShapeKind shape, TransferKind transfer);
// The stability stress suite (cases_stress.cpp, `damimpact validate --stress`).
std::vector<ValidationCase> stress_cases();
// stress = true runs stress_cases() instead of validation_cases(); same output.
int validate_main(const std::vector<std::string>& cases, bool json, bool list, int threads, bool stress = false);
// True while validate_main runs without --json: cases may print per-run details to stderr.
bool& validate_verbose();

// Helpers for cases and tests.
const Series& series(const Results& r, const std::string& path);
double column_max(const Series& s, std::size_t comp, bool absolute = false);
// Times at which component comp crosses zero (linear interpolation).
std::vector<double> zero_crossings(const std::vector<double>& t, const Series& s, std::size_t comp);
// Least-squares slope of comp against t over [t0, t1].
double slope(const std::vector<double>& t, const Series& s, std::size_t comp, double t0, double t1);
// Mean of comp over [t0, t1] (trapezoid in time).
double time_mean(const std::vector<double>& t, const Series& s, std::size_t comp, double t0, double t1);

}  // namespace dmi
