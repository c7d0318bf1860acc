// Two statements on how far a run's peaks can be trusted, as typed records of design.json (docs/design-json.md): the
// share of the impact's energy the members' damping took (runs[].damping) and each body probe's volume against its
// particles' (runs[].volume_health). Built by damping_share and volume_health, written by to_json, read back validated.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace dmi::design {

struct DampingShareRecord {
  double impact_energy_J = 0, damping_energy_J = 0, damping_energy_at_governing_J = 0, governing_time_s = 0;
  double share_at_governing = 0, share = 0, received_at_governing_J = 0, share_of_received_at_governing = 0, flag_above = 0;
  struct AtBaseShearPeak {
    double time_s = 0, damping_J = 0, received_J = 0, share_of_received = 0;
  };
  std::optional<AtBaseShearPeak> base_shear_peak;
  bool flagged = false;
};

struct VolumeHealthRecord {
  std::string probe;
  double final_ratio = 0, largest_ratio = 0, largest_time_s = 0, flag_above = 0;
  bool flagged = false;
};

nlohmann::json to_json(const DampingShareRecord& d);
nlohmann::json to_json(const std::vector<VolumeHealthRecord>& v);
// null reads as nullopt; `where` names the place in errors.
std::optional<DampingShareRecord> damping_from_json(const nlohmann::json& j, const std::string& where);
std::vector<VolumeHealthRecord> volume_health_from_json(const nlohmann::json& j, const std::string& where);

}  // namespace dmi::design
