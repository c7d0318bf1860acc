#include "design/phases.hpp"

#include "design/record_reader.hpp"

#include <algorithm>
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

json DebrisLoad::to_json() const {
  json out = phases.to_json();
  out["froude"] = froude;
  out["cui"] = {{"alpha", cui.alpha}, {"force_N", cui.force_N}, {"in_range", cui_in_range}, {"source", cui.source}};
  out["geo"] = {{"alpha", geo.alpha}, {"force_N", geo.force_N}, {"source", geo.source}};
  out["deposit"] = deposit ? json{{"height_m", deposit->height_m}, {"hydrostatic_N", deposit->hydrostatic_N}, {"face_resultant_N", deposit->face_resultant_N}}
                           : json(nullptr);
  return out;
}

using namespace record;

namespace {
DebrisLoad::Practice practice_from(const json& j, const char* key, const std::string& where) {
  const std::string w = where + "." + key;
  if (!j.is_object() || !j.contains(key) || !j[key].is_object()) throw std::runtime_error(w + " is not an object");
  const json& p = j[key];
  if (!p.contains("source") || !p["source"].is_string()) throw std::runtime_error(w + ".source is not a string");
  return {number(p, "alpha", w), number(p, "force_N", w), p["source"].get<std::string>()};
}
}  // namespace

std::optional<DebrisLoad> debris_load_from_json(const json& j, const std::string& w) {
  if (j.is_null()) return std::nullopt;
  DebrisLoad d;
  DebrisPhases& p = d.phases;
  p.flux_N = number(j, "flux_N", w), p.passage_s = number(j, "passage_s", w), p.arrival_s = number(j, "arrival_s", w);
  p.peak_N = number(j, "peak_N", w), p.peak_time_s = number(j, "peak_time_s", w), p.dynamic_N = number(j, "dynamic_N", w);
  if (!j.contains("static_N")) throw std::runtime_error(w + ": no 'static_N'");
  if (!j["static_N"].is_null()) p.static_N = number(j, "static_N", w);
  d.froude = number(j, "froude", w);
  d.geo = practice_from(j, "geo", w), d.cui = practice_from(j, "cui", w);
  if (!j["cui"].contains("in_range") || !j["cui"]["in_range"].is_boolean()) throw std::runtime_error(w + ".cui.in_range is not true or false");
  d.cui_in_range = j["cui"]["in_range"];
  if (!j.contains("deposit")) throw std::runtime_error(w + ": no 'deposit'");
  if (const json& dep = j["deposit"]; !dep.is_null())
    d.deposit = DepositLoad{number(dep, "height_m", w + ".deposit"), number(dep, "hydrostatic_N", w + ".deposit"), number(dep, "face_resultant_N", w + ".deposit")};
  return d;
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

// The deposit at rest against the face over the last 10 % of the run: its height, the highest element of the face
// profile carrying more than 5 % of the largest mean pressure there, and the hydrostatic load of a fluid of the
// debris' density that high, rho g h_d^2 w / 2 (K = 1: the upper bound of a granular deposit's earth pressure).
// Null without a face profile.
std::optional<DepositLoad> deposit_load(const Results& r, double rho) {
  const Series* p = r.find("face/pressure");
  const auto& d = r.info.face_profile;
  if (!p || !d || r.time.size() < 2) return std::nullopt;
  const std::size_t nb = p->components.size();
  if (d->bins.size() != nb) return std::nullopt;
  const double width = d->width;  // the face's: the one its pressures were measured over
  std::vector<double> mean(nb, 0.0);
  const double tail = r.time.back() - 0.1 * (r.time.back() - r.time.front());
  double span = 0;
  for (std::size_t k = 1; k < r.time.size(); ++k) {
    if (r.time[k] <= tail) continue;
    const double dt = r.time[k] - r.time[k - 1];
    for (std::size_t b = 0; b < nb; ++b) mean[b] += p->data[k * nb + b] * dt;
    span += dt;
  }
  const double top = *std::max_element(mean.begin(), mean.end());
  if (!(span > 0) || !(top > 0)) return std::nullopt;
  double height = 0, measured = 0;
  for (std::size_t b = 0; b < nb; ++b) {
    const FaceBin& bin = d->bins[b];
    const double from = bin.from, to = bin.to;
    if (mean[b] > 0.05 * top) height = std::max(height, bin.height_to);  // above the foot, not along the face
    measured += mean[b] / span * (to - from) * width;
  }
  return DepositLoad{height, 0.5 * rho * 9.81 * height * height * width, measured};
}

std::optional<DebrisLoad> debris_phases(const Results& r, const DesignBasis& basis) {
  if (!basis.debris || !is_set(basis.debris->length_m)) return std::nullopt;
  const Series* s = r.find("frame/contact_force");
  if (!s || s->components.size() != 2 || r.time.empty()) return std::nullopt;
  const DebrisBasis& f = *basis.debris;
  const double rho = f.density_kg_m3, h = f.depth_m, v = f.speed_m_s, L = f.length_m, w = basis.dam.width_m;
  std::vector<double> F(r.time.size());
  for (std::size_t k = 0; k < F.size(); ++k) F[k] = std::hypot(s->data[2 * k], s->data[2 * k + 1]);
  const auto p = debris_phases(r.time, F, rho * v * v * h * w, L / v);
  if (!p) return std::nullopt;
  DebrisLoad out;
  out.phases = *p;
  const double g = 9.81, Fr = v / std::sqrt(g * h), alpha_cui = 5.3 * std::pow(Fr, -1.5);
  out.froude = Fr;
  out.cui = {alpha_cui, alpha_cui * p->flux_N,
             "Cui, Zeng & Lei (2015): alpha = 5.3 Fr^-1.5 for a viscous debris flow in a flume (depth 7.2-11.2 cm, "
             "speed 2.4-5.2 m/s, Fr about 2.3-6.2); read second-hand, not checked against the paper"};
  out.cui_in_range = Fr >= 2.3 && Fr <= 6.2;
  out.geo = {2.5, 2.5 * p->flux_N, "Kwan (2012), GEO Report 270: alpha = 2.5 for a rigid barrier"};
  out.deposit = deposit_load(r, rho);
  return out;
}

}  // namespace dmi::design
