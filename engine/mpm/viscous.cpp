#include "engine/mpm/viscous.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <Eigen/Eigenvalues>
#include <omp.h>

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
  for (auto& w : s.walls) w.carried.setZero();  // this step's share only (the grid update records and clears it)
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
    st.nn = kernels.stencils(s, b.begin, b.end, st.node, st.weight, st.grad, &st.H);
    const std::vector<Mat<D>>& old = *s.materials[b.material]->viscous_stress();
    const Index off = b.field * nn;
    // The bound on the fastest viscous rate: with H_p = sum_i grad N_ip grad N_ip^T / N_ip (D x D) and
    // W_p = sum_i N_ip |u_i|^2, (tr D_p)^2 = (sum_i u_i . grad N_ip)^2 <= tr(H_p) W_p (Cauchy-Schwarz) and
    // D_p:D_p <= |L_p|^2 = |U N^1/2 N^-1/2 G|^2 <= lambda_max(H_p) W_p (|A B|_F <= |A|_F |B|_2), so
    // u^T K_v u <= sum_p q_p W_p = sum_i |u_i|^2 sum_p N_ip q_p, q_p = V_p (a tr H_p + 2 b lambda_max(H_p)), while
    // u^T M u >= sum_p m_p W_p = sum_i |u_i|^2 sum_p N_ip m_p: lambda_max(M^-1 K_v) <= max_i sum_p N_ip q_p /
    // sum_p N_ip m_p, at each node a weighted mean of the q_p / m_p around it (at most their largest, the bound used
    // before). H_p is bounded where N vanishes as the square of the distance (quadratic B-splines: 4-6 / h^2 per axis;
    // uGIMP), and grows near a nearly empty node of linear hats; the stencil sums it from its 1D factors (a few terms
    // per axis instead of a product per entry). The plain Cauchy-Schwarz bound on |L_p|^2 (tr H_p) read 4-5x the
    // fastest rate on the buffered dam (power iteration), the spectral one about half that, per particle; stages go
    // as the bound's square root.
    if (rate_num_.size() != static_cast<std::size_t>(nn)) rate_num_.assign(static_cast<std::size_t>(nn), 0.0), rate_den_.assign(static_cast<std::size_t>(nn), 0.0);
    for (Index i = b.begin; i < b.end; ++i) {
      const std::size_t k0 = static_cast<std::size_t>(i - b.begin) * st.nn;
      const Mat<D> so = P.vol[i] * old[i];
      for (int e = 0; e < st.nn; ++e) g.f[off + st.node[k0 + e]] += so * st.grad[k0 + e];
      const Mat<D>& H = st.H[static_cast<std::size_t>(i - b.begin)];
      const bool finite = H.allFinite();
      double top = 0;
      if constexpr (D == 2) {
        const double m = 0.5 * H.trace(), d = H.determinant();
        if (finite) top = m + std::sqrt(std::max(0.0, m * m - d));
      } else if (finite) {
        Eigen::SelfAdjointEigenSolver<Mat<D>> es;
        es.computeDirect(H, Eigen::EigenvaluesOnly);
        top = es.eigenvalues()(D - 1);
      }
      // a = beta lambda < 0 for a negative Poisson's ratio: a (tr D)^2 <= 0 then, and only the shear term bounds.
      const double q = finite ? (std::max(a, 0.0) * H.trace() + 2 * bv * top) * P.vol[i] : std::numeric_limits<double>::infinity();
      for (int e = 0; e < st.nn; ++e)
        if (const double w = st.weight[k0 + e]; w > 0) {
          rate_num_[static_cast<std::size_t>(st.node[k0 + e])] += w * q;
          rate_den_[static_cast<std::size_t>(st.node[k0 + e])] += w * P.mass[i];
        }
    }
    double lambda = 0;
    for (Index id : st.node) {
      const auto j = static_cast<std::size_t>(id);
      if (rate_den_[j] > 0) lambda = std::max(lambda, rate_num_[j] / rate_den_[j]);
      rate_num_[j] = rate_den_[j] = 0;
    }
    st.lambda = lambda;
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

// V_p sigma_v(D_p(u)) of one particle from its stencil entries (unknown l, grad N); an entry without an unknown names
// the pad u[n] = 0, so the loop has no branch. NN: entries per particle when known at compile time (0: nn).
template <int D, int NN>
inline Mat<D> viscous_stress(const int* l, const Vec<D>* grad, int nn, const std::vector<Vec<D>>& u, double vol, double a, double bv) {
  Mat<D> L = Mat<D>::Zero();
  for (int e = 0; e < (NN > 0 ? NN : nn); ++e) L.noalias() += u[static_cast<std::size_t>(l[e])] * grad[e].transpose();
  const Mat<D> Dm = 0.5 * (L + L.transpose());
  return Mat<D>(vol * (a * Dm.trace() * Mat<D>::Identity() + 2 * bv * Dm));
}

// out = K_v u over the unknowns: sum_p V_p sigma_v(D_p(u)) grad N_ip (u and out carry the pad entry n). On one thread
// (serial_) a scatter in particle and entry order; else in two passes that run in parallel and give the same sums:
// each particle's V_p sigma_v, then each unknown's sum over its incident particle entries in their order (incidence():
// the order of that scatter).
template <int D>
template <int NN>
void ImplicitViscosity<D>::operate_nn(const Scene<D>& s, const Body& b, const Stencils& st, double a, double bv, const std::vector<Vec<D>>& u,
                                      std::vector<Vec<D>>& out) {
  const Particles<D>& P = s.particles;
  const int nn = NN > 0 ? NN : st.nn;
  auto stress = [&](Index i) {
    const std::size_t k0 = static_cast<std::size_t>(i - b.begin) * static_cast<std::size_t>(nn);
    return viscous_stress<D, NN>(&entry_[k0], &st.grad[k0], nn, u, P.vol[i], a, bv);
  };
  if (serial_) {
    out.assign(nodes_.size() + 1, Vec<D>::Zero());
    for (Index i = b.begin; i < b.end; ++i) {
      const Mat<D> sv = stress(i);
      const std::size_t k0 = static_cast<std::size_t>(i - b.begin) * static_cast<std::size_t>(nn);
      const int* l = &entry_[k0];
      const Vec<D>* grad = &st.grad[k0];
      for (int e = 0; e < nn; ++e) out[static_cast<std::size_t>(l[e])].noalias() += sv * grad[e];
    }
    out.back().setZero();
    return;
  }
  sv_.resize(static_cast<std::size_t>(b.end - b.begin));
  parallel_for(b.begin, b.end, [&](Index i) { sv_[static_cast<std::size_t>(i - b.begin)] = stress(i); });
  out.resize(nodes_.size() + 1);
  out.back().setZero();
  parallel_for(0, static_cast<Index>(nodes_.size()), [&](Index l) {
    Vec<D> f = Vec<D>::Zero();
    for (int j = inc_start_[l]; j < inc_start_[l + 1]; ++j) f.noalias() += sv_[inc_particle_[j]] * inc_grad_[j];
    out[l] = f;
  });
}

template <int D>
void ImplicitViscosity<D>::operate(const Scene<D>& s, const Body& b, const Stencils& st, double a, double bv, const std::vector<Vec<D>>& u,
                                   std::vector<Vec<D>>& out) {
  switch (st.nn) {  // the stencils of linear hats, quadratic B-splines and uGIMP (3 nodes a side), and cubic reach
    case D == 2 ? 4 : 8: return operate_nn<D == 2 ? 4 : 8>(s, b, st, a, bv, u, out);
    case D == 2 ? 9 : 27: return operate_nn<D == 2 ? 9 : 27>(s, b, st, a, bv, u, out);
    default: return operate_nn<0>(s, b, st, a, bv, u, out);
  }
}

// Per unknown, the particle entries whose node it is, in entry order (counting sort of entry_), with their grad N.
template <int D> void ImplicitViscosity<D>::incidence(const Stencils& st) {
  const std::size_t n = nodes_.size();
  inc_start_.assign(n + 1, 0);
  for (int l : entry_)
    if (l < static_cast<int>(n)) ++inc_start_[static_cast<std::size_t>(l) + 1];
  for (std::size_t l = 0; l < n; ++l) inc_start_[l + 1] += inc_start_[l];
  fill_.assign(inc_start_.begin(), inc_start_.end() - 1);
  inc_particle_.resize(static_cast<std::size_t>(inc_start_[n])), inc_grad_.resize(inc_particle_.size());
  for (std::size_t k = 0; k < entry_.size(); ++k)
    if (const int l = entry_[k]; l < static_cast<int>(n)) {
      const int j = fill_[static_cast<std::size_t>(l)]++;
      inc_particle_[static_cast<std::size_t>(j)] = static_cast<int>(k / static_cast<std::size_t>(st.nn)), inc_grad_[static_cast<std::size_t>(j)] = st.grad[k];
    }
}

template <int D>
void ImplicitViscosity<D>::solve_body(Scene<D>& s, const Body& b, const Stencils& st, double a, double bv, double dt, double mass_eps,
                                      const Held& held) {
  Grid<D>& g = *s.grid;
  const Index nn = g.nnodes(), off = b.field * nn;
  if (static_cast<Index>(local_.size()) != nn) local_.assign(nn, -1);
  nodes_.clear();
  for (Index id : st.node)
    if (local_[id] < 0 && g.m[off + id] > mass_eps) local_[id] = static_cast<int>(nodes_.size()), nodes_.push_back(id);
  const std::size_t n = nodes_.size();
  entry_.resize(st.node.size());
  for (std::size_t e = 0; e < st.node.size(); ++e) entry_[e] = local_[st.node[e]] >= 0 ? local_[st.node[e]] : static_cast<int>(n);  // n: the pad
  // One thread: both passes would run inline, and the scatter adds in the gather's order.
  serial_ = omp_get_max_threads() == 1 || (b.end - b.begin <= kParallelMin && static_cast<Index>(n) <= kParallelMin);
  if (!serial_) incidence(st);
  for (auto* v : {&rhs_, &fe_, &q_}) v->assign(n, Vec<D>::Zero());
  u_.assign(n + 1, Vec<D>::Zero());  // u_[n]: the pad of the entries without an unknown, always zero
  free_.assign(n, Vec<D>::Ones());
  ties_.clear(), slaves_.clear(), walled_node_.assign(n, 0), master_of_.assign(n, 0);
  for (std::size_t l = 0; l < n; ++l) {
    const Index k = off + nodes_[l];
    const double m = g.m[k];
    u_[l] = (g.p[k] + dt * g.f[k]) / m;  // v* (kept where held)
    rhs_[l] = g.p[k], fe_[l] = g.f[k];   // the flow starts from the step's momentum and takes f_e as a constant force
    if (!probed_) continue;
    bool walled = false;  // held where a wall or region would change v*
    for (int c = 0; c < D; ++c)
      if (walled_[k][c] != vstar_[k][c]) free_[l][c] = 0, u_[l][c] = walled_[k][c], walled = true;
    walled_node_[l] = walled;
    if (walled || !detected_) continue;
    const Vec<D> dv = probe_[k] - walled_[k];  // body contact would change the damped field: join its partners along n
    if (!(dv.squaredNorm() > 0)) continue;
    const Vec<D> nrm = dv.normalized();
    for (int f = 0; f < g.nfields(); ++f) {
      const Index kb = f * nn + nodes_[l];
      if (f == b.field || !(g.m[kb] > mass_eps) || probe_[kb] == walled_[kb]) continue;  // partners are undamped: needed()
      ties_.push_back(Tie{kb, static_cast<int>(l), nrm});
      rhs_[l] += g.p[kb].dot(nrm) * nrm, fe_[l] += g.f[kb].dot(nrm) * nrm;
    }
  }
  for (const auto& [k, v] : held)
    if (k >= off && k < off + nn)
      if (const int l = local_[k - off]; l >= 0) free_[l].setZero(), u_[l] = v, walled_node_[l] = 0;
  // A node that a bilateral wall gives the velocity of its image in front (wall_mirror) follows that image through
  // the flow, u_l = S u_image: it is no unknown of its own, its mass, momentum, f_e and K_v rows join the image's
  // (M' += m_l S^T S = m_l, Galerkin: the bound on the rate still holds). Held at v*'s image instead, it pulled the
  // material at a stick wall away from it in a growing mode (quadratic B-splines reach the nodes behind the wall).
  // Only where the image is free, has no contact ties and no other such node (a corner's); otherwise it stays held.
  if (probed_)
    for (std::size_t l = 0; l < n; ++l) {
      if (!walled_node_[l]) continue;
      for (std::size_t w = 0; w < s.walls.size(); ++w) {
        Index image;
        Mat<D> S;
        if (!wall_mirror(g, s.walls[w], nodes_[l], image, S)) continue;
        const int mst = local_[image];
        // ... and only where the walls and regions left it the image's velocity reflected (no later wall or region set it).
        if (mst >= 0 && !master_of_[static_cast<std::size_t>(mst)] && free_[static_cast<std::size_t>(mst)] == Vec<D>::Ones() &&
            walled_[off + nodes_[l]] == S * walled_[off + image] &&
            std::none_of(ties_.begin(), ties_.end(), [&](const Tie& t) { return t.l == mst; })) {
          slaves_.push_back(Slave{static_cast<int>(l), mst, static_cast<int>(w), S});
          master_of_[static_cast<std::size_t>(mst)] = 1;
        }
        break;
      }
    }
  for (const Slave& sl : slaves_) rhs_[sl.master] += sl.S.transpose() * rhs_[sl.l], fe_[sl.master] += sl.S.transpose() * fe_[sl.l];
  // The viscous sub-step by damped Chebyshev stages, as many as the bound on the fastest rate asks: in one piece where
  // the body's elastic Courant number keeps (omega_max dt)^2 <= 1 (DampedChebyshev::one_piece), else in two half-steps,
  // or more pieces when one half-step would need more than kMaxStages (a nearly empty node under linear shape functions).
  const double z = dt * st.lambda;
  double vmax = 0;
  for (Index i = b.begin; i < b.end; ++i) vmax = std::max(vmax, s.particles.v[i].norm());
  const double omega_dt = 2 * std::sqrt(static_cast<double>(D)) * (s.materials[b.material]->wave_speed() + vmax) * dt / g.h();
  const int pieces = DampedChebyshev::one_piece(omega_dt) && DampedChebyshev::stages_for(2 * z) > 0 ? 1 : DampedChebyshev::pieces_for(z);
  if (pieces == 0)
    throw RunError("body '" + b.name + "': the bound on the fastest viscous rate is not finite (dt times it: " + std::to_string(z) +
                   "; a particle on a node line of linear shape functions): use shape_function bspline2 or gimp, or damping explicit");
  chebyshev(s, b, st, a, bv, dt, DampedChebyshev::stages_for(2 * z / pieces), pieces);
  // q = mean K_v u - f_e (with the joined partners' f_e along n): f = -q less the partners' part, which their
  // momentum exchange along n carries: the partner reaches the normal velocity u.n, the damped field loses what it gains.
  // A mirrored pair (image I, node l behind the wall): q_l and f_e,l are l's own, q_I and f_e,I the pair's (joined). l
  // keeps its own force -q_l, which the wall then turns into u_l = S u_I and records; I takes its momentum change
  // (m_I u_I - p_I) / dt, which exceeds its own force f_e,I - K_v u_I by a part of the wall's reaction carried by
  // the joined mass: recorded with the wall's force of the step (Wall::carried).
  for (const Slave& sl : slaves_) {
    const auto l = static_cast<std::size_t>(sl.l), i = static_cast<std::size_t>(sl.master);
    const Index k = off + nodes_[i];
    const Vec<D> own = q_[i] - sl.S.transpose() * q_[l], fi = (g.m[k] * u_[i] - g.p[k]) / dt;  // own: K_v u_I - f_e,I
    s.walls[static_cast<std::size_t>(sl.wall)].carried -= fi + own;
    acc_k_.push_back(k), acc_f_.push_back(own + g.f[k]);
    g.f[k] = fi;
  }
  for (std::size_t l = 0; l < n; ++l) {
    if (master_of_[l]) continue;
    g.f[off + nodes_[l]] -= q_[l] + fe_[l];
    acc_k_.push_back(off + nodes_[l]), acc_f_.push_back(q_[l] + fe_[l]);
  }
  for (const Tie& c : ties_) {
    const Vec<D> fc = g.m[c.k] * (u_[c.l] - vstar_[c.k]).dot(c.n) * c.n / dt;
    g.f[c.k] += fc;
    g.f[off + nodes_[c.l]] -= fc;
  }
  for (Index id : nodes_) local_[id] = -1;
}

DampedChebyshev::DampedChebyshev(int s) : s(s) {
  w0 = 1 + kDamping / (static_cast<double>(s) * s);
  T.assign(static_cast<std::size_t>(s + 1), 1.0);
  double d0 = 0, d1 = 1;  // T_j'(w0)
  T[1] = w0;
  for (int j = 2; j <= s; ++j) {
    T[j] = 2 * w0 * T[j - 1] - T[j - 2];
    const double d = 2 * T[j - 1] + 2 * w0 * d1 - d0;
    d0 = d1, d1 = d;
  }
  w1 = T[static_cast<std::size_t>(s)] / d1;
}

double DampedChebyshev::amplification(double z) const {
  double t0 = 1, t1 = w0 - w1 * z;
  for (int j = 2; j <= s; ++j) {
    const double t = 2 * (w0 - w1 * z) * t1 - t0;
    t0 = t1, t1 = t;
  }
  return t1 / T[static_cast<std::size_t>(s)];
}

int DampedChebyshev::stages_for(double z) {
  static const double beta_max = DampedChebyshev(kMaxStages).beta();
  const double need = 1.02 * 0.5 * z;  // each half-step's interval, with a margin for round-off in the bound
  if (!(need <= beta_max)) return 0;   // also not finite
  for (int s = std::max(1, static_cast<int>(std::sqrt(need / 1.4))); s <= kMaxStages; ++s)  // beta_s < 1.4 s^2: start below
    if (DampedChebyshev(s).beta() >= need) return s;
  return 0;
}

bool DampedChebyshev::one_piece(double omega_dt) { return omega_dt * omega_dt <= 1.0; }

int DampedChebyshev::pieces_for(double z) {
  if (!(z < std::numeric_limits<double>::infinity())) return 0;
  for (int p = 2; p <= (1 << 24); p *= 2)
    if (stages_for(2 * z / p) > 0) return p;
  return 0;
}

// The step as the flow M' du/dt = f_e - K_v u of the free components from u0 = M'^-1 (p + ties), the elastic force f_e
// constant over it, held ones fixed, by the damped Chebyshev recurrence (M' = M + the joined partners' m_B n n^T, per
// node). Written for the forces, per piece h = dt / pieces, with G(Y) = K Y - f_e: Y_j = Y_0 - h M'^-1 Q_j, Q_0 = 0,
// Q_1 = (w1 / w0) G(Y_0), Q_j = mu_j Q_j-1 + nu_j Q_j-2 + mu'_j G(Y_j-1) with mu_j = 2 w0 T_j-1 / T_j, nu_j = -T_j-2 /
// T_j, mu'_j = 2 w1 T_j-1 / T_j (mu_j + nu_j = 1), so that the pieces' mean of Q_s + f_e is the step's mean viscous
// force K_v u on every component, held ones included (it reaches the wall or member there), and the free components'
// momentum change is exactly -dt times the mean Q_s. A state where f_e and K_v u balance (a damped body creeping under
// load) is a fixed point of every stage, so it is kept at any step; a kick of the whole step's f_e before the flow
// (the earlier form) let the flow remove a part of it, an error of order dt lambda that at the rubber's CFL 0.5 read
// the buffered dam's base shear 5-8 % low (docs/verification.md, "Rigid boulder").
template <int D>
void ImplicitViscosity<D>::chebyshev(Scene<D>& s, const Body& b, const Stencils& st, double a, double bv, double dt, int stages, int pieces) {
  const Grid<D>& g = *s.grid;
  const Index off = b.field * g.nnodes();
  const std::size_t n = nodes_.size();
  minv_.resize(n);
  for (std::size_t l = 0; l < n; ++l) minv_[l] = g.m[off + nodes_[l]] * Mat<D>::Identity();
  for (const Tie& c : ties_) minv_[static_cast<std::size_t>(c.l)] += g.m[c.k] * c.n * c.n.transpose();
  for (const Slave& sl : slaves_) minv_[static_cast<std::size_t>(sl.master)] += g.m[off + nodes_[static_cast<std::size_t>(sl.l)]] * Mat<D>::Identity();
  for (std::size_t l = 0; l < n; ++l) {
    minv_[l] = minv_[l].inverse().eval();
    for (int c = 0; c < D; ++c)
      if (free_[l][c] != 0) u_[l][c] = (minv_[l] * rhs_[l])[c];
  }
  auto follow = [&] {  // mirrored nodes take their image's velocity
    for (const Slave& sl : slaves_) u_[static_cast<std::size_t>(sl.l)] = sl.S * u_[static_cast<std::size_t>(sl.master)];
  };
  auto operate_joined = [&] {  // ky = K_v u, a mirrored node's rows joined to its image's
    operate(s, b, st, a, bv, u_, ky_);
    for (const Slave& sl : slaves_) ky_[static_cast<std::size_t>(sl.master)] += sl.S.transpose() * ky_[static_cast<std::size_t>(sl.l)];
  };
  follow();
  const DampedChebyshev cs(stages);
  const double h = dt / pieces;  // one piece, or an even number: R_s(z/p)^p >= 0 (DampedChebyshev)
  auto velocities = [&](const std::vector<Vec<D>>& Q) {  // Y = Y_0 - h M'^-1 Q on the free components
    for (std::size_t l = 0; l < n; ++l) u_[l] = y0_[l] - h * free_[l].cwiseProduct(minv_[l] * Q[l]);
    follow();
  };
  qsum_.assign(n, Vec<D>::Zero()), ky_.assign(n, Vec<D>::Zero()), q_.resize(n);
  for (int piece = 0; piece < pieces; ++piece) {
    y0_ = u_;
    q2_.assign(n, Vec<D>::Zero());
    operate_joined();
    for (std::size_t l = 0; l < n; ++l) q_[l] = (cs.w1 / cs.w0) * (ky_[l] - fe_[l]);
    for (int j = 2; j <= stages; ++j) {
      velocities(q_);
      operate_joined();
      const double mu = 2 * cs.w0 * cs.T[j - 1] / cs.T[j], nu = -cs.T[j - 2] / cs.T[j], mu1 = 2 * cs.w1 * cs.T[j - 1] / cs.T[j];
      for (std::size_t l = 0; l < n; ++l) q2_[l] = mu * q_[l] + nu * q2_[l] + mu1 * (ky_[l] - fe_[l]);
      std::swap(q_, q2_);
    }
    velocities(q_);
    for (std::size_t l = 0; l < n; ++l) qsum_[l] += q_[l] / pieces;
  }
  std::swap(q_, qsum_);
  ++stats_.steps, stats_.stages += static_cast<long>(pieces) * stages;
  for (const Vec<D>& v : u_)
    if (!v.allFinite()) throw RunError("body '" + b.name + "': the viscous sub-step gave a non-finite velocity");
}

template <int D> void ImplicitViscosity<D>::save_state(StateWriter& w) const { w.put(dissipated_), w.put(stats_); }

template <int D> void ImplicitViscosity<D>::load_state(StateReader& r) { r.get(dissipated_), r.get(stats_); }

template <int D> void ImplicitViscosity<D>::account(const Grid<D>& g, double dt) {
  double w = 0;
  for (std::size_t j = 0; j < acc_k_.size(); ++j) w += acc_f_[j].dot(g.vL[acc_k_[j]]);
  dissipated_ += dt * w;
  acc_k_.clear(), acc_f_.clear();
}

template class ImplicitViscosity<2>;
template class ImplicitViscosity<3>;

}  // namespace dmi
