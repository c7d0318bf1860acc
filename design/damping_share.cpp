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

namespace {

// A history's value at the last sample at or before t (0 before the first).
double at_time(const Results& r, const Series* s, double t) {
  if (!s || s->data.size() != r.time.size()) return 0.0;
  const auto k = std::upper_bound(r.time.begin(), r.time.end(), t) - r.time.begin();
  return k > 0 ? s->data[static_cast<std::size_t>(k - 1)] : 0.0;
}

}  // namespace

nlohmann::json damping_share(const Results& r, const DesignBasis& b, double t_gov, double t_base) {
  const Series* s = r.find("energy/frame_damping");
  const Series* w = r.find("energy/contact_work");
  const double E = impact_energy(b);
  if (!s || s->data.empty() || !(E > 0) || r.time.size() != s->data.size()) return nullptr;
  const auto share = [](double d, double received) { return received > 0 ? d / received : 0.0; };
  const double at = at_time(r, s, t_gov), end = s->data.back(), received = at_time(r, w, t_gov);
  nlohmann::json j{{"impact_energy_J", E}, {"damping_energy_J", end}, {"damping_energy_at_governing_J", at},
                   {"governing_time_s", t_gov}, {"share_at_governing", at / E}, {"share", end / E},
                   {"received_at_governing_J", received}, {"share_of_received_at_governing", share(at, received)},
                   {"base_shear_peak", nullptr}, {"flag_above", kDampingShareFlag}};
  bool flagged = at / E > kDampingShareFlag || share(at, received) > kDampingShareFlag;
  if (t_base >= 0) {
    const double d = at_time(r, s, t_base), e = at_time(r, w, t_base);
    j["base_shear_peak"] = {{"time_s", t_base}, {"damping_J", d}, {"received_J", e}, {"share_of_received", share(d, e)}};
    flagged = flagged || share(d, e) > kDampingShareFlag;
  }
  j["flagged"] = flagged;
  return j;
}

}  // namespace dmi::design
