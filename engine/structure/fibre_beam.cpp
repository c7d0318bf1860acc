#include "engine/structure/fibre_beam.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace dmi {

namespace {
// The plastic strain a Menegotto-Pinto member is said to have yielded at, as a fraction of the yield strain.
constexpr double kYieldedPlasticStrain = 0.1;
}  // namespace

std::vector<LobattoPoint> gauss_lobatto(int n) {
  // On [-1, 1]: n = 3: 0, +-1 (4/3, 1/3); n = 4: +-1/sqrt5 (5/6), +-1 (1/6); n = 5: 0 (32/45), +-sqrt(3/7) (49/90), +-1 (1/10).
  std::vector<std::pair<double, double>> r;
  if (n == 3) r = {{-1, 1.0 / 3}, {0, 4.0 / 3}, {1, 1.0 / 3}};
  else if (n == 4) r = {{-1, 1.0 / 6}, {-1 / std::sqrt(5.0), 5.0 / 6}, {1 / std::sqrt(5.0), 5.0 / 6}, {1, 1.0 / 6}};
  else if (n == 5) r = {{-1, 0.1}, {-std::sqrt(3.0 / 7), 49.0 / 90}, {0, 32.0 / 45}, {std::sqrt(3.0 / 7), 49.0 / 90}, {1, 0.1}};
  else throw std::invalid_argument("gauss_lobatto: " + std::to_string(n) + " points (3, 4 or 5)");
  std::vector<LobattoPoint> out;
  for (const auto& [x, w] : r) out.push_back({0.5 * (x + 1), 0.5 * w});
  return out;
}

template <int NP>
FibreBeam<NP>::FibreBeam(const Section& section, double s0, double s1, double L, const SteelLaw& law, int points, double torsion)
    : law_(law), L_(L), torsion_(torsion) {
  for (const LobattoPoint& g : gauss_lobatto(points)) {
    const double s = s0 + g.xi * (s1 - s0);
    const std::vector<Fibre> f = fibre_layout(section, s, NP == 2);
    const bool round = section.kind() == SectionKind::pipe;
    points_.push_back({g.xi, g.w * L, static_cast<int>(fibres_.size()), static_cast<int>(f.size()),
                       {section.half_depth(s), 0.5 * section.width(s)}, round});
    fibres_.insert(fibres_.end(), f.begin(), f.end());
  }
  history_.assign(fibres_.size(), FibreHistory{});
  if (law_.curve == SteelCurve::menegotto_pinto) curve_.assign(fibres_.size(), CurveState{});
  accumulated_.assign(fibres_.size(), 0.0);
  e_.assign(points_.size(), SecV::Zero());
  q_.setZero(), v_.setZero();
  MatV F = MatV::Zero();
  for (const Point& p : points_) {
    SecV sv;
    SecM ks;
    this->section(static_cast<int>(&p - points_.data()), SecV::Zero(), sv, ks, nullptr);
    ks_elastic_.push_back(ks);
    fs_elastic_.push_back(ks.inverse());
    const BMat b = force_matrix(p.xi);
    F += p.weight * b.transpose() * fs_elastic_.back() * b;
  }
  if constexpr (NP == 2) F(5, 5) = 1 / torsion_;
  k_elastic_ = F.inverse();
  // Elastic below the yield strain (bilinear); Menegotto-Pinto's curve departs from E eps by (1 - b) a^R0 / R0 at
  // eps = a eps_y on its first branch: below 1e-9 of the stress while a < (1e-9 R0 / (1 - b))^(1/R0) (0.41 for R0 20).
  linear_strain_ = law_.curve == SteelCurve::bilinear ? law_.yield_strain()
                                                      : law_.yield_strain() * std::pow(1e-9 * law_.r0 / (1 - law_.hardening), 1 / law_.r0);
  // Yield forces and deformations of the first section: the scales of the state determination's tolerance.
  const double A = ks_elastic_[0](0, 0) / law_.E, eps_y = law_.yield_strain();
  s_yield_(0) = law_.fy * A;
  v_yield_.setConstant(eps_y * L);
  for (int c = 0; c < NP; ++c) {
    const double I = ks_elastic_[0](1 + c, 1 + c) / law_.E, extent = points_[0].extent[c];
    s_yield_(1 + c) = law_.fy * I / extent;
    v_yield_(1 + 2 * c) = v_yield_(2 + 2 * c) = eps_y * L / extent;
  }
}

template <int NP> typename FibreBeam<NP>::BMat FibreBeam<NP>::force_matrix(double xi) const {
  BMat b = BMat::Zero();
  b(0, 0) = 1;
  for (int c = 0; c < NP; ++c) b(1 + c, 1 + 2 * c) = xi - 1, b(1 + c, 2 + 2 * c) = xi;
  return b;
}

template <int NP> double FibreBeam<NP>::surface_strain(const Point& p, const SecV& e) const {
  if constexpr (NP == 1) return std::abs(e(0)) + std::abs(e(1)) * p.extent[0];
  else {
    if (p.round) return std::abs(e(0)) + std::hypot(e(1), e(2)) * p.extent[0];
    return std::abs(e(0)) + std::abs(e(1)) * p.extent[0] + std::abs(e(2)) * p.extent[1];
  }
}

template <int NP> void FibreBeam<NP>::section(int g, const SecV& e, SecV& s, SecM& ks, Trial* t) const {
  const Point& p = points_[g];
  s.setZero();
  ks.setZero();
  const auto add = [&](int f, const SecV& a, double sigma, double tangent) {
    s += sigma * fibres_[f].area * a;
    ks += tangent * fibres_[f].area * a * a.transpose();
  };
  const auto direction = [&](int f) {  // d eps / d (eps_0, kappa_1 .. kappa_NP) of fibre f
    SecV a;
    a(0) = 1;
    for (int c = 0; c < NP; ++c) a(1 + c) = -fibres_[f].c[c];
    return a;
  };
  if (law_.curve == SteelCurve::menegotto_pinto) {
    CurveState scratch;  // the state after the increment, when no trial keeps it
    for (int f = p.first; f < p.first + p.count; ++f) {
      const SecV a = direction(f);
      const double eps = a.dot(e);
      double tangent = 0;
      const double sigma = menegotto_pinto_stress(law_, curve_[f], eps, tangent, t ? t->curve[f] : scratch);
      if (t) t->history[f].eps_p = eps - sigma / law_.E;
      add(f, a, sigma, tangent);
    }
  } else {
    for (int f = p.first; f < p.first + p.count; ++f) {
      const SecV a = direction(f);
      const FibreResponse r = bilinear_response(law_, history_[f], a.dot(e));
      if (t) t->history[f] = r.history;
      add(f, a, r.sigma, r.tangent);
    }
  }
  // A section yielded through (perfect plasticity, every fibre) keeps 1e-9 of its elastic stiffness in its tangent:
  // the flexibility stays finite.
  if (law_.hardening == 0 && g < static_cast<int>(ks_elastic_.size())) ks += 1e-9 * ks_elastic_[g];
}

template <int NP> bool FibreBeam<NP>::elastic_at(const VecV& v, Trial& t) const {
  if (record_.yielded || left_linear_) return false;
  t.q.noalias() = k_elastic_ * v;
  t.k = k_elastic_;
  t.e.resize(points_.size());
  for (std::size_t g = 0; g < points_.size(); ++g) {
    t.e[g] = fs_elastic_[g] * (force_matrix(points_[g].xi) * t.q);
    if (surface_strain(points_[g], t.e[g]) > linear_strain_) return false;
  }
  return true;
}

template <int NP> typename FibreBeam<NP>::Trial FibreBeam<NP>::state_at(const VecV& v) const {
  Trial t;
  if (elastic_at(v, t)) return t;
  // From the committed state with Newton's full steps; failing that, with damped steps, and then by continuation: the
  // same v reached in k sub-increments, each starting from the last one's forces and section deformations (the fibres
  // always return from their committed history).
  constexpr std::pair<int, bool> kAttempts[] = {{1, false}, {1, true}, {4, true}, {16, true}, {64, true}};
  for (const auto& [k, damped] : kAttempts) {
    t.q = q_;
    t.e = e_;
    t.history = history_;
    t.curve = curve_;
    bool ok = true;
    for (int j = 1; j <= k && ok; ++j) ok = iterate(v_ + (v - v_) * (double(j) / k), t, damped);
    if (ok) return t;
  }
  throw std::runtime_error("FibreBeam: the element state did not converge (a fully plastic section under a growing force?)");
}

template <int NP> bool FibreBeam<NP>::iterate(const VecV& v, Trial& t, bool damped) const {
  constexpr int kMaxIterations = 50;
  const int n = static_cast<int>(points_.size());
  std::vector<SecM> fs(n);
  std::vector<SecV> r(n), ds(n);
  // Newton's iteration on a piecewise-linear (bilinear fibre) response can cycle between two branches. Damped: a step
  // that does not lower the unbalance halves the next one (down to 1/64), a step that does lengthens it by a quarter
  // (up to 1), with twice the iterations.
  double alpha = 1, previous = std::numeric_limits<double>::infinity();
  for (int it = 0;; ++it) {
    MatV F = MatV::Zero();
    VecV vr = VecV::Zero(), magnitude = v.cwiseAbs() + v_yield_;  // magnitude: the round-off scale of v - vr
    for (int g = 0; g < n; ++g) {
      SecV s;
      SecM ks;
      section(g, t.e[g], s, ks, &t);
      fs[g] = ks.inverse();
      const BMat b = force_matrix(points_[g].xi);
      ds[g] = b * t.q - s;
      r[g] = fs[g] * ds[g];
      F += points_[g].weight * b.transpose() * fs[g] * b;
      vr += points_[g].weight * b.transpose() * (t.e[g] + r[g]);
      magnitude += points_[g].weight * b.cwiseAbs().transpose() * (t.e[g] + r[g]).cwiseAbs();
    }
    if constexpr (NP == 2) F(5, 5) = 1 / torsion_, vr(5) = t.q(5) / torsion_;
    t.k = F.inverse();
    const VecV dq = t.k * (v - vr);
    // Converged when every section's forces balance b q to 1e-10 of its yield forces and compatibility holds to 1e-8
    // of the deformations summed (a yielded-through section's curvature can exceed the element's rotations by far, and
    // its flexibility, 1e9 times the elastic one, costs as many digits).
    double unbalance = 1e-2 * (v - vr).cwiseQuotient(magnitude).cwiseAbs().maxCoeff();
    for (int g = 0; g < n; ++g) unbalance = std::max(unbalance, ds[g].cwiseQuotient(s_yield_).cwiseAbs().maxCoeff());
    if (unbalance <= 1e-10) return true;
    if (it == (damped ? 2 * kMaxIterations : kMaxIterations) || !std::isfinite(unbalance)) return false;
    if (damped) alpha = unbalance < previous ? std::min(1.0, 1.25 * alpha) : std::max(1.0 / 64, 0.5 * alpha);
    previous = unbalance;
    t.q += alpha * dq;
    for (int g = 0; g < n; ++g) t.e[g] += alpha * (r[g] + fs[g] * (force_matrix(points_[g].xi) * dq));
  }
}

template <int NP> void FibreBeam<NP>::respond(const VecV& v, VecV& q, MatV* k) const {
  last_ = state_at(v);
  last_v_ = v, has_last_ = true;
  q = last_.q;
  if (k) *k = last_.k;
}

template <int NP> void FibreBeam<NP>::commit(const VecV& v) {
  Trial t = has_last_ && v == last_v_ ? std::move(last_) : state_at(v);
  has_last_ = false;
  if (law_.curve != SteelCurve::bilinear && !t.history.empty()) left_linear_ = true;
  for (std::size_t g = 0; g < points_.size(); ++g) record_.peak_strain = std::max(record_.peak_strain, surface_strain(points_[g], t.e[g]));
  double energy = 0;
  if (t.history.empty()) {
    energy = 0.5 * v.dot(t.q);  // virgin and elastic: no history to update
  } else {
    for (const Point& p : points_)
      for (int f = p.first; f < p.first + p.count; ++f) {
        const double deps_p = t.history[f].eps_p - history_[f].eps_p;
        double eps = t.e[&p - points_.data()](0);
        for (int c = 0; c < NP; ++c) eps -= fibres_[f].c[c] * t.e[&p - points_.data()](1 + c);
        const double sigma = law_.E * (eps - t.history[f].eps_p);
        if (deps_p != 0) {
          // Menegotto-Pinto's knee is smooth: the member has yielded once a fibre's plastic strain reaches a tenth of
          // the yield strain (on the first branch at 1.1 eps_y, the stress then within 1 % of f_y).
          if (law_.curve == SteelCurve::bilinear || std::abs(t.history[f].eps_p) >= kYieldedPlasticStrain * law_.yield_strain())
            record_.yielded = true;
          record_.plastic_work += sigma * deps_p * fibres_[f].area * p.weight;
          accumulated_[f] += std::abs(deps_p);
          record_.peak_plastic_strain = std::max(record_.peak_plastic_strain, accumulated_[f]);
        }
        energy += 0.5 * sigma * sigma / law_.E * fibres_[f].area * p.weight;
      }
    if constexpr (NP == 2) energy += 0.5 * t.q(5) * v(5);
    history_ = std::move(t.history);
    curve_ = std::move(t.curve);
  }
  q_ = t.q, v_ = v, e_ = std::move(t.e);
  elastic_energy_ = energy;
}

template <int NP> void FibreBeam<NP>::save_state(StateWriter& w) const {
  w.put(history_), w.put(curve_), w.put(accumulated_), w.put(record_), w.put(elastic_energy_), w.put(e_), w.put(left_linear_);
  for (int c = 0; c < NV; ++c) w.put(q_(c)), w.put(v_(c));
}

template <int NP> void FibreBeam<NP>::load_state(StateReader& r) {
  const std::size_t n = fibres_.size();
  has_last_ = false;
  r.get(history_), r.get(curve_), r.get(accumulated_), r.get(record_), r.get(elastic_energy_), r.get(e_), r.get(left_linear_);
  for (int c = 0; c < NV; ++c) r.get(q_(c)), r.get(v_(c));
  r.expect_size("element sections", e_.size(), points_.size());
  r.expect_size("element fibres", history_.size(), n);
  r.expect_size("element fibres", curve_.size(), law_.curve == SteelCurve::menegotto_pinto ? n : 0);
  r.expect_size("element fibres", accumulated_.size(), n);
}

template class FibreBeam<1>;
template class FibreBeam<2>;

}  // namespace dmi
