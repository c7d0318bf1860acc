#include "engine/mpm/inflow.hpp"

#include <algorithm>
#include <cmath>

#include "engine/mpm/scene.hpp"

namespace dmi {

template <int D> double Inflow<D>::min_particle_mass() const {
  // A full-spacing particle, rho_min dx^2 (times the thickness in 2D): a scale for the solver's empty-node threshold
  // (1e-12 of the lightest particle). Slices shallower than dx are lighter in proportion.
  return min_density() * spacing * spacing * (D == 2 ? thickness : spacing);
}

template <int D> void Inflow<D>::save_state(StateWriter& w) const {
  w.tag("inflow");
  w.put(length), w.put(slices), w.put(mass), w.put(energy), w.put(momentum), w.put(force);
}

template <int D> void Inflow<D>::load_state(StateReader& r) {
  r.tag("inflow");
  r.get(length), r.get(slices), r.get(mass), r.get(energy), r.get(momentum), r.get(force);
}

template <int D> Index inject(Scene<D>& s, Inflow<D>& in, double t, double dt) {
  if (in.hydrograph.empty() || t + dt <= in.hydrograph.start() || t >= in.hydrograph.end()) return 0;
  const double l0 = in.length;
  in.length += in.hydrograph.advance(t, t + dt);
  const double dx = in.spacing;
  Particles<D>& P = s.particles;
  Body& b = s.bodies[static_cast<std::size_t>(in.body)];
  const Index first = static_cast<Index>(P.size());
  while (static_cast<double>(in.slices + 1) * dx <= in.length * (1 + 1e-12)) {
    const double lc = static_cast<double>(in.slices + 1) * dx;  // plug length at which this slice enters
    // Its entry time, linear within the step (the step is a small part of any hydrograph row interval).
    const double tc = in.length > l0 ? t + dt * std::clamp((lc - l0) / (in.length - l0), 0.0, 1.0) : t + dt;
    const Hydrograph::State st = in.hydrograph.at(std::min(tc, in.hydrograph.end()), in.density);
    ++in.slices;
    if (!(st.depth > 0)) continue;
    const int n = std::max(1, static_cast<int>(std::lround(st.depth / dx)));
    const double dn = st.depth / n;
    // Its centre: created at the zone's upstream end, carried since by the plug's advance beyond lc.
    const double sc = -in.zone + std::max(0.0, in.length - lc) + 0.5 * dx;
    const Vec<D> v = st.velocity * in.along;
    double vol = dx * dn;
    vol *= D == 2 ? in.thickness : dx;
    Vec<D> half;
    for (int d = 0; d < D; ++d) half[d] = 0.5 * (std::abs(in.along[d]) * dx + std::abs(in.up[d]) * dn);
    for (int j = 0; j < n; ++j) {
      const Vec<D> x = in.point + sc * in.along + (j + 0.5) * dn * in.up;
      const double m = st.density * vol;
      P.push(x, v, half, m, vol, in.body);
      in.mass += m;
      in.momentum += m * v;
      in.energy += 0.5 * m * v.squaredNorm();
    }
  }
  const Index last = static_cast<Index>(P.size());
  if (last > first) {
    b.end = last;
    s.materials[static_cast<std::size_t>(b.material)]->attach(P, first, last);
  }
  return last - first;
}

template <int D> bool backed_up(const Scene<D>& s, const Inflow<D>& in, double t) {
  if (!in.driving(t)) return false;
  const Hydrograph::State st = in.hydrograph.at(t, in.density);
  if (!(st.velocity > 0) || !(st.depth > 0)) return false;
  const Particles<D>& P = s.particles;
  const Body& b = s.bodies[static_cast<std::size_t>(in.body)];
  const double reach = std::max(st.depth, 2 * s.grid->h());
  double m = 0, mv = 0;
  for (Index i = b.begin; i < b.end; ++i) {
    const Vec<D> r = P.x[i] - in.point;
    const double a = r.dot(in.along), d = r.dot(in.up);
    if (a > 0 && a <= reach && d >= 0 && d <= st.depth) m += P.mass[i], mv += P.mass[i] * P.v[i].dot(in.along);
  }
  // At least half the mass of a full-depth strip that long: the front has passed.
  const double strip = 0.5 * in.min_density() * st.depth * reach * (D == 2 ? in.thickness : in.spacing);
  return m >= strip && mv < 0.5 * st.velocity * m;
}

template struct Inflow<2>;
template struct Inflow<3>;
template Index inject<2>(Scene<2>&, Inflow<2>&, double, double);
template Index inject<3>(Scene<3>&, Inflow<3>&, double, double);
template bool backed_up<2>(const Scene<2>&, const Inflow<2>&, double);
template bool backed_up<3>(const Scene<3>&, const Inflow<3>&, double);

}  // namespace dmi
