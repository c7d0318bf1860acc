// design.json's "plastic" as a typed record (docs/design-json.md): the energy the yielding members took, per member and
// per member group, the crest's residual drift and the struck pipe's dent. Built by plastic_checks, written by to_json,
// read back validated by plastic_from_json for the report and `check`'s summary.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace dmi::design {

struct PlasticRecord {
  std::string member_model = "elasto-plastic fibre beam-columns";
  struct Energy {
    double plastic_work_J = 0, damping_J = 0, elastic_at_end_J = 0, kinetic_at_end_J = 0;
    std::optional<double> contact_work_max_J, boulder_kinetic_J;
    std::map<std::string, double> by_group_J;  // member group -> plastic work
  } energy;
  struct Member {
    std::string member, group;
    double plastic_work_J = 0, peak_strain = 0;
    bool yielded = false;
  };
  std::vector<Member> members;
  struct Drift {
    int node_index = 0;
    double residual_m = 0, amplitude_m = 0, height_m = 0, window_s = 0, drift = 0;
    bool settled = false;
  };
  std::optional<Drift> residual_drift;
  struct Dent {
    std::string member;
    double diameter_m = 0, wall_thickness_m = 0, pulse_mean_force_N = 0, energy_J = 0, depth_at_force_m = 0, depth_for_energy_m = 0, depth_m = 0;
  };
  std::optional<Dent> dent;
};

nlohmann::json to_json(const PlasticRecord& p);
// null reads as nullopt (no elasto-plastic member); `where` names the place in errors.
std::optional<PlasticRecord> plastic_from_json(const nlohmann::json& j, const std::string& where);

}  // namespace dmi::design
