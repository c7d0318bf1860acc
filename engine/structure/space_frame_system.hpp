// The assembled operators of a SpaceFrame (internal to engine/structure; the shared part in assembled_system.hpp):
// space elements (space_element.hpp), their coordinate transformation (space_transform.hpp), supports, nodal masses.
// 6 DOFs per node [ux, uy, uz, rx, ry, rz]. The consistent mass is formed once in the initial axes; the lumped one
// is diagonal in each element's local axes, so a node's rotational block is a full 3 x 3 in global axes.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/structure/assembled_system.hpp"
#include "engine/structure/fibre_beam.hpp"
#include "engine/structure/space_element.hpp"
#include "engine/structure/space_transform.hpp"

namespace dmi {

class SpaceFrameSystem final : public AssembledSystem {
 public:
  explicit SpaceFrameSystem(SpaceFrameModel model);

  const SpaceFrameModel& model() const { return model_; }
  int nelements() const { return static_cast<int>(elements_.size()); }
  // Linear: the linear transformation and elastic elements only (K0 is then the stiffness at every state).
  bool linear() const override { return model_.transform == FrameTransform::linear && !fibres_.any; }
  bool plastic() const { return fibres_.any; }
  const SpaceBeamElement& element(int e) const { return elements_[e]; }
  const SpaceChord& chord(int e) const { return chords_[e]; }
  const SpaceTransform& transform() const { return *transform_; }
  Vec12 element_dofs(int e, const Eigen::VectorXd& d) const;
  SpaceChordState element_state(int e, const Eigen::VectorXd& d) const { return transform_->state(chords_[e], element_dofs(e, d)); }
  // Basic forces of element e at deformations v: kb v, or a plastic element's from its fibres; k: dq/dv.
  Vec6 basic_forces(int e, const Vec6& v, Mat6* k = nullptr) const;
  const FibreBeam<2>* fibre_beam(int e) const { return fibres_.at(e); }
  // The plastic elements (plastic work, records, checkpoints; empty slots for an elastic frame).
  FibreBeams<2>& fibres() { return fibres_; }
  const FibreBeams<2>& fibres() const { return fibres_; }
  void commit(const Eigen::VectorXd& d) override;
  void keep_committed() override { fibres_.keep(); }
  void restore_committed() override { fibres_.restore(); }

  void internal_force(const Eigen::VectorXd& d, Eigen::VectorXd& out) const override;
  SpMat tangent(const Eigen::VectorXd& d) const override;

  // Element load intensity (local axes at d): uniform w_local plus the self-weight of the model's gravity.
  SpaceElementLoad element_load(int e, const Vec3& w_local, const Eigen::VectorXd& d) const;
  // f += equivalent nodal loads of all element loads (w per element, self-weight) in the axes at d.
  void add_element_loads(const std::vector<Vec3>& w, const Eigen::VectorXd& d, Eigen::VectorXd& f) const;

 private:
  std::string dof_name(int dof) const override;
  [[noreturn]] void fail(const std::string& what) const override;
  void validate() const;
  void assemble();

  SpaceFrameModel model_;
  std::vector<SpaceBeamElement> elements_;
  FibreBeams<2> fibres_;  // the plastic elements' basic systems
  std::vector<SpaceChord> chords_;
  std::unique_ptr<SpaceTransform> transform_;
};

}  // namespace dmi
