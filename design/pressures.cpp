#include "design/pressures.hpp"

#include "design/record_reader.hpp"

#include <stdexcept>

namespace dmi::design {

using json = nlohmann::json;

std::optional<FaceProfileAtMoment> face_profile(const Results& r, const std::string& where) {
  const auto& d = r.info.face_profile;
  const Series *p = r.find("face/pressure"), *R = r.find("face/resultant"), *z = r.find("face/height");
  if (!d || !p || !R || !z) return std::nullopt;
  if (d->bins.size() != p->components.size())
    throw std::runtime_error(where + ": /documents/face_profile does not match the history face/pressure; the file is altered");
  std::size_t best = 0, peak = 0;
  double moment = -1, peak_R = -1;
  for (std::size_t k = 0; k < R->samples(); ++k) {
    if (R->data[k] * z->data[k] > moment) moment = R->data[k] * z->data[k], best = k;
    if (R->data[k] > peak_R) peak_R = R->data[k], peak = k;
  }
  if (!(peak_R > 0)) return std::nullopt;
  FaceProfileAtMoment f;
  f.members = d->members, f.direction.assign(d->direction.begin(), d->direction.end()), f.width_m = d->width;
  const std::size_t nb = p->components.size();
  for (std::size_t b = 0; b < nb; ++b) {
    const double from = d->bins[b].from, to = d->bins[b].to;
    f.positions_m.push_back(0.5 * (from + to));
    f.lengths_m.push_back(to - from);
    f.pressure_Pa.push_back(p->data[best * nb + b]);
  }
  f.time_s = r.time.at(best), f.resultant_N = R->data[best], f.height_m = z->data[best], f.moment_N_m = moment;
  f.peak_resultant_N = peak_R, f.peak_resultant_time_s = r.time.at(peak);
  return f;
}

std::vector<SensorPeak> sensor_peaks(const Results& r) {
  std::vector<SensorPeak> out;
  const std::string head = "sensors/", tail = "/pressure";
  for (const Series& s : r.series) {
    if (s.path.rfind(head, 0) != 0 || s.path.size() <= head.size() + tail.size() || s.samples() == 0) continue;
    std::size_t best = 0;
    double sum = 0;
    for (std::size_t k = 0; k < s.samples(); ++k) {
      if (s.data[k] > s.data[best]) best = k;
      sum += s.data[k];
    }
    out.push_back({s.path.substr(head.size(), s.path.size() - head.size() - tail.size()), s.data[best], r.time.at(best),
                   sum / static_cast<double>(s.samples())});
  }
  return out;
}

json to_json(const FaceProfileAtMoment& f) {
  return json{{"members", f.members}, {"direction", f.direction}, {"width_m", f.width_m}, {"positions_m", f.positions_m},
              {"lengths_m", f.lengths_m}, {"time_s", f.time_s}, {"pressure_Pa", f.pressure_Pa}, {"resultant_N", f.resultant_N},
              {"height_m", f.height_m}, {"moment_N_m", f.moment_N_m}, {"peak_resultant_N", f.peak_resultant_N},
              {"peak_resultant_time_s", f.peak_resultant_time_s}};
}

json to_json(const std::vector<SensorPeak>& s) {
  json out = json::array();
  for (const auto& p : s)
    out.push_back({{"name", p.name}, {"peak_pressure_Pa", p.peak_pressure_Pa}, {"peak_time_s", p.peak_time_s}, {"mean_pressure_Pa", p.mean_pressure_Pa}});
  return out;
}

using namespace record;

std::optional<FaceProfileAtMoment> face_profile_from_json(const json& j, const std::string& w) {
  if (j.is_null()) return std::nullopt;
  FaceProfileAtMoment f;
  if (!j.is_object() || !j.contains("members") || !j["members"].is_array()) throw std::runtime_error(w + ".members is not an array");
  for (const json& m : j["members"]) {
    if (!m.is_string()) throw std::runtime_error(w + ".members holds a name that is not a string");
    f.members.push_back(m.get<std::string>());
  }
  f.direction = numbers(j, "direction", w), f.positions_m = numbers(j, "positions_m", w), f.lengths_m = numbers(j, "lengths_m", w);
  f.pressure_Pa = numbers(j, "pressure_Pa", w);
  if (f.positions_m.size() != f.pressure_Pa.size() || f.lengths_m.size() != f.pressure_Pa.size())
    throw std::runtime_error(w + ": positions_m, lengths_m and pressure_Pa differ in length");
  f.width_m = number(j, "width_m", w), f.time_s = number(j, "time_s", w), f.resultant_N = number(j, "resultant_N", w);
  f.height_m = number(j, "height_m", w), f.moment_N_m = number(j, "moment_N_m", w), f.peak_resultant_N = number(j, "peak_resultant_N", w);
  f.peak_resultant_time_s = number(j, "peak_resultant_time_s", w);
  return f;
}

std::vector<SensorPeak> sensors_from_json(const json& j, const std::string& w) {
  return record::items<SensorPeak>(j, w, [](const json& s, const std::string& at) {
    return SensorPeak{record::text(s, "name", at), number(s, "peak_pressure_Pa", at), number(s, "peak_time_s", at), number(s, "mean_pressure_Pa", at)};
  });
}

}  // namespace dmi::design
