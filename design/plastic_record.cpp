#include "design/plastic_record.hpp"

#include "design/record_reader.hpp"

#include <stdexcept>

namespace dmi::design {

using nlohmann::json;

using namespace record;

namespace {

json energy_json(const PlasticRecord::Energy& e) {
  json j{{"plastic_work_J", e.plastic_work_J}, {"by_group_J", e.by_group_J}, {"damping_J", e.damping_J}, {"elastic_at_end_J", e.elastic_at_end_J},
         {"kinetic_at_end_J", e.kinetic_at_end_J}};
  if (e.contact_work_max_J) j["contact_work_max_J"] = *e.contact_work_max_J;
  if (e.boulder_kinetic_J) j["boulder_kinetic_J"] = *e.boulder_kinetic_J;
  return j;
}

PlasticRecord::Energy energy_from(const json& j, const std::string& where) {
  PlasticRecord::Energy e;
  e.plastic_work_J = number(j, "plastic_work_J", where), e.damping_J = number(j, "damping_J", where);
  e.elastic_at_end_J = number(j, "elastic_at_end_J", where), e.kinetic_at_end_J = number(j, "kinetic_at_end_J", where);
  e.contact_work_max_J = number_if_there(j, "contact_work_max_J", where), e.boulder_kinetic_J = number_if_there(j, "boulder_kinetic_J", where);
  const json& g = field(j, "by_group_J", where);
  if (!g.is_object()) throw std::runtime_error(where + ".by_group_J is not an object");
  for (const auto& [name, v] : g.items()) e.by_group_J[name] = number(g, name.c_str(), where + ".by_group_J");
  return e;
}

}  // namespace

json to_json(const PlasticRecord& p) {
  json members = json::array();
  for (const auto& m : p.members)
    members.push_back({{"member", m.member}, {"group", m.group}, {"plastic_work_J", m.plastic_work_J}, {"peak_strain", m.peak_strain}, {"yielded", m.yielded}});
  json out{{"member_model", p.member_model}, {"energy", energy_json(p.energy)}, {"members", members}, {"residual_drift", nullptr}, {"dent", nullptr}};
  if (const auto& d = p.residual_drift)
    out["residual_drift"] = {{"node_index", d->node_index}, {"residual_m", d->residual_m}, {"amplitude_m", d->amplitude_m}, {"height_m", d->height_m},
                             {"window_s", d->window_s}, {"drift", d->drift}, {"settled", d->settled}};
  if (const auto& d = p.dent)
    out["dent"] = {{"member", d->member}, {"diameter_m", d->diameter_m}, {"wall_thickness_m", d->wall_thickness_m},
                   {"pulse_mean_force_N", d->pulse_mean_force_N}, {"energy_J", d->energy_J}, {"depth_at_force_m", d->depth_at_force_m},
                   {"depth_for_energy_m", d->depth_for_energy_m}, {"depth_m", d->depth_m}};
  return out;
}

std::optional<PlasticRecord> plastic_from_json(const json& j, const std::string& where) {
  if (j.is_null()) return std::nullopt;
  PlasticRecord p;
  p.member_model = text(j, "member_model", where);
  p.energy = energy_from(field(j, "energy", where), where + ".energy");
  const json& ms = field(j, "members", where);
  if (!ms.is_array()) throw std::runtime_error(where + ".members is not an array");
  for (std::size_t k = 0; k < ms.size(); ++k) {
    const std::string at = where + ".members[" + std::to_string(k) + "]";
    p.members.push_back({text(ms[k], "member", at), text(ms[k], "group", at), number(ms[k], "plastic_work_J", at), number(ms[k], "peak_strain", at),
                         flag(ms[k], "yielded", at)});
  }
  if (const json& d = field(j, "residual_drift", where); !d.is_null()) {
    const std::string at = where + ".residual_drift";
    const json& n = field(d, "node_index", at);
    if (!n.is_number_integer()) throw std::runtime_error(at + ".node_index is not a whole number");
    p.residual_drift = PlasticRecord::Drift{n.get<int>(), number(d, "residual_m", at), number(d, "amplitude_m", at), number(d, "height_m", at),
                                            number(d, "window_s", at), number(d, "drift", at), flag(d, "settled", at)};
  }
  if (const json& d = field(j, "dent", where); !d.is_null()) {
    const std::string at = where + ".dent";
    p.dent = PlasticRecord::Dent{text(d, "member", at), number(d, "diameter_m", at), number(d, "wall_thickness_m", at),
                                 number(d, "pulse_mean_force_N", at), number(d, "energy_J", at), number(d, "depth_at_force_m", at),
                                 number(d, "depth_for_energy_m", at), number(d, "depth_m", at)};
  }
  return p;
}

}  // namespace dmi::design
