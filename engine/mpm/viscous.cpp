#include "engine/mpm/viscous.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/common/error.hpp"
#include "engine/common/parallel.hpp"
#include "engine/mpm/boundary.hpp"

namespace dmi {
namespace {

template <int D> double dot(const std::vector<Vec<D>>& x, const std::vector<Vec<D>>& y) {
  double s = 0;
  for (std::size_t i = 0; i < x.size(); ++i) s += x[i].dot(y[i]);
  return s;
}

}  // namespace

template <int D> bool ImplicitViscosity<D>::needed(const Scene<D>& s) {
  std::vector<char> fields(static_cast<std::size_t>(s.grid->nfields()), 0);
  for (const Body& b : s.bodies) {
    double a, bv;
    if (s.materials[b.material]->viscous_coefficients(a, bv)) fields[b.field] = 1;
  }
  const long n = std::count(fields.begin(), fields.end(), 1);
  return n == 1;
}

template <int D>
int ImplicitViscosity<D>::apply(Scene<D>& s, const TransferKernels<D>& kernels, double dt, double t, double mass_eps,
                                const std::vector<char>& bodies, const Held& held) {
  Grid<D>& g = *s.grid;
  const Particles<D>& P = s.particles;
  const Index nn = g.nnodes();
  acc_k_.clear(), acc_f_.clear();
  probed_ = detected_ = false;
  material_on_.assign(s.materials.size(), 0);
  for (std::size_t k = 0; k < s.bodies.size(); ++k) material_on_[s.bodies[k].material] |= bodies[k];
  for (std::size_t m = 0; m < s.materials.size(); ++m) s.materials[m]->set_implicit_viscosity(material_on_[m] != 0);
  auto damped = [&](const Body& b, double& a, double& bv) {
    return material_on_[b.material] && b.end > b.begin && s.materials[b.material]->viscous_coefficients(a, bv);
  };
  // 1. The last update's viscous stress, which P2G scattered with the elastic one, comes off the nodal force:
  //    f_e = f + sum_p V_p sigma_v,p grad N_ip.
  stencils_.resize(s.bodies.size());
  bool any = false;
  for (std::size_t k = 0; k < s.bodies.size(); ++k) {
    const Body& b = s.bodies[k];
    double a, bv;
    if (!damped(b, a, bv)) continue;
    any = true;
    Stencils& st = stencils_[k];
    st.nn = kernels.stencils(s, b.begin, b.end, st.node, st.grad);
    const std::vector<Mat<D>>& old = *s.materials[b.material]->viscous_stress();
    const Index off = b.field * nn;
    for (Index i = b.begin; i < b.end; ++i) {
      const std::size_t k0 = static_cast<std::size_t>(i - b.begin) * st.nn;
      const Mat<D> so = P.vol[i] * old[i];
      for (int e = 0; e < st.nn; ++e) g.f[off + st.node[k0 + e]] += so * st.grad[k0 + e];
    }
  }
  if (!any) return 0;
  // 2. The predictor of every field, and what the walls, regions and body contact would make of it.
  probed_ = !s.walls.empty() || !s.regions.empty() || g.nfields() > 1;
  if (probed_) {
    vstar_.resize(g.v.size()), walled_.resize(g.v.size()), probe_.resize(g.v.size());
    const auto& active = g.active();
    parallel_for(0, static_cast<Index>(active.size()), [&](Index j) {
      for (int f = 0; f < g.nfields(); ++f) {
        const Index k = f * nn + active[j];
        vstar_[k] = g.m[k] > mass_eps ? Vec<D>((g.p[k] + dt * g.f[k]) / g.m[k]) : Vec<D>::Zero();
        probe_[k] = vstar_[k];
      }
    });
    apply_boundaries(s, probe_, dt, t, false);
    parallel_for(0, static_cast<Index>(active.size()), [&](Index j) {
      for (int f = 0; f < g.nfields(); ++f) walled_[f * nn + active[j]] = probe_[f * nn + active[j]];
    });
    if (g.nfields() > 1) {
      body_contact(s, probe_);
      detected_ = true;
    }
  }
  // 3. Per damped body, the implicit viscous force.
  field_solved_.assign(g.nfields(), 0);
  for (std::size_t k = 0; k < s.bodies.size(); ++k) {
    double a, bv;
    if (damped(s.bodies[k], a, bv)) field_solved_[s.bodies[k].field] = 1;
  }
  int worst = 0;
  for (std::size_t k = 0; k < s.bodies.size(); ++k) {
    const Body& b = s.bodies[k];
    double a, bv;
    if (!damped(b, a, bv)) continue;
    solve_body(s, b, stencils_[k], a, bv, dt, mass_eps, held);
    worst = std::max(worst, iterations_);
  }
  return worst;
}

// out = K_v u over the unknowns: sum_p V_p sigma_v(D_p(u)) grad N_ip.
template <int D>
void ImplicitViscosity<D>::operate(const Scene<D>& s, const Body& b, const Stencils& st, double a, double bv, const std::vector<Vec<D>>& u,
                                   std::vector<Vec<D>>& out) const {
  const Particles<D>& P = s.particles;
  std::fill(out.begin(), out.end(), Vec<D>::Zero());
  for (Index i = b.begin; i < b.end; ++i) {
    const std::size_t k0 = static_cast<std::size_t>(i - b.begin) * st.nn;
    Mat<D> L = Mat<D>::Zero();
    for (int n = 0; n < st.nn; ++n)
      if (const int l = entry_[k0 + n]; l >= 0) L += u[l] * st.grad[k0 + n].transpose();
    const Mat<D> Dm = 0.5 * (L + L.transpose());
    const Mat<D> sv = P.vol[i] * (a * Dm.trace() * Mat<D>::Identity() + 2 * bv * Dm);
    for (int n = 0; n < st.nn; ++n)
      if (const int l = entry_[k0 + n]; l >= 0) out[l] += sv * st.grad[k0 + n];
  }
}

template <int D>
void ImplicitViscosity<D>::solve_body(Scene<D>& s, const Body& b, const Stencils& st, double a, double bv, double dt, double mass_eps,
                                      const Held& held) {
  Grid<D>& g = *s.grid;
  const Particles<D>& P = s.particles;
  const Index nn = g.nnodes(), off = b.field * nn;
  if (static_cast<Index>(local_.size()) != nn) local_.assign(nn, -1);
  nodes_.clear();
  for (Index id : st.node)
    if (local_[id] < 0 && g.m[off + id] > mass_eps) local_[id] = static_cast<int>(nodes_.size()), nodes_.push_back(id);
  const std::size_t n = nodes_.size();
  entry_.resize(st.node.size());
  for (std::size_t e = 0; e < st.node.size(); ++e) entry_[e] = local_[st.node[e]];
  for (auto* v : {&rhs_, &u_, &r_, &z_, &p_, &q_, &diag_}) v->assign(n, Vec<D>::Zero());
  free_.assign(n, Vec<D>::Ones());
  // Jacobi preconditioner: diag(A)_l,c = m_l + dt sum_p V_p (a g_c^2 + b (|g|^2 + g_c^2)), g = grad N_lp.
  for (Index i = b.begin; i < b.end; ++i) {
    const std::size_t k0 = static_cast<std::size_t>(i - b.begin) * st.nn;
    for (int e = 0; e < st.nn; ++e)
      if (const int l = entry_[k0 + e]; l >= 0) {
        const Vec<D>& gr = st.grad[k0 + e];
        diag_[l] += dt * P.vol[i] * (a * gr.cwiseProduct(gr) + bv * (gr.squaredNorm() * Vec<D>::Ones() + gr.cwiseProduct(gr)));
      }
  }
  double bnorm = 0;
  ties_.clear();
  for (std::size_t l = 0; l < n; ++l) {
    const Index k = off + nodes_[l];
    const double m = g.m[k];
    u_[l] = (g.p[k] + dt * g.f[k]) / m;  // v*, the initial guess
    rhs_[l] = m * u_[l];
    diag_[l] += Vec<D>::Constant(m);
    if (!probed_) continue;
    bool walled = false;  // held where a wall or region would change v*
    for (int c = 0; c < D; ++c)
      if (walled_[k][c] != vstar_[k][c]) free_[l][c] = 0, u_[l][c] = walled_[k][c], walled = true;
    if (walled || !detected_) continue;
    const Vec<D> dv = probe_[k] - walled_[k];  // body contact would change the damped field: join its partners along n
    if (!(dv.squaredNorm() > 0)) continue;
    const Vec<D> nrm = dv.normalized();
    for (int f = 0; f < g.nfields(); ++f) {
      const Index kb = f * nn + nodes_[l];
      if (f == b.field || field_solved_[f] || !(g.m[kb] > mass_eps) || probe_[kb] == walled_[kb]) continue;
      ties_.push_back(Tie{kb, static_cast<int>(l), nrm});
      const double mb = g.m[kb];
      rhs_[l] += mb * vstar_[kb].dot(nrm) * nrm;
      diag_[l] += mb * nrm.cwiseProduct(nrm);
    }
  }
  for (const auto& [k, v] : held)
    if (k >= off && k < off + nn)
      if (const int l = local_[k - off]; l >= 0) free_[l].setZero(), u_[l] = v;
  for (std::size_t l = 0; l < n; ++l) bnorm += rhs_[l].squaredNorm();
  bnorm = std::sqrt(bnorm);
  auto A = [&](const std::vector<Vec<D>>& x, std::vector<Vec<D>>& y) {
    operate(s, b, st, a, bv, x, y);
    for (std::size_t l = 0; l < n; ++l) y[l] = g.m[off + nodes_[l]] * x[l] + dt * y[l];
    for (const Tie& c : ties_) y[c.l] += g.m[c.k] * x[c.l].dot(c.n) * c.n;
    for (std::size_t l = 0; l < n; ++l) y[l] = y[l].cwiseProduct(free_[l]);
  };
  // Preconditioned conjugate gradients (Jacobi) on the free components, from u = v* (held components at their value).
  A(u_, q_);
  for (std::size_t l = 0; l < n; ++l)
    r_[l] = (rhs_[l] - q_[l]).cwiseProduct(free_[l]), z_[l] = r_[l].cwiseQuotient(diag_[l]), p_[l] = z_[l];
  double rz = dot(r_, z_);
  const double tol = 1e-8 * bnorm;
  const int max_it = 200 + static_cast<int>(n);
  iterations_ = 0;
  while (std::sqrt(dot(r_, r_)) > tol) {
    if (++iterations_ > max_it || !std::isfinite(rz))
      throw RunError("body '" + b.name + "': the implicit viscous solve did not converge in " + std::to_string(max_it) +
                     " iterations (residual " + std::to_string(std::sqrt(dot(r_, r_)) / std::max(bnorm, 1e-300)) + ")");
    A(p_, q_);
    const double alpha = rz / dot(p_, q_);
    for (std::size_t l = 0; l < n; ++l) u_[l] += alpha * p_[l], r_[l] -= alpha * q_[l], z_[l] = r_[l].cwiseQuotient(diag_[l]);
    const double rz_new = dot(r_, z_);
    const double beta = rz_new / rz;
    rz = rz_new;
    for (std::size_t l = 0; l < n; ++l) p_[l] = z_[l] + beta * p_[l];
  }
  // f = f_e - K_v u, and the joined partners' momentum exchange along n: the partner reaches the normal velocity u.n,
  // the damped field loses what it gains.
  operate(s, b, st, a, bv, u_, q_);
  for (std::size_t l = 0; l < n; ++l) {
    g.f[off + nodes_[l]] -= q_[l];
    acc_k_.push_back(off + nodes_[l]), acc_f_.push_back(q_[l]);
  }
  for (const Tie& c : ties_) {
    const Vec<D> fc = g.m[c.k] * (u_[c.l] - vstar_[c.k]).dot(c.n) * c.n / dt;
    g.f[c.k] += fc;
    g.f[off + nodes_[c.l]] -= fc;
  }
  for (Index id : nodes_) local_[id] = -1;
}

template <int D> void ImplicitViscosity<D>::account(const Grid<D>& g, double dt) {
  double w = 0;
  for (std::size_t j = 0; j < acc_k_.size(); ++j) w += acc_f_[j].dot(g.vL[acc_k_[j]]);
  dissipated_ += dt * w;
  acc_k_.clear(), acc_f_.clear();
}

template class ImplicitViscosity<2>;
template class ImplicitViscosity<3>;

}  // namespace dmi
