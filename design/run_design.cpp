#include "design/run_design.hpp"

#include <cmath>
#include <stdexcept>

#include "design/members_json.hpp"
#include "design/record_reader.hpp"

namespace dmi::design {

using nlohmann::json;
using record::field;
using record::text;

std::optional<double> RunDesign::base_abs_max(const std::string& key) const {
  if (!base_total) return std::nullopt;
  for (const ReactionComponent& c : base_total->peaks.components)
    if (c.key == key && c.abs.set) return c.abs.value;
  return std::nullopt;
}

json to_json(const RunDesign& r) {
  json j{{"results_file", r.results_file}, {"scenario_name", r.scenario_name}, {"variant", r.variant}, {"reference", r.reference}};
  j["members"] = json::array();
  for (const MemberEnvelope& m : r.members) j["members"].push_back(member_json(m));
  j["supports"] = json::array();
  for (const ReactionPeaks& s : r.supports) j["supports"].push_back(to_json(s));
  j["base_total"] = r.base_total ? to_json(*r.base_total) : json(nullptr);
  if (r.dimension) j["dimension"] = *r.dimension;
  j["contact"] = to_json(r.contact);
  j["solid"] = r.solid ? to_json(*r.solid) : json(nullptr);
  j["plastic"] = r.plastic ? to_json(*r.plastic) : json(nullptr);
  j["steel_yield_strength_Pa"] = r.steel_yield_strength_Pa;
  j["estimates"] = json::array();
  for (const Estimate& e : r.estimates) j["estimates"].push_back(e.to_json());
  j["debris_phases"] = r.debris_phases ? r.debris_phases->to_json() : json(nullptr);
  j["stability"] = r.stability ? to_json(*r.stability) : json(nullptr);
  j["local_damage"] = r.local_damage ? to_json(*r.local_damage) : json(nullptr);
  j["checks"] = json::array();
  for (const Check& k : r.checks) j["checks"].push_back(k.to_json());
  j["verdict"] = to_json(r.verdict);
  j["damping"] = r.damping ? to_json(*r.damping) : json(nullptr);
  j["volume_health"] = to_json(r.volume_health);
  j["face_profile"] = r.face_profile ? to_json(*r.face_profile) : json(nullptr);
  j["sensors"] = to_json(r.sensors);
  return j;
}

namespace {

const json& section(const json& j, const char* key) {
  static const json none;
  return j.is_object() && j.contains(key) ? j[key] : none;
}

}  // namespace

RunDesign run_design_from_json(const json& j, const std::string& where) {
  if (!j.is_object()) throw std::runtime_error(where + " is not an object");
  RunDesign r;
  r.results_file = text(j, "results_file", where), r.scenario_name = text(j, "scenario_name", where), r.variant = text(j, "variant", where);
  if (j.contains("dimension")) {
    const int d = record::count(j, "dimension", where);
    if (d != 2 && d != 3) throw std::runtime_error(where + ".dimension is not 2 or 3");
    r.dimension = d;
  }
  r.reference = j.contains("reference") && record::flag(j, "reference", where);
  r.members = members_from_json(j, where);
  r.supports = record::items<ReactionPeaks>(record::list(j, "supports", where), where + ".supports", reaction_from_json);
  r.base_total = base_total_from_json(field(j, "base_total", where), where + ".base_total");
  r.contact = contact_from_json(field(j, "contact", where), where + ".contact");
  r.solid = solid_design_from_json(field(j, "solid", where), where + ".solid");
  r.plastic = plastic_from_json(section(j, "plastic"), where + ".plastic");
  r.steel_yield_strength_Pa = record::number(j, "steel_yield_strength_Pa", where);
  r.estimates = estimates_from_json(j, where);
  r.debris_phases = debris_load_from_json(section(j, "debris_phases"), where + ".debris_phases");
  r.stability = stability_from_json(section(j, "stability"), where + ".stability");
  r.local_damage = local_damage_from_json(section(j, "local_damage"), where + ".local_damage");
  r.checks = checks_from_json(j, where);
  r.verdict = verdict_from_json(field(j, "verdict", where), false, where + ".verdict");
  r.damping = damping_from_json(section(j, "damping"), where + ".damping");
  r.volume_health = volume_health_from_json(section(j, "volume_health"), where + ".volume_health");
  r.face_profile = face_profile_from_json(section(j, "face_profile"), where + ".face_profile");
  r.sensors = sensors_from_json(section(j, "sensors"), where + ".sensors");
  return r;
}

}  // namespace dmi::design
