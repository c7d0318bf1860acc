#include "engine/structure/frame_system.hpp"
#include "engine/structure/frame_validate.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dmi {
namespace {

[[noreturn]] void fail(const std::string& what) { throw std::invalid_argument("Frame: " + what); }

}  // namespace

FrameSystem::FrameSystem(FrameModel model) : AssembledSystem(3), model_(std::move(model)) {
  validate();
  assemble();
  finish(model_.mass == MassMatrix::lumped, model_.rayleigh_mass, model_.rayleigh_stiffness, model_.modal_damping);
}

std::string FrameSystem::dof_name(int dof) const {
  static constexpr const char* kComponent[3] = {"ux", "uy", "rz"};
  return std::string(kComponent[dof % 3]) + " of node " + std::to_string(dof / 3);
}

void FrameSystem::fail(const std::string& what) const { dmi::fail(what); }

void FrameSystem::validate() const {
  validate_frame_model(model_, [this](const std::string& w) { fail(w); });
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
    fibres_.beams.emplace_back();
    if (el.steel.fy > 0) {
      fibres_.beams.back().emplace(el.section, el.s0, el.s1, c.L0, with_modulus(el.steel, el.E), el.integration_points);
      fibres_.any = true;
    }
    const BeamElement& be = elements_.back();
    const Mat6 Ke = transform_->tangent(transform_->state(c, Vec6::Zero()), be.stiffness(), Vec3::Zero());
    scatter_element<3>(tk, el.i, el.j, Ke);
    const Mat6 R = global_to_local(c.e1);
    const Mat6 Me = model_.mass == MassMatrix::lumped ? Mat6(be.lumped_mass().asDiagonal())
                                                      : Mat6(R.transpose() * be.consistent_mass() * R);
    scatter_element<3>(tm, el.i, el.j, Me);
    // Irons (1970): the largest eigenvalue of an assembly is at most the largest of its elements'.
    Eigen::GeneralizedSelfAdjointEigenSolver<Mat6> es(Ke, Me, Eigen::EigenvaluesOnly);
    element_bound_ = std::max(element_bound_, es.eigenvalues().maxCoeff());
  }
  assemble_supports_and_masses(n, 2, model_.supports, model_.masses, tk, tm);
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
    const Vec6 fe = s.B.transpose() * basic_forces(e, s.v);
    out.segment<3>(3 * model_.elements[e].i) += fe.head<3>();
    out.segment<3>(3 * model_.elements[e].j) += fe.tail<3>();
  }
}

SpMat FrameSystem::tangent(const Eigen::VectorXd& d) const {
  if (linear()) return K0_;
  Triplets t;
  for (int e = 0; e < nelements(); ++e) {
    const ChordState s = transform_->state(chords_[e], element_dofs(e, d));
    Mat3 k;
    const Vec3 q = basic_forces(e, s.v, &k);
    scatter_element<3>(t, model_.elements[e].i, model_.elements[e].j, transform_->tangent(s, k, q));
  }
  for (int i = 0; i < ndof(); ++i)
    if (springs_(i) > 0) t.emplace_back(i, i, springs_(i));
  return from_triplets(ndof(), t);
}

Vec3 FrameSystem::basic_forces(int e, const Vec3& v, Mat3* k) const {
  if (!fibres_.beams[e]) {
    if (k) *k = elements_[e].stiffness();
    return elements_[e].forces(v);
  }
  Vec3 q;
  fibres_.beams[e]->respond(v, q, k);
  return q;
}

void FrameSystem::commit(const Eigen::VectorXd& d) {
  if (!fibres_.any) return;
  for (int e = 0; e < nelements(); ++e)
    if (fibres_.beams[e]) fibres_.beams[e]->commit(transform_->state(chords_[e], element_dofs(e, d)).v);
}

Vec2 FrameSystem::axis(int e, const Eigen::VectorXd& d) const {
  const Chord& c = chords_[e];
  if (model_.transform == FrameTransform::linear) return c.e1;
  const Vec6 de = element_dofs(e, d);
  return (c.L0 * c.e1 + de.segment<2>(3) - de.head<2>()).normalized();
}

ElementLoad FrameSystem::element_load(int e, const Vec2& w_local, const Eigen::VectorXd& d) const {
  const Vec2 e1 = axis(e, d), g = model_.gravity;
  ElementLoad p = elements_[e].self_weight(Vec2(g.dot(e1), e1.x() * g.y() - e1.y() * g.x()));
  p.a += w_local;
  p.b += w_local;
  if (!model_.permanent.empty()) {
    const auto local = [&](const Vec2& q) { return Vec2(q.dot(e1), e1.x() * q.y() - e1.y() * q.x()); };
    p.a += local(model_.permanent[e][0]);
    p.b += local(model_.permanent[e][1]);
  }
  return p;
}

void FrameSystem::add_element_loads(const std::vector<Vec2>& w, const Eigen::VectorXd& d, Eigen::VectorXd& f) const {
  const bool gravity = model_.gravity.squaredNorm() > 0;
  for (int e = 0; e < nelements(); ++e) {
    if (!gravity && w[e].squaredNorm() == 0 && model_.permanent.empty()) continue;
    const ElementLoad p = element_load(e, w[e], d);
    const Vec6 fg = global_to_local(axis(e, d)).transpose() * elements_[e].equivalent_loads(p);
    f.segment<3>(3 * model_.elements[e].i) += fg.head<3>();
    f.segment<3>(3 * model_.elements[e].j) += fg.tail<3>();
  }
}

}  // namespace dmi
