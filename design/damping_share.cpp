#include "design/damping_share.hpp"

#include <algorithm>
#include <cmath>

namespace dmi::design {

double impact_energy(const DesignBasis& b) {
  if (b.boulder) return 0.5 * b.boulder->mass_kg * b.boulder->speed_m_s * b.boulder->speed_m_s;
  if (b.debris && is_set(b.debris->length_m)) {
    const DebrisBasis& f = *b.debris;
    return 0.5 * f.density_kg_m3 * f.depth_m * f.length_m * b.dam.width_m * f.speed_m_s * f.speed_m_s;
  }
  return kUnset;
}

nlohmann::json damping_share(const Results& r, const DesignBasis& b, double t_gov) {
  const Series* s = r.find("energy/frame_damping");
  const double E = impact_energy(b);
  if (!s || s->data.empty() || !(E > 0) || r.time.size() != s->data.size()) return nullptr;
  // The damping work up to the governing instant: the last sample at or before it.
  const auto k = std::upper_bound(r.time.begin(), r.time.end(), t_gov) - r.time.begin();
  const double at = k > 0 ? s->data[static_cast<std::size_t>(k - 1)] : 0.0, end = s->data.back();
  return nlohmann::json{{"impact_energy_J", E}, {"damping_energy_J", end}, {"damping_energy_at_governing_J", at},
                        {"governing_time_s", t_gov}, {"share_at_governing", at / E}, {"share", end / E},
                        {"flagged", at / E > kDampingShareFlag}, {"flag_above", kDampingShareFlag}};
}

}  // namespace dmi::design
