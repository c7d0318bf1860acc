// design_run: one results.h5 -> the design of one run (design.json "runs"[], docs/design-json.md).
#include "design/design.hpp"
#include "design/verdict.hpp"
#include "design/plastic_checks.hpp"

#include "engine/common/json_input.hpp"
#include "engine/io/records_json.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <stdexcept>

#include "design/damping_share.hpp"
#include "design/estimates.hpp"
#include "design/pressures.hpp"
#include "design/volume_health.hpp"
#include "design/phases.hpp"
#include "design/local_damage_checks.hpp"
#include "design/stability_checks.hpp"
#include "design/loads.hpp"
#include "design/members.hpp"
#include "design/members_json.hpp"
#include "design/run_design.hpp"

namespace dmi::design {

using nlohmann::json;

namespace {

// Solid-FE peaks (Lin, Cheng & Tuan, Table 1) and their concrete checks: max principal vs phi_f f_t, min principal vs phi_c alpha f'c.
std::optional<SolidDesign> solid_part(const std::optional<SolidCheckRecord>& doc, const Limits& L, std::vector<Check>& checks) {
  if (!doc) return std::nullopt;
  SolidDesign out{doc->model, {}};
  for (const SolidCase& c : doc->cases) {
    const SolidPeak& mx = c.peaks.at("max_principal").at("gauss");
    const SolidPeak& mn = c.peaks.at("min_principal").at("gauss");
    out.cases.push_back({c.name, c.type, c.load_resultant_N, c.max_nodal_base_reaction_N, c.max_displacement_m, c.peaks.at("von_mises").at("gauss"), mx, mn});
    auto add = [&](const char* id, const char* title, double demand, double cap, const std::vector<double>& loc, const char* formula, const char* src) {
      Check k;
      k.id = id, k.title = title, k.member = "solid: " + c.name, k.material = "concrete", k.unit = "Pa";
      k.level = "information";  // a linear stress under the contact patch: singular under a point load, local
      k.demand = demand, k.capacity = cap, k.formula = formula, k.source = src;
      k.x_m = loc.at(0), k.y_m = loc.size() > 2 ? loc.at(2) : loc.at(1);
      if (c.time_s) k.time_s = *c.time_s;
      k.finish();
      checks.push_back(k);
    };
    add("solid_principal_tension", "principal tension", std::max(0.0, mx.value_Pa), L.concrete.tensile_capacity(), mx.location_m,
        "sigma_1 <= phi_f f_t", "Lin, Cheng & Tuan, Table 1; ACI 318-19 21.2.1");
    add("solid_principal_compression", "principal compression", std::max(0.0, -mn.value_Pa), L.concrete.compressive_capacity(), mn.location_m,
        "|sigma_3| <= phi_c alpha f'c", "ACI 318-19 21.2.1, 22.2.2.4.1");
  }
  return out;
}

double norm(const std::vector<double>& v) {
  double s = 0;
  for (double c : v) s += c * c;
  return std::sqrt(s);
}

// Punching around the contact patch (ACI 318-19 Table 14.5.5.1(b)), concrete members only. Demand: the total contact
// force at the peak contact (the step of the largest contact force), at the force-weighted position of its loads on
// the most loaded member, where the member depth is taken.
void punching(const std::optional<PeakContact>& pc, const std::vector<MemberEnvelope>& members, const Limits& L, std::vector<Check>& checks) {
  if (!L.concrete.punching_patch_width || !pc) return;
  std::map<std::string, std::pair<double, double>> on;  // member -> (sum |F|, sum |F| position)
  for (const ContactLoadAt& l : pc->loads) {
    const double f = norm(l.force);
    auto& s = on[l.member];
    s.first += f, s.second += f * std::clamp(l.position, 0.0, 1.0);
  }
  if (on.empty()) return;
  const auto best = std::max_element(on.begin(), on.end(), [](const auto& a, const auto& b) { return a.second.first < b.second.first; });
  const auto m = std::find_if(members.begin(), members.end(), [&](const MemberEnvelope& e) { return e.name == best->first; });
  if (m == members.end() || m->cls != "concrete" || !(best->second.first > 0)) return;
  const double pos = best->second.second / best->second.first;
  const auto& st = m->stations;  // depth at the load: linear between stations
  std::size_t k = 0;
  while (k + 2 < st.size() && st[k + 1].position < pos) ++k;
  const double w = std::clamp((pos - st[k].position) / (st[k + 1].position - st[k].position), 0.0, 1.0);
  const double h = st[k].depth + w * (st[k + 1].depth - st[k].depth);
  Check p;
  p.id = "concrete_punching", p.title = "punching shear at the contact patch", p.member = m->name, p.material = "concrete", p.unit = "N";
  p.level = "ultimate";
  p.demand = norm(pc->total_force);
  p.capacity = concrete_punching_capacity(L.concrete.compressive_strength, L.concrete.lambda, *L.concrete.punching_patch_width,
                                          *L.concrete.punching_patch_height, h, L.concrete.phi_shear);
  p.position = pos, p.s_m = pos * m->length, p.time_s = pc->time;
  p.x_m = st[k].x + w * (st[k + 1].x - st[k].x), p.y_m = st[k].y + w * (st[k + 1].y - st[k].y), p.z_m = st[k].z + w * (st[k + 1].z - st[k].z);
  p.space = m->dim == 3;
  p.formula = "F_contact <= phi_v min(0.11 (1 + 2/beta), 0.22) lambda sqrt(f'c) b_o h, b_o = 2 (c1 + h) + 2 (c2 + h)";
  p.source = "ACI 318-19 Table 14.5.5.1(b), 22.6.4.1";
  p.finish();
  checks.push_back(p);
}

// The documents the run's own scenario promises: a file whose scenario has members (or a solid check) but not their
// document was cut or altered, and checking what is left would read "NO CHECKS" or a partial PASS.
void require_documents(const Results& r, const std::string& where) {
  const std::string& text = r.info.scenario_expanded_json.empty() ? r.info.scenario_json : r.info.scenario_expanded_json;
  if (text.empty()) throw std::runtime_error(where + ": /scenario is missing: the file does not say what was simulated; nothing to check");
  check_json_structure(text, where + ": /scenario");
  const json sc = json::parse(text, nullptr, false);
  if (sc.is_discarded() || !sc.is_object()) throw std::runtime_error(where + ": /scenario is not a JSON object; nothing to check");
  const json* members = sc.contains("structure") && sc["structure"].is_object() && sc["structure"].contains("members") ? &sc["structure"]["members"] : nullptr;
  if (members && members->is_array() && !members->empty() && !r.info.structure)
    throw std::runtime_error(where + ": /documents/structure is missing although the scenario has " + std::to_string(members->size()) +
                             " member(s): the file is incomplete or altered; nothing to check");
  if (sc.contains("solid_check") && !r.info.solid_check)
    throw std::runtime_error(where + ": /documents/solid_check is missing although the scenario has a solid_check: the file is incomplete or altered; nothing to check");
}

}  // namespace

RunDesign design_run(const Results& r, const Limits& limits, const std::string& where) {
  if (!r.complete) throw std::runtime_error(where + ": the run did not finish (complete = 0); nothing to check");
  require_documents(r, where);
  const std::optional<DesignBasis>& basis = r.info.design_basis;
  Limits L = limits;  // the steel's f_y is the one the run simulated, when its design basis gives it
  if (basis && is_set(basis->dam.yield_strength_Pa)) L.steel.yield_strength = basis->dam.yield_strength_Pa;
  RunDesign run;
  run.results_file = where, run.scenario_name = r.info.scenario_name, run.variant = r.info.variant;
  std::vector<Check> checks;
  run.contact = contact(r);
  const Contact& c = run.contact;
  double base_shear = 0, base_shear_time = -1;
  std::optional<FrameInfo> frame;
  if (r.info.structure) {
    const FrameInfo& f = frame.emplace(frame_info(*r.info.structure, where, L));
    if (!(basis && is_set(basis->dam.yield_strength_Pa)))  // else the f_y its plastic members yielded at
      for (const auto& e : f.elements)
        if (e.yield_strength > 0) {
          L.steel.yield_strength = e.yield_strength;
          break;
        }
    run.members = member_envelopes(r, f, L, where);
    for (auto& m : run.members) {  // the run's checks hold them (as design.json does)
      checks.insert(checks.end(), m.checks.begin(), m.checks.end());
      m.checks.clear();
    }
    Reactions re = reactions(r, f, where);
    run.supports = re.supports;
    if (!re.supports.empty()) {
      run.base_total = BaseTotal{re.total, f.dim == 3 ? std::vector<double>{re.about[0], re.about[1], re.about[2]} : std::vector<double>{re.about[0], re.about[1]}};
      base_shear = re.total.at(shear_key(f.dim)).abs.value;
      base_shear_time = re.total.at(shear_key(f.dim)).abs.time;
    }
    run.dimension = f.dim;
  }
  punching(r.info.peak_contact, run.members, L, checks);
  run.solid = solid_part(r.info.solid_check, L, checks);
  run.plastic = frame ? plastic_part(r, *frame, run.members, basis, c, L.steel, checks, where) : std::nullopt;
  run.steel_yield_strength_Pa = L.steel.yield_strength;
  if (basis) run.estimates = estimates(*basis, base_shear, c.present ? c.peak_N : 0.0, r.info.dimension);
  if (basis) run.debris_phases = debris_phases(r, *basis);
  if (basis && frame) run.stability = stability(r, *frame, *basis, L.foundation, checks, where);
  if (basis) run.local_damage = local_damage_checks(*basis, L.concrete, checks);
  run.verdict = run_verdict(checks, L.verdict_level);
  // The damping's share by the instant of the most utilised member check (else the contact peak).
  double t_member = c.present ? c.peak_time_s : r.time.empty() ? 0.0 : r.time.back(), u_member = -1;
  for (const auto& k : checks)
    if (k.s_m >= 0 && k.time_s >= 0 && k.situation == "accidental" && k.utilisation > u_member) u_member = k.utilisation, t_member = k.time_s;
  if (basis) run.damping = damping_share(r, *basis, t_member, base_shear_time);
  run.volume_health = volume_health(r);
  run.face_profile = face_profile(r, where);
  run.sensors = sensor_peaks(r);
  run.checks = std::move(checks);
  return run;
}

}  // namespace dmi::design
