#include "engine/sim/recorder.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
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

template <int D> Recorder<D>::Recorder(const Solver<D>& solver, const Scenario& s) : pressures_(solver, s) {
  const Scene<D>& sc = solver.scene();
  for (const char* e : {"kinetic", "strain", "gravity_work", "boundary_work", "balance_error", "dissipated"})
    add(std::string("energy/") + e, "J", {"value"});
  add("momentum", "kg m/s", axes<D>());
  add("dt", "s", {"value"});
  add("step", "-", {"value"});
  for (const auto& w : sc.walls) add("walls/" + w.name + "/force", "N", axes<D>());
  for (const auto& r : sc.regions) add("regions/" + r.name + "/force", "N", axes<D>());
  for (const auto& in : sc.inflows) {  // what entered since t = 0, and the driven zone's force (engine/mpm/inflow.hpp)
    add("inflows/" + in.name + "/force", "N", axes<D>());
    add("inflows/" + in.name + "/mass", "kg", {"value"});
    add("inflows/" + in.name + "/momentum", "kg m/s", axes<D>());
    add("inflows/" + in.name + "/energy", "J", {"value"});
  }
  if (sc.frame) add_frame_series(*sc.frame, s);
  const auto& P = sc.particles;
  for (const auto& pc : s.output.probes) {
    Probe p;
    p.name = pc.name;
    p.particle = pc.type == "particle";
    p.member = pc.type == "member";
    p.quantities = pc.quantities;
    if constexpr (D == 2) if (p.member) {
      const auto& ms = sc.frame->model().members;
      const auto it = std::find_if(ms.begin(), ms.end(), [&](const FrameMemberDef& m) { return m.name == pc.target; });
      const double u = pc.position * it->elements;
      const int k = std::min(static_cast<int>(u), it->elements - 1);
      p.element = it->first_element + k;
      p.xi = u - k;
      const std::string base = "probes/" + p.name + "/";
      for (const auto& q : p.quantities) {
        if (q == "section_forces") add(base + q, "N, N, N m", {"N", "V", "M"});
        else if (q == "fibre_stress") add(base + q, "Pa", {"sigma_top", "sigma_bottom", "tau_max", "von_mises_top", "von_mises_bottom", "von_mises_max"});
        else if (q == "rotation") add(base + q, "rad", {"value"});
        else add(base + q, "m", axes<D>());
      }
      probes_.push_back(p);
      continue;
    }
    while (sc.bodies[p.body].name != pc.target) ++p.body;
    const Body& b = sc.bodies[p.body];
    if (p.particle) {
      Vec<D> x;
      for (int d = 0; d < D; ++d) x[d] = pc.point[d];
      double best = std::numeric_limits<double>::infinity();
      for (Index i = b.begin; i < b.end; ++i)
        if ((P.x[i] - x).squaredNorm() < best) { best = (P.x[i] - x).squaredNorm(); p.index = P.id[i]; }
    }
    const std::string base = "probes/" + p.name + "/";
    for (const auto& q : p.quantities) {
      if (q == "stress") add(base + q, "Pa", D == 2 ? std::vector<std::string>{"xx", "yy", "zz", "xy"} : std::vector<std::string>{"xx", "yy", "zz", "xy", "yz", "xz"});
      else if (q == "von_mises") add(base + q, "Pa", {"value"});
      else if (q == "kinetic_energy") add(base + q, "J", {"value"});
      else if (q == "volume") add(base + q, "m^3", {"current", "initial"});
      else add(base + q, q == "velocity" ? "m/s" : "m", axes<D>());
    }
    probes_.push_back(p);
  }
  pressures_.add_series(series_);
  impulse_.assign(sc.walls.size() + sc.regions.size() + sc.inflows.size(), Vec<D>::Zero());
  const auto d0 = solver.diagnostics();
  e0_ = d0.kinetic + d0.strain + d0.frame_kinetic + d0.frame_strain;
}

template <int D> void Recorder<D>::accumulate(const Solver<D>& solver, double dt) {
  const Scene<D>& sc = solver.scene();
  std::size_t b = 0;
  for (const auto& w : sc.walls) impulse_[b++] += w.force * dt;
  for (const auto& r : sc.regions) impulse_[b++] += r.force * dt;
  for (const auto& in : sc.inflows) impulse_[b++] += in.force * dt;
  pressures_.accumulate(solver, dt);
  if (const auto* mc = solver.member_contact()) {
    member_impulse_ += mc->force() * dt;
    if (mc->force().norm() > peak_contact_) {
      peak_contact_ = mc->force().norm();
      peak_contact_time_ = solver.time();
      peak_loads_ = mc->loads();
    }
  }
  elapsed_ += dt;
}

template <int D> std::optional<PeakContact> Recorder<D>::peak_contact(const FrameOf<D>& f) const {
  if (peak_loads_.empty()) return std::nullopt;
  const auto& m = f.model();
  PeakContact p;
  p.time = peak_contact_time_;
  Vec<D> total = Vec<D>::Zero();
  auto list = [](const Vec<D>& v) { return std::vector<double>(v.data(), v.data() + D); };
  for (const ContactLoadOf<D>& l : peak_loads_) {
    const auto& e = m.elements[l.element];
    const FrameMemberDef& mem = m.members[e.member];
    // Position along the member as a fraction of its length: elements are equal in length along it.
    const double s = (l.element - mem.first_element + l.xi) / mem.elements;
    p.loads.push_back({mem.name, s, list(l.point), list(l.force)});
    total += l.force;
  }
  p.total_force = list(total);
  return p;
}

template <int D> void Recorder<D>::sample(const Solver<D>& solver, double dt) {
  const Scene<D>& sc = solver.scene();
  const auto d = solver.diagnostics();
  time_.push_back(solver.time());
  std::size_t k = 0;
  for (double e : {d.kinetic, d.strain, d.gravity_work, d.boundary_work, d.balance(e0_), d.dissipated}) series_[k++].data.push_back(e);
  push<D>(series_[k++], d.momentum);
  series_[k++].data.push_back(dt);
  series_[k++].data.push_back(static_cast<double>(solver.steps()));
  std::size_t j = 0;  // index into impulse_: walls, regions, then inflows
  for (const auto& w : sc.walls) push<D>(series_[k++], elapsed_ > 0 ? Vec<D>(impulse_[j++] / elapsed_) : w.force);
  for (const auto& r : sc.regions) push<D>(series_[k++], elapsed_ > 0 ? Vec<D>(impulse_[j++] / elapsed_) : r.force);
  for (const auto& in : sc.inflows) {
    push<D>(series_[k++], elapsed_ > 0 ? Vec<D>(impulse_[j++] / elapsed_) : in.force);
    series_[k++].data.push_back(in.mass);
    push<D>(series_[k++], in.momentum);
    series_[k++].data.push_back(in.energy);
  }
  for (auto& i : impulse_) i.setZero();
  if (sc.frame) sample_frame(*sc.frame, *solver.member_contact(), d, k);
  const double elapsed = elapsed_;
  elapsed_ = 0;
  const auto& P = sc.particles;
  for (const auto& p : probes_) {
    if (p.member) {
      if constexpr (D == 2)
        for (const auto& q : p.quantities) sample_member_probe(*sc.frame, p, q, series_[k++]);
      continue;
    }
    const Body& b = sc.bodies[p.body];
    double m = 0, ke = 0, vol = 0, vol0 = 0;
    Vec<D> mx = Vec<D>::Zero(), mu = Vec<D>::Zero(), mv = Vec<D>::Zero();
    if (!p.particle) {
      for (Index i = b.begin; i < b.end; ++i) {
        m += P.mass[i];
        vol += P.vol[i], vol0 += P.vol0[i];
        mx += P.mass[i] * P.x[i];
        mu += P.mass[i] * (P.x[i] - P.x0[i]);
        mv += P.mass[i] * P.v[i];
        ke += 0.5 * P.mass[i] * P.v[i].squaredNorm();
      }
    }
    for (const auto& q : p.quantities) {
      Series& s = series_[k++];
      const Index i = p.particle ? solver.scene().particles.slot[p.index] : 0;  // p.index: creation order
      // A body with no particles yet (an inflow before its debris enters) records zeros.
      const double w = m > 0 ? 1 / m : 0.0;
      if (q == "position") push<D>(s, p.particle ? P.x[i] : Vec<D>(mx * w));
      else if (q == "displacement") push<D>(s, p.particle ? Vec<D>(P.x[i] - P.x0[i]) : Vec<D>(mu * w));
      else if (q == "velocity") push<D>(s, p.particle ? P.v[i] : Vec<D>(mv * w));
      else if (q == "kinetic_energy") s.data.push_back(ke);
      else if (q == "volume") s.data.push_back(vol), s.data.push_back(vol0);
      else if (q == "von_mises") s.data.push_back(von_mises(voigt_stress(P, static_cast<std::size_t>(i))));
      else if (q == "stress") {
        const Voigt6 v = voigt_stress(P, static_cast<std::size_t>(i));
        for (std::size_t c = 0; c < s.components.size(); ++c) s.data.push_back(v[c]);
      }
    }
  }
  pressures_.sample(series_, k, elapsed);
  // Results never hold NaN or inf: a recorded quantity that overflowed (an energy of a 1e200 m/s body) stops the run
  // here, before it is written, as a non-finite particle state stops it in the step.
  for (const Series& s : series_) {
    const std::size_t nc = s.components.size();
    for (std::size_t c = 0; c < nc && s.data.size() >= nc; ++c)
      if (const double v = s.data[s.data.size() - nc + c]; !std::isfinite(v))
        throw RunError("run stopped at step " + std::to_string(solver.steps()) + ", t = " + std::to_string(solver.time()) + " s: the recorded " +
                       s.path + (nc > 1 ? " (" + s.components[c] + ")" : std::string()) + " is " + (std::isnan(v) ? "NaN" : "infinite") +
                       " (an overflow: check the velocities, moduli and loads for values far out of range)");
  }
}

// Frame histories: energies, all nodal DOFs, section forces at element ends, support reactions. Plane frames: DOFs
// ux, uy, rz, end forces N, V, M (frame.hpp), reactions Fx, Fy, M; space frames: ux, uy, uz, rx, ry, rz, end forces N,
// Vy, Vz, T, My, Mz (space_frame.hpp), reactions Fx, Fy, Fz, Mx, My, Mz.
template <int D> void Recorder<D>::add_frame_series(const FrameOf<D>& f, const Scenario& s) {
  for (const char* e : {"frame_kinetic", "frame_strain", "frame_gravity_work", "frame_damping", "contact_work"})
    add(std::string("energy/") + e, "J", {"value"});
  const std::vector<std::string> dof = D == 2 ? std::vector<std::string>{"ux", "uy", "rz"} : std::vector<std::string>{"ux", "uy", "uz", "rx", "ry", "rz"};
  const std::vector<std::string> force = D == 2 ? std::vector<std::string>{"N", "V", "M"} : std::vector<std::string>{"N", "Vy", "Vz", "T", "My", "Mz"};
  std::vector<std::string> dofs, ends;
  for (int n = 0; n < f.nnodes(); ++n)
    for (const std::string& c : dof) dofs.push_back("n" + std::to_string(n) + "_" + c);
  for (int e = 0; e < f.nelements(); ++e)
    for (const char* end : {"_i", "_j"})
      for (const std::string& c : force) ends.push_back("e" + std::to_string(e) + "_" + c + end);
  if constexpr (D == 2) {  // the plane layout the design layer reads: N_i, V_i, M_i, N_j, V_j, M_j
    ends.clear();
    for (int e = 0; e < f.nelements(); ++e)
      for (const char* c : {"N_i", "V_i", "M_i", "N_j", "V_j", "M_j"}) ends.push_back("e" + std::to_string(e) + "_" + c);
  }
  add("frame/displacement", D == 2 ? "m, m, rad" : "m, rad", dofs);
  add("frame/end_forces", D == 2 ? "N, N, N m" : "N, N m", ends);
  add("frame/contact_force", "N", axes<D>());  // force of the material on the members, interval mean
  if (f.plastic()) {  // elasto-plastic members: plastic work, and per element what it has done so far
    add("energy/frame_plastic", "J", {"value"});
    std::vector<std::string> pc;
    for (int e = 0; e < f.nelements(); ++e)
      for (const char* c : {"_work", "_peak_strain", "_plastic_strain"}) pc.push_back("e" + std::to_string(e) + c);
    add("frame/plastic", "J, -, -", pc);
  }
  for (const auto& sup : s.structure.supports)
    add("supports/" + sup.node + "/reaction", D == 2 ? "N, N, N m" : "N, N m", D == 2 ? std::vector<std::string>{"Fx", "Fy", "M"} : std::vector<std::string>{"Fx", "Fy", "Fz", "Mx", "My", "Mz"});
}

template <int D>
void Recorder<D>::sample_frame(const FrameOf<D>& f, const MemberContact<D>& mc, const Diagnostics<D>& d, std::size_t& k) {
  for (double e : {d.frame_kinetic, d.frame_strain, d.frame_gravity_work, d.frame_damping, d.contact_work}) series_[k++].data.push_back(e);
  const Eigen::VectorXd& u = f.displacement();
  Series& disp = series_[k++];
  disp.data.insert(disp.data.end(), u.data(), u.data() + u.size());
  Series& ends = series_[k++];
  for (int e = 0; e < f.nelements(); ++e)
    for (double xi : {0.0, 1.0}) {
      const auto sf = f.forces_at(e, xi);
      if constexpr (D == 2) ends.data.insert(ends.data.end(), {sf.N, sf.V, sf.M});
      else ends.data.insert(ends.data.end(), {sf.N, sf.Vy, sf.Vz, sf.T, sf.My, sf.Mz});
    }
  Series& cf = series_[k++];
  const Vec<D> mean = elapsed_ > 0 ? Vec<D>(member_impulse_ / elapsed_) : mc.force();
  cf.data.insert(cf.data.end(), mean.data(), mean.data() + D);
  member_impulse_.setZero();
  if (f.plastic()) {
    series_[k++].data.push_back(d.frame_plastic);
    Series& ps = series_[k++];
    for (int e = 0; e < f.nelements(); ++e) {
      const auto r = f.plastic_record(e).value_or(PlasticRecord{});
      ps.data.insert(ps.data.end(), {r.plastic_work, r.peak_strain, r.peak_plastic_strain});
    }
  }
  for (int r = 0; r < static_cast<int>(f.model().supports.size()); ++r) {
    const auto rf = f.reaction(r);
    Series& rs = series_[k++];
    rs.data.insert(rs.data.end(), rf.data(), rf.data() + rf.size());
  }
}

// Member probe at (element, xi): centre-line and top-surface displacement, rotation of the
// tangent, section forces and fibre stresses (conventions of engine/structure/frame.hpp).
template <int D> void Recorder<D>::sample_member_probe(const Frame& f, const Probe& p, const std::string& q, Series& s) const {
  const FrameElementDef& el = f.model().elements[p.element];
  const Vec2 X0 = f.model().nodes[el.i] + p.xi * (f.model().nodes[el.j] - f.model().nodes[el.i]);
  const Vec2 t0 = (f.model().nodes[el.j] - f.model().nodes[el.i]).normalized();
  const ElementCurve c = f.curve(p.element);
  const Vec2 x = c.point(p.xi), t = c.d1(p.xi).normalized();
  const double hc = f.half_depth(p.element, p.xi);
  if (q == "displacement") {
    s.data.insert(s.data.end(), {x.x() - X0.x(), x.y() - X0.y()});
  } else if (q == "top_displacement") {
    const Vec2 u = (x + hc * Vec2(-t.y(), t.x())) - (X0 + hc * Vec2(-t0.y(), t0.x()));
    s.data.insert(s.data.end(), {u.x(), u.y()});
  } else if (q == "rotation") {
    s.data.push_back(std::atan2(t0.x() * t.y() - t0.y() * t.x(), t0.dot(t)));
  } else if (q == "section_forces") {
    const SectionForces sf = f.forces_at(p.element, p.xi);
    s.data.insert(s.data.end(), {sf.N, sf.V, sf.M});
  } else if (q == "fibre_stress") {
    const FibreStresses fs = f.stresses_at(p.element, p.xi);
    s.data.insert(s.data.end(), {fs.sigma_top, fs.sigma_bottom, fs.tau_max, fs.von_mises_top, fs.von_mises_bottom, fs.von_mises_max});
  }
}

// Members sampled at 9 points along every element's deformed centre-line: plane frames N, V, M and the fibre stresses
// of both faces; space frames N, Vy, Vz, T, My, Mz and the extremes around the section.
template <int D> LineSnapshot Recorder<D>::member_snapshot(const FrameOf<D>& f) {
  LineSnapshot s;
  s.dim = D;
  const std::vector<const char*> names =
      D == 2 ? std::vector<const char*>{"N (N)", "V (N)", "M (N m)", "sigma_top (Pa)", "sigma_bottom (Pa)", "von_mises_max (Pa)"}
             : std::vector<const char*>{"N (N)", "Vy (N)", "Vz (N)", "T (N m)", "My (N m)", "Mz (N m)", "sigma_max (Pa)", "sigma_min (Pa)",
                                        "tau_max (Pa)", "von_mises_max (Pa)"};
  for (const char* n : names) s.point_scalars.push_back({n, {}});
  constexpr int kSamples = 9;
  for (int e = 0; e < f.nelements(); ++e) {
    const auto& el = f.model().elements[e];
    const Vec<D> Xi = f.model().nodes[el.i], Xj = f.model().nodes[el.j];
    const auto c = f.curve(e);
    for (int k = 0; k < kSamples; ++k) {
      const double xi = double(k) / (kSamples - 1);
      const Vec<D> x = c.point(xi), u = x - (Xi + xi * (Xj - Xi));
      s.points.insert(s.points.end(), x.data(), x.data() + D);
      s.displacement.insert(s.displacement.end(), u.data(), u.data() + D);
      const auto sf = f.forces_at(e, xi);
      const auto fs = f.stresses_at(e, xi);
      std::vector<double> v;
      if constexpr (D == 2) v = {sf.N, sf.V, sf.M, fs.sigma_top, fs.sigma_bottom, fs.von_mises_max};
      else v = {sf.N, sf.Vy, sf.Vz, sf.T, sf.My, sf.Mz, fs.sigma_max, fs.sigma_min, fs.tau_max, fs.von_mises_max};
      for (std::size_t q = 0; q < v.size(); ++q) s.point_scalars[q].second.push_back(v[q]);
    }
    s.ends.push_back(s.points.size() / D);
    s.member.push_back(el.member);
  }
  return s;
}

template <int D> Snapshot Recorder<D>::snapshot(const Solver<D>& solver) const {
  const Scene<D>& sc = solver.scene();
  const auto& P = sc.particles;
  Snapshot s;
  s.time = solver.time();
  s.step = solver.steps();
  s.dim = D;
  s.count = P.size();
  for (std::size_t k = 0; k < P.size(); ++k) {  // creation order, whatever the solver's current order
    const std::size_t i = static_cast<std::size_t>(P.slot[k]);
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

template <int D> void Recorder<D>::save_state(StateWriter& w) const {
  w.tag("recorder");
  w.put(time_);
  w.put<std::uint64_t>(series_.size());
  for (const Series& s : series_) w.put(s.path), w.put(s.data);
  w.put(impulse_), w.put(member_impulse_), w.put(elapsed_), w.put(peak_contact_), w.put(peak_contact_time_), w.put(e0_);
  save_loads(w, peak_loads_);
  pressures_.save_state(w);
}

template <int D> void Recorder<D>::load_state(StateReader& r) {
  r.tag("recorder");
  r.get(time_);
  r.expect_size("history series", r.get<std::uint64_t>(), series_.size());
  for (Series& s : series_) {
    std::string path;
    r.get(path);
    if (path != s.path) r.fail("history series '" + path + "' where the scenario gives '" + s.path + "'");
    r.get(s.data);
    r.expect_size(("history '" + s.path + "'").c_str(), s.data.size(), time_.size() * s.components.size());
  }
  const std::size_t ni = impulse_.size();
  r.get(impulse_);
  r.expect_size("wall, region and inflow impulses", impulse_.size(), ni);
  r.get(member_impulse_), r.get(elapsed_), r.get(peak_contact_), r.get(peak_contact_time_), r.get(e0_);
  load_loads(r, peak_loads_);
  pressures_.load_state(r);
}

template class Recorder<2>;
template class Recorder<3>;

}  // namespace dmi
