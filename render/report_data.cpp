// The report template's data: every value formatted for reading, units stated (templates/report.html.mustache).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <ctime>
#include <functional>
#include <numbers>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "design/design.hpp"
#include "design/grid_study_record.hpp"
#include "design/stability_record.hpp"
#include "design/verdict.hpp"
#include "render/report.hpp"
#include "render/report_rows.hpp"

#include "core/variants.hpp"
#include "engine/scenario/sha256.hpp"

namespace dmi::render {

using nlohmann::json;
namespace fs = std::filesystem;

std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

// Engineering units: Pa -> MPa, N -> kN, N m -> kN m, N s -> kN s, s -> ms, m below 0.1 m -> mm; other units as
// given ("-" and "" dimensionless).
std::string eng(double v, const std::string& unit) {
  if (unit == "Pa") return fmt("%.3g MPa", v / 1e6);
  auto kilo = [](double x, const char* u) { return fmt(std::abs(x) < 1e4 ? "%.4g" : "%.0f", x) + " " + u; };  // 21216 kN, not 2.122e+04 kN
  if (unit == "N") return kilo(v / 1e3, "kN");
  if (unit == "N m") return kilo(v / 1e3, "kN m");
  if (unit == "N s") return kilo(v / 1e3, "kN s");
  if (unit == "s") return fmt("%.4g ms", v * 1e3);
  if (unit == "m") return std::abs(v) < 0.1 ? fmt("%.3g mm", v * 1e3) : fmt("%.3g m", v);
  if (unit.empty() || unit == "-") return fmt("%.3g", v);
  return fmt("%.3g", v) + " " + unit;
}

std::string label(const RunData& r) {
  const std::string v = plane_variant(r.variant);
  const std::string plane = v == "with_buffer" ? "with buffer" : v == "without_buffer" ? "without buffer" : "simulation";
  return is_space_variant(r.variant) ? plane + " (3D)" : plane;
}

namespace {

std::string where(const design::Check& c) {
  std::string s;
  if (c.s_m >= 0) s = "s = " + fmt("%.2f", c.s_m) + " m";
  else if (c.member.rfind("solid", 0) == 0) s = "(" + fmt("%.2f", c.x_m) + ", " + fmt("%.2f", c.y_m) + ") m";
  if (c.time_s >= 0) s += (s.empty() ? "" : ", ") + std::string("t = ") + eng(c.time_s, "s");
  return s.empty() ? "—" : s;
}

}  // namespace

static void plane_and_space_data(const design::DesignDocument& design_doc, json& d) {
  const std::optional<design::PlaneAndSpace>& ps = design_doc.plane_and_space;
  d["has_plane_and_space"] = ps.has_value();
  json cases = json::array();
  if (!ps) {
    d["plane_and_space"] = cases;
    return;
  }
  for (const auto& pair : ps->pairs) {
    const std::string& v = pair.variant;
    json rows = json::array();
    for (const auto& q : pair.quantities) {
      // The plane model on the safe side: a larger demand (every quantity here is a demand).
      rows.push_back({{"title", q.title}, {"plane", eng(q.plane, q.unit)}, {"space", eng(q.space, q.unit)},
                      {"ratio", q.ratio ? fmt("%.2f", *q.ratio) : "—"}, {"side_class", !q.ratio || *q.ratio >= 1 ? "reduced" : "increased"}});
    }
    auto verdict = [](const std::optional<bool>& p) { return p ? (*p ? "PASS" : "FAIL") : "—"; };
    cases.push_back({{"case", v.empty() ? "the scenario" : v == "with_buffer" ? "with buffer" : "without buffer"}, {"rows", rows},
                     {"plane_verdict", verdict(pair.plane_passed)}, {"space_verdict", verdict(pair.space_passed)}});
  }
  d["plane_and_space"] = cases;
  d["plane_and_space_note"] = ps->note + " A ratio below 1 (red) is a quantity the plane model puts below the 3D one.";
}

std::string estimate_note(double ratio, const std::string& note) {
  if (!(ratio < 0.5 || ratio > 2)) return note;
  return "MORE THAN A FACTOR OF 2 FROM THE SIMULATION: outside the conditions the formula was written for, or a reason to "
         "look again at the model" + (note.empty() ? "" : "; " + note);
}

std::string member_damping_text(const json& scenario) {
  const json* st = scenario.contains("structure") && scenario["structure"].is_object() ? &scenario["structure"] : nullptr;
  const json* rd = st && st->contains("rayleigh_damping") && (*st)["rayleigh_damping"].is_object() ? &(*st)["rayleigh_damping"] : nullptr;
  const double a = rd ? rd->value("mass", 0.0) : 0.0, b = rd ? rd->value("stiffness", 0.0) : 0.0;
  const json* md = st && st->contains("modal_damping") && (*st)["modal_damping"].is_object() ? &(*st)["modal_damping"] : nullptr;
  if (md) {
    const std::string top = md->contains("max_frequency") ? "up to " + eng((*md)["max_frequency"].get<double>(), "Hz") : "every mode";
    return "modal: ζ " + fmt("%.3g", 100 * md->value("ratio", 0.0)) + " % in " + top +
           " of the assembled frame (computed modes), so the kHz modes of a hard impact are damped as lightly as the first" +
           (a > 0 || b > 0 ? "; plus Rayleigh α " + fmt("%.3g", a) + " 1/s, β " + fmt("%.3g", b) + " s" : std::string());
  }
  if (!(a > 0) && !(b > 0)) return "none";
  std::string z;
  for (double f : {10.0, 100.0, 1e3, 1e4}) z += (z.empty() ? "" : " / ") + fmt("%.3g", 100 * (a / (4 * std::numbers::pi * f) + std::numbers::pi * f * b));
  return "Rayleigh (α " + fmt("%.3g", a) + " 1/s, β " + fmt("%.3g", b) + " s): ζ at 10 Hz / 100 Hz / 1 kHz / 10 kHz = " + z +
         " %; ζ grows with frequency, so a bare hard impact's member peaks depend on it (docs/verification.md, structural damping)";
}

std::string boulder_model_text(BoulderModel model, double cfl) {
  if (model == BoulderModel::rigid)
    return "rigid: against the tyre buffer its deformation does not matter (same loads as an elastic boulder at the same step, "
           "docs/verification.md); the step is the buffer's" +
           (std::isfinite(cfl) ? fmt(", at CFL %.3g", cfl) : std::string());
  if (model == BoulderModel::elastic) return "elastic: on a bare face the rock's stiffness sets the impact's peak";
  if (model == BoulderModel::elastic_when_touching)
    return "elastic while it can touch the dam (on a bare face the rock's stiffness sets the impact's peak), rigid in free flight "
           "before and after the strike (its waves then do not set the step; its vibration after the rebound is given up, "
           "docs/verification.md)";
  return "";
}

namespace {

json scenario_rows(const RunData& r) {
  json rows = json::array();
  auto row = [&](const std::string& k, const std::string& v) { rows.push_back({{"key", k}, {"value", v}}); };
  const std::optional<DesignBasis>& basis = r.results.info.design_basis;
  if (!basis) {
    row("bodies", std::to_string(r.results.info.body_names.size()));
    if (r.frame) row("members", std::to_string(r.frame->members.size()));
    return rows;
  }
  const DamBasis& dam = basis->dam;
  const bool concrete = dam.type == DamKind::concrete_gravity;
  row("dam", concrete ? "concrete gravity check dam" : "steel open check dam (pipe frame)");
  row("height", fmt("%.3g m", dam.height_m));
  const bool space = r.frame && r.frame->dim == 3;
  row(space ? (concrete ? "crest length (across the channel)" : "column spacing across the channel") : "width represented (out of plane)",
      fmt("%.3g m", dam.width_m) + (space || dam.width_rule.empty() ? std::string() : ": " + dam.width_rule) +
          (space ? std::string() : "; the plane model strikes this width with the boulder as a cylinder of its mass, a line load (a 3D run is the check)"));
  if (concrete)
    row("crest / base thickness", fmt("%.3g m", dam.crest_thickness_m) + " / " + fmt("%.3g m", dam.base_thickness_m));
  else
    row("column pipe", fmt("D %.3g m", dam.column_diameter_m) + fmt(", t %.3g m", dam.column_wall_thickness_m));
  row("dam material", fmt("E %.3g GPa", dam.youngs_modulus_Pa / 1e9) + fmt(", ν %.2f", dam.poisson_ratio) + fmt(", ρ %.0f kg/m³", dam.density_kg_m3));
  if (is_set(dam.deposit_height_m))
    row("deposit behind the dam", fmt("%.3g m", dam.deposit_height_m) + fmt(", %.3g kN/m³", dam.deposit_unit_weight_N_m3 / 1e3) +
                                      (dam.deposit_submerged ? " (saturated; buoyant below the water surface)" : "") +
                                      fmt(", K %.2f: pressure on the face from t = 0 (the accidental situation's permanent part, γ = 1; "
                                          "the persistent situation's with γ_G 1.35)",
                                          dam.deposit_coefficient));
  if (is_set(dam.water_height_m))
    row("water behind the dam", fmt("%.3g m", dam.water_height_m) + fmt(", %.3g kN/m³", dam.water_unit_weight_N_m3 / 1e3) +
                                    ": pressure on the face from t = 0, and its uplift on the base joint in the stability checks");
  if (const auto& k = basis->boulder) {
    row("boulder", fmt("%.4g kg", k->mass_kg) + fmt(" (sphere of %.3g m)", k->diameter_m) + fmt(" at %.3g m/s", k->speed_m_s) +
                       fmt(", centre %.3g m above the base at impact", k->impact_height_m));
    row("rock", fmt("E %.3g GPa", k->youngs_modulus_Pa / 1e9) + fmt(", ν %.2f", k->poisson_ratio) + fmt(", ρ %.0f kg/m³", k->density_kg_m3));
    row("impact energy", fmt("%.4g kJ", 0.5 * k->mass_kg * k->speed_m_s * k->speed_m_s / 1e3));
    const RunStats& n = r.results.info.stats;
    const double cfl = n.cfl_used ? *n.cfl_used : n.cfl.value_or(NAN);  // cfl_used: reduced to the stable limit
    if (const std::string t = boulder_model_text(k->model, cfl); !t.empty()) row("boulder model", t);
  }
  if (const auto& k = basis->debris; k && k->hydrograph) {
    const HydrographBasis& g = *k->hydrograph;
    row("debris surge", "from a hydrograph (" + g.source + "): flowing " + fmt("%.3g s", g.duration_s) + fmt(", %.3g m³", g.volume_m3_per_m) +
                            fmt(" (%.4g kg) per metre", g.mass_kg_per_m) + fmt(", entering %.3g m upstream of the face", g.section_distance_m) +
                            fmt(", channel slope %.3g°", k->channel_slope_deg));
    row("largest momentum flux", fmt("at %.3g s: ", g.peak_flux_time_s) + fmt("depth %.3g m", k->depth_m) + fmt(", %.3g m/s", k->speed_m_s) +
                                     fmt(", ρ %.0f kg/m³", k->density_kg_m3) + " (the estimates' surge; its passage T is the flowing time)");
    if (const Series* m = r.results.find("inflows/debris/mass"); m && !m->data.empty()) {
      const double want = g.mass_kg_per_m * dam.width_m;
      row("debris entered", fmt("%.5g kg", m->data.back()) + fmt(" of the hydrograph's %.5g kg", want) + fmt(" (%.2f %%)", 100 * m->data.back() / want));
    }
  } else if (k) {
    row("debris surge", fmt("depth %.3g m", k->depth_m) + fmt(", length %.3g m", k->length_m) + fmt(", front speed %.3g m/s", k->speed_m_s) +
                            fmt(", ρ %.0f kg/m³", k->density_kg_m3) + fmt(", channel slope %.3g°", k->channel_slope_deg));
  }
  if (const auto& k = basis->buffer)
    row("tyre buffer", k->type + fmt(", %.3g m thick", k->thickness_m) + fmt(", from %.3g m", k->bottom_m) + fmt(" to %.3g m", k->top_m) +
                           fmt(", effective E %.3g MPa", k->youngs_modulus_Pa / 1e6));
  return rows;
}

json materials(const RunData& r) {
  json out = json::array();
  const std::string text = r.results.info.scenario_expanded_json.empty() ? r.results.info.scenario_json : r.results.info.scenario_expanded_json;
  json s;
  try {
    s = json::parse(text);
  } catch (const json::exception&) {
    return out;
  }
  for (const auto& m : s.value("materials", json::array())) {
    std::string other;
    for (auto it = m.begin(); it != m.end(); ++it) {
      const std::string k = it.key();
      if (k == "name" || k == "model" || k == "density" || k == "youngs_modulus" || k == "poisson_ratio") continue;
      other += (other.empty() ? "" : ", ") + k + " " + (it.value().is_number() ? fmt("%.4g", it.value().get<double>()) : it.value().dump());
    }
    out.push_back({{"name", m.value("name", "")}, {"model", m.value("model", "")}, {"density", fmt("%.0f", m.value("density", 0.0))},
                   {"E", m.contains("youngs_modulus") ? fmt(m["youngs_modulus"].get<double>() >= 1e10 ? "%.0f" : "%.4g", m["youngs_modulus"].get<double>() / 1e6) : "—"},
                   {"nu", m.contains("poisson_ratio") ? fmt("%.3g", m["poisson_ratio"].get<double>()) : "—"}, {"other", other}});
  }
  return out;
}

}  // namespace

// Rows of a per-run table: key, then one value per run.
// A row per quantity, a value per run; a value every run shares is written once across the runs' columns (`same`,
// `span`), so that a long text does not repeat in narrow columns.
json per_run_rows(const std::vector<RunData>& runs, const std::vector<std::pair<std::string, std::function<std::string(const RunData&)>>>& rows) {
  json out = json::array();
  for (const auto& [k, f] : rows) {
    json v = json::array();
    for (const auto& r : runs) v.push_back(f(r));
    const bool shared = v.size() > 1 && std::all_of(v.begin(), v.end(), [&](const json& x) { return x == v.front(); });
    json row{{"key", k}, {"values", v}, {"shared", shared}, {"span", v.size()}};
    if (shared) row["same"] = v.front();
    out.push_back(row);
  }
  return out;
}

namespace {

// The dam on its foundation (design.json runs[].stability), a column per run; empty when no run has it.
json stability_rows(const std::vector<RunData>& runs) {
  // A run whose dam was not assessed keeps its column, with dashes.
  std::vector<std::optional<design::StabilityRecord>> records;
  bool any = false;
  for (const auto& r : runs) {
    const std::optional<design::StabilityRecord>& s = r.design.stability;
    any = any || s.has_value();
    records.push_back(s && s->not_assessed.empty() ? s : std::nullopt);
  }
  if (!any) return json::array();
  using S = design::StabilityRecord;
  const auto of = [&runs, &records](const RunData& r) -> const std::optional<S>& { return records[&r - runs.data()]; };
  // A number of the run's record ("—" without one); not finite (a factor without demand, a block that does not stop or
  // topples): `infinite`.
  const auto show = [of](std::function<double(const S&)> get, const char* unit, const char* infinite = "∞") {
    return [of, get, unit, infinite](const RunData& r) {
      if (!of(r)) return std::string("—");
      const double v = get(*of(r));
      return std::isfinite(v) ? eng(v, unit) : std::string(infinite);
    };
  };
  return per_run_rows(runs, {
      {"dam weight (width represented)", show([](const S& s) { return s.dam.weight_N; }, "N")},
      {"at rest: eccentricity of the resultant (B/6 limit)", [of](const RunData& r) {
         if (!of(r) || std::isnan(of(r)->persistent.eccentricity_m)) return std::string("—");
         return eng(of(r)->persistent.eccentricity_m, "m") + " (" + eng(of(r)->dam.base_m / 6, "m") + ")";
       }},
      {"at rest: toe / heel pressure", [show](const RunData& r) {
         return show([](const S& s) { return s.persistent.toe_pressure_Pa; }, "Pa", "∞")(r) + " / " +
                show([](const S& s) { return s.persistent.heel_pressure_Pa; }, "Pa", "∞")(r);
       }},
      {"impact: least sliding factor (instant)", [of, show](const RunData& r) {
         return show([](const S& s) { return s.impact.least_sliding_factor.sliding_factor; }, "", "∞")(r) +
                (of(r) ? " (" + eng(of(r)->impact.least_sliding_factor.time_s, "s") + ")" : "");
       }},
      {"impact: time the resultant is outside the middle third / the base", [show](const RunData& r) {
         return show([](const S& s) { return s.impact.time_outside_middle_third_s; }, "s", "∞")(r) + " / " +
                show([](const S& s) { return s.impact.time_outside_base_s; }, "s", "∞")(r);
       }},
      {"impact: sliding displacement (Newmark)", show([](const S& s) { return s.impact.sliding_displacement_m; }, "m", "does not stop")},
      {"impact: peak rocking rotation about the toe (critical angle)", [of, show](const RunData& r) {
         return show([](const S& s) { return s.impact.peak_rocking_rotation_rad; }, "rad", "topples")(r) +
                (of(r) ? " (" + fmt("%.3g rad", of(r)->dam.critical_angle_rad) + ")" : "");
       }},
  });
}


}  // namespace

double series_max(const Results& r, const char* path, bool absolute) {
  const Series* s = r.find(path);
  double m = -1e300;
  if (!s) return NAN;
  for (double v : s->data) m = std::max(m, absolute ? std::abs(v) : v);
  return m;
}

double reference_energy(const Results& r) {  // the largest kinetic + strain energy in the system (J)
  double e = 0;
  for (std::size_t k = 0; k < r.time.size(); ++k) {
    double t = 0;
    for (const char* p : {"energy/kinetic", "energy/strain", "energy/frame_kinetic", "energy/frame_strain"})
      if (const Series* s = r.find(p)) t += s->data[k];
    e = std::max(e, t);
  }
  return e;
}

bool all_finite(const Results& r) {
  for (const auto& s : r.series)
    for (double v : s.data)
      if (!std::isfinite(v)) return false;
  return true;
}


namespace {

// The verdict's headline class and word in d; returns its sentence: failed checks, the governing one, each level and
// situation.
std::string verdict_data(const design::Verdict& v, json& d) {
  const std::string& status = v.status;
  d["verdict_class"] = status == "pass" ? "pass" : status == "fail" ? "fail" : "none";
  d["verdict_word"] = status == "pass" ? "PASS" : status == "fail" ? "FAIL" : "NO CHECKS";
  std::string vt = std::to_string(v.failed) + " of " + std::to_string(v.checks) + " checks failed (judged: " + v.runs_judged + ").";
  if (v.governing) {
    const design::Check& g = *v.governing;
    vt += " Governing: " + g.title + (g.member.empty() ? "" : " in " + g.member) + ", utilisation " + fmt("%.2f", g.utilisation) + " (" +
          eng(g.demand, g.unit) + " against " + eng(g.capacity, g.unit) + "; " + where(g) + ").";
  }
  for (const char* level : {"serviceability", "ultimate"}) {
    const auto l = v.levels.find(level);
    if (l == v.levels.end() || l->second.checks == 0) continue;
    vt += std::string(" ") + (std::string(level) == "ultimate" ? "Ultimate" : "Serviceability") + " level: " + (l->second.passed ? "pass" : "FAIL") +
          ", largest utilisation " + fmt("%.2f", l->second.max_utilisation()) + " (" + l->second.governing->title + ").";
  }
  for (const char* situation : {"persistent", "accidental"}) {
    const auto l = v.situations.find(situation);
    if (l == v.situations.end() || l->second.checks == 0) continue;
    vt += std::string(" ") + (std::string(situation) == "persistent" ? "Persistent situation (the loads at rest, factored)" : "Accidental situation (the impact)") +
          ": " + (l->second.passed ? "pass" : "FAIL") + ", largest utilisation " + fmt("%.2f", l->second.max_utilisation()) + ".";
  }
  if (v.judged_levels != "both") vt += " The verdict judges the " + v.judged_levels + " level only (limits file).";
  return vt;
}

// The grid study's table in d; returns the sentence on the governing utilisation's grid uncertainty (judged: the runs
// the verdict judges).
std::string grid_data(const design::DesignDocument& design_doc, const std::string& judged, json& d) {
  // Grid uncertainty: the governing numbers with their GCI, or a plain statement that it is unknown.
  auto grid_word = [](const std::string& b) -> std::string {
    if (b == "converged") return "converged";
    if (b == "monotone") return "converging";
    if (b == "outside_asymptotic_range") return "outside the asymptotic range";
    if (b == "oscillatory") return "NOT CONVERGED: oscillates";
    return "NOT CONVERGED: grows as h falls";
  };
  json gq = json::array();
  std::string gov_grid;
  if (const auto& gs = design_doc.grid_study) {
    for (const design::GridQuantity& q : gs->quantities) {
      const std::string &unit = q.unit, &var = q.variant;
      auto val = [&](double x) { return unit == "-" ? fmt("%.3f", x) : eng(x, unit); };
      const bool ok = q.converged;
      gq.push_back({{"run", var.empty() ? "—" : var}, {"title", q.title}, {"fine", val(q.values[0])}, {"medium", val(q.values[1])},
                    {"coarse", val(q.values[2])}, {"gci", fmt("± %.0f %%", 100 * q.gci)},
                    {"order", q.observed_order ? fmt("%.2f", *q.observed_order) : std::string("—")},
                    {"extrapolated", q.extrapolated && ok ? val(*q.extrapolated) : std::string("—")},
                    {"statement", grid_word(q.behaviour)}, {"status_class", ok ? "pass" : "fail"}});
      if (q.id == "governing_utilisation" && (judged.empty() || var.empty() || judged.find(var) != std::string::npos))
        gov_grid = " Grid uncertainty of the governing utilisation: " + fmt("%.2f", q.values[0]) + fmt(" ± %.0f %%", 100 * q.gci) + " (" + q.statement + ").";
    }
    d["grid_cells"] = fmt("%.4g", gs->cell_sizes_m[0]) + ", " + fmt("%.4g", gs->cell_sizes_m[1]) + " and " + fmt("%.4g m", gs->cell_sizes_m[2]);
    d["grid_not_converged"] = gs->not_converged;
  } else {
    gov_grid = " These numbers come from one grid: their grid uncertainty is unknown (damimpact run --grid-study states it).";
  }
  d["has_grid_study"] = !gq.empty();
  d["grid_quantities"] = gq;
  return gov_grid;
}

// Per run: its label, whether it is the bare reference, its checks' rows, the governing check's sentence and the
// summary by member group.
json run_checks(const std::vector<RunData>& runs) {
  json rl = json::array();
  for (const auto& r : runs) {
    const bool reference = r.design.reference;  // the bare run of a comparison (design/document.cpp)
    json checks = json::array();
    for (const design::Check& c : r.design.checks) {
      const double u = c.utilisation;
      const bool info = c.level == "information";
      checks.push_back({{"id", c.id}, {"title", c.title}, {"member", c.member.rfind("solid: ", 0) == 0 ? "solid FE, " + c.member.substr(7) : c.member},
                        {"demand", eng(c.demand, c.unit)}, {"capacity", eng(c.capacity, c.unit)}, {"util", fmt("%.2f", u)},
                        {"bar_pct", fmt("%.0f", std::min(100.0, 100 * u))}, {"bar_class", u > 1 ? "over" : u > 0.8 ? "high" : "ok"},
                        {"status", info ? "info" : c.passed ? "pass" : "FAIL"}, {"status_class", info ? "info" : c.passed ? "pass" : "fail"},
                        {"where", where(c)}, {"level", c.level == "ultimate" ? "ULS" : c.level == "serviceability" ? "SLS" : "info"}});
    }
    std::string gov;
    const design::Verdict& verdict = r.design.verdict;
    if (verdict.governing) {
      const design::Check& g = *verdict.governing;
      gov = g.title + (g.member.empty() ? "" : ", " + g.member) + ": " + eng(g.demand, g.unit) + " against " + eng(g.capacity, g.unit) +
            ", utilisation " + fmt("%.2f", g.utilisation) + " (" + where(g) + "). " + g.formula + "; " + g.source + ".";
    }
    const json groups = check_group_rows(r.design);
    rl.push_back({{"label", label(r)}, {"reference", reference}, {"checks", checks}, {"governing", gov}, {"groups", groups},
                  {"has_groups", !groups.empty()}});
  }
  return rl;
}

// The model table: a row per quantity, a column per run.
json model_rows(const std::vector<RunData>& runs) {
  return per_run_rows(runs, {
      {"cell size", [](const RunData& r) { return fmt("%.3g m", r.results.info.stats.cell_size.value_or(NAN)); }},
      {"particles", [](const RunData& r) { return fmt("%.0f", r.results.info.stats.particles.value_or(NAN)); }},
      {"members / elements", [](const RunData& r) { return r.frame ? std::to_string(r.frame->members.size()) + " / " + std::to_string(r.frame->elements.size()) : std::string("—"); }},
      {"members' lowest natural periods", [](const RunData& r) {
         std::string t;
         const std::vector<double>& periods = r.results.info.stats.frame_periods;
         for (std::size_t k = 0; k < std::min<std::size_t>(3, periods.size()); ++k) t += (t.empty() ? "" : ", ") + eng(periods[k], "s");
         return t.empty() ? std::string("—") : t;
       }},
      {"member damping", [](const RunData& r) {
         const std::string& t = r.results.info.scenario_expanded_json.empty() ? r.results.info.scenario_json : r.results.info.scenario_expanded_json;
         const json s = json::parse(t, nullptr, false);
         return r.frame && s.is_object() ? member_damping_text(s) : std::string("—");
       }},
      {"shape functions, transfer, stress update", [](const RunData& r) {
         const RunStats& s = r.results.info.stats;
         return s.shape_function.value_or("?") + ", " + s.transfer.value_or("?") + ", " + s.stress_update.value_or("?");
       }},
      {"simulated time", [](const RunData& r) { return r.results.time.empty() ? std::string("—") : eng(r.results.time.back(), "s"); }},
      {"time steps", [](const RunData& r) { return fmt("%.0f", r.results.info.stats.steps.value_or(NAN)); }},
      {"time step min / max", [](const RunData& r) {
         const RunStats& n = r.results.info.stats;
         return n.dt_min && n.dt_max ? fmt("%.3g", *n.dt_min * 1e6) + " / " + fmt("%.3g µs", *n.dt_max * 1e6) : std::string("—");
       }},
      {"wall time", [](const RunData& r) { return fmt("%.1f s", r.results.info.stats.wall_seconds.value_or(NAN)); }},
      {"threads", [](const RunData& r) { return fmt("%.0f", r.results.info.stats.threads.value_or(NAN)); }}});
}

}  // namespace

json report_data(const std::vector<RunData>& runs, const design::DesignDocument& design_doc, const Manifest& manifest, const std::string& image_dir,
                 const std::string& software_version) {
  const RunData& first = runs.front();
  json d;
  std::string name = first.results.info.scenario_name;
  for (const char* suffix : {" (with buffer)", " (without buffer)"})
    if (name.size() > std::strlen(suffix) && name.compare(name.size() - std::strlen(suffix), std::string::npos, suffix) == 0)
      name.erase(name.size() - std::strlen(suffix));
  d["scenario_name"] = name;
  try {
    d["description"] = json::parse(first.results.info.scenario_json).value("description", "");
  } catch (const json::exception&) {
    d["description"] = "";
  }
  d["software_version"] = software_version.empty() ? first.results.info.software_version : software_version;
  d["input_file"] = first.results.info.scenario_file.empty() ? "(not recorded)" : first.results.info.scenario_file;
  d["input_sha256"] = sha256_hex(first.results.info.scenario_json);
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  char when[64];
  std::strftime(when, sizeof when, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  d["generated"] = when;
  const design::Verdict& v = design_doc.verdict;
  const std::string vt = verdict_data(v, d);
  const std::string gov_grid = grid_data(design_doc, v.runs_judged, d);
  d["verdict_text"] = vt + gov_grid;
  std::string rt, files;
  for (const auto& r : runs) rt += (rt.empty() ? "" : ", ") + label(r), files += (files.empty() ? "" : ", ") + r.file;
  d["runs_text"] = rt;
  d["results_files"] = files;
  d["scenario_rows"] = scenario_rows(first);
  d["materials"] = materials(first);
  // Model.
  const bool space = first.frame ? first.frame->dim == 3 : (!first.results.snapshots.empty() && first.results.snapshots[0].dim == 3);
  d["methods"] =
      std::string("Material Point Method for the boulder, debris and buffer (explicit, Lin & Yang 2024); beam-column finite elements for the dam "
                  "members, coupled to the particles by Lin & Yang's two-stage contact with Yang's equivalent force field (Lin & Yang 2024, eqs. 15–29); ") +
      (space ? "three dimensions (z up): space beam-columns with biaxial bending and torsion, checked around their sections. "
             : "plane strain, the out-of-plane width as given. ") +
      (std::any_of(runs.begin(), runs.end(), [](const RunData& r) { return is_space_variant(r.variant); })
           ? "The runs marked (3D) are the same scenario in three dimensions (compare_3d): the sphere of the boulder's mass on the "
             "dam's crest, the dam a space beam-column whose section is the crest length wide. "
           : "") +
      "Checks and estimates: docs/design-checks.md.";
  d["runs"] = run_checks(runs);
  d["checks_intro"] =
      "Each check compares the largest demand over the whole run and along every member (or in the solid-FE model) with its factored "
      "capacity; utilisation = demand / capacity. The bar turns orange above 0.8 and red above 1. Level: SLS serviceability (the dam stays "
      "elastic and undamaged), ULS ultimate (it stands and is not holed), info reported and never judged (a linear stress under the "
      "contact patch is singular under a concentrated load).";
  std::set<std::string> seen;
  json formulas = json::array();
  for (const auto& r : runs)
    for (const design::Check& c : r.design.checks)
      if (seen.insert(c.id + c.title).second) formulas.push_back({{"title", c.title}, {"formula", c.formula}, {"source", c.source}});
  d["formulas"] = formulas;
  d["stability_rows"] = stability_rows(runs);
  d["has_stability"] = !d["stability_rows"].empty();
  d["plastic_rows"] = plastic_rows(runs);
  d["has_plastic"] = !d["plastic_rows"].empty();
  d["pressure_rows"] = pressure_rows(runs);
  d["has_pressure"] = !d["pressure_rows"].empty();
  d["model_rows"] = model_rows(runs);
  // Comparison.
  const std::optional<design::BufferComparison>& comparison = design_doc.comparison;
  d["has_comparison"] = comparison.has_value();
  json cmp = json::array();
  if (comparison) {
    for (const auto& q : comparison->quantities) {
      const double red = q.reduction_percent.value_or(NAN);
      cmp.push_back({{"title", q.title}, {"with", eng(q.with_buffer, q.unit)}, {"without", eng(q.without_buffer, q.unit)},
                     {"reduction", std::isnan(red) ? "—" : red < -100 ? fmt("%.3g× larger", 1 - red / 100) : fmt("%.0f %%", red)},
                     {"sign_class", red >= 0 ? "reduced" : "increased"}});
    }
    d["comparison_note"] = comparison->note;
  }
  d["comparison"] = cmp;
  int section = d["has_comparison"].get<bool>() ? 5 : 4;
  plane_and_space_data(design_doc, d);
  if (d["has_plane_and_space"].get<bool>()) d["plane_and_space_number"] = std::to_string(section++);
  d["figures_number"] = std::to_string(section++);
  d["estimates_number"] = std::to_string(section++);
  d["health_number"] = std::to_string(section++);
  d["software_number"] = std::to_string(section++);
  // Figures, embedded: the comparison, the governing pictures, the charts, then the sequences.
  json figs = json::array();
  int n = 1;
  for (const char* kind : {"field_comparison", "field_solid", "field_governing", "chart", "field_sequence"})
    for (const Picture& img : manifest.images) {
      if (img.kind != kind) continue;
      // Charts as vector graphics where the renderer wrote them (sharp lines and text in the PDF), else the PNG.
      const bool vector = img.vector_file && fs::exists(fs::path(image_dir) / *img.vector_file);
      std::ifstream in(fs::path(image_dir) / (vector ? *img.vector_file : img.file), std::ios::binary);
      std::stringstream ss;
      ss << in.rdbuf();
      std::string caption = img.caption;
      if (img.field && img.field->deform_scale > 0) caption += fmt("; members' centre line deformed × %g", img.field->deform_scale);
      figs.push_back({{"n", std::to_string(n++)}, {"kind", img.kind}, {"caption", caption}, {"src", std::string(vector ? "data:image/svg+xml;base64," : "data:image/png;base64,") + base64(ss.str())}});
    }
  d["figures"] = figs;
  d["no_figures_reason"] = manifest.error.value_or("the runs have no snapshots or members");
  estimates_data(runs, design_doc, space, d);
  health_data(runs, d);
  d["limit_rows"] = limit_rows(design_doc);
  return d;
}

}  // namespace dmi::render
