#include "design/volume_health.hpp"

namespace dmi::design {

std::vector<VolumeHealthRecord> volume_health(const Results& r) {
  std::vector<VolumeHealthRecord> out;
  for (const Series& s : r.series) {
    const std::string suffix = "/volume";
    if (s.path.rfind("probes/", 0) != 0 || s.path.size() <= suffix.size() || s.path.compare(s.path.size() - suffix.size(), suffix.size(), suffix) != 0 ||
        s.components.size() != 2 || s.samples() == 0)
      continue;
    double largest = 0, t_largest = 0, last = 0;
    for (std::size_t k = 0; k < s.samples(); ++k) {
      const double now = s.data[2 * k], created = s.data[2 * k + 1];
      if (!(created > 0)) continue;  // nothing has entered yet
      last = now / created;
      if (last > largest) largest = last, t_largest = k < r.time.size() ? r.time[k] : 0.0;
    }
    if (!(largest > 0)) continue;
    out.push_back({s.path.substr(7, s.path.size() - 7 - suffix.size()), last, largest, t_largest, 1 + kVolumeGrowthFlag, largest > 1 + kVolumeGrowthFlag});
  }
  return out;
}

}  // namespace dmi::design
