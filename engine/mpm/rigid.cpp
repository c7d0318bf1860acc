#include "engine/mpm/rigid.hpp"

#include <algorithm>
#include <cmath>

#include "engine/common/coulomb.hpp"
#include "engine/materials/material.hpp"
#include "engine/mpm/boundary.hpp"

namespace dmi {
namespace {

// [w]x: the velocity gradient of a rigid rotation.
Mat<2> spin_matrix(double w) { return (Mat<2>() << 0, -w, w, 0).finished(); }
Mat<3> spin_matrix(const Vec<3>& w) { return (Mat<3>() << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0).finished(); }
Vec<2> cross(double w, const Vec<2>& r) { return Vec<2>(-w * r.y(), w * r.x()); }
Vec<3> cross(const Vec<3>& w, const Vec<3>& r) { return w.cross(r); }

// exp(dt [w]x): exact rotation over the step (Rodrigues in 3D).
Mat<2> rotation(double w, double dt) {
  const double c = std::cos(w * dt), s = std::sin(w * dt);
  return (Mat<2>() << c, -s, s, c).finished();
}
Mat<3> rotation(const Vec<3>& w, double dt) {
  const double a = w.norm() * dt;
  if (a < 1e-300) return Mat<3>::Identity();
  const Mat<3> K = spin_matrix(Vec<3>(w.normalized()));
  return Mat<3>::Identity() + std::sin(a) * K + (1 - std::cos(a)) * K * K;
}

}  // namespace

template <int D> RigidBodies<D>::RigidBodies(Scene<D>& s) {
  const Particles<D>& P = s.particles;
  ref_.assign(P.size(), Vec<D>::Zero());
  F0_.assign(P.size(), Mat<D>::Identity());
  for (std::size_t k = 0; k < s.bodies.size(); ++k)
    if (s.bodies[k].rigid) bodies_.push_back(make_state(s, static_cast<int>(k), P.x0));
  project(s);
  move(s, 0.0);
}

// A rigid body in the configuration x of its particles: mass, centre, inertia about it; the particles' reference
// offsets from the centre and their F at this moment (F_p = R F_0 from then on).
template <int D> typename RigidBodies<D>::State RigidBodies<D>::make_state(const Scene<D>& s, int k, const std::vector<Vec<D>>& x) {
  const Particles<D>& P = s.particles;
  const Body& b = s.bodies[k];
  if (ref_.size() < P.size()) ref_.resize(P.size(), Vec<D>::Zero()), F0_.resize(P.size(), Mat<D>::Identity());
  State st;
  st.body = k;
  if constexpr (D == 2) st.omega = 0; else st.omega.setZero();
  for (Index i = b.begin; i < b.end; ++i) st.mass += P.mass[i], st.xc0 += P.mass[i] * x[i];
  st.xc0 /= st.mass;
  st.xc = st.xc0;
  Mat<3> own = Mat<3>::Zero();  // the particles' own (cell) inertia, m (a_j^2 + a_k^2) / 3 for half-sizes a
  for (Index i = b.begin; i < b.end; ++i) {
    ref_[i] = x[i] - st.xc0;
    F0_[i] = P.F[i];
    Vec<3> r = Vec<3>::Zero(), a = Vec<3>::Zero();  // offset and half-sizes, padded to 3D
    r.head<D>() = ref_[i];
    a.head<D>() = P.half_size[i];
    st.I0 += P.mass[i] * (r.squaredNorm() * Mat<3>::Identity() - r * r.transpose());
    for (int c = 0; c < 3; ++c) own(c, c) += P.mass[i] * (a.squaredNorm() - a[c] * a[c]) / 3;
  }
  // A body of one particle (or one row of them, about its axis) has no orbital inertia: the own inertia keeps its
  // spin finite there, and only there (elsewhere it would make the projection shrink a rigid spin every step).
  const Mat<3> spin_plane = D == 2 ? Mat<3>(Vec<3>(0, 0, 1).asDiagonal()) : Mat<3>::Identity();
  for (int c = 0; c < 3; ++c)
    if (spin_plane(c, c) > 0 && !(st.I0(c, c) > 1e-6 * own(c, c))) st.I0(c, c) += own(c, c);
  return st;
}

template <int D> double RigidBodies<D>::add(Scene<D>& s, int k) {
  Particles<D>& P = s.particles;
  const Body& b = s.bodies[k];
  auto kinetic = [&] {
    double e = 0;
    for (Index i = b.begin; i < b.end; ++i) e += 0.5 * P.mass[i] * P.v[i].squaredNorm();
    return e;
  };
  const double before = kinetic();
  bodies_.push_back(make_state(s, k, P.x));
  project_one(s, bodies_.back());
  move_one(s, bodies_.back(), 0.0);
  return before - kinetic();
}

template <int D> void RigidBodies<D>::remove(int k) {
  bodies_.erase(std::remove_if(bodies_.begin(), bodies_.end(), [k](const State& st) { return st.body == k; }), bodies_.end());
}

template <int D> void RigidBodies<D>::permute(const std::vector<Index>& perm) {
  if (ref_.size() < perm.size()) ref_.resize(perm.size(), Vec<D>::Zero()), F0_.resize(perm.size(), Mat<D>::Identity());
  permute_array(ref_, perm), permute_array(F0_, perm);
}

template <int D> void RigidBodies<D>::project(Scene<D>& s) {
  for (State& st : bodies_) project_one(s, st);
}

template <int D> void RigidBodies<D>::project_one(Scene<D>& s, State& st) {
  Particles<D>& P = s.particles;
  {
    const Body& b = s.bodies[st.body];
    Vec<D> p = Vec<D>::Zero();
    Vec<3> l = Vec<3>::Zero();
    for (Index i = b.begin; i < b.end; ++i) {
      const Vec<D> r = st.R * ref_[i];
      p += P.mass[i] * P.v[i];
      if constexpr (D == 2) {
        l.z() += P.mass[i] * (r.x() * P.v[i].y() - r.y() * P.v[i].x());
      } else {
        l += P.mass[i] * r.cross(P.v[i]);
      }
    }
    st.V = p / st.mass;
    if constexpr (D == 2) {
      st.omega = l.z() / st.I0(2, 2);
    } else {
      st.omega = (st.R * st.I0 * st.R.transpose()).ldlt().solve(l);
    }
    for (Index i = b.begin; i < b.end; ++i) P.v[i] = st.V + cross(st.omega, Vec<D>(st.R * ref_[i]));
  }
}

namespace {

// The rigid motion of a field's nodal velocities: mass, mass centre, momentum velocity, inertia about the centre and
// spin (momentum and angular momentum of the field kept).
template <int D> struct NodalMotion {
  double M = 0, rmax = 0;
  Vec<D> xc = Vec<D>::Zero(), V = Vec<D>::Zero();
  Mat<3> I = Mat<3>::Zero();
  Vec<3> w = Vec<3>::Zero();  // 2D: (0, 0, w)
  Vec<D> at(const Vec<D>& x) const {
    Vec<3> r = Vec<3>::Zero();
    r.head<D>() = x - xc;
    return V + w.cross(r).head<D>();
  }
  double speed_scale(double s_min) const { return s_min + V.norm() + w.norm() * rmax; }  // |V| + |omega| r_max + s
  Mat<3> inverse_inertia() const {  // 2D: rotation about z only
    Mat<3> Iinv = Mat<3>::Zero();
    if constexpr (D == 2) Iinv(2, 2) = 1 / I(2, 2); else Iinv = I.inverse();
    return Iinv;
  }
};

// The rigid field's nodes (field offset off) take the motion m; returns the largest change of a nodal velocity over
// scale.
template <int D>
double take_motion(const Grid<D>& g, std::vector<Vec<D>>& vel, Index off, const std::vector<Index>& nodes, const NodalMotion<D>& m,
                   double scale) {
  double change = 0;
  for (Index id : nodes)
    if (g.m[off + id] > 0) {
      const Vec<D> v = m.at(g.node_pos(id));
      change = std::max(change, (v - vel[off + id]).norm());
      vel[off + id] = v;
    }
  return change / scale;
}

template <int D> NodalMotion<D> nodal_motion(const Grid<D>& g, const std::vector<Vec<D>>& vel, Index off, const std::vector<Index>& nodes) {
  NodalMotion<D> m;
  Vec<D> mx = Vec<D>::Zero(), p = Vec<D>::Zero();
  for (Index id : nodes)
    if (const double mi = g.m[off + id]; mi > 0) m.M += mi, mx += mi * g.node_pos(id), p += mi * vel[off + id];
  if (!(m.M > 0)) return m;
  m.xc = mx / m.M, m.V = p / m.M;
  if constexpr (D == 2) {  // rotation about z alone: I_zz = sum m |r|^2, L_z = sum m (r x v)_z (the 3 x 3 sums cost 3x)
    double izz = 0, lz = 0, r2max = 0;
    for (Index id : nodes)
      if (const double mi = g.m[off + id]; mi > 0) {
        const Vec<D> r = g.node_pos(id) - m.xc, &v = vel[off + id];
        const double r2 = r.squaredNorm();
        izz += mi * r2, lz += mi * (r.x() * v.y() - r.y() * v.x()), r2max = std::max(r2max, r2);
      }
    m.I(2, 2) = izz, m.w.z() = lz / izz, m.rmax = std::sqrt(r2max);
  } else {
    Vec<3> l = Vec<3>::Zero();
    for (Index id : nodes)
      if (const double mi = g.m[off + id]; mi > 0) {
        const Vec<3> r = g.node_pos(id) - m.xc, &v = vel[off + id];
        m.I += mi * (r.squaredNorm() * Mat<3>::Identity() - r * r.transpose());
        l += mi * r.cross(v);
        m.rmax = std::max(m.rmax, r.norm());
      }
    m.w = m.I.ldlt().solve(l);
  }
  return m;
}

}  // namespace

template <int D> std::vector<char> hull_fields(const Scene<D>& s) {
  std::vector<int> bodies(s.grid->nfields(), 0);
  std::vector<char> hull(s.grid->nfields(), 1);
  for (const Body& b : s.bodies) {
    ++bodies[b.field];
    if (!b.rigid || b.hull_points.empty()) hull[b.field] = 0;
  }
  for (std::size_t f = 0; f < hull.size(); ++f) hull[f] = hull[f] && bodies[f] == 1;
  return hull;
}

template <int D>
double RigidBodies<D>::wall_contact(Scene<D>& s, std::vector<Vec<D>>& vel, double dt, double s_min, double& change,
                                    const std::vector<Index>* only) const {
  const Grid<D>& g = *s.grid;
  const std::vector<Index>& nodes = only ? *only : g.active();
  const std::vector<char> hull = hull_fields(s);
  double work = 0;
  change = 0;
  struct Contact { Wall<D>* wall; Vec<3> r, n, P; double gap, lambda; };
  for (const State& st : bodies_) {
    const Body& b = s.bodies[st.body];
    const Index off = b.field * g.nnodes();
    if (!hull[b.field] || !(dt > 0)) continue;
    NodalMotion<D> m = nodal_motion(g, vel, off, nodes);
    if (!(m.M > 0)) continue;
    const Mat<3> Iinv = m.inverse_inertia();
    std::vector<Contact> cs;
    for (Wall<D>& w : s.walls) {
      if (w.box || !(w.condition == WallCondition::slip || w.condition == WallCondition::friction)) continue;
      for (std::size_t k = 0; k < b.hull_points.size(); k += D) {
        const Vec<D> p0 = Eigen::Map<const Vec<D>>(&b.hull_points[k]);
        const Vec<D> c = st.xc + st.R * (p0 - st.xc0) - b.hull_radius * w.normal;
        const double gap = (c - w.point).dot(w.normal);
        if (gap + dt * m.at(c).dot(w.normal) >= 0) continue;
        Contact ct{&w, Vec<3>::Zero(), Vec<3>::Zero(), Vec<3>::Zero(), gap, 0.0};
        ct.r.template head<D>() = c - m.xc, ct.n.template head<D>() = w.normal;
        cs.push_back(ct);
      }
    }
    if (cs.empty()) continue;
    Vec<3> V = Vec<3>::Zero();
    V.head<D>() = m.V;
    Vec<3> W = m.w;
    const auto apply = [&](const Contact& c, const Vec<3>& P) { V += P / m.M, W += Iinv * c.r.cross(P); };
    const auto eff = [&](const Contact& c, const Vec<3>& u) { return 1 / m.M + u.dot((Iinv * c.r.cross(u)).cross(c.r)); };
    for (int it = 0; it < 50; ++it) {
      double moved = 0;  // largest impulse increment of the sweep
      for (Contact& c : cs) {
        const double target = c.gap > 0 ? -c.gap / dt : 0.0;  // reach the wall within the step, no deeper
        const double vn = (V + W.cross(c.r)).dot(c.n);
        const double lam = std::max(0.0, c.lambda + (target - vn) / eff(c, c.n)), dl = lam - c.lambda;
        c.lambda = lam;
        apply(c, dl * c.n);
        c.P += dl * c.n;
        moved = std::max(moved, std::abs(dl));
        const double mu = c.wall->condition == WallCondition::friction ? c.wall->friction : 0.0;
        if (mu <= 0) continue;
        const Vec<3> v = V + W.cross(c.r), vt = v - v.dot(c.n) * c.n;
        const double st_norm = vt.norm();
        if (st_norm <= 0) continue;
        const Vec<3> t = vt / st_norm;
        const Vec<3> Pt = c.P - c.P.dot(c.n) * c.n, Pt_new = coulomb_projection(Vec<3>(Pt - st_norm / eff(c, t) * t), mu * c.lambda);
        apply(c, Pt_new - Pt);
        c.P += Pt_new - Pt;
        moved = std::max(moved, (Pt_new - Pt).norm());
      }
      if (moved <= 1e-14 * m.M * (m.V.norm() + W.norm() * m.rmax + 1e-300)) break;
    }
    for (const Contact& c : cs) {
      c.wall->force -= c.P.template head<D>() / dt;
      for (auto& ps : c.wall->sensors) patch_add(ps, Vec<D>(m.xc + c.r.template head<D>()), Vec<D>(-c.P.template head<D>() / dt), g.h());
      const Vec<3> v = V + W.cross(c.r);  // friction's work where the point slips; the fixed wall's normal impulse does none
      work += (c.P - c.P.dot(c.n) * c.n).dot(v - v.dot(c.n) * c.n);
    }
    NodalMotion<D> after = m;
    after.V = V.head<D>(), after.w = W;
    change = std::max(change, take_motion(g, vel, off, nodes, after, m.speed_scale(s_min)));
  }
  return work;
}

template <int D>
double RigidBodies<D>::project_nodes(Scene<D>& s, std::vector<Vec<D>>& vel, double s_min, const std::vector<Index>* only) const {
  const Grid<D>& g = *s.grid;
  const std::vector<Index>& nodes = only ? *only : g.active();
  double worst = 0;
  for (const State& st : bodies_) {
    const Index off = s.bodies[st.body].field * g.nnodes();
    const NodalMotion<D> m = nodal_motion(g, vel, off, nodes);
    if (!(m.M > 0)) continue;
    worst = std::max(worst, take_motion(g, vel, off, nodes, m, m.speed_scale(s_min)));
  }
  return worst;
}

template <int D> std::vector<char> RigidBodies<D>::contact_fields(const Scene<D>& s) const {
  std::vector<int> bodies(s.grid->nfields(), 0);
  std::vector<char> rigid(s.grid->nfields(), 1);
  for (const Body& b : s.bodies) ++bodies[b.field], rigid[b.field] = rigid[b.field] && b.rigid;
  for (std::size_t f = 0; f < rigid.size(); ++f) rigid[f] = rigid[f] && bodies[f] == 1;
  return rigid;
}

template <int D>
double RigidBodies<D>::body_contact(Scene<D>& s, std::vector<Vec<D>>& vel, double s_min, const std::vector<Index>& nodes,
                                    const std::vector<char>& rigid) const {
  const Grid<D>& g = *s.grid;
  if (g.nfields() < 2 || s.options.contact_detection != BodyDetection::surface || s.body_pair.size() != static_cast<std::size_t>(g.nnodes()))
    return 0;
  const double tol = 1e-6 * g.h(), mu = s.options.contact_friction;
  struct Contact { Index kb; double mb; Vec<3> r, n; };
  std::vector<Contact> cs;
  double worst = 0;
  for (const State& st : bodies_) {
    const int f = s.bodies[st.body].field;
    if (!rigid[f]) continue;
    const Index off = f * g.nnodes();
    const NodalMotion<D> m = nodal_motion(g, vel, off, nodes);
    if (!(m.M > 0)) continue;
    cs.clear();
    for (Index id : nodes) {
      const auto& pair = s.body_pair[id];
      if (pair[0] < 0 || (pair[0] != f && pair[1] != f)) continue;
      const int o = pair[0] == f ? pair[1] : pair[0];
      Vec<D> n;
      if (rigid[o] || !pair_normal(s, id, tol, n)) continue;
      const Index kb = o * g.nnodes() + id;
      if (!pair_masses_count(g.m[off + id], g.m[kb])) continue;
      Contact c{kb, g.m[kb], Vec<3>::Zero(), Vec<3>::Zero()};
      c.r.template head<D>() = g.node_pos(id) - m.xc;
      c.n.template head<D>() = pair[0] == f ? n : Vec<D>(-n);  // from the rigid body towards the other field
      cs.push_back(c);
    }
    if (cs.empty()) continue;
    const Mat<3> Iinv = m.inverse_inertia();
    Vec<3> V = Vec<3>::Zero(), W = m.w;
    V.head<D>() = m.V;
    const double scale = m.speed_scale(s_min);
    for (int sweep = 0; sweep < 100; ++sweep) {
      double moved = 0;  // largest impulse of the sweep
      for (const Contact& c : cs) {
        Vec<3> vb = Vec<3>::Zero();
        vb.head<D>() = vel[c.kb];
        const Vec<3> u = V + W.cross(c.r) - vb;  // the rigid side's velocity relative to the other field's
        const double un = u.dot(c.n);
        if (un <= 0) continue;  // separating
        // u changes by A P for an impulse P on the body (-P on the node): A = K(r) + 1/m_b.
        const Mat<3> rx = spin_matrix(c.r);  // [r]x
        Mat<3> A = (1 / m.M + 1 / c.mb) * Mat<3>::Identity() - rx * Iinv * rx;
        if constexpr (D == 2) A(2, 2) = 1;  // no motion along z: keep A invertible, u_z = 0
        Vec<3> P = -A.inverse() * u;  // stick: the relative velocity removed
        const double lam = -P.dot(c.n);
        if ((P + lam * c.n).norm() > mu * lam) {  // slip: the normal approach removed, Coulomb's mu lam_n against the slip
          const double ln = un / c.n.dot(A * c.n);
          const Vec<3> ut = u - un * c.n;
          P = -ln * c.n - (ut.norm() > 0 ? Vec<3>(mu * ln * ut.normalized()) : Vec<3>::Zero());
        }
        V += P / m.M, W += Iinv * c.r.cross(P);
        vel[c.kb] -= P.template head<D>() / c.mb;
        moved = std::max(moved, P.norm());
      }
      if (moved <= 1e-12 * m.M * scale) break;
    }
    NodalMotion<D> after = m;
    after.V = V.head<D>(), after.w = W;
    worst = std::max(worst, take_motion(g, vel, off, nodes, after, scale));
  }
  return worst;
}

template <int D> void RigidBodies<D>::take_nodal_motion(Scene<D>& s, const std::vector<Vec<D>>& vel, bool affine) {
  Particles<D>& P = s.particles;
  for (State& st : bodies_) {
    const Body& b = s.bodies[st.body];
    const NodalMotion<D> m = nodal_motion(*s.grid, vel, b.field * s.grid->nnodes(), s.grid->active());
    if (!(m.M > 0)) continue;
    st.V = m.V;
    if constexpr (D == 2) {
      st.omega = affine ? m.w.z() : m.I(2, 2) * m.w.z() / st.I0(2, 2);
    } else {
      st.omega = affine ? m.w : Vec<3>((st.R * st.I0 * st.R.transpose()).ldlt().solve(m.I * m.w));
    }
    for (Index i = b.begin; i < b.end; ++i) P.v[i] = st.V + cross(st.omega, Vec<D>(st.R * ref_[i]));
  }
}

template <int D> bool RigidBodies<D>::move(Scene<D>& s, double dt) {
  bool ok = true;
  for (State& st : bodies_) ok = move_one(s, st, dt) && ok;
  return ok;
}

template <int D> bool RigidBodies<D>::move_one(Scene<D>& s, State& st, double dt) {
  Particles<D>& P = s.particles;
  bool ok = true;
  const Body& b = s.bodies[st.body];
  st.xc += dt * st.V;
  st.R = rotation(st.omega, dt) * st.R;
  const Mat<D> W = spin_matrix(st.omega);
  for (Index i = b.begin; i < b.end; ++i) {
    const Vec<D> r = st.R * ref_[i];
    P.x[i] = st.xc + r;
    P.v[i] = st.V + cross(st.omega, r);
    P.F[i] = st.R * F0_[i];
    P.L[i] = W;
    P.C[i] = W;  // the affine velocity of APIC: exact for a rigid motion
    ok = ok && s.grid->interior(P.x[i]) && P.v[i].allFinite();
  }
  return ok;
}

// The rigid set changes during a run (rigid_when_free bodies): every state is written whole, with the reference offsets.
template <int D> void RigidBodies<D>::save_state(StateWriter& w) const {
  w.tag("rigid");
  w.put<std::uint64_t>(bodies_.size());
  for (const State& st : bodies_)
    w.put(st.body), w.put(st.mass), w.put(st.xc0), w.put(st.I0), w.put(st.xc), w.put(st.V), w.put(st.R), w.put(st.omega);
  w.put(ref_), w.put(F0_);
}

template <int D> void RigidBodies<D>::load_state(StateReader& r) {
  r.tag("rigid");
  const auto n = r.get<std::uint64_t>();
  if (n > (std::uint64_t{1} << 20)) r.fail("rigid body count " + std::to_string(n) + " out of range");
  bodies_.resize(static_cast<std::size_t>(n));
  for (State& st : bodies_)
    r.get(st.body), r.get(st.mass), r.get(st.xc0), r.get(st.I0), r.get(st.xc), r.get(st.V), r.get(st.R), r.get(st.omega);
  r.get(ref_), r.get(F0_);
}

template class RigidBodies<2>;
template class RigidBodies<3>;
template std::vector<char> hull_fields(const Scene<2>&);
template std::vector<char> hull_fields(const Scene<3>&);

}  // namespace dmi
