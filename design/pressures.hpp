// Pressures on the struck face (docs/design-json.md, "face_profile" and "sensors"): the profile of the contact
// pressure along a dam's upstream face at the instant its overturning moment about the face's foot is largest (the
// height of the resultant sets the base moment), and the peak of every pressure sensor.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "engine/io/results.hpp"

namespace dmi::design {

// {members, direction, width_m, positions_m (bin centres along the face), lengths_m, time_s, pressure_Pa (per bin at
// time_s), resultant_N, height_m (of the resultant above the foot, across the load), moment_N_m (resultant x height), peak_resultant_N,
// peak_resultant_time_s}; null when the run recorded no face profile or no load reached the face.
nlohmann::json face_profile(const Results& r, const std::string& where);

// [{name, peak_pressure_Pa, peak_time_s, mean_pressure_Pa}] over the run, one per sensors/<name>/pressure series.
nlohmann::json sensor_peaks(const Results& r);

}  // namespace dmi::design
