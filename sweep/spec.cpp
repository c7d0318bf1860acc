#include "sweep/spec.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "engine/common/error.hpp"
#include "engine/common/json_input.hpp"
#include "engine/scenario/hydrograph_io.hpp"
#include "engine/scenario/scenario.hpp"

namespace dmi::sweep {
namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

std::string escape(const std::string& key) {  // a key as one JSON-pointer token (RFC 6901)
  std::string t;
  for (char c : key) t += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
  return t;
}

// A range object {from, to, count} (count values, ends included) or {from, to, step}.
std::vector<json> expand_range(const json& r, const std::string& file, const std::string& where) {
  for (const auto& [k, v] : r.items())
    if (k != "from" && k != "to" && k != "count" && k != "step")
      throw InputError(file, where + "/" + escape(k), v.dump(), "one of the range keys from, to, count, step");
  if (!r.contains("from") || !r["from"].is_number()) throw InputError(file, where + "/from", r.value("from", json()).dump(), "a number");
  if (!r.contains("to") || !r["to"].is_number()) throw InputError(file, where + "/to", r.value("to", json()).dump(), "a number");
  if (r.contains("count") == r.contains("step")) throw InputError(file, where, r.dump(), "exactly one of count or step");
  const double a = r["from"], b = r["to"];
  std::vector<json> v;
  if (r.contains("count")) {
    const json& c = r["count"];
    if (!c.is_number_integer() || c.get<long>() < 1 || c.get<long>() > 100000)
      throw InputError(file, where + "/count", c.dump(), "an integer from 1 to 100000");
    const long n = c;
    for (long i = 0; i < n; ++i) v.push_back(n == 1 ? a : a + (b - a) * double(i) / double(n - 1));
  } else {
    const json& st = r["step"];
    if (!st.is_number() || !(st.get<double>() > 0)) throw InputError(file, where + "/step", st.dump(), "a number > 0");
    const double h = st;
    if ((b - a) / h > 100000) throw InputError(file, where + "/step", st.dump(), "at most 100000 values from 'from' to 'to'");
    for (long i = 0; a + i * h <= b + 1e-9 * std::abs(h); ++i) v.push_back(a + i * h);
    if (v.empty()) throw InputError(file, where, r.dump(), "from <= to");
  }
  return v;
}

// The parameter path must lead into the base scenario: its parent must exist (the key itself may be absent when the
// scenario format gives it a default; the dry run of the first case then checks it).
void check_path(const json& base, const std::string& ptr, const std::string& file, const std::string& where) {
  json::json_pointer p;
  try {
    p = json::json_pointer(ptr);
  } catch (const std::exception&) {
    throw InputError(file, where, "\"" + ptr + "\"", "a JSON pointer into the base scenario, e.g. \"/boulder/velocity\"");
  }
  if (ptr.empty()) throw InputError(file, where, "\"\"", "a JSON pointer to one key of the base scenario, not the whole scenario");
  const json::json_pointer parent = p.parent_pointer();
  if (!base.contains(parent) || !(base.at(parent).is_object() || base.at(parent).is_array()))
    throw InputError(file, where, "\"" + ptr + "\"", "a path into the base scenario (" + parent.to_string() + " is not in it)");
  if (base.at(parent).is_array() && !base.contains(p))
    throw InputError(file, where, "\"" + ptr + "\"", "an index inside the array " + parent.to_string() + " of the base scenario");
}

}  // namespace

std::string case_id(std::size_t k) {
  char b[32];
  std::snprintf(b, sizeof b, "case_%04zu", k + 1);
  return b;
}

json case_scenario(const SweepSpec& s, std::size_t k) {
  json j = s.base;
  for (std::size_t p = 0; p < s.parameters.size(); ++p) j[json::json_pointer(s.parameters[p])] = s.cases[k][p];
  return j;
}

namespace {

// /base: a scenario file (relative to the sweep file) or an object; file references resolved (the cases are written
// into OUT/cases/).
void read_base(const nlohmann::ordered_json& j, const std::string& file, const std::string& dir, SweepSpec& s) {
  if (!j.contains("base")) throw InputError(file, "/base", "", "the base scenario: a file name (relative to the sweep file) or an object");
  if (j["base"].is_string()) {
    const fs::path p = fs::path(dir) / j["base"].get<std::string>();
    std::ifstream probe(p);
    if (!probe) throw InputError(file, "/base", j["base"].dump(), "a readable scenario file (" + p.string() + " cannot be opened)");
    const std::string text = read_json_file(p.string(), "scenario");
    check_json_structure(text, p.string());
    try {
      s.base = json::parse(text);
    } catch (const json::parse_error& e) {
      throw InputError(p.string() + ": not valid JSON: " + e.what());
    }
    s.base_file = p.string();
    resolve_file_references(s.base, p.string());  // the cases are written into OUT/cases/
  } else if (j["base"].is_object()) {
    s.base = json::parse(j["base"].dump());
    s.base_file = file + " (/base)";
    resolve_file_references(s.base, file);
  } else {
    throw InputError(file, "/base", j["base"].dump().substr(0, 60), "a file name or a scenario object");
  }
}

// /grid_study: true (ratio sqrt 2), false, or {"ratio": r >= sqrt 2}.
void read_grid_study(const nlohmann::ordered_json& j, const std::string& file, SweepSpec& s) {
  if (!j.contains("grid_study")) return;
  const auto& g = j["grid_study"];
  if (g.is_boolean()) {
    s.grid_ratio = g.get<bool>() ? std::sqrt(2.0) : 0.0;
  } else if (g.is_object() && g.size() == 1 && g.contains("ratio") && g["ratio"].is_number()) {
    s.grid_ratio = g["ratio"].get<double>();
    if (!(s.grid_ratio >= std::sqrt(2.0) - 1e-12))
      throw InputError(file, "/grid_study/ratio", g["ratio"].dump(), "a refinement ratio >= sqrt(2) (1.41421)");
  } else {
    throw InputError(file, "/grid_study", g.dump().substr(0, 60), "true, false or {\"ratio\": r} with r >= sqrt(2)");
  }
}

// /parameters: values per parameter (a list or a range), combined as a product or zipped.
void read_parameters(const nlohmann::ordered_json& j, const std::string& file, const std::string& combine, SweepSpec& s) {
  const nlohmann::ordered_json& P = j["parameters"];  // in the order given: the columns of the summary
  if (!P.is_object() || P.empty()) throw InputError(file, "/parameters", P.dump().substr(0, 60), "an object: JSON pointer -> values");
  std::vector<std::vector<json>> values;
  for (const auto& [ptr, v] : P.items()) {
    const std::string where = "/parameters/" + escape(ptr);
    check_path(s.base, ptr, file, where);
    s.parameters.push_back(ptr);
    if (v.is_array() && !v.empty()) values.push_back(std::vector<json>(v.begin(), v.end()));
    else if (v.is_object()) values.push_back(expand_range(json::parse(v.dump()), file, where));
    else throw InputError(file, where, v.dump().substr(0, 60), "a non-empty list of values or a range {from, to, count|step}");
  }
  if (combine == "zip") {
    for (std::size_t p = 1; p < values.size(); ++p)
      if (values[p].size() != values[0].size())
        throw InputError(file, "/parameters/" + escape(s.parameters[p]), std::to_string(values[p].size()) + " values",
                         std::to_string(values[0].size()) + " values, as many as the first parameter (combine: zip)");
    for (std::size_t k = 0; k < values[0].size(); ++k) {
      std::vector<json> c;
      for (const auto& v : values) c.push_back(v[k]);
      s.cases.push_back(c);
    }
  } else {  // cartesian product, the last parameter varying fastest
    std::size_t n = 1;
    for (const auto& v : values) n *= v.size();
    if (n > 100000) throw InputError(file, "/parameters", std::to_string(n) + " cases", "at most 100000 cases");
    for (std::size_t k = 0; k < n; ++k) {
      std::vector<json> c(values.size());
      std::size_t r = k;
      for (std::size_t p = values.size(); p-- > 0;) c[p] = values[p][r % values[p].size()], r /= values[p].size();
      s.cases.push_back(c);
    }
  }
}

// /cases: a table of {pointer: value} rows, every row giving every parameter.
void read_cases(const nlohmann::ordered_json& j, const std::string& file, SweepSpec& s) {
  const nlohmann::ordered_json& C = j["cases"];
  if (!C.is_array() || C.empty()) throw InputError(file, "/cases", C.dump().substr(0, 60), "a non-empty array of {pointer: value} objects");
  std::set<std::string> seen;
  for (std::size_t k = 0; k < C.size(); ++k) {
    if (!C[k].is_object() || C[k].empty()) throw InputError(file, "/cases/" + std::to_string(k), C[k].dump().substr(0, 60), "an object {pointer: value}");
    for (const auto& [ptr, v] : C[k].items())
      if (seen.insert(ptr).second) {
        check_path(s.base, ptr, file, "/cases/" + std::to_string(k) + "/" + escape(ptr));
        s.parameters.push_back(ptr);
      }
  }
  for (std::size_t k = 0; k < C.size(); ++k) {  // every row names every parameter, so no value silently falls back
    std::vector<json> c;
    for (const auto& ptr : s.parameters) {
      if (!C[k].contains(ptr)) throw InputError(file, "/cases/" + std::to_string(k), "", "a value for " + ptr + " (every case gives every parameter)");
      c.push_back(C[k][ptr]);
    }
    s.cases.push_back(c);
  }
}

// Dry run of the first case: a parameter key the scenario format does not know (a misspelt path) fails the whole
// sweep here, naming the sweep file; a bad value only fails its own case when the sweep runs.
void check_first_case(const SweepSpec& s, const std::string& file) {
  try {
    parse_scenario_variants(case_scenario(s, 0).dump(), s.base_file);
  } catch (const InputError& e) {
    const std::string what = e.what();
    for (const auto& ptr : s.parameters)
      if (what.find(ptr) != std::string::npos && what.find("unknown key") != std::string::npos)
        throw InputError(file + ": parameter " + ptr + " is not a key of the scenario format: " + what);
  }
}

}  // namespace

SweepSpec parse_sweep(const nlohmann::ordered_json& j, const std::string& file, const std::string& dir) {
  if (!j.is_object()) throw InputError(file, "", j.type_name(), "a JSON object with base and parameters or cases");
  for (const auto& [k, v] : j.items())
    if (k != "name" && k != "description" && k != "base" && k != "parameters" && k != "combine" && k != "cases" && k != "grid_study")
      throw InputError(file, "/" + escape(k), v.dump().substr(0, 60), "one of name, description, base, parameters, combine, cases, grid_study");
  SweepSpec s;
  s.file = file;
  s.name = j.value("name", fs::path(file).stem().string());
  read_base(j, file, dir, s);
  read_grid_study(j, file, s);
  const bool has_params = j.contains("parameters"), has_cases = j.contains("cases");
  if (has_params == has_cases) throw InputError(file, "", "", "either parameters (values per parameter) or cases (a table), not both");
  const std::string combine = j.value("combine", std::string("product"));
  if (combine != "product" && combine != "zip") throw InputError(file, "/combine", j["combine"].dump(), "\"product\" or \"zip\"");
  if (has_params)
    read_parameters(j, file, combine, s);
  else
    read_cases(j, file, s);
  check_first_case(s, file);
  return s;
}

SweepSpec load_sweep(const std::string& path) {
  const std::string text = read_json_file(path, "sweep");
  check_json_structure(text, path);
  nlohmann::ordered_json j;
  try {
    j = nlohmann::ordered_json::parse(text);
  } catch (const json::parse_error& e) {
    throw InputError(path + ": not valid JSON: " + e.what());
  }
  return parse_sweep(j, path, fs::path(path).parent_path().string());
}

}  // namespace dmi::sweep
