#include "design/section_records.hpp"

#include <cmath>
#include <stdexcept>

#include "design/members_json.hpp"
#include "design/record_reader.hpp"
#include "engine/io/records_json.hpp"

namespace dmi::design {

using nlohmann::json;
using record::field;
using record::flag;
using record::list;
using record::number;
using record::numbers;
using record::text;

namespace {

constexpr const char* kPulseThreshold = "5 % of the peak";

json peak_json(const SolidPeak& p) { return {{"value_Pa", p.value_Pa}, {"location_m", p.location_m}}; }

SolidPeak peak_from(const json& j, const char* key, const std::string& where) {
  const json& p = field(j, key, where);
  SolidPeak out{number(p, "value_Pa", where + "." + key), numbers(p, "location_m", where + "." + key)};
  if (out.location_m.size() != 2 && out.location_m.size() != 3) throw std::runtime_error(where + "." + key + ".location_m is not 2 or 3 numbers");
  return out;
}

}  // namespace

json to_json(const ReactionPeaks& p) {
  json j{{"name", p.name}};
  for (const auto& c : p.components)
    j[c.key] = {{"max", extreme_json(c.max)}, {"min", extreme_json(c.min)}, {"abs_max", extreme_json(c.abs)}, {"final", c.final}};
  return j;
}

json to_json(const BaseTotal& b) {
  json j = to_json(b.peaks);
  j["about_m"] = b.about_m;
  return j;
}

json to_json(const Contact& c) {
  if (!c.present) return nullptr;
  return json{{"peak_force_N", c.peak_N}, {"peak_time_s", c.peak_time_s >= 0 ? json(c.peak_time_s) : json(nullptr)},
              {"impulse_N_s", c.impulse_N_s}, {"impulse_magnitude_N_s", c.impulse_magnitude()},
              {"pulse", {{"start_s", c.pulse_start_s}, {"end_s", c.pulse_end_s}, {"duration_s", c.pulse_end_s - c.pulse_start_s},
                         {"impulse_N_s", c.pulse_impulse_N_s}}},
              {"loaded_time_s", c.loaded_time_s}, {"threshold", kPulseThreshold}};
}

json to_json(const SolidDesign& s) {
  json cases = json::array();
  for (const SolidDesignCase& c : s.cases)
    cases.push_back({{"name", c.name}, {"type", c.type}, {"load_resultant_N", c.load_resultant_N}, {"von_mises", peak_json(c.von_mises)},
                     {"max_principal", peak_json(c.max_principal)}, {"min_principal", peak_json(c.min_principal)},
                     {"max_nodal_base_reaction_N", c.max_nodal_base_reaction_N}, {"max_displacement_m", c.max_displacement_m}});
  return {{"model", solid_model_to_json(s.model)}, {"cases", cases}};
}

json to_json(const LocalDamageRecord& l) {
  return {{"model", l.model}, {"mass_kg", l.mass_kg}, {"diameter_m", l.diameter_m}, {"speed_m_s", l.speed_m_s},
          {"compressive_strength_Pa", l.compressive_strength_Pa}, {"impact_height_m", l.impact_height_m}, {"thickness_m", l.thickness_m},
          {"penetration_m", l.penetration_m}, {"scabbing_m", {{"ndrc", l.scabbing_ndrc_m}, {"chang", l.scabbing_chang_m}}},
          {"perforation_m", {{"ndrc", l.perforation_ndrc_m}, {"degen", l.perforation_degen_m}, {"chang", l.perforation_chang_m}}},
          {"in_range", {{"ndrc", l.ndrc_in_range}, {"degen", l.degen_in_range}, {"chang", l.chang_in_range}}},
          {"scabbing_design_m", l.scabbing_design_m}, {"perforation_design_m", l.perforation_design_m}};
}

ReactionPeaks reaction_from_json(const json& j, const std::string& where) {
  ReactionPeaks p;
  p.name = text(j, "name", where);
  for (const auto& [key, c] : j.items()) {
    if (key == "name" || key == "about_m") continue;
    const std::string at = where + "." + key;
    if (!c.is_object()) throw std::runtime_error(at + " is not an object");
    p.components.push_back({key, extreme_from_json(c, "max", at), extreme_from_json(c, "min", at), extreme_from_json(c, "abs_max", at),
                            number(c, "final", at)});
  }
  return p;
}

std::optional<BaseTotal> base_total_from_json(const json& j, const std::string& where) {
  if (j.is_null()) return std::nullopt;
  return BaseTotal{reaction_from_json(j, where), numbers(j, "about_m", where)};
}

Contact contact_from_json(const json& j, const std::string& where) {
  Contact c;
  if (j.is_null()) return c;
  c.present = true;
  c.peak_N = number(j, "peak_force_N", where), c.peak_time_s = record::number_or(j, "peak_time_s", -1, where);
  c.impulse_N_s = numbers(j, "impulse_N_s", where), c.loaded_time_s = number(j, "loaded_time_s", where);
  const json& p = field(j, "pulse", where);
  c.pulse_start_s = number(p, "start_s", where + ".pulse"), c.pulse_end_s = number(p, "end_s", where + ".pulse");
  c.pulse_impulse_N_s = number(p, "impulse_N_s", where + ".pulse");
  return c;
}

std::optional<SolidDesign> solid_design_from_json(const json& j, const std::string& where) {
  if (j.is_null()) return std::nullopt;
  SolidDesign s;
  s.model = solid_model_from_json(field(j, "model", where), where + ".model");
  s.cases = record::items<SolidDesignCase>(list(j, "cases", where), where + ".cases", [](const json& c, const std::string& at) {
    return SolidDesignCase{text(c, "name", at), text(c, "type", at), number(c, "load_resultant_N", at), number(c, "max_nodal_base_reaction_N", at),
                           number(c, "max_displacement_m", at), peak_from(c, "von_mises", at), peak_from(c, "max_principal", at),
                           peak_from(c, "min_principal", at)};
  });
  return s;
}

std::optional<LocalDamageRecord> local_damage_from_json(const json& j, const std::string& where) {
  if (j.is_null()) return std::nullopt;
  LocalDamageRecord l;
  l.model = text(j, "model", where);
  l.mass_kg = number(j, "mass_kg", where), l.diameter_m = number(j, "diameter_m", where), l.speed_m_s = number(j, "speed_m_s", where);
  l.compressive_strength_Pa = number(j, "compressive_strength_Pa", where), l.impact_height_m = number(j, "impact_height_m", where);
  l.thickness_m = number(j, "thickness_m", where), l.penetration_m = number(j, "penetration_m", where);
  const json& sc = field(j, "scabbing_m", where);
  l.scabbing_ndrc_m = number(sc, "ndrc", where + ".scabbing_m"), l.scabbing_chang_m = number(sc, "chang", where + ".scabbing_m");
  const json& pf = field(j, "perforation_m", where);
  l.perforation_ndrc_m = number(pf, "ndrc", where + ".perforation_m"), l.perforation_degen_m = number(pf, "degen", where + ".perforation_m");
  l.perforation_chang_m = number(pf, "chang", where + ".perforation_m");
  const json& r = field(j, "in_range", where);
  l.ndrc_in_range = flag(r, "ndrc", where + ".in_range"), l.degen_in_range = flag(r, "degen", where + ".in_range");
  l.chang_in_range = flag(r, "chang", where + ".in_range");
  l.scabbing_design_m = number(j, "scabbing_design_m", where), l.perforation_design_m = number(j, "perforation_design_m", where);
  return l;
}

}  // namespace dmi::design
