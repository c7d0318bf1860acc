#include "design/pressures.hpp"

#include <stdexcept>

namespace dmi::design {

using json = nlohmann::json;

json face_profile(const Results& r, const std::string& where) {
  const auto& d = r.info.face_profile;
  const Series *p = r.find("face/pressure"), *R = r.find("face/resultant"), *z = r.find("face/height");
  if (!d || !p || !R || !z) return nullptr;
  if (d->bins.size() != p->components.size())
    throw std::runtime_error(where + ": /documents/face_profile does not match the history face/pressure; the file is altered");
  std::size_t best = 0, peak = 0;
  double moment = -1, peak_R = -1;
  for (std::size_t k = 0; k < R->samples(); ++k) {
    if (R->data[k] * z->data[k] > moment) moment = R->data[k] * z->data[k], best = k;
    if (R->data[k] > peak_R) peak_R = R->data[k], peak = k;
  }
  if (!(peak_R > 0)) return nullptr;
  json positions = json::array(), lengths = json::array(), pressure = json::array();
  const std::size_t nb = p->components.size();
  for (std::size_t b = 0; b < nb; ++b) {
    const double from = d->bins[b].from, to = d->bins[b].to;
    positions.push_back(0.5 * (from + to));
    lengths.push_back(to - from);
    pressure.push_back(p->data[best * nb + b]);
  }
  return json{{"members", d->members}, {"direction", d->direction}, {"width_m", d->width}, {"positions_m", positions},
              {"lengths_m", lengths}, {"time_s", r.time.at(best)}, {"pressure_Pa", pressure}, {"resultant_N", R->data[best]},
              {"height_m", z->data[best]}, {"moment_N_m", moment}, {"peak_resultant_N", peak_R}, {"peak_resultant_time_s", r.time.at(peak)}};
}

json sensor_peaks(const Results& r) {
  json out = json::array();
  const std::string head = "sensors/", tail = "/pressure";
  for (const Series& s : r.series) {
    if (s.path.rfind(head, 0) != 0 || s.path.size() <= head.size() + tail.size() || s.samples() == 0) continue;
    std::size_t best = 0;
    double sum = 0;
    for (std::size_t k = 0; k < s.samples(); ++k) {
      if (s.data[k] > s.data[best]) best = k;
      sum += s.data[k];
    }
    out.push_back({{"name", s.path.substr(head.size(), s.path.size() - head.size() - tail.size())}, {"peak_pressure_Pa", s.data[best]},
                   {"peak_time_s", r.time.at(best)}, {"mean_pressure_Pa", sum / static_cast<double>(s.samples())}});
  }
  return out;
}

}  // namespace dmi::design
