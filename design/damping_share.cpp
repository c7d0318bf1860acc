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

std::optional<DampingShareRecord> damping_share(const Results& r, const DesignBasis& b, double t_gov, double t_base) {
  const Series* s = r.find("energy/frame_damping");
  const Series* w = r.find("energy/contact_work");
  const double E = impact_energy(b);
  if (!s || s->data.empty() || !(E > 0) || r.time.size() != s->data.size()) return std::nullopt;
  const auto share = [](double d, double received) { return received > 0 ? d / received : 0.0; };
  const double at = at_time(r, s, t_gov), end = s->data.back(), received = at_time(r, w, t_gov);
  DampingShareRecord j;
  j.impact_energy_J = E, j.damping_energy_J = end, j.damping_energy_at_governing_J = at, j.governing_time_s = t_gov;
  j.share_at_governing = at / E, j.share = end / E, j.received_at_governing_J = received, j.share_of_received_at_governing = share(at, received);
  j.flag_above = kDampingShareFlag;
  j.flagged = at / E > kDampingShareFlag || share(at, received) > kDampingShareFlag;
  if (t_base >= 0) {
    const double d = at_time(r, s, t_base), e = at_time(r, w, t_base);
    j.base_shear_peak = DampingShareRecord::AtBaseShearPeak{t_base, d, e, share(d, e)};
    j.flagged = j.flagged || share(d, e) > kDampingShareFlag;
  }
  return j;
}

}  // namespace dmi::design
