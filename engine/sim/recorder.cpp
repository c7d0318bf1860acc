#include "engine/sim/recorder.hpp"

#include <limits>

namespace dmi {
namespace {
template <int D> std::vector<std::string> axes() { return D == 2 ? std::vector<std::string>{"x", "y"} : std::vector<std::string>{"x", "y", "z"}; }
template <int D> void push(Series& s, const Vec<D>& v) { for (int d = 0; d < D; ++d) s.data.push_back(v[d]); }
}  // namespace

template <int D> Series& Recorder<D>::add(const std::string& path, const std::string& unit, std::vector<std::string> comps) {
  series_.push_back(Series{path, unit, std::move(comps), {}});
  return series_.back();
}

template <int D> Recorder<D>::Recorder(const Solver<D>& solver, const Scenario& s) {
  const Scene<D>& sc = solver.scene();
  for (const char* e : {"kinetic", "strain", "gravity_work", "boundary_work", "balance_error"}) add(std::string("energy/") + e, "J", {"value"});
  add("momentum", "kg m/s", axes<D>());
  add("dt", "s", {"value"});
  add("step", "-", {"value"});
  for (const auto& w : sc.walls) add("walls/" + w.name + "/force", "N", axes<D>());
  for (const auto& r : sc.regions) add("regions/" + r.name + "/force", "N", axes<D>());
  const auto& P = sc.particles;
  for (const auto& pc : s.output.probes) {
    Probe p;
    p.name = pc.name;
    p.particle = pc.type == "particle";
    p.quantities = pc.quantities;
    while (sc.bodies[p.body].name != pc.target) ++p.body;
    const Body& b = sc.bodies[p.body];
    if (p.particle) {
      Vec<D> x;
      for (int d = 0; d < D; ++d) x[d] = pc.point[d];
      double best = std::numeric_limits<double>::infinity();
      for (Index i = b.begin; i < b.end; ++i)
        if ((P.x[i] - x).squaredNorm() < best) { best = (P.x[i] - x).squaredNorm(); p.index = i; }
    }
    const std::string base = "probes/" + p.name + "/";
    for (const auto& q : p.quantities) {
      if (q == "stress") add(base + q, "Pa", D == 2 ? std::vector<std::string>{"xx", "yy", "zz", "xy"} : std::vector<std::string>{"xx", "yy", "zz", "xy", "yz", "xz"});
      else if (q == "von_mises") add(base + q, "Pa", {"value"});
      else if (q == "kinetic_energy") add(base + q, "J", {"value"});
      else add(base + q, q == "velocity" ? "m/s" : "m", axes<D>());
    }
    probes_.push_back(p);
  }
  impulse_.assign(sc.walls.size() + sc.regions.size(), Vec<D>::Zero());
  const auto d0 = solver.diagnostics();
  e0_ = d0.kinetic + d0.strain;
}

template <int D> void Recorder<D>::accumulate(const Solver<D>& solver, double dt) {
  const Scene<D>& sc = solver.scene();
  std::size_t b = 0;
  for (const auto& w : sc.walls) impulse_[b++] += w.force * dt;
  for (const auto& r : sc.regions) impulse_[b++] += r.force * dt;
  elapsed_ += dt;
}

template <int D> void Recorder<D>::sample(const Solver<D>& solver, double dt) {
  const Scene<D>& sc = solver.scene();
  const auto d = solver.diagnostics();
  time_.push_back(solver.time());
  std::size_t k = 0;
  for (double e : {d.kinetic, d.strain, d.gravity_work, d.boundary_work, d.balance(e0_)}) series_[k++].data.push_back(e);
  push<D>(series_[k++], d.momentum);
  series_[k++].data.push_back(dt);
  series_[k++].data.push_back(static_cast<double>(solver.steps()));
  std::size_t j = 0;  // index into impulse_: walls, then regions
  for (const auto& w : sc.walls) push<D>(series_[k++], elapsed_ > 0 ? Vec<D>(impulse_[j++] / elapsed_) : w.force);
  for (const auto& r : sc.regions) push<D>(series_[k++], elapsed_ > 0 ? Vec<D>(impulse_[j++] / elapsed_) : r.force);
  for (auto& i : impulse_) i.setZero();
  elapsed_ = 0;
  const auto& P = sc.particles;
  for (const auto& p : probes_) {
    const Body& b = sc.bodies[p.body];
    double m = 0, ke = 0;
    Vec<D> mx = Vec<D>::Zero(), mu = Vec<D>::Zero(), mv = Vec<D>::Zero();
    if (!p.particle) {
      for (Index i = b.begin; i < b.end; ++i) {
        m += P.mass[i];
        mx += P.mass[i] * P.x[i];
        mu += P.mass[i] * (P.x[i] - P.x0[i]);
        mv += P.mass[i] * P.v[i];
        ke += 0.5 * P.mass[i] * P.v[i].squaredNorm();
      }
    }
    for (const auto& q : p.quantities) {
      Series& s = series_[k++];
      const Index i = p.index;
      if (q == "position") push<D>(s, p.particle ? P.x[i] : Vec<D>(mx / m));
      else if (q == "displacement") push<D>(s, p.particle ? Vec<D>(P.x[i] - P.x0[i]) : Vec<D>(mu / m));
      else if (q == "velocity") push<D>(s, p.particle ? P.v[i] : Vec<D>(mv / m));
      else if (q == "kinetic_energy") s.data.push_back(ke);
      else if (q == "von_mises") s.data.push_back(von_mises(voigt_stress(P, static_cast<std::size_t>(i))));
      else if (q == "stress") {
        const Voigt6 v = voigt_stress(P, static_cast<std::size_t>(i));
        for (std::size_t c = 0; c < s.components.size(); ++c) s.data.push_back(v[c]);
      }
    }
  }
}

template <int D> Snapshot Recorder<D>::snapshot(const Solver<D>& solver) const {
  const Scene<D>& sc = solver.scene();
  const auto& P = sc.particles;
  Snapshot s;
  s.time = solver.time();
  s.step = solver.steps();
  s.dim = D;
  s.count = P.size();
  for (std::size_t i = 0; i < P.size(); ++i) {
    const Voigt6 v = voigt_stress(P, i);
    for (int d = 0; d < D; ++d) {
      s.position.push_back(P.x[i][d]);
      s.displacement.push_back(P.x[i][d] - P.x0[i][d]);
      s.velocity.push_back(P.v[i][d]);
    }
    for (int c = 0; c < 6; ++c) s.stress.push_back(v[c]);
    s.von_mises.push_back(von_mises(v));
    s.volume.push_back(P.vol[i]);
    s.body.push_back(P.body[i]);
    s.material.push_back(sc.bodies[P.body[i]].material);
  }
  return s;
}

template class Recorder<2>;
template class Recorder<3>;

}  // namespace dmi
