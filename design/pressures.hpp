// Pressures on the struck face (docs/design-json.md, "face_profile" and "sensors"): the profile of the contact
// pressure along a dam's upstream face at the instant its overturning moment about the face's foot is largest (the
// height of the resultant sets the base moment), and the peak of every pressure sensor.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/io/results.hpp"

namespace dmi::design {

// design.json's "face_profile": the face's members, the load's direction, the face width, per element its centre and
// length along the face and its pressure at time_s, the instant of the largest moment about the foot; the resultant
// there, its height above the foot (across the load) and moment; the largest resultant of the run and when.
struct FaceProfileAtMoment {
  std::vector<std::string> members;
  std::vector<double> direction, positions_m, lengths_m, pressure_Pa;
  double width_m = 0, time_s = 0, resultant_N = 0, height_m = 0, moment_N_m = 0, peak_resultant_N = 0, peak_resultant_time_s = 0;
};
// design.json's "sensors": per sensors/<name>/pressure series its peak, when, and its mean over the run.
struct SensorPeak {
  std::string name;
  double peak_pressure_Pa = 0, peak_time_s = 0, mean_pressure_Pa = 0;
};

// None when the run recorded no face profile or no load reached the face.
std::optional<FaceProfileAtMoment> face_profile(const Results& r, const std::string& where);
std::vector<SensorPeak> sensor_peaks(const Results& r);

nlohmann::json to_json(const FaceProfileAtMoment& f);
nlohmann::json to_json(const std::vector<SensorPeak>& s);
// Read back validated (`where` names the place in errors); null reads as nullopt / none.
std::optional<FaceProfileAtMoment> face_profile_from_json(const nlohmann::json& j, const std::string& where);
std::vector<SensorPeak> sensors_from_json(const nlohmann::json& j, const std::string& where);

}  // namespace dmi::design
