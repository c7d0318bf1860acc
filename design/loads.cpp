#include "design/loads.hpp"

#include <cmath>
#include <stdexcept>

namespace dmi::design {

namespace {

const std::vector<std::string>& component_keys(int dim) {
  static const std::vector<std::string> plane{"Fx_N", "Fy_N", "M_Nm"};
  static const std::vector<std::string> space{"Fx_N", "Fy_N", "Fz_N", "Mx_Nm", "My_Nm", "Mz_Nm", "H_N", "M_overturning_Nm"};
  return dim == 3 ? space : plane;
}

ReactionPeaks empty_peaks(const std::string& name, int dim) {
  ReactionPeaks p;
  p.name = name;
  for (const auto& k : component_keys(dim)) p.components.push_back({k, {}, {}, {}, 0});
  return p;
}

void add(ReactionPeaks& p, const std::vector<double>& v, double t) {
  for (std::size_t c = 0; c < v.size(); ++c) {
    auto& q = p.components[c];
    q.max.max(v[c], t), q.min.min(v[c], t), q.abs.max(std::abs(v[c]), t), q.final = v[c];
  }
}

// The stored reaction (Fx, Fy, M or Fx .. Mz) as the components of component_keys: space frames add H and M_overturning.
std::vector<double> expand(const double* v, int dim) {
  if (dim == 2) return {v[0], v[1], v[2]};
  return {v[0], v[1], v[2], v[3], v[4], v[5], std::hypot(v[0], v[1]), std::hypot(v[3], v[4])};
}

std::vector<const Series*> support_series(const Results& r, const FrameInfo& f, const std::string& where) {
  const std::size_t n = f.dim == 3 ? 6 : 3;
  std::vector<const Series*> out;
  for (const auto& s : f.supports) {
    const Series* p = r.find(s.series);
    if (!p || p->components.size() != n)
      throw std::runtime_error(where + ": missing history " + s.series + (f.dim == 3 ? " (Fx, Fy, Fz, Mx, My, Mz)" : " (Fx, Fy, M)") + " of support '" +
                               s.node + "'");
    out.push_back(p);
  }
  return out;
}

}  // namespace

const ReactionComponent& ReactionPeaks::at(const std::string& key) const {
  for (const auto& c : components)
    if (c.key == key) return c;
  throw std::out_of_range("reaction component " + key);
}

const std::vector<double>& BaseHistory::at(const std::string& key) const {
  for (std::size_t c = 0; c < keys.size(); ++c)
    if (keys[c] == key) return values[c];
  throw std::out_of_range("base history component " + key);
}

const char* shear_key(int dim) { return dim == 3 ? "H_N" : "Fx_N"; }
const char* moment_key(int dim) { return dim == 3 ? "M_overturning_Nm" : "M_Nm"; }

const std::vector<double>& BaseHistory::shear() const { return at(shear_key(keys.size() == 3 ? 2 : 3)); }
const std::vector<double>& BaseHistory::moment() const { return at(moment_key(keys.size() == 3 ? 2 : 3)); }

std::vector<double> contact_magnitude(const Results& r) {
  std::vector<double> mag;
  const Series* s = r.find("frame/contact_force");
  const std::size_t n = s ? s->components.size() : 0;
  if (n != 2 && n != 3) return mag;
  for (std::size_t k = 0; k < s->samples(); ++k) {
    double m2 = 0;
    for (std::size_t d = 0; d < n; ++d) m2 += s->data[n * k + d] * s->data[n * k + d];
    mag.push_back(std::sqrt(m2));
  }
  return mag;
}

BaseHistory base_history(const Results& r, const FrameInfo& f, const std::string& where) {
  const auto series = support_series(r, f, where);
  const int n = f.dim == 3 ? 6 : 3;
  BaseHistory h;
  h.keys = component_keys(f.dim);
  h.values.assign(h.keys.size(), {});
  for (const auto& s : f.supports)
    for (int d = 0; d < 3; ++d) h.about[d] += f.nodes[s.node_index][d] / f.supports.size();
  for (std::size_t k = 0; k < r.time.size() && !series.empty(); ++k) {
    double sum[6] = {0, 0, 0, 0, 0, 0};
    for (std::size_t i = 0; i < series.size(); ++i) {
      const double* v = &series[i]->data[n * k];
      const auto& x = f.nodes[f.supports[i].node_index];
      const double a[3] = {x[0] - h.about[0], x[1] - h.about[1], x[2] - h.about[2]};
      if (f.dim == 2) {
        sum[0] += v[0], sum[1] += v[1];
        sum[2] += v[2] + a[0] * v[1] - a[1] * v[0];
      } else {  // M + a x F
        for (int c = 0; c < 6; ++c) sum[c] += v[c];
        sum[3] += a[1] * v[2] - a[2] * v[1], sum[4] += a[2] * v[0] - a[0] * v[2], sum[5] += a[0] * v[1] - a[1] * v[0];
      }
    }
    const std::vector<double> row = expand(sum, f.dim);
    for (std::size_t c = 0; c < row.size(); ++c) h.values[c].push_back(row[c]);
  }
  return h;
}

Reactions reactions(const Results& r, const FrameInfo& f, const std::string& where) {
  Reactions out;
  out.total = empty_peaks("base total", f.dim);
  const auto series = support_series(r, f, where);
  const int n = f.dim == 3 ? 6 : 3;
  for (const auto& s : f.supports) out.supports.push_back(empty_peaks(s.node, f.dim));
  for (std::size_t k = 0; k < r.time.size(); ++k)
    for (std::size_t i = 0; i < series.size(); ++i) add(out.supports[i], expand(&series[i]->data[n * k], f.dim), r.time[k]);
  const BaseHistory h = base_history(r, f, where);
  out.about = h.about;
  for (std::size_t k = 0; k < r.time.size() && !series.empty(); ++k) {
    std::vector<double> row;
    for (const auto& v : h.values) row.push_back(v[k]);
    add(out.total, row, r.time[k]);
  }
  return out;
}

Contact contact(const Results& r) {
  Contact c;
  const Series* s = r.find("frame/contact_force");
  const std::size_t n = s ? s->components.size() : 0;
  if (!s || (n != 2 && n != 3) || r.time.empty()) return c;
  c.present = true;
  c.impulse_N_s.assign(n, 0.0);
  const auto& t = r.time;
  const std::vector<double> mag = contact_magnitude(r);
  std::size_t kp = 0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (mag[k] > c.peak_N) c.peak_N = mag[k], c.peak_time_s = t[k], kp = k;
    const double dt = k == 0 ? 0.0 : t[k] - t[k - 1];  // sample k holds the mean over (t_{k-1}, t_k]
    for (std::size_t d = 0; d < n; ++d) c.impulse_N_s[d] += s->data[n * k + d] * dt;
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
