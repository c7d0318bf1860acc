#include "design/phases.hpp"

#include <cmath>
#include <stdexcept>

namespace dmi::design {

using nlohmann::json;

json DebrisPhases::to_json() const {
  return json{{"flux_N", flux_N},       {"passage_s", passage_s},           {"arrival_s", arrival_s},
              {"peak_N", peak_N},       {"peak_time_s", peak_time_s},       {"alpha_peak", peak_N / flux_N},
              {"dynamic_N", dynamic_N}, {"alpha_dynamic", dynamic_N / flux_N},
              {"static_N", static_N ? json(*static_N) : json(nullptr)},
              {"alpha_static", static_N ? json(*static_N / flux_N) : json(nullptr)}};
}

std::optional<DebrisPhases> debris_phases(const std::vector<double>& t, const std::vector<double>& F, double flux, double passage) {
  if (t.size() != F.size() || t.size() < 2 || !(flux > 0) || !(passage > 0)) return std::nullopt;
  DebrisPhases p;
  p.flux_N = flux, p.passage_s = passage;
  std::size_t a = 0;
  while (a < t.size() && !(F[a] > 0.01 * flux)) ++a;
  if (a == t.size()) return std::nullopt;
  p.arrival_s = a > 0 ? t[a - 1] : t[0];  // the interval of sample a starts at t_{a-1}
  // Time-weighted mean of the interval means whose intervals end in (t0, t1].
  auto mean = [&](double t0, double t1) -> std::optional<double> {
    double s = 0, w = 0;
    for (std::size_t k = 1; k < t.size(); ++k)
      if (t[k] > t0 && t[k] <= t1) s += F[k] * (t[k] - t[k - 1]), w += t[k] - t[k - 1];
    return w > 0 ? std::optional<double>(s / w) : std::nullopt;
  };
  const double end = p.arrival_s + passage;
  for (std::size_t k = a; k < t.size() && t[k] <= end; ++k)
    if (F[k] > p.peak_N) p.peak_N = F[k], p.peak_time_s = t[k];
  p.dynamic_N = mean(p.arrival_s + 0.25 * passage, end).value_or(std::nan(""));
  const double tail = t.back() - 0.1 * (t.back() - t.front());
  if (tail >= end) p.static_N = mean(tail, t.back());
  return p;
}

json debris_phases(const Results& r, const DesignBasis& basis) {
  if (!basis.debris || !is_set(basis.debris->length_m)) return nullptr;
  const Series* s = r.find("frame/contact_force");
  if (!s || s->components.size() != 2 || r.time.empty()) return nullptr;
  const DebrisBasis& f = *basis.debris;
  const double rho = f.density_kg_m3, h = f.depth_m, v = f.speed_m_s, L = f.length_m, w = basis.dam.width_m;
  std::vector<double> F(r.time.size());
  for (std::size_t k = 0; k < F.size(); ++k) F[k] = std::hypot(s->data[2 * k], s->data[2 * k + 1]);
  const auto p = debris_phases(r.time, F, rho * v * v * h * w, L / v);
  return p ? p->to_json() : json(nullptr);
}

}  // namespace dmi::design
