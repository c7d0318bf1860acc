#include "engine/structure/frame_system.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dmi {
namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

std::string dof_name(int dof) {
  static constexpr const char* kComponent[3] = {"ux", "uy", "rz"};
  return std::string(kComponent[dof % 3]) + " of node " + std::to_string(dof / 3);
}

[[noreturn]] void fail(const std::string& what) { throw std::invalid_argument("Frame: " + what); }

void scatter(Triplets& t, int i, int j, const Mat6& ke) {
  const int base[2] = {3 * i, 3 * j};
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 6; ++c)
      if (ke(r, c) != 0) t.emplace_back(base[r / 3] + r % 3, base[c / 3] + c % 3, ke(r, c));
}

SpMat from_triplets(int n, const Triplets& t) {
  SpMat A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

}  // namespace

FrameSystem::FrameSystem(FrameModel model) : model_(std::move(model)) {
  validate();
  assemble();
  check_mechanism();
  factorise_mass();
}

void FrameSystem::validate() const {
  const int nn = static_cast<int>(model_.nodes.size()), ne = static_cast<int>(model_.elements.size());
  if (ne == 0) fail("the model has no elements");
  for (int n = 0; n < nn; ++n)
    if (!model_.nodes[n].allFinite()) fail("node " + std::to_string(n) + " has a non-finite coordinate");
  const auto node_ok = [nn](int n) { return n >= 0 && n < nn; };
  Vec2 lo = Vec2::Constant(INFINITY), hi = -lo;
  for (const Vec2& x : model_.nodes) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  const double min_length = 1e-12 * std::max(1.0, (hi - lo).norm());  // m
  for (int e = 0; e < ne; ++e) {
    const FrameElementDef& el = model_.elements[e];
    const std::string id = "element " + std::to_string(e) + ": ";
    if (!node_ok(el.i) || !node_ok(el.j))
      fail(id + "node index " + std::to_string(node_ok(el.i) ? el.j : el.i) + " outside [0, " +
           std::to_string(nn) + ")");
    if ((model_.nodes[el.j] - model_.nodes[el.i]).norm() <= min_length) fail(id + "zero length");
    if (!(el.E > 0) || !std::isfinite(el.E)) fail(id + "Young's modulus E must be positive");
    if (!(el.rho > 0) || !std::isfinite(el.rho)) fail(id + "density rho must be positive");
    if (!(el.nu > -1 && el.nu <= 0.5)) fail(id + "Poisson's ratio outside (-1, 0.5]");
    if (!(el.s0 >= 0 && el.s0 <= 1 && el.s1 >= 0 && el.s1 <= 1)) fail(id + "section span s0, s1 outside [0, 1]");
    for (double s : {el.s0, el.s1})
      if (!(el.section.depth(s) > 0 && el.section.width(s) > 0 && el.section.area(s) > 0 &&
            el.section.inertia(s) > 0))
        fail(id + "section dimensions must be positive");
    if (!model_.members.empty() && (el.member < 0 || el.member >= static_cast<int>(model_.members.size())))
      fail(id + "member index " + std::to_string(el.member) + " out of range");
  }
  for (size_t m = 0; m < model_.members.size(); ++m) {
    const FrameMemberDef& mb = model_.members[m];
    if (mb.first_element < 0 || mb.elements < 1 || mb.first_element + mb.elements > ne)
      fail("member " + std::to_string(m) + " (" + mb.name + "): element range outside the model");
  }
  std::vector<bool> supported(nn, false);
  for (size_t k = 0; k < model_.supports.size(); ++k) {
    const FrameSupportDef& s = model_.supports[k];
    const std::string id = "support " + std::to_string(k) + ": ";
    if (!node_ok(s.node)) fail(id + "node index " + std::to_string(s.node) + " out of range");
    if (supported[s.node]) fail(id + "node " + std::to_string(s.node) + " already has a support");
    supported[s.node] = true;
    for (double kc : s.spring)
      if (!(kc >= 0) || !std::isfinite(kc)) fail(id + "spring stiffness must be finite and >= 0");
  }
  for (size_t k = 0; k < model_.masses.size(); ++k) {
    const FrameMassDef& m = model_.masses[k];
    if (!node_ok(m.node))
      fail("mass " + std::to_string(k) + ": node index " + std::to_string(m.node) + " out of range");
    if (!(m.mass >= 0 && m.rotary_inertia >= 0) || !std::isfinite(m.mass + m.rotary_inertia))
      fail("mass " + std::to_string(k) + ": mass and rotary inertia must be finite and >= 0");
  }
  if (!(model_.rayleigh_mass >= 0 && model_.rayleigh_stiffness >= 0) ||
      !std::isfinite(model_.rayleigh_mass + model_.rayleigh_stiffness))
    fail("Rayleigh coefficients must be finite and >= 0");
  if (!model_.gravity.allFinite()) fail("gravity must be finite");
}

void FrameSystem::assemble() {
  const int n = 3 * static_cast<int>(model_.nodes.size());
  transform_ = make_transform(model_.transform);
  Triplets tk, tm;
  for (const FrameElementDef& el : model_.elements) {
    const Vec2 dx = model_.nodes[el.j] - model_.nodes[el.i];
    const Chord c{model_.nodes[el.i], dx / dx.norm(), dx.norm()};
    chords_.push_back(c);
    elements_.emplace_back(el, c.L0, model_.theory);
    const BeamElement& be = elements_.back();
    const Mat6 Ke = transform_->tangent(transform_->state(c, Vec6::Zero()), be.stiffness(), Vec3::Zero());
    scatter(tk, el.i, el.j, Ke);
    const Mat6 R = global_to_local(c.e1);
    const Mat6 Me = model_.mass == MassMatrix::lumped ? Mat6(be.lumped_mass().asDiagonal())
                                                      : Mat6(R.transpose() * be.consistent_mass() * R);
    scatter(tm, el.i, el.j, Me);
    // Irons (1970): the largest eigenvalue of an assembly is at most the largest of its elements'.
    Eigen::GeneralizedSelfAdjointEigenSolver<Mat6> es(Ke, Me, Eigen::EigenvaluesOnly);
    element_bound_ = std::max(element_bound_, es.eigenvalues().maxCoeff());
  }
  free_ = Eigen::VectorXd::Ones(n);
  springs_ = Eigen::VectorXd::Zero(n);
  for (const FrameSupportDef& s : model_.supports)
    for (int c = 0; c < 3; ++c) {
      if (s.fixed[c]) free_(3 * s.node + c) = 0;
      else springs_(3 * s.node + c) += s.spring[c];
    }
  for (int i = 0; i < n; ++i)
    if (springs_(i) > 0) tk.emplace_back(i, i, springs_(i));
  for (const FrameMassDef& m : model_.masses) {
    tm.emplace_back(3 * m.node, 3 * m.node, m.mass);
    tm.emplace_back(3 * m.node + 1, 3 * m.node + 1, m.mass);
    tm.emplace_back(3 * m.node + 2, 3 * m.node + 2, m.rotary_inertia);
  }
  K0_ = from_triplets(n, tk);
  M_ = from_triplets(n, tm);
  double spring_bound = 0;  // lambda_max(K + S, M) <= lambda_max(K, M) + max s_i / M_ii (S diagonal)
  for (int i = 0; i < n; ++i)
    if (springs_(i) > 0) spring_bound = std::max(spring_bound, springs_(i) / M_.coeff(i, i));
  element_bound_ += spring_bound;
}

double FrameSystem::max_eigenvalue() const {
  int nf = 0;
  for (int i = 0; i < ndof(); ++i) nf += free_(i) > 0;
  // Exact (dense) for small frames; above ~200 elements the O(n^3) solve costs seconds, so the
  // element bound (conservative: a smaller stable step) is used.
  return nf <= kDenseEigenMax ? eigenvalues().maxCoeff() : element_bound_;
}

void FrameSystem::factorise_mass() {
  if (model_.mass == MassMatrix::consistent) {
    mass_solver_.compute(constrained(M_));
    if (mass_solver_.info() != Eigen::Success) fail("consistent mass matrix is not positive definite");
    return;
  }
  inv_lumped_ = Eigen::VectorXd::Zero(ndof());
  for (int i = 0; i < ndof(); ++i) {
    if (free_(i) == 0) continue;
    if (!(M_.coeff(i, i) > 0)) fail("no mass at " + dof_name(i));  // HRZ gives every element DOF mass
    inv_lumped_(i) = 1 / M_.coeff(i, i);
  }
}

// Singular K0 on the free DOFs: a zero diagonal, a failed LDLT or a pivot below 1e-12 of its diagonal. The
// DOF named is the largest entry of the lowest eigenvector of the diagonally scaled stiffness (the mode).
void FrameSystem::check_mechanism() const {
  const SpMat K = constrained(K0_);
  const auto mechanism = [](int dof) {
    fail("the frame is a mechanism: no stiffness against " + dof_name(dof) +
         " (add supports, or release only one side of a hinge)");
  };
  const Eigen::VectorXd diag = K.diagonal();
  for (int i = 0; i < ndof(); ++i)
    if (!(diag(i) > 0)) mechanism(i);
  Eigen::SimplicialLDLT<SpMat> ldlt(K);
  bool singular = ldlt.info() != Eigen::Success;
  if (!singular) {
    const Eigen::VectorXd D = ldlt.vectorD();
    const auto& perm = ldlt.permutationP().indices();  // original DOF i sits at pivot perm(i)
    for (int i = 0; i < ndof(); ++i) singular = singular || !(D(perm(i)) > 1e-12 * diag(i));
  }
  if (!singular) return;
  if (ndof() > 3 * kDenseEigenMax)
    fail("the frame is a mechanism: its stiffness matrix is singular (add supports, or release only one side of a hinge)");
  const Eigen::VectorXd s = diag.cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd scaled = s.asDiagonal() * Eigen::MatrixXd(K) * s.asDiagonal();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(scaled);
  int worst = 0;
  es.eigenvectors().col(0).cwiseAbs().maxCoeff(&worst);
  mechanism(worst);
}

SpMat FrameSystem::constrained(const SpMat& A) const {
  Triplets t;
  t.reserve(A.nonZeros() + ndof());
  for (int c = 0; c < A.outerSize(); ++c)
    for (SpMat::InnerIterator it(A, c); it; ++it)
      if (free_(it.row()) > 0 && free_(it.col()) > 0) t.emplace_back(it.row(), it.col(), it.value());
  for (int i = 0; i < ndof(); ++i)
    if (free_(i) == 0) t.emplace_back(i, i, 1.0);
  return from_triplets(ndof(), t);
}

Vec6 FrameSystem::element_dofs(int e, const Eigen::VectorXd& d) const {
  const FrameElementDef& el = model_.elements[e];
  Vec6 de;
  de << d.segment<3>(3 * el.i), d.segment<3>(3 * el.j);
  return de;
}

void FrameSystem::internal_force(const Eigen::VectorXd& d, Eigen::VectorXd& out) const {
  if (linear()) {
    out.noalias() = K0_ * d;
    return;
  }
  out = springs_.cwiseProduct(d);
  for (int e = 0; e < nelements(); ++e) {
    const ChordState s = transform_->state(chords_[e], element_dofs(e, d));
    const Vec6 fe = s.B.transpose() * elements_[e].forces(s.v);
    out.segment<3>(3 * model_.elements[e].i) += fe.head<3>();
    out.segment<3>(3 * model_.elements[e].j) += fe.tail<3>();
  }
}

SpMat FrameSystem::tangent(const Eigen::VectorXd& d) const {
  if (linear()) return K0_;
  Triplets t;
  for (int e = 0; e < nelements(); ++e) {
    const ChordState s = transform_->state(chords_[e], element_dofs(e, d));
    const BeamElement& be = elements_[e];
    scatter(t, model_.elements[e].i, model_.elements[e].j, transform_->tangent(s, be.stiffness(), be.forces(s.v)));
  }
  for (int i = 0; i < ndof(); ++i)
    if (springs_(i) > 0) t.emplace_back(i, i, springs_(i));
  return from_triplets(ndof(), t);
}

void FrameSystem::damping_force(const Eigen::VectorXd& v, Eigen::VectorXd& out) const {
  out.noalias() = model_.rayleigh_mass * (M_ * v);
  if (model_.rayleigh_stiffness > 0) out.noalias() += model_.rayleigh_stiffness * (K0_ * v);
}

void FrameSystem::solve_mass(Eigen::VectorXd& r, Eigen::VectorXd& a) const {
  r.array() *= free_.array();
  if (model_.mass == MassMatrix::lumped) a = inv_lumped_.cwiseProduct(r);
  else a = mass_solver_.solve(r);
}

Vec2 FrameSystem::axis(int e, const Eigen::VectorXd& d) const {
  const Chord& c = chords_[e];
  if (linear()) return c.e1;
  const Vec6 de = element_dofs(e, d);
  return (c.L0 * c.e1 + de.segment<2>(3) - de.head<2>()).normalized();
}

ElementLoad FrameSystem::element_load(int e, const Vec2& w_local, const Eigen::VectorXd& d) const {
  const Vec2 e1 = axis(e, d), g = model_.gravity;
  ElementLoad p = elements_[e].self_weight(Vec2(g.dot(e1), e1.x() * g.y() - e1.y() * g.x()));
  p.a += w_local;
  p.b += w_local;
  return p;
}

void FrameSystem::add_element_loads(const std::vector<Vec2>& w, const Eigen::VectorXd& d, Eigen::VectorXd& f) const {
  const bool gravity = model_.gravity.squaredNorm() > 0;
  for (int e = 0; e < nelements(); ++e) {
    if (!gravity && w[e].squaredNorm() == 0) continue;
    const ElementLoad p = element_load(e, w[e], d);
    const Vec6 fg = global_to_local(axis(e, d)).transpose() * elements_[e].equivalent_loads(p);
    f.segment<3>(3 * model_.elements[e].i) += fg.head<3>();
    f.segment<3>(3 * model_.elements[e].j) += fg.tail<3>();
  }
}

Eigen::VectorXd FrameSystem::eigenvalues() const {
  std::vector<int> idx;
  for (int i = 0; i < ndof(); ++i)
    if (free_(i) > 0) idx.push_back(i);
  const int nf = static_cast<int>(idx.size());
  const Eigen::MatrixXd K(K0_), M(M_);
  Eigen::MatrixXd Kf(nf, nf), Mf(nf, nf);
  for (int r = 0; r < nf; ++r)
    for (int c = 0; c < nf; ++c) {
      Kf(r, c) = K(idx[r], idx[c]);
      Mf(r, c) = M(idx[r], idx[c]);
    }
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(Kf, Mf, Eigen::EigenvaluesOnly);
  if (es.info() != Eigen::Success) throw std::runtime_error("Frame: generalised eigen solve failed");
  return es.eigenvalues();
}

}  // namespace dmi
