// The report's sections on design-practice loads (the estimates, a debris surge's phases), numerical health and the
// limits used (docs/design-checks.md), for report_data.cpp.
#include <cmath>
#include <string>

#include "design/estimates.hpp"
#include "design/health_record.hpp"
#include "design/phases.hpp"
#include "render/report_rows.hpp"

namespace dmi::render {

using nlohmann::json;

void estimates_data(const std::vector<RunData>& runs, const design::DesignDocument& design_doc, bool space, json& d) {
  // Design-practice loads beside the simulation.
  json est = json::array();
  bool banded = false;
  for (const auto& r : runs)
    for (const design::Estimate& e : r.design.estimates) {
      const bool ok = e.applicable;
      const std::string what = e.compare_to == "peak_base_shear" ? "base shear" : "contact";
      std::string sim = ok ? eng(e.simulated, "N") : "—", sim_note = ok ? what : "", ratio = ok ? fmt("%.2f", e.ratio) : "—", band;
      if (ok && e.grid) {
        banded = true;
        sim_note += fmt(", GCI %.0f %%", 100 * e.simulated_gci);
        band = fmt("%.2f", e.ratio_low) + "–" + (e.ratio_high ? fmt("%.2f", *e.ratio_high) : std::string("∞"));
      }
      const double q = ok ? e.ratio : NAN;
      const bool far = ok && (q < 0.5 || q > 2);
      const std::string note = estimate_note(q, e.note);
      est.push_back({{"run", label(r)}, {"title", e.title}, {"formula", e.formula}, {"parameters", e.parameters},
                     {"value", ok ? eng(e.value, "N") : std::string("n/a")}, {"simulated", sim}, {"simulated_note", sim_note}, {"ratio", ratio}, {"ratio_band", band}, {"source", e.source},
                     {"note", note}, {"row_class", ok ? (far ? "far" : "") : "muted"}});
    }
  d["estimates"] = est;
  // The debris load in its three phases, against the momentum flux of the surge.
  json phases = json::array();
  for (const auto& r : runs) {
    const std::optional<design::DebrisLoad>& load = r.design.debris_phases;
    if (!load) continue;
    const design::DebrisPhases& p = load->phases;
    auto force = [&](std::optional<double> f) {  // the force, and α = F / F0 under it
      return f && std::isfinite(*f / p.flux_N) ? json{{"v", eng(*f, "N")}, {"a", fmt("α %.2f", *f / p.flux_N)}}
                                               : json{{"v", "—"}, {"a", "the run ends within the passage"}};
    };
    auto seconds = [](double t) { return std::isfinite(t) ? fmt("%.3f s", t) : std::string("—"); };
    phases.push_back({{"run", label(r)}, {"flux", eng(p.flux_N, "N")}, {"arrival", seconds(p.arrival_s)}, {"passage", seconds(p.passage_s)},
                      {"peak", force(p.peak_N)}, {"peak_at", seconds(p.peak_time_s)}, {"dynamic", force(p.dynamic_N)}, {"static", force(p.static_N)}});
  }
  d["has_debris_phases"] = !phases.empty();
  d["debris_practice"] = debris_practice_rows(runs, design_doc);
  d["debris_phases"] = phases;
  d["debris_phases_intro"] =
      "The contact force of the surge in its three phases (Cui, Zeng & Lei 2015): the peak while the surge passes (from its arrival, the "
      "first 1 % of the momentum flux, for T = L / v), the dynamic load of its body (mean over the last three quarters of T) and the static "
      "load of the deposit (mean over the last 10 % of the run). α = F / (ρ v² h w), the dynamic impact coefficient (GEO Report 270 takes "
      "α = 2.5 for a rigid barrier). The surge's snout is set by debris_surge.front_length; a blunt front strikes as an elastic wave set by "
      "the debris modulus (the bound row of the table above).";
  d["estimates_intro"] =
      std::string("The loads design practice would assign to this impact, beside the simulated peak they stand for (a sanity band, not checks): "
                  "ratio = estimate / simulated. A model that does not fit the scenario is listed with the reason. ") +
      (space ? "The 3D model strikes with a sphere, as the boulder formulas assume. "
             : "The 2D model strikes with a cylinder of the boulder's mass, while the boulder formulas assume a sphere. ") +
      "Formulas, sources and assumptions: docs/design-checks.md." +
      (banded ? " With the grid study, the simulated peak carries its grid convergence index (GCI) and the ratio the band it spans for the simulated peak within ± GCI." : "");
}

void health_data(const std::vector<RunData>& runs, json& d) {
  // Health.
  d["health_intro"] =
      "Energy balance error = kinetic + strain (+ frame) − work of gravity and walls − energy brought in by inflows − initial energy; member "
      "contact is internal, so "
      "its losses show as a negative error. Reference: the largest kinetic + strain energy of the run.";
  d["health_rows"] = per_run_rows(runs, {
      {"status", [](const RunData& r) { return r.results.complete ? std::string("complete") : std::string("incomplete"); }},
      {"non-finite values in the histories", [](const RunData& r) { return all_finite(r.results) ? std::string("none") : std::string("FOUND"); }},
      {"reference energy", [](const RunData& r) { return fmt("%.4g kJ", reference_energy(r.results) / 1e3); }},
      {"largest energy created", [](const RunData& r) {
         const double e = series_max(r.results, "energy/balance_error", false), ref = reference_energy(r.results);
         return std::isnan(e) ? std::string("—") : fmt("%.3g J", std::max(0.0, e)) + fmt(" (%.2f %%)", 100 * std::max(0.0, e) / ref);
       }},
      {"largest |balance error|", [](const RunData& r) {
         const double e = series_max(r.results, "energy/balance_error", true), ref = reference_energy(r.results);
         return std::isnan(e) ? std::string("—") : fmt("%.3g J", e) + fmt(" (%.1f %%)", 100 * e / ref);
       }},
      {"energy dissipated by the members' structural damping", [](const RunData& r) {
         const Series* s = r.results.find("energy/frame_damping");
         if (!s || s->data.empty()) return std::string("—");
         std::string t = fmt("%.4g J", s->data.back());
         if (const auto& d = r.design.damping)
           t += fmt(" (%.1f %% of the impact energy; by the governing member demand ", 100 * d->share) +
                fmt("%.1f %% of it", 100 * d->share_at_governing) +
                fmt(" and %.1f %% of the energy the members had received", 100 * d->share_of_received_at_governing) +
                (d->base_shear_peak ? fmt("; by the peak base shear %.1f %% of it", 100 * d->base_shear_peak->share_of_received) : std::string()) +
                (d->flagged ? ": ABOVE 10 %, the peaks rest on the damping ratio)" : ")");
         return t;
       }},
      {"bodies' volume (largest / as created; flagged above 1.05)", [](const RunData& r) {
         std::string t;
         for (const auto& v : r.design.volume_health)
           t += (t.empty() ? "" : "; ") + v.probe + fmt(" %.3f", v.largest_ratio) +
                (v.flagged ? " (GAINED VOLUME: a non-dilatant body should keep it; its loads are suspect)" : "");
         return t.empty() ? std::string("—") : t;
       }},
      {"largest Courant number used", [](const RunData& r) {
         const auto& c = r.results.info.stats.courant_max;
         return c ? fmt("%.3f", *c) : std::string("—");
       }},
      {"smallest particle J = V/V0", [](const RunData& r) {
         const auto& j = r.results.info.stats.jacobian_min;
         return j ? fmt("%.4f", *j) : std::string("—");
       }},
      {"contact projection iterations, max", [](const RunData& r) {
         const auto& p = r.results.info.stats.projection_iterations_max;
         return p ? fmt("%.0f", *p) : std::string("—");
       }}});
}

json limit_rows(const design::DesignDocument& design_doc) {
  // Limits.
  json lr = json::array();
  const design::Limits& L = design_doc.limits;
  const design::ConcreteLimits& c = L.concrete;
  const design::FoundationLimits& f = L.foundation;
  lr.push_back({{"key", "concrete f'c, f_t (rule)"}, {"value", eng(c.compressive_strength, "Pa") + ", " + eng(c.tensile_value(), "Pa") + " (" + c.tensile_rule + ")"}});
  lr.push_back({{"key", "concrete φ flexure / compression / shear, α"},
                {"value", fmt("%.2f", c.phi_flexure) + " / " + fmt("%.2f", c.phi_compression) + " / " + fmt("%.2f", c.phi_shear) + ", " +
                              fmt("%.2f", c.compression_coefficient)}});
  lr.push_back({{"key", "steel f_y, γ_M0"}, {"value", eng(L.steel.yield_strength, "Pa") + ", " + fmt("%.2f", L.steel.gamma_M0)}});
  lr.push_back({{"key", "concrete strengths under the impact"}, {"value", c.strain_rate_effects ? "raised by the strain rate (fib MC2010 5.1.11.1)" : "static"}});
  lr.push_back({{"key", "foundation joint: tan φ, c, allowable bearing, uplift"},
                {"value", fmt("%.2f", f.friction) + ", " + eng(f.cohesion, "Pa") + ", " + eng(f.bearing_capacity, "Pa") +
                              fmt(", %.2f of full (assumptions unless the limits file sets them)", f.uplift_factor)}});
  lr.push_back({{"key", "stability: sliding factor at rest, sliding limit, rocking factor"},
                {"value", fmt("%.2f", f.sliding_factor_usual) + ", " + eng(f.sliding_displacement_limit, "m") + fmt(", %.2f", f.rocking_safety_factor)}});
  lr.push_back({{"key", "levels judged"}, {"value", L.verdict_level}});
  return lr;
}

}  // namespace dmi::render
