// The assembled operators of a Frame (internal to engine/structure; the shared part in assembled_system.hpp):
// elements (basic system), their coordinate transformation, supports, the mass matrix M (lumped HRZ or consistent,
// plus nodal masses), the initial (linear) stiffness K0 with support springs, and Rayleigh damping
// C = alpha M + beta K0 (initial stiffness also under the corotational transformation). The consistent mass is formed once in the
// initial axes (exact for the linear transformation; the usual constant-mass approximation for the
// corotational one); the HRZ lumped mass is isotropic per node, hence exact under any rotation.
// Vectors are full size, 3 DOFs per node [ux, uy, rz]; restrained DOFs are masked: free() is 1 on free and
// 0 on restrained DOFs, solves use constrained() matrices (identity on restrained rows/columns), so a
// restrained DOF keeps a zero displacement, velocity and acceleration. The unmasked rows of mass() and
// stiffness() give the support reactions.
#pragma once
#include <Eigen/Sparse>
#include <memory>
#include <optional>
#include <vector>

#include "engine/structure/assembled_system.hpp"
#include "engine/structure/element.hpp"
#include "engine/structure/fibre_beam.hpp"
#include "engine/structure/transform.hpp"

namespace dmi {

class FrameSystem final : public AssembledSystem {
 public:
  // Validates the model (std::invalid_argument naming the element, node or support) and assembles.
  explicit FrameSystem(FrameModel model);

  const FrameModel& model() const { return model_; }
  int nelements() const { return static_cast<int>(elements_.size()); }
  // Linear: the linear transformation and elastic elements only (K0 is then the stiffness at every state).
  bool linear() const override { return model_.transform == FrameTransform::linear && !fibres_.any; }
  bool plastic() const { return fibres_.any; }
  const BeamElement& element(int e) const { return elements_[e]; }
  const Chord& chord(int e) const { return chords_[e]; }
  const CoordTransform& transform() const { return *transform_; }
  Vec6 element_dofs(int e, const Eigen::VectorXd& d) const;
  ChordState element_state(int e, const Eigen::VectorXd& d) const { return transform_->state(chords_[e], element_dofs(e, d)); }
  // Basic forces of element e at deformations v: kb v, or a plastic element's from its fibres; k: dq/dv.
  Vec3 basic_forces(int e, const Vec3& v, Mat3* k = nullptr) const;
  const FibreBeam<1>* fibre_beam(int e) const { return fibres_.at(e); }
  // The plastic elements (plastic work, records, checkpoints; empty slots for an elastic frame).
  FibreBeams<1>& fibres() { return fibres_; }
  const FibreBeams<1>& fibres() const { return fibres_; }
  void commit(const Eigen::VectorXd& d) override;
  void keep_committed() override { fibres_.keep(); }
  void restore_committed() override { fibres_.restore(); }
  Vec2 axis(int e, const Eigen::VectorXd& d) const;  // e1 of the element's load and result axes at d

  void internal_force(const Eigen::VectorXd& d, Eigen::VectorXd& out) const override;
  SpMat tangent(const Eigen::VectorXd& d) const override;

  // Element load intensity (local, current axes at d): uniform w_local plus self-weight of model gravity.
  ElementLoad element_load(int e, const Vec2& w_local, const Eigen::VectorXd& d) const;
  // f += equivalent nodal loads of all element loads (w per element, self-weight) in the axes at d.
  void add_element_loads(const std::vector<Vec2>& w, const Eigen::VectorXd& d, Eigen::VectorXd& f) const;

 private:
  std::string dof_name(int dof) const override;
  [[noreturn]] void fail(const std::string& what) const override;
  void validate() const;
  void assemble();

  FrameModel model_;
  std::vector<BeamElement> elements_;
  FibreBeams<1> fibres_;  // the plastic elements' basic systems
  std::vector<Chord> chords_;
  std::unique_ptr<CoordTransform> transform_;
};

}  // namespace dmi
