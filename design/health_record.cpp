#include "design/health_record.hpp"

#include "design/record_reader.hpp"

#include <stdexcept>

namespace dmi::design {

using nlohmann::json;

using namespace record;

json to_json(const DampingShareRecord& d) {
  json j{{"impact_energy_J", d.impact_energy_J}, {"damping_energy_J", d.damping_energy_J}, {"damping_energy_at_governing_J", d.damping_energy_at_governing_J},
         {"governing_time_s", d.governing_time_s}, {"share_at_governing", d.share_at_governing}, {"share", d.share},
         {"received_at_governing_J", d.received_at_governing_J}, {"share_of_received_at_governing", d.share_of_received_at_governing},
         {"base_shear_peak", nullptr}, {"flag_above", d.flag_above}, {"flagged", d.flagged}};
  if (const auto& b = d.base_shear_peak)
    j["base_shear_peak"] = {{"time_s", b->time_s}, {"damping_J", b->damping_J}, {"received_J", b->received_J}, {"share_of_received", b->share_of_received}};
  return j;
}

json to_json(const std::vector<VolumeHealthRecord>& v) {
  json out = json::array();
  for (const auto& p : v)
    out.push_back({{"probe", p.probe}, {"final_ratio", p.final_ratio}, {"largest_ratio", p.largest_ratio}, {"largest_time_s", p.largest_time_s},
                   {"flagged", p.flagged}, {"flag_above", p.flag_above}});
  return out;
}

std::optional<DampingShareRecord> damping_from_json(const json& j, const std::string& w) {
  if (j.is_null()) return std::nullopt;
  DampingShareRecord d;
  d.impact_energy_J = number(j, "impact_energy_J", w), d.damping_energy_J = number(j, "damping_energy_J", w);
  d.damping_energy_at_governing_J = number(j, "damping_energy_at_governing_J", w), d.governing_time_s = number(j, "governing_time_s", w);
  d.share_at_governing = number(j, "share_at_governing", w), d.share = number(j, "share", w);
  d.received_at_governing_J = number(j, "received_at_governing_J", w);
  d.share_of_received_at_governing = number(j, "share_of_received_at_governing", w);
  d.flag_above = number(j, "flag_above", w), d.flagged = flag(j, "flagged", w);
  if (!j.contains("base_shear_peak")) throw std::runtime_error(w + ": no 'base_shear_peak'");
  if (const json& b = j["base_shear_peak"]; !b.is_null()) {
    const std::string wb = w + ".base_shear_peak";
    d.base_shear_peak = DampingShareRecord::AtBaseShearPeak{number(b, "time_s", wb), number(b, "damping_J", wb), number(b, "received_J", wb),
                                                            number(b, "share_of_received", wb)};
  }
  return d;
}

std::vector<VolumeHealthRecord> volume_health_from_json(const json& j, const std::string& w) {
  return record::items<VolumeHealthRecord>(j, w, [](const json& v, const std::string& at) {
    return VolumeHealthRecord{record::text(v, "probe", at), number(v, "final_ratio", at), number(v, "largest_ratio", at),
                              number(v, "largest_time_s", at), number(v, "flag_above", at), flag(v, "flagged", at)};
  });
}

}  // namespace dmi::design
