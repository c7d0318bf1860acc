#include "engine/structure/space_frame_system.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <stdexcept>

#include "engine/structure/frame_validate.hpp"

namespace dmi {

SpaceFrameSystem::SpaceFrameSystem(SpaceFrameModel model) : AssembledSystem(6), model_(std::move(model)) {
  validate();
  assemble();
  finish(model_.mass == MassMatrix::lumped, model_.rayleigh_mass, model_.rayleigh_stiffness, model_.modal_damping);
}

std::string SpaceFrameSystem::dof_name(int dof) const {
  static constexpr const char* kComponent[6] = {"ux", "uy", "uz", "rx", "ry", "rz"};
  return std::string(kComponent[dof % 6]) + " of node " + std::to_string(dof / 6);
}

void SpaceFrameSystem::fail(const std::string& what) const { throw std::invalid_argument("SpaceFrame: " + what); }

void SpaceFrameSystem::validate() const {
  validate_frame_model(model_, [this](const std::string& w) { fail(w); });
  for (std::size_t e = 0; e < model_.elements.size(); ++e) {
    const SpaceElementDef& el = model_.elements[e];
    for (double s : {el.s0, el.s1})
      if (!(el.section.inertia_y(s) > 0 && el.section.torsion_constant(s) > 0))
        fail("element " + std::to_string(e) + ": section dimensions must be positive");
    if (!el.orientation.allFinite()) fail("element " + std::to_string(e) + ": non-finite orientation vector");
  }
}

void SpaceFrameSystem::assemble() {
  const int n = 6 * static_cast<int>(model_.nodes.size());
  transform_ = make_space_transform(model_.transform);
  Triplets tk, tm;
  for (std::size_t e = 0; e < model_.elements.size(); ++e) {
    const SpaceElementDef& el = model_.elements[e];
    const Vec3 dx = model_.nodes[el.j] - model_.nodes[el.i];
    SpaceChord c{model_.nodes[el.i], Eigen::Matrix3d::Identity(), dx.norm()};
    if (!local_axes(dx / c.L0, el.orientation, c.R))
      fail("element " + std::to_string(e) + ": the orientation vector is parallel to the element (it must give the section's depth direction)");
    chords_.push_back(c);
    elements_.emplace_back(el, c.L0, model_.theory);
    fibres_.beams.emplace_back();
    if (el.steel.fy > 0) {
      const double torsion = elements_.back().stiffness()(5, 5);
      fibres_.beams.back().emplace(el.section, el.s0, el.s1, c.L0, with_modulus(el.steel, el.E), el.integration_points, torsion);
      fibres_.any = true;
    }
    const SpaceBeamElement& be = elements_.back();
    const Mat12 Ke = transform_->tangent(c, Vec12::Zero(), transform_->state(c, Vec12::Zero()), be.stiffness(), Vec6::Zero());
    scatter_element<6>(tk, el.i, el.j, Ke);
    const Mat12 T = rotation12(c.R);
    const Mat12 Me = T.transpose() * (model_.mass == MassMatrix::lumped ? be.lumped_mass() : be.consistent_mass()) * T;
    scatter_element<6>(tm, el.i, el.j, Me);
    // Irons (1970): the largest eigenvalue of an assembly is at most the largest of its elements'.
    Eigen::GeneralizedSelfAdjointEigenSolver<Mat12> es(Ke, Me, Eigen::EigenvaluesOnly);
    element_bound_ = std::max(element_bound_, es.eigenvalues().maxCoeff());
  }
  assemble_supports_and_masses(n, 3, model_.supports, model_.masses, tk, tm);
}

Vec12 SpaceFrameSystem::element_dofs(int e, const Eigen::VectorXd& d) const {
  const SpaceElementDef& el = model_.elements[e];
  Vec12 de;
  de << d.segment<6>(6 * el.i), d.segment<6>(6 * el.j);
  return de;
}

void SpaceFrameSystem::internal_force(const Eigen::VectorXd& d, Eigen::VectorXd& out) const {
  if (linear()) {
    out.noalias() = K0_ * d;
    return;
  }
  out = springs_.cwiseProduct(d);
  for (int e = 0; e < nelements(); ++e) {
    const SpaceChordState s = element_state(e, d);
    const Vec12 fe = s.B.transpose() * basic_forces(e, s.v);
    out.segment<6>(6 * model_.elements[e].i) += fe.head<6>();
    out.segment<6>(6 * model_.elements[e].j) += fe.tail<6>();
  }
}

SpMat SpaceFrameSystem::tangent(const Eigen::VectorXd& d) const {
  if (linear()) return K0_;
  Triplets t;
  for (int e = 0; e < nelements(); ++e) {
    const Vec12 de = element_dofs(e, d);
    const SpaceChordState s = transform_->state(chords_[e], de);
    Mat6 k;
    const Vec6 q = basic_forces(e, s.v, &k);
    scatter_element<6>(t, model_.elements[e].i, model_.elements[e].j, transform_->tangent(chords_[e], de, s, k, q));
  }
  for (int i = 0; i < ndof(); ++i)
    if (springs_(i) > 0) t.emplace_back(i, i, springs_(i));
  return from_triplets(ndof(), t);
}

Vec6 SpaceFrameSystem::basic_forces(int e, const Vec6& v, Mat6* k) const {
  if (!fibres_.beams[e]) {
    if (k) *k = elements_[e].stiffness();
    return elements_[e].forces(v);
  }
  Vec6 q;
  fibres_.beams[e]->respond(v, q, k);
  return q;
}

void SpaceFrameSystem::commit(const Eigen::VectorXd& d) {
  if (!fibres_.any) return;
  for (int e = 0; e < nelements(); ++e)
    if (fibres_.beams[e]) fibres_.beams[e]->commit(element_state(e, d).v);
}

SpaceElementLoad SpaceFrameSystem::element_load(int e, const Vec3& w_local, const Eigen::VectorXd& d) const {
  const Eigen::Matrix3d R = model_.transform == FrameTransform::linear ? chords_[e].R : element_state(e, d).R;
  SpaceElementLoad p = elements_[e].self_weight(R * model_.gravity);
  p.a += w_local;
  p.b += w_local;
  if (!model_.permanent.empty()) {
    p.a += R * model_.permanent[e][0];
    p.b += R * model_.permanent[e][1];
  }
  return p;
}

void SpaceFrameSystem::add_element_loads(const std::vector<Vec3>& w, const Eigen::VectorXd& d, Eigen::VectorXd& f) const {
  const bool gravity = model_.gravity.squaredNorm() > 0;
  for (int e = 0; e < nelements(); ++e) {
    if (!gravity && w[e].squaredNorm() == 0 && model_.permanent.empty()) continue;
    const Eigen::Matrix3d R = model_.transform == FrameTransform::linear ? chords_[e].R : element_state(e, d).R;
    const Vec12 fg = rotation12(R).transpose() * elements_[e].equivalent_loads(element_load(e, w[e], d));
    f.segment<6>(6 * model_.elements[e].i) += fg.head<6>();
    f.segment<6>(6 * model_.elements[e].j) += fg.tail<6>();
  }
}

}  // namespace dmi
