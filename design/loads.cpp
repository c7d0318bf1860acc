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

namespace {

std::vector<const Series*> support_series(const Results& r, const FrameInfo& f, const std::string& where) {
  std::vector<const Series*> out;
  for (const auto& s : f.supports) {
    const Series* p = r.find(s.series);
    if (!p || p->components.size() != 3) throw std::runtime_error(where + ": missing history " + s.series + " (Fx, Fy, M) of support '" + s.node + "'");
    out.push_back(p);
  }
  return out;
}

}  // namespace

BaseHistory base_history(const Results& r, const FrameInfo& f, const std::string& where) {
  const auto series = support_series(r, f, where);
  BaseHistory h;
  for (const auto& s : f.supports)
    for (int d = 0; d < 2; ++d) h.about[d] += f.nodes[s.node_index][d] / f.supports.size();
  for (std::size_t k = 0; k < r.time.size() && !series.empty(); ++k) {
    double fx = 0, fy = 0, m = 0;
    for (std::size_t i = 0; i < series.size(); ++i) {
      const double* v = &series[i]->data[3 * k];
      const auto& x = f.nodes[f.supports[i].node_index];
      fx += v[0], fy += v[1];
      m += v[2] + (x[0] - h.about[0]) * v[1] - (x[1] - h.about[1]) * v[0];
    }
    h.fx.push_back(fx), h.fy.push_back(fy), h.m.push_back(m);
  }
  return h;
}

Reactions reactions(const Results& r, const FrameInfo& f, const std::string& where) {
  Reactions out;
  out.total.name = "base total";
  const auto series = support_series(r, f, where);
  for (const auto& s : f.supports) {
    out.supports.emplace_back();
    out.supports.back().name = s.node;
  }
  for (std::size_t k = 0; k < r.time.size(); ++k)
    for (std::size_t i = 0; i < series.size(); ++i) {
      const double* v = &series[i]->data[3 * k];
      add(out.supports[i], v[0], v[1], v[2], r.time[k]);
    }
  const BaseHistory h = base_history(r, f, where);
  out.about = h.about;
  for (std::size_t k = 0; k < h.fx.size(); ++k) add(out.total, h.fx[k], h.fy[k], h.m[k], r.time[k]);
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
