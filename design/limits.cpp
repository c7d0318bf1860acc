#include "design/limits.hpp"

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "engine/common/error.hpp"
#include "engine/common/json_input.hpp"

namespace dmi::design {

using nlohmann::json;

double ConcreteLimits::tensile_value() const {
  // ACI 318-19 eq. (19.2.3.1): modulus of rupture f_r = 0.62 lambda sqrt(f'c), f'c in MPa.
  if (tensile_rule == "aci_rupture") return 0.62 * lambda * std::sqrt(compressive_strength / 1e6) * 1e6;
  // ACI 318-19 Table 14.5.2.1(a): plain-concrete flexure M_n = 5 lambda sqrt(f'c) S_m [psi] = 0.42 lambda sqrt(f'c) S_m [MPa].
  if (tensile_rule == "aci_plain") return 0.42 * lambda * std::sqrt(compressive_strength / 1e6) * 1e6;
  return tensile_strength;
}
double ConcreteLimits::tensile_capacity() const { return phi_flexure * tensile_value(); }
double ConcreteLimits::compressive_capacity() const { return phi_compression * compression_coefficient * compressive_strength; }

json Limits::to_json() const {
  json c{{"compressive_strength_Pa", concrete.compressive_strength}, {"tensile_strength_Pa", concrete.tensile_value()},
         {"tensile_rule", concrete.tensile_rule}, {"lambda", concrete.lambda}, {"compression_coefficient", concrete.compression_coefficient},
         {"phi_flexure", concrete.phi_flexure}, {"phi_compression", concrete.phi_compression}, {"phi_shear", concrete.phi_shear},
         {"shear_strength_Pa", concrete.shear_strength ? json(*concrete.shear_strength) : json(nullptr)},
         {"strain_rate_effects", concrete.strain_rate_effects}};
  if (concrete.punching_patch_width)
    c["punching_patch_m"] = {*concrete.punching_patch_width, *concrete.punching_patch_height};
  else
    c["punching_patch_m"] = nullptr;
  return json{{"concrete", c},
              {"steel", {{"yield_strength_Pa", steel.yield_strength}, {"gamma_M0", steel.gamma_M0}, {"gamma_M1", steel.gamma_M1},
                         {"strain_limit", steel.strain_limit}, {"residual_drift_limit", steel.residual_drift_limit},
                         {"dent_depth_limit", steel.dent_depth_limit}, {"buckling_curve", steel.buckling_curve}}},
              {"foundation", {{"friction", foundation.friction}, {"cohesion_Pa", foundation.cohesion},
                              {"bearing_capacity_Pa", foundation.bearing_capacity}, {"uplift_factor", foundation.uplift_factor},
                              {"sliding_factor_usual", foundation.sliding_factor_usual},
                              {"sliding_displacement_limit_m", foundation.sliding_displacement_limit},
                              {"rocking_safety_factor", foundation.rocking_safety_factor}}},
              {"members", member_material}, {"grid_study", {{"judge_on", grid_judge_on}}}, {"verdict", {{"level", verdict_level}}}};
}

namespace {

struct Reader {
  const std::string& file;
  [[noreturn]] void fail(const std::string& path, const json* v, const std::string& expected) const {
    throw InputError(file, path, v ? v->dump() : "", expected);
  }
  // A word among `options`, when given; `expected` says which in the message.
  void choice(const json& o, const std::string& path, const char* key, const std::set<std::string>& options, const std::string& expected,
              std::string& out) const {
    if (!o.contains(key)) return;
    const json& v = o[key];
    if (!v.is_string() || !options.count(v.get<std::string>())) fail(path + "/" + key, &v, expected);
    out = v.get<std::string>();
  }
  void keys(const json& o, const std::string& path, const std::set<std::string>& allowed) const {
    if (!o.is_object()) fail(path, &o, "an object");
    for (auto it = o.begin(); it != o.end(); ++it)
      if (!allowed.count(it.key())) {
        std::string list;
        for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
        fail(path + "/" + it.key(), &it.value(), "a known key (one of: " + list + ")");
      }
  }
  // A value already read that must lie in [lo, hi] (a unit slip otherwise), named as the user wrote it.
  void range(const json& o, const std::string& path, const char* key, double v, double lo, double hi, const std::string& expected) const {
    if (o.contains(key) && !(v >= lo && v <= hi)) fail(path + "/" + key, &o[key], expected);
  }
  // A number > 0 (or in (0, 1] when factor).
  void number(const json& o, const std::string& path, const char* key, double& out, bool factor = false) const {
    if (!o.contains(key)) return;
    const json& v = o[key];
    const std::string p = path + "/" + key;
    if (!v.is_number() || !std::isfinite(v.get<double>())) fail(p, &v, factor ? "a number in (0, 1]" : "a number > 0");
    const double x = v.get<double>();
    if (!(x > 0) || (factor && x > 1)) fail(p, &v, factor ? "a number in (0, 1]" : "a number > 0");
    out = x;
  }
};

// /verdict: the level the verdict is judged on.
void read_verdict(const Reader& r, const json& j, Limits& L) {
  if (!j.contains("verdict")) return;
  const json& v = j["verdict"];
  r.keys(v, "/verdict", {"level"});
  r.choice(v, "/verdict", "level", {"both", "ultimate", "serviceability"}, "\"both\", \"ultimate\" or \"serviceability\"", L.verdict_level);
}

// /foundation: friction, cohesion, bearing capacity, uplift and the stability factors.
void read_foundation(const Reader& r, const json& j, Limits& L) {
  if (!j.contains("foundation")) return;
  const json& f = j["foundation"];
  const std::string p = "/foundation";
  r.keys(f, p, {"friction", "cohesion_Pa", "bearing_capacity_Pa", "uplift_factor", "sliding_factor_usual", "sliding_displacement_limit_m",
                "rocking_safety_factor"});
  FoundationLimits& k = L.foundation;
  r.number(f, p, "friction", k.friction);
  if (f.contains("cohesion_Pa")) {  // may be 0
    const json& v = f["cohesion_Pa"];
    if (!v.is_number() || !(v.get<double>() >= 0) || !std::isfinite(v.get<double>())) r.fail(p + "/cohesion_Pa", &v, "a number >= 0");
    k.cohesion = v.get<double>();
  }
  r.number(f, p, "bearing_capacity_Pa", k.bearing_capacity);
  if (f.contains("uplift_factor")) {  // may be 0 (fully drained)
    const json& v = f["uplift_factor"];
    if (!v.is_number() || !(v.get<double>() >= 0 && v.get<double>() <= 1)) r.fail(p + "/uplift_factor", &v, "a number in [0, 1]");
    k.uplift_factor = v.get<double>();
  }
  r.number(f, p, "sliding_factor_usual", k.sliding_factor_usual);
  r.number(f, p, "sliding_displacement_limit_m", k.sliding_displacement_limit);
  r.number(f, p, "rocking_safety_factor", k.rocking_safety_factor);
  if (k.friction > 2) r.fail(p + "/friction", &f["friction"], "a friction coefficient tan(phi) <= 2 (phi <= 63 deg)");
  if (k.bearing_capacity < 1e4) r.fail(p + "/bearing_capacity_Pa", &f["bearing_capacity_Pa"], "a pressure in Pa >= 1e4 (10 kPa; kPa given?)");
}

// /grid_study: the value a grid study judges the verdict on.
void read_grid_study(const Reader& r, const json& j, Limits& L) {
  if (!j.contains("grid_study")) return;
  const json& g = j["grid_study"];
  r.keys(g, "/grid_study", {"judge_on"});
  r.choice(g, "/grid_study", "judge_on", {"finest", "conservative_bound"}, "\"finest\" or \"conservative_bound\"", L.grid_judge_on);
}

// /concrete: strengths (in Pa: a value in MPa is the usual slip), resistance factors, punching patch.
void read_concrete(const Reader& r, const json& j, Limits& L) {
  if (!j.contains("concrete")) return;
  const json& c = j["concrete"];
  const std::string p = "/concrete";
  r.keys(c, p, {"compressive_strength_Pa", "tensile_strength_Pa", "tensile_rule", "lambda", "compression_coefficient", "phi_flexure",
                "phi_compression", "phi_shear", "shear_strength_Pa", "punching_patch_m", "strain_rate_effects"});
  ConcreteLimits& k = L.concrete;
  if (c.contains("strain_rate_effects")) {
    if (!c["strain_rate_effects"].is_boolean()) r.fail(p + "/strain_rate_effects", &c["strain_rate_effects"], "true or false");
    k.strain_rate_effects = c["strain_rate_effects"].get<bool>();
  }
  r.number(c, p, "compressive_strength_Pa", k.compressive_strength);
  r.number(c, p, "tensile_strength_Pa", k.tensile_strength);
  // Strengths in Pa: a value in MPa (28 for 28 MPa) is the usual slip.
  r.range(c, p, "compressive_strength_Pa", k.compressive_strength, 5e6, 2e8, "a concrete f'c in Pa between 5e6 and 2e8 (28 MPa is 28e6 Pa)");
  r.range(c, p, "tensile_strength_Pa", k.tensile_strength, 5e5, 2e7, "a concrete tensile strength in Pa between 5e5 and 2e7 (3.28 MPa is 3.28e6 Pa)");
  r.choice(c, p, "tensile_rule", {"given", "aci_rupture", "aci_plain"}, "\"given\", \"aci_plain\" or \"aci_rupture\"", k.tensile_rule);
  r.number(c, p, "lambda", k.lambda, true);
  r.number(c, p, "compression_coefficient", k.compression_coefficient, true);
  r.number(c, p, "phi_flexure", k.phi_flexure, true);
  r.number(c, p, "phi_compression", k.phi_compression, true);
  r.number(c, p, "phi_shear", k.phi_shear, true);
  if (c.contains("shear_strength_Pa") && !c["shear_strength_Pa"].is_null()) {
    double v = 0;
    r.number(c, p, "shear_strength_Pa", v);
    k.shear_strength = v;
  }
  if (c.contains("punching_patch_m") && !c["punching_patch_m"].is_null()) {
    const json& v = c["punching_patch_m"];
    if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number() || !(v[0].get<double>() > 0) || !(v[1].get<double>() > 0))
      r.fail(p + "/punching_patch_m", &v, "[width, height] of the contact patch, both > 0 (m)");
    k.punching_patch_width = v[0].get<double>();
    k.punching_patch_height = v[1].get<double>();
  }
}

// /steel: yield strength, partial factors and the ultimate-level limits of yielding members.
void read_steel(const Reader& r, const json& j, Limits& L) {
  if (!j.contains("steel")) return;
  const json& s = j["steel"];
  r.keys(s, "/steel", {"yield_strength_Pa", "gamma_M0", "gamma_M1", "strain_limit", "residual_drift_limit", "dent_depth_limit", "buckling_curve"});
  r.number(s, "/steel", "yield_strength_Pa", L.steel.yield_strength);
  r.range(s, "/steel", "yield_strength_Pa", L.steel.yield_strength, 1e8, 2e9, "a steel yield strength in Pa between 1e8 and 2e9 (235 MPa is 235e6 Pa)");
  if (s.contains("gamma_M0")) {
    const json& v = s["gamma_M0"];
    if (!v.is_number() || !(v.get<double>() >= 1.0) || !std::isfinite(v.get<double>())) r.fail("/steel/gamma_M0", &v, "a partial factor >= 1");
    L.steel.gamma_M0 = v.get<double>();
  }
  if (s.contains("gamma_M1")) {
    const json& v = s["gamma_M1"];
    if (!v.is_number() || !(v.get<double>() >= 1.0) || !std::isfinite(v.get<double>())) r.fail("/steel/gamma_M1", &v, "a partial factor >= 1");
    L.steel.gamma_M1 = v.get<double>();
  }
  r.number(s, "/steel", "strain_limit", L.steel.strain_limit);
  r.range(s, "/steel", "strain_limit", L.steel.strain_limit, 1e-3, 0.2, "a strain between 0.001 and 0.2 (5 % is 0.05)");
  r.number(s, "/steel", "residual_drift_limit", L.steel.residual_drift_limit);
  r.range(s, "/steel", "residual_drift_limit", L.steel.residual_drift_limit, 1e-4, 0.1, "a drift ratio between 1e-4 and 0.1 (1 % is 0.01)");
  r.number(s, "/steel", "dent_depth_limit", L.steel.dent_depth_limit);
  r.range(s, "/steel", "dent_depth_limit", L.steel.dent_depth_limit, 1e-3, 0.5, "a dent depth over the diameter between 0.001 and 0.5 (6 % is 0.06)");
  r.choice(s, "/steel", "buckling_curve", {"a0", "a", "b", "c", "d"}, "one of \"a0\", \"a\", \"b\", \"c\", \"d\" (EN 1993-1-1 Table 6.2)",
           L.steel.buckling_curve);
}

// /members: which members are concrete and which steel.
void read_member_materials(const Reader& r, const json& j, Limits& L) {
  if (!j.contains("members")) return;
  const json& m = j["members"];
  if (!m.is_object()) r.fail("/members", &m, "an object {member name: \"concrete\" | \"steel\"}");
  for (auto it = m.begin(); it != m.end(); ++it) {
    if (!it.value().is_string() || (it.value() != "concrete" && it.value() != "steel"))
      r.fail("/members/" + it.key(), &it.value(), "\"concrete\" or \"steel\"");
    L.member_material[it.key()] = it.value().get<std::string>();
  }
}

}  // namespace

Limits parse_limits(const json& j, const std::string& file) {
  const Reader r{file};
  Limits L;
  r.keys(j, "", {"concrete", "steel", "members", "grid_study", "foundation", "verdict"});
  read_verdict(r, j, L);
  read_foundation(r, j, L);
  read_grid_study(r, j, L);
  read_concrete(r, j, L);
  read_steel(r, j, L);
  read_member_materials(r, j, L);
  return L;
}

Limits read_limits(const std::string& path) {
  const std::string text = read_json_file(path, "limits");
  check_json_structure(text, path);
  json j;
  try {
    j = json::parse(text);
  } catch (const json::parse_error& e) {
    throw InputError(path + ": invalid JSON (" + std::string(e.what()) + ")");
  }
  return parse_limits(j, path);
}

}  // namespace dmi::design
