#include "engine/mpm/rigid.hpp"

#include <algorithm>
#include <cmath>

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
  for (std::size_t k = 0; k < s.bodies.size(); ++k) {
    const Body& b = s.bodies[k];
    if (!b.rigid) continue;
    State st;
    st.body = static_cast<int>(k);
    for (Index i = b.begin; i < b.end; ++i) st.mass += P.mass[i], st.xc0 += P.mass[i] * P.x0[i];
    st.xc0 /= st.mass;
    st.xc = st.xc0;
    for (Index i = b.begin; i < b.end; ++i) {
      Vec<3> r = Vec<3>::Zero(), a = Vec<3>::Zero();  // offset and half-sizes, padded to 3D
      r.head<D>() = P.x0[i] - st.xc0;
      a.head<D>() = P.half_size[i];
      Mat<3> own = Mat<3>::Zero();  // a uniform box of half-sizes a about its centre: m (a_j^2 + a_k^2) / 3
      for (int c = 0; c < 3; ++c) own(c, c) = (a.squaredNorm() - a[c] * a[c]) / 3;
      st.I0 += P.mass[i] * (r.squaredNorm() * Mat<3>::Identity() - r * r.transpose() + own);
    }
    bodies_.push_back(st);
  }
  project(s);
  move(s, 0.0);
}

template <int D> void RigidBodies<D>::project(Scene<D>& s) {
  Particles<D>& P = s.particles;
  for (State& st : bodies_) {
    const Body& b = s.bodies[st.body];
    Vec<D> p = Vec<D>::Zero();
    Vec<3> l = Vec<3>::Zero();
    for (Index i = b.begin; i < b.end; ++i) {
      const Vec<D> r = st.R * (P.x0[i] - st.xc0);
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
    for (Index i = b.begin; i < b.end; ++i) P.v[i] = st.V + cross(st.omega, Vec<D>(st.R * (P.x0[i] - st.xc0)));
  }
}

template <int D> double RigidBodies<D>::project_nodes(Scene<D>& s, std::vector<Vec<D>>& vel, double s_min) const {
  const Grid<D>& g = *s.grid;
  const Index nn = g.nnodes();
  double worst = 0;
  for (const State& st : bodies_) {
    const Index off = s.bodies[st.body].field * nn;
    double M = 0;
    Vec<D> mx = Vec<D>::Zero(), p = Vec<D>::Zero();
    for (Index id : g.active())
      if (const double m = g.m[off + id]; m > 0) M += m, mx += m * g.node_pos(id), p += m * vel[off + id];
    if (!(M > 0)) continue;
    const Vec<D> xc = mx / M, V = p / M;
    Mat<3> I = Mat<3>::Zero();
    Vec<3> l = Vec<3>::Zero();
    double rmax = 0;
    for (Index id : g.active())
      if (const double m = g.m[off + id]; m > 0) {
        Vec<3> r = Vec<3>::Zero(), v = Vec<3>::Zero();
        r.head<D>() = g.node_pos(id) - xc, v.head<D>() = vel[off + id];
        I += m * (r.squaredNorm() * Mat<3>::Identity() - r * r.transpose());
        l += m * r.cross(v);
        rmax = std::max(rmax, r.norm());
      }
    Spin w;
    if constexpr (D == 2) {
      w = l.z() / I(2, 2);
    } else {
      w = I.ldlt().solve(l);
    }
    double scale = s_min + V.norm(), change = 0;
    if constexpr (D == 2) scale += std::abs(w) * rmax; else scale += w.norm() * rmax;
    for (Index id : g.active())
      if (g.m[off + id] > 0) {
        const Vec<D> vr = V + cross(w, Vec<D>(g.node_pos(id) - xc));
        change = std::max(change, (vr - vel[off + id]).norm());
        vel[off + id] = vr;
      }
    worst = std::max(worst, change / scale);
  }
  return worst;
}

template <int D> bool RigidBodies<D>::move(Scene<D>& s, double dt) {
  Particles<D>& P = s.particles;
  bool ok = true;
  for (State& st : bodies_) {
    const Body& b = s.bodies[st.body];
    st.xc += dt * st.V;
    st.R = rotation(st.omega, dt) * st.R;
    const Mat<D> W = spin_matrix(st.omega);
    for (Index i = b.begin; i < b.end; ++i) {
      const Vec<D> r = st.R * (P.x0[i] - st.xc0);
      P.x[i] = st.xc + r;
      P.v[i] = st.V + cross(st.omega, r);
      P.F[i] = st.R;
      P.L[i] = W;
      P.C[i] = W;  // the affine velocity of APIC: exact for a rigid motion
      ok = ok && s.grid->interior(P.x[i]) && P.v[i].allFinite();
    }
  }
  return ok;
}

template <int D> void RigidBodies<D>::save_state(StateWriter& w) const {
  w.tag("rigid");
  w.put<std::uint64_t>(bodies_.size());
  for (const State& st : bodies_) w.put(st.xc), w.put(st.V), w.put(st.R), w.put(st.omega);
}

template <int D> void RigidBodies<D>::load_state(StateReader& r) {
  r.tag("rigid");
  r.expect_size("rigid bodies", r.get<std::uint64_t>(), bodies_.size());
  for (State& st : bodies_) r.get(st.xc), r.get(st.V), r.get(st.R), r.get(st.omega);
}

template class RigidBodies<2>;
template class RigidBodies<3>;

}  // namespace dmi
