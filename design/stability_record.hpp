// design.json's "stability" as a typed record (docs/design-json.md): the concrete gravity dam as a rigid block on its
// foundation joint, at rest and under the impact. Built by stability_checks, written by to_json, read back validated
// by stability_from_json for the report.
#pragma once
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace dmi::design {

struct StabilityRecord {
  // One instant on the joint: the normal and shear forces, the factors (NaN where undefined: written null), where
  // the resultant cuts the base and the pressures at toe and heel.
  struct Sample {
    double time_s = 0, N_N = 0, H_N = 0, sliding_factor = NAN, overturning_factor = NAN;
    double resultant_from_toe_m = NAN, eccentricity_m = NAN, compressed_fraction = 0, toe_pressure_Pa = NAN, heel_pressure_Pa = NAN;
  };
  // Set when the run cannot be assessed (its frame's weight is not the dam's): why; the rest is then unset.
  std::string not_assessed;
  std::string model;
  struct Dam {
    double mass_kg = 0, weight_N = 0, base_m = 0, width_m = 0, weight_lever_from_toe_m = 0, centroid_height_m = 0, inertia_about_toe_kg_m2 = 0;
    double critical_angle_rad = 0;
  } dam;
  struct Foundation {
    double friction = 0, cohesion_Pa = 0, bearing_capacity_Pa = 0, uplift_factor = 0, uplift_N = 0;
  } foundation;
  Sample persistent;
  struct Impact {
    Sample least_sliding_factor, least_compressed_base;
    double time_outside_middle_third_s = 0, time_outside_base_s = 0;
    double sliding_displacement_m = 0, peak_rocking_rotation_rad = 0;  // +inf: does not stop, topples (written null)
  } impact;
};

nlohmann::json to_json(const StabilityRecord& s);
// null reads as nullopt (not a gravity dam); `where` names the place in errors.
std::optional<StabilityRecord> stability_from_json(const nlohmann::json& j, const std::string& where);

}  // namespace dmi::design
