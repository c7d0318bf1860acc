// Basic system of an elasto-plastic beam-column (force-based, as OpenSees' forceBeamColumn: Spacone, Filippou & Taucer
// 1996; Neuenhofer & Filippou 1997), for the plane element (NP = 1 bending plane, basic deformations
// v = [elongation, theta_i, theta_j], basic forces q = [N, M_i, M_j], element.hpp) and the space element (NP = 2,
// v = [elongation, theta_i, theta_j, theta'_i, theta'_j, twist], space_element.hpp). Within the chord (the
// corotational transformation takes the large rotations) the section forces follow from q by equilibrium,
//   s(xi) = b(xi) q:  N = q_0,  M_p(xi) = -q_{1+2p} (1 - xi) + q_{2+2p} xi,
// exactly (no element loads inside: they reach the element as nodal loads), and compatibility holds in the weak form
//   v = sum_g w_g L b_g^T e_g,  e_g = [eps_0, kappa_1 .. kappa_NP] the section deformations at the Gauss-Lobatto
// points xi_g (weights w_g on [0, 1]; the end sections, where hinges form, are sampled). Element state determination
// (Neuenhofer & Filippou 1997, sec. 4): from the committed q and e_g, iterate
//   r_g = f_s,g (b_g q - s(e_g)),  F = sum_g w_g L b_g^T f_s,g b_g,  dq = F^-1 (v - sum_g w_g L b_g^T (e_g + r_g)),
//   q += dq,  e_g += r_g + f_s,g b_g dq
// until the compatibility residual vanishes; the tangent is F^-1 (consistent: f_s,g from the fibres' algorithmic
// moduli). With the moment linear along the element, the plastic hinge forms at an end section and a member between
// loads needs one element (a displacement-based element needs many: its curvature is linear). Section (fibre.hpp
// conventions): eps(y', z') = eps_0 - kappa_1 y' - kappa_2 z'. Twist stays elastic (St Venant: T = (G J / L) twist),
// shear deformation is not modelled (Euler-Bernoulli). Each fibre follows steel_law.hpp.
// The state is committed; respond() depends on it and v alone (a Newton iteration may call it at any trial v; it keeps
// its last result for commit, so one element is not to be responded to from two threads at once),
// commit() accepts v as the end of a step and books the plastic work sum sigma d(eps_p) A w L, the peak strain at the
// section's surface and the accumulated plastic strain.
#pragma once
#include <Eigen/Dense>
#include <optional>
#include <vector>

#include "engine/common/state_io.hpp"
#include "engine/structure/fibre_section.hpp"
#include "engine/structure/steel_law.hpp"

namespace dmi {

// Gauss-Lobatto points and weights on [0, 1] (n = 3, 4 or 5): exact to degree 2n - 3, the ends included.
struct LobattoPoint { double xi, w; };
std::vector<LobattoPoint> gauss_lobatto(int n);

// What a plastic element has done so far (J, -, -).
struct PlasticRecord {
  double plastic_work = 0;        // sum over fibres of int sigma d(eps_p) A dx
  double peak_strain = 0;         // largest |eps| reached at the section surface
  double peak_plastic_strain = 0; // largest accumulated |d eps_p| of a fibre
  bool yielded = false;
};

template <int NP> class FibreBeam {
 public:
  static constexpr int NV = NP == 1 ? 3 : 6;  // basic deformations
  static constexpr int NS = 1 + NP;           // section deformations [eps_0, kappa_1 .. kappa_NP]
  using VecV = Eigen::Matrix<double, NV, 1>;
  using MatV = Eigen::Matrix<double, NV, NV>;
  using SecV = Eigen::Matrix<double, NS, 1>;
  using BMat = Eigen::Matrix<double, NS, NV>;

  // section over the element's span [s0, s1] of its member's taper; L the initial length; torsion: G J / L (space).
  FibreBeam(const Section& section, double s0, double s1, double L, const SteelLaw& law, int points, double torsion = 0);

  // Basic forces q at v (and the tangent dq/dv when k is given) from the committed state.
  void respond(const VecV& v, VecV& q, MatV* k) const;
  // Accepts v as the end of a step.
  void commit(const VecV& v);
  const PlasticRecord& record() const { return record_; }
  // Elastic strain energy of the fibres at the committed state, sum sigma^2 / (2 E) A dx (J); twist's G J twist^2 / 2L.
  double elastic_energy() const { return elastic_energy_; }
  const SteelLaw& law() const { return law_; }

  void save_state(StateWriter& w) const;
  void load_state(StateReader& r);

 private:
  struct Point {
    double xi, weight;   // weight: w_g L (m)
    int first, count;    // its fibres in fibres_
    double extent[2];    // distance of the surface from the axis along y', z' (m)
    bool round;          // a pipe: the surface strain takes the resultant curvature
  };
  using SecM = Eigen::Matrix<double, NS, NS>;
  // The state determination at v: q, the tangent, the section deformations and the fibres' histories.
  struct Trial {
    VecV q;
    MatV k;
    std::vector<SecV> e;
    std::vector<FibreHistory> history;
    std::vector<CurveState> curve;  // Menegotto-Pinto
  };
  BMat force_matrix(double xi) const;  // b(xi): s = b q
  double surface_strain(const Point& p, const SecV& e) const;
  // s(e) and its tangent at point p from the committed histories (the fibres' histories after the increment in t).
  void section(int g, const SecV& e, SecV& s, SecM& ks, Trial* t) const;
  bool elastic_at(const VecV& v, Trial& t) const;  // virgin and every surface within its elastic range
  Trial state_at(const VecV& v) const;
  // Element state determination from t (damped: halved steps where the unbalance stops falling); false: not converged.
  bool iterate(const VecV& v, Trial& t, bool damped) const;

  SteelLaw law_;
  double L_ = 0, torsion_ = 0;
  std::vector<Point> points_;
  std::vector<Fibre> fibres_;
  std::vector<FibreHistory> history_;  // committed, one per fibre
  std::vector<CurveState> curve_;      // committed, one per fibre (Menegotto-Pinto; empty for the bilinear law)
  std::vector<double> accumulated_;    // accumulated plastic strain, one per fibre
  VecV q_, v_;                         // committed basic forces and deformations
  std::vector<SecV> e_;                // committed section deformations, one per point
  std::vector<SecM> ks_elastic_, fs_elastic_;  // the virgin sections' stiffnesses and flexibilities
  MatV k_elastic_;                     // the virgin element's stiffness
  SecV s_yield_;                       // yield force and moments of a section (tolerance scales)
  VecV v_yield_;                       // deformations at first yield (tolerance scales)
  PlasticRecord record_;
  double elastic_energy_ = 0;
  // The last state determination respond() made and its v: a step's commit at the v of its last Newton iteration
  // takes it instead of determining the same state again.
  mutable Trial last_;
  mutable VecV last_v_;
  mutable bool has_last_ = false;
  bool left_linear_ = false;  // Menegotto-Pinto: a state beyond linear_strain_ was committed (its fibres keep a history)
  double linear_strain_ = 0;  // the surface strain below which the element is taken as elastic (a sharp law: eps_y)
};

extern template class FibreBeam<1>;
extern template class FibreBeam<2>;

// The elasto-plastic elements of a frame (one slot per element, empty for an elastic one), shared by the plane and the
// space frame: their plastic work, records and checkpoints.
template <int NP> struct FibreBeams {
  std::vector<std::optional<FibreBeam<NP>>> beams;
  bool any = false;
  // The elements as committed before a step's sub-steps (each committed), put back when the sub-steps fail.
  std::optional<std::vector<std::optional<FibreBeam<NP>>>> kept;
  void keep() {
    if (any) kept = beams;
  }
  void restore() {
    if (kept) beams = *kept;
  }
  const FibreBeam<NP>* at(int e) const { return beams[e] ? &*beams[e] : nullptr; }
  double plastic_work() const {
    double w = 0;
    for (const auto& b : beams)
      if (b) w += b->record().plastic_work;
    return w;
  }
  std::optional<PlasticRecord> record(int e) const { return beams[e] ? std::optional<PlasticRecord>(beams[e]->record()) : std::nullopt; }
  void save_state(StateWriter& w) const {
    for (const auto& b : beams)
      if (b) b->save_state(w);
  }
  void load_state(StateReader& r) {
    for (auto& b : beams)
      if (b) b->load_state(r);
  }
};

}  // namespace dmi
