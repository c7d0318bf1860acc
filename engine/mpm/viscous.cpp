#include "engine/mpm/viscous.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/common/error.hpp"
#include "engine/common/parallel.hpp"
#include "engine/mpm/boundary.hpp"

namespace dmi {

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
void ImplicitViscosity<D>::apply(Scene<D>& s, const TransferKernels<D>& kernels, double dt, double t, double mass_eps,
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
  if (!any) return;
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
  for (std::size_t k = 0; k < s.bodies.size(); ++k) {
    const Body& b = s.bodies[k];
    double a, bv;
    if (damped(b, a, bv)) solve_body(s, b, stencils_[k], a, bv, dt, mass_eps, held);
  }
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
  for (auto* v : {&rhs_, &u_, &q_}) v->assign(n, Vec<D>::Zero());
  free_.assign(n, Vec<D>::Ones());
  ties_.clear();
  for (std::size_t l = 0; l < n; ++l) {
    const Index k = off + nodes_[l];
    const double m = g.m[k];
    u_[l] = (g.p[k] + dt * g.f[k]) / m;  // v* (kept where held)
    rhs_[l] = m * u_[l];
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
      if (f == b.field || !(g.m[kb] > mass_eps) || probe_[kb] == walled_[kb]) continue;  // partners are undamped: needed()
      ties_.push_back(Tie{kb, static_cast<int>(l), nrm});
      const double mb = g.m[kb];
      rhs_[l] += mb * vstar_[kb].dot(nrm) * nrm;
    }
  }
  for (const auto& [k, v] : held)
    if (k >= off && k < off + nn)
      if (const int l = local_[k - off]; l >= 0) free_[l].setZero(), u_[l] = v;
  // A = M + dt K_v (+ the joined partners' m_B n n^T), assembled as D x D blocks over the 5^D neighbour offsets of
  // each unknown node (two nodes couple when a particle's stencil holds both: |offset| <= 2 per axis), with
  //   K_lm += V_p [a g_l g_m^T + b (g_l . g_m) I + b g_m g_l^T],   g = grad N of the particle at nodes l, m,
  // then solved on the free components by a sparse LDL^T factorisation (exact; CG's iteration count grew with the
  // damping and the grid, 5-130 Jacobi-PCG iterations per step on the tyre buffer).
  constexpr int NB = D == 2 ? 25 : 125;
  const IVec<D> nodes = g.nodes();
  // The slot of the offset between stencil entries e1 and e2: entry e holds the node base + (e's digits base K,
  // axis 0 least significant: TransferKernels::stencils), slot = sum_d (q_d + 2) 5^d for the offset q.
  if (static_cast<int>(pair_slot_.size()) != st.nn * st.nn) {
    const int K = D == 2 ? (st.nn == 9 ? 3 : 2) : (st.nn == 27 ? 3 : 2);
    pair_slot_.resize(static_cast<std::size_t>(st.nn * st.nn));
    for (int e1 = 0; e1 < st.nn; ++e1)
      for (int e2 = 0; e2 < st.nn; ++e2) {
        int o = 0;
        for (int d = 0, kd = 1, w = 1; d < D; ++d, kd *= K, w *= 5) o += (e2 / kd % K - e1 / kd % K + 2) * w;
        pair_slot_[static_cast<std::size_t>(e1 * st.nn + e2)] = o;
      }
  }
  auto offset_diff = [&](int o) {  // slot -> node-id difference
    Index diff = 0, stride = 1;
    for (int d = 0; d < D; ++d) diff += static_cast<Index>(o % 5 - 2) * stride, stride *= nodes[d], o /= 5;
    return diff;
  };
  const int centre = D == 2 ? 12 : 62;  // offset 0
  blocks_.assign(n * NB, Mat<D>::Zero());
  used_.assign(n * NB, 0);
  // K is symmetric (K_ml = K_lm^T): only the blocks towards nodes of larger id are accumulated, e2 >= e1 (entries and
  // node ids both run x fastest), and each stands for its transpose below.
  for (Index i = b.begin; i < b.end; ++i) {
    const std::size_t k0 = static_cast<std::size_t>(i - b.begin) * st.nn;
    const double w = dt * P.vol[i];
    for (int e1 = 0; e1 < st.nn; ++e1) {
      const int l1 = entry_[k0 + e1];
      if (l1 < 0) continue;
      const Vec<D>& g1 = st.grad[k0 + e1];
      for (int e2 = e1; e2 < st.nn; ++e2) {
        if (entry_[k0 + e2] < 0) continue;
        const Vec<D>& g2 = st.grad[k0 + e2];
        const std::size_t at = static_cast<std::size_t>(l1) * NB + pair_slot_[static_cast<std::size_t>(e1 * st.nn + e2)];
        blocks_[at] += w * (a * g1 * g2.transpose() + bv * g1.dot(g2) * Mat<D>::Identity() + bv * g2 * g1.transpose());
        used_[at] = 1;
      }
    }
  }
  for (std::size_t l = 0; l < n; ++l) blocks_[l * NB + centre] += g.m[off + nodes_[l]] * Mat<D>::Identity(), used_[l * NB + centre] = 1;
  for (const Tie& c : ties_) blocks_[static_cast<std::size_t>(c.l) * NB + centre] += g.m[c.k] * c.n * c.n.transpose();
  // Free components numbered; held ones move to the right-hand side.
  dof_.assign(n * D, -1);
  int nf = 0;
  for (std::size_t l = 0; l < n; ++l)
    for (int c = 0; c < D; ++c)
      if (free_[l][c] != 0) dof_[l * D + c] = nf++;
  triplets_.clear();
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(nf);
  for (std::size_t l = 0; l < n; ++l)
    for (int c = 0; c < D; ++c)
      if (const int r = dof_[l * D + c]; r >= 0) rhs[r] = rhs_[l][c];
  for (std::size_t l = 0; l < n; ++l)
    for (int o = 0; o < NB; ++o) {
      if (!used_[l * NB + o]) continue;
      const int m = local_[nodes_[l] + offset_diff(o)];
      const Mat<D>& B = blocks_[l * NB + o];  // A_lm; off the diagonal also A_ml = B^T
      for (int c = 0; c < D; ++c)
        for (int c2 = 0; c2 < D; ++c2) {
          const int r = dof_[l * D + c], col = dof_[static_cast<std::size_t>(m) * D + c2];
          if (r >= 0 && col >= 0) {  // the lower triangle is what LDL^T reads
            if (col <= r) {
              triplets_.emplace_back(r, col, B(c, c2));
            } else if (o != centre) {
              triplets_.emplace_back(col, r, B(c, c2));
            }
          } else if (r >= 0) {
            rhs[r] -= B(c, c2) * u_[m][c2];  // a held component
          } else if (col >= 0 && o != centre) {
            rhs[col] -= B(c, c2) * u_[l][c];
          }
        }
    }
  if (nf > 0) {
    A_.resize(nf, nf);
    A_.setFromTriplets(triplets_.begin(), triplets_.end());
    // The last step's factor preconditions conjugate gradients on this step's matrix (A changes little per step),
    // mapped onto this step's unknowns by node and component (the body moves a fraction of a cell per step and
    // contact holds and releases components: the set changes, most of it stays; new unknowns take Jacobi). The
    // matrix is factorised afresh when too few unknowns map or CG does not converge within the budget; the ordering
    // and symbolic factorisation are kept while the pattern is.
    Eigen::VectorXd x;
    if (!(factored_ && !stale_ && map_onto_factor(off, nf) && preconditioned_solve(rhs, x))) {
      const bool same = outer_.size() == static_cast<std::size_t>(nf + 1) && inner_.size() == static_cast<std::size_t>(A_.nonZeros()) &&
                        std::equal(outer_.begin(), outer_.end(), A_.outerIndexPtr()) && std::equal(inner_.begin(), inner_.end(), A_.innerIndexPtr());
      if (!same) {
        ldlt_.analyzePattern(A_);
        outer_.assign(A_.outerIndexPtr(), A_.outerIndexPtr() + nf + 1);
        inner_.assign(A_.innerIndexPtr(), A_.innerIndexPtr() + A_.nonZeros());
      }
      ldlt_.factorize(A_);
      factored_ = ldlt_.info() == Eigen::Success, stale_ = false;
      factored_values_.assign(A_.valuePtr(), A_.valuePtr() + A_.nonZeros());
      ++stats_.factorisations;
      if (!factored_) throw RunError("body '" + b.name + "': the implicit viscous system could not be factorised");
      factor_key_.assign(static_cast<std::size_t>(nf), 0);
      for (std::size_t l = 0; l < n; ++l)
        for (int c = 0; c < D; ++c)
          if (const int r = dof_[l * D + c]; r >= 0) factor_key_[static_cast<std::size_t>(r)] = (off + nodes_[l]) * D + c;
      index_factor_keys(g.m.size() * D);
      // What a factorisation costs in solves (~sum of squared column counts of L against a solve and a product):
      // CG on an older factor may take that many iterations before refactorising is cheaper (a count, not a clock,
      // so that runs repeat exactly).
      const auto& L = ldlt_.matrixL().nestedExpression();
      double flops = 0;
      for (Eigen::Index j = 0; j < L.outerSize(); ++j) {
        const double c = static_cast<double>(L.outerIndexPtr()[j + 1] - L.outerIndexPtr()[j]);
        flops += c * c;
      }
      const double per_iteration = 4.0 * static_cast<double>(L.nonZeros()) + 4.0 * static_cast<double>(A_.nonZeros()) + 10.0 * nf;
      budget_ = static_cast<int>(std::clamp(flops / per_iteration, 1.0, 40.0));
      x = ldlt_.solve(rhs);
    }
    if (!x.allFinite()) throw RunError("body '" + b.name + "': the implicit viscous solve gave a non-finite velocity");
    for (std::size_t l = 0; l < n; ++l)
      for (int c = 0; c < D; ++c)
        if (const int r = dof_[l * D + c]; r >= 0) u_[l][c] = x[r];
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

// The factor's unknowns by key (node-field x D + component) -> index, in a table over all node-fields; the previous
// factor's entries are cleared first.
template <int D> void ImplicitViscosity<D>::index_factor_keys(std::size_t keys) {
  if (factor_slot_.size() != keys) factor_slot_.assign(keys, -1);
  for (Index k : slot_keys_) factor_slot_[static_cast<std::size_t>(k)] = -1;
  for (std::size_t i = 0; i < factor_key_.size(); ++i) factor_slot_[static_cast<std::size_t>(factor_key_[i])] = static_cast<int>(i);
  slot_keys_ = factor_key_;
}

// This step's unknowns onto the factor's (map_: -1 where the factor has none); false when fewer than 90 % map (a
// different body or a large change: factorise instead) or the table does not fit this grid.
template <int D> bool ImplicitViscosity<D>::map_onto_factor(Index off, int nf) {
  if (factor_slot_.empty()) return false;
  map_.assign(static_cast<std::size_t>(nf), -1);
  identity_ = nf == static_cast<int>(factor_key_.size());
  int mapped = 0;
  for (std::size_t l = 0; l < nodes_.size(); ++l)
    for (int c = 0; c < D; ++c)
      if (const int r = dof_[l * D + c]; r >= 0) {
        const std::size_t key = static_cast<std::size_t>((off + nodes_[l]) * D + c);
        if (key >= factor_slot_.size()) return false;
        map_[static_cast<std::size_t>(r)] = factor_slot_[key];
        mapped += map_[static_cast<std::size_t>(r)] >= 0;
        identity_ = identity_ && map_[static_cast<std::size_t>(r)] == r;
      }
  if (10 * static_cast<long>(mapped) < 9 * static_cast<long>(nf)) return false;
  if (!identity_) jacobi_ = A_.diagonal();
  return true;
}

// z = M^-1 r: the factor's solve on the mapped unknowns (the others zero in its right-hand side), Jacobi on the rest.
// Block diagonal with SPD blocks (S^T A_f^-1 S, S the injection of the mapped unknowns), so CG's preconditioner.
template <int D> void ImplicitViscosity<D>::precondition(const Eigen::VectorXd& r, Eigen::VectorXd& z) {
  if (identity_) {
    z = ldlt_.solve(r);
    return;
  }
  work_.setZero(static_cast<Eigen::Index>(factor_key_.size()));
  for (Eigen::Index i = 0; i < r.size(); ++i)
    if (const int j = map_[static_cast<std::size_t>(i)]; j >= 0) work_[j] = r[i];
  work_ = ldlt_.solve(work_);
  z.resize(r.size());
  for (Eigen::Index i = 0; i < r.size(); ++i) {
    const int j = map_[static_cast<std::size_t>(i)];
    z[i] = j >= 0 ? work_[j] : r[i] / jacobi_[i];
  }
}

// Conjugate gradients on A_ (its lower triangle stored) preconditioned by the last factor, from x = M^-1 b, to a
// relative residual of 1e-10 (the step's own truncation error is far larger), within budget_ solves. Returns false
// (x undefined) when that is not enough; a solve that needed more than half of them marks the factor stale, so
// that the next step factorises afresh rather than try.
template <int D> bool ImplicitViscosity<D>::preconditioned_solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  const auto A = A_.template selfadjointView<Eigen::Lower>();
  const double tol = 1e-10 * b.norm();
  precondition(b, x);
  Eigen::VectorXd r = b - A * x;
  int solves = 1;
  auto done = [&] {
    ++stats_.reused, stats_.iterations += solves - 1;
    stale_ = 2 * solves > budget_;
    return x.allFinite();
  };
  if (r.norm() <= tol) return done();
  Eigen::VectorXd z, q(b.size());
  precondition(r, z);
  Eigen::VectorXd p = z;
  double rz = r.dot(z);
  for (++solves; solves <= budget_; ++solves) {
    q.noalias() = A * p;
    const double alpha = rz / p.dot(q);
    x += alpha * p, r -= alpha * q;
    if (r.norm() <= tol) return done();
    precondition(r, z);
    const double rz1 = r.dot(z);
    p = z + (rz1 / rz) * p, rz = rz1;
  }
  stats_.iterations += solves - 1;
  return false;
}

template <int D> void ImplicitViscosity<D>::save_state(StateWriter& w) const {
  w.put(dissipated_);
  w.put<std::uint8_t>(factored_ ? 1 : 0), w.put<std::uint8_t>(stale_ ? 1 : 0), w.put(budget_);
  w.put(outer_), w.put(inner_), w.put(factored_values_), w.put(factor_key_), w.put(static_cast<std::uint64_t>(factor_slot_.size()));
  w.put(stats_);
}

template <int D> void ImplicitViscosity<D>::load_state(StateReader& r) {
  r.get(dissipated_);
  factored_ = r.get<std::uint8_t>() != 0, stale_ = r.get<std::uint8_t>() != 0, r.get(budget_);
  r.get(outer_), r.get(inner_), r.get(factored_values_), r.get(factor_key_);
  const auto keys = r.get<std::uint64_t>();
  r.get(stats_);
  factor_slot_.clear(), slot_keys_.clear();
  if (!factored_) return;
  for (Index k : factor_key_)
    if (k < 0 || static_cast<std::uint64_t>(k) >= keys) r.fail("the viscous factor names an unknown outside the grid");
  index_factor_keys(static_cast<std::size_t>(keys));
  const Eigen::Index n = static_cast<Eigen::Index>(outer_.size()) - 1;
  r.expect_size("the viscous factor's values", factored_values_.size(), inner_.size());
  if (n < 1 || static_cast<std::size_t>(outer_.back()) != inner_.size()) r.expect_size("the viscous factor's pattern", inner_.size(), outer_.empty() ? 0 : static_cast<std::size_t>(outer_.back()));
  Eigen::Map<const Eigen::SparseMatrix<double>> m(n, n, static_cast<Eigen::Index>(inner_.size()), outer_.data(), inner_.data(), factored_values_.data());
  A_ = m;
  ldlt_.analyzePattern(A_);
  ldlt_.factorize(A_);
  factored_ = ldlt_.info() == Eigen::Success;
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
