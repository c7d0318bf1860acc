// A debris-flow hydrograph at a channel section: flow depth (normal to the bed), mean velocity along the bed and
// bulk density against time, as run-out models (RAMMS, DAN3D, FLO-2D) export them. Linear between the rows, no flow
// before the first row or after the last. Read by engine/scenario/hydrograph_io.hpp.
#pragma once
#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

namespace dmi {

struct Hydrograph {
  std::vector<double> time, depth, velocity, density;  // s, m, m/s, kg/m^3; density empty: the body material's
  std::string source;                   // "inline", or the CSV file as the scenario names it

  struct State {
    double depth = 0, velocity = 0, density = 0;
  };
  bool empty() const { return time.empty(); }
  double start() const { return time.front(); }
  double end() const { return time.back(); }
  // Linear between rows; zero depth and velocity outside [start, end]. rho: density when the hydrograph has none.
  State at(double t, double rho) const;
  // Integral of the velocity over [a, b] (m), exact for the piecewise-linear velocity.
  double advance(double a, double b) const;
  // Volume per unit width that passes the section, int v h dt (m^2), and mass per width, int rho v h dt (kg/m).
  double volume_per_width() const;
  double mass_per_width(double rho) const;
  double max_depth() const;
  double max_velocity() const;
  double min_density(double rho) const;
  // The row with the largest momentum flux rho v^2 h (design loads).
  std::size_t peak_flux_row(double rho) const;
  // The first row of the first interval that carries flow (depth and velocity above zero at one of its ends).
  std::size_t first_flow_row() const;
  // Particles an inflow of spacing dx creates from it in 2D: its volume per width over dx^2, plus one column's worth
  // for the depth rounding (run-time and memory estimates).
  double particle_estimate(double dx) const { return volume_per_width() / (dx * dx) + max_depth() / dx; }
};

inline Hydrograph::State Hydrograph::at(double t, double rho) const {
  State s;
  if (empty() || t < start() || t > end()) return s;
  const std::size_t k = std::min<std::size_t>(static_cast<std::size_t>(std::upper_bound(time.begin(), time.end(), t) - time.begin()), time.size() - 1);
  const std::size_t a = k - 1;
  const double w = (t - time[a]) / (time[k] - time[a]);
  s.depth = depth[a] + w * (depth[k] - depth[a]);
  s.velocity = velocity[a] + w * (velocity[k] - velocity[a]);
  s.density = density.empty() ? rho : density[a] + w * (density[k] - density[a]);
  return s;
}

inline double Hydrograph::advance(double a, double b) const {
  if (empty()) return 0.0;
  a = std::max(a, start()), b = std::min(b, end());
  double sum = 0.0;
  double t = a;
  while (t < b) {  // piece by piece between the rows: the trapezoid is exact on each
    const auto it = std::upper_bound(time.begin(), time.end(), t);
    const double next = it == time.end() ? b : std::min(b, *it);
    sum += 0.5 * (at(t, 0).velocity + at(next, 0).velocity) * (next - t);
    t = next;
  }
  return sum;
}

inline double Hydrograph::volume_per_width() const {
  // v h is quadratic on each interval: Simpson's rule is exact.
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < time.size(); ++i) {
    const double dt = time[i + 1] - time[i], vm = 0.5 * (velocity[i] + velocity[i + 1]), hm = 0.5 * (depth[i] + depth[i + 1]);
    sum += dt / 6 * (velocity[i] * depth[i] + 4 * vm * hm + velocity[i + 1] * depth[i + 1]);
  }
  return sum;
}

inline double Hydrograph::mass_per_width(double rho) const {
  // rho v h is cubic on each interval: Simpson's rule is exact.
  double sum = 0.0;
  auto r = [&](std::size_t i) { return density.empty() ? rho : density[i]; };
  for (std::size_t i = 0; i + 1 < time.size(); ++i) {
    const double dt = time[i + 1] - time[i], vm = 0.5 * (velocity[i] + velocity[i + 1]), hm = 0.5 * (depth[i] + depth[i + 1]);
    const double rm = 0.5 * (r(i) + r(i + 1));
    sum += dt / 6 * (r(i) * velocity[i] * depth[i] + 4 * rm * vm * hm + r(i + 1) * velocity[i + 1] * depth[i + 1]);
  }
  return sum;
}

inline double Hydrograph::max_depth() const { return empty() ? 0.0 : *std::max_element(depth.begin(), depth.end()); }
inline double Hydrograph::max_velocity() const { return empty() ? 0.0 : *std::max_element(velocity.begin(), velocity.end()); }
inline double Hydrograph::min_density(double rho) const { return density.empty() ? rho : *std::min_element(density.begin(), density.end()); }

inline std::size_t Hydrograph::first_flow_row() const {
  std::size_t a = 0;
  while (a + 1 < time.size() && !(depth[a] * velocity[a] > 0 || depth[a + 1] * velocity[a + 1] > 0)) ++a;
  return a;
}

inline std::size_t Hydrograph::peak_flux_row(double rho) const {
  std::size_t best = 0;
  auto flux = [&](std::size_t i) { return (density.empty() ? rho : density[i]) * velocity[i] * velocity[i] * depth[i]; };
  for (std::size_t i = 1; i < time.size(); ++i)
    if (flux(i) > flux(best)) best = i;
  return best;
}

}  // namespace dmi
