// The report's rows on the pressure of the struck face (design.json runs[].face_profile) and the pressure sensors
// (runs[].sensors); docs/results.md "Pressures".
#include <algorithm>
#include <string>

#include "render/report_rows.hpp"

namespace dmi::render {

using nlohmann::json;

namespace {

const json* face(const RunData& r) {
  return r.design.contains("face_profile") && r.design["face_profile"].is_object() ? &r.design["face_profile"] : nullptr;
}

// The row of a face quantity: its value per run, "—" where the run has no face profile.
std::pair<std::string, std::function<std::string(const RunData&)>> face_row(const std::string& key, std::function<std::string(const json&)> f) {
  return {key, [f](const RunData& r) { return face(r) ? f(*face(r)) : std::string("—"); }};
}

}  // namespace

json pressure_rows(const std::vector<RunData>& runs) {
  std::vector<std::pair<std::string, std::function<std::string(const RunData&)>>> rows;
  if (std::any_of(runs.begin(), runs.end(), [](const RunData& r) { return face(r) != nullptr; })) {
    rows.push_back(face_row("instant of the largest moment about the foot", [](const json& f) { return eng(f["time_s"], "s"); }));
    rows.push_back(face_row("resultant of the face pressure", [](const json& f) { return eng(f["resultant_N"], "N"); }));
    rows.push_back(face_row("its position along the face from the foot", [](const json& f) { return fmt("%.3g m", f["height_m"].get<double>()); }));
    rows.push_back(face_row("its moment about the foot", [](const json& f) { return eng(f["moment_N_m"], "N m"); }));
    rows.push_back(face_row("largest pressure of the profile (element length × face width)", [](const json& f) {
      std::size_t k = 0;
      for (std::size_t b = 0; b < f["pressure_Pa"].size(); ++b)
        if (f["pressure_Pa"][b].get<double>() > f["pressure_Pa"][k].get<double>()) k = b;
      return eng(f["pressure_Pa"][k], "Pa") + fmt(" at %.3g m", f["positions_m"][k].get<double>());
    }));
    rows.push_back(face_row("largest resultant over the run", [](const json& f) {
      return eng(f["peak_resultant_N"], "N") + " at " + eng(f["peak_resultant_time_s"], "s");
    }));
  }
  std::vector<std::string> sensors;
  for (const auto& r : runs)
    for (const auto& s : r.design.value("sensors", json::array()))
      if (std::find(sensors.begin(), sensors.end(), s["name"].get<std::string>()) == sensors.end()) sensors.push_back(s["name"]);
  for (const std::string& name : sensors)
    rows.push_back({"sensor " + name + ": peak pressure", [name](const RunData& r) {
                      for (const auto& s : r.design.value("sensors", json::array()))
                        if (s["name"] == name) return eng(s["peak_pressure_Pa"], "Pa") + " at " + eng(s["peak_time_s"], "s");
                      return std::string("—");
                    }});
  return rows.empty() ? json::array() : per_run_rows(runs, rows);
}

}  // namespace dmi::render
