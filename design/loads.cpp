#include "design/loads.hpp"

#include <cmath>
#include <stdexcept>

namespace dmi::design {

namespace {

void add(ReactionPeaks& p, double fx, double fy, double m, double t) {
  p.Fx_max.max(fx, t), p.Fx_min.min(fx, t), p.Fy_max.max(fy, t), p.Fy_min.min(fy, t), p.M_max.max(m, t), p.M_min.min(m, t);
  p.Fx_abs.max(std::abs(fx), t), p.Fy_abs.max(std::abs(fy), t), p.M_abs.max(std::abs(m), t);
  p.final = {fx, fy, m};
}

}  // namespace

Reactions reactions(const Results& r, const FrameInfo& f, const std::string& where) {
  Reactions out;
  out.total.name = "base total";
  std::vector<const Series*> series;
  for (const auto& s : f.supports) {
    const Series* p = r.find(s.series);
    if (!p || p->components.size() != 3) throw std::runtime_error(where + ": missing history " + s.series + " (Fx, Fy, M) of support '" + s.node + "'");
    series.push_back(p);
    out.supports.emplace_back();
    out.supports.back().name = s.node;
    out.about[0] += f.nodes[s.node_index][0] / f.supports.size();
    out.about[1] += f.nodes[s.node_index][1] / f.supports.size();
  }
  for (std::size_t k = 0; k < r.time.size(); ++k) {
    double fx = 0, fy = 0, m = 0;
    for (std::size_t i = 0; i < series.size(); ++i) {
      const double* v = &series[i]->data[3 * k];
      add(out.supports[i], v[0], v[1], v[2], r.time[k]);
      const auto& x = f.nodes[f.supports[i].node_index];
      fx += v[0], fy += v[1];
      m += v[2] + (x[0] - out.about[0]) * v[1] - (x[1] - out.about[1]) * v[0];
    }
    if (!series.empty()) add(out.total, fx, fy, m, r.time[k]);
  }
  return out;
}

Contact contact(const Results& r) {
  Contact c;
  const Series* s = r.find("frame/contact_force");
  if (!s || s->components.size() != 2 || r.time.empty()) return c;
  c.present = true;
  const auto& t = r.time;
  std::vector<double> mag(t.size());
  std::size_t kp = 0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    mag[k] = std::hypot(s->data[2 * k], s->data[2 * k + 1]);
    if (mag[k] > c.peak_N) c.peak_N = mag[k], c.peak_time_s = t[k], kp = k;
    const double dt = k == 0 ? 0.0 : t[k] - t[k - 1];  // sample k holds the mean over (t_{k-1}, t_k]
    c.impulse_N_s[0] += s->data[2 * k] * dt, c.impulse_N_s[1] += s->data[2 * k + 1] * dt;
  }
  if (c.peak_N <= 0) return c;
  const double th = 0.05 * c.peak_N;
  std::size_t a = kp, b = kp;
  while (a > 0 && mag[a - 1] >= th) --a;
  while (b + 1 < t.size() && mag[b + 1] >= th) ++b;
  c.pulse_start_s = a > 0 ? t[a - 1] : t[0];  // the interval of sample a starts at t_{a-1}
  c.pulse_end_s = t[b];
  for (std::size_t k = std::max<std::size_t>(a, 1); k <= b; ++k) c.pulse_impulse_N_s += mag[k] * (t[k] - t[k - 1]);
  for (std::size_t k = 1; k < t.size(); ++k)
    if (mag[k] >= th) c.loaded_time_s += t[k] - t[k - 1];
  return c;
}

}  // namespace dmi::design
