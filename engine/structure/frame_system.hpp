// The assembled operators of a Frame (internal to engine/structure): elements (basic system), their
// coordinate transformation, supports, the mass matrix M (lumped HRZ or consistent, plus nodal masses),
// the initial (linear) stiffness K0 with support springs, and Rayleigh damping C = alpha M + beta K0
// (initial stiffness also under the corotational transformation). The consistent mass is formed once in the
// initial axes (exact for the linear transformation; the usual constant-mass approximation for the
// corotational one); the HRZ lumped mass is isotropic per node, hence exact under any rotation.
// Vectors are full size, 3 DOFs per node [ux, uy, rz]; restrained DOFs are masked: free() is 1 on free and
// 0 on restrained DOFs, solves use constrained() matrices (identity on restrained rows/columns), so a
// restrained DOF keeps a zero displacement, velocity and acceleration. The unmasked rows of mass() and
// stiffness() give the support reactions.
#pragma once
#include <Eigen/Sparse>
#include <memory>
#include <vector>

#include "engine/structure/element.hpp"
#include "engine/structure/transform.hpp"

namespace dmi {

using SpMat = Eigen::SparseMatrix<double>;

class FrameSystem {
 public:
  // Validates the model (std::invalid_argument naming the element, node or support) and assembles.
  explicit FrameSystem(FrameModel model);

  const FrameModel& model() const { return model_; }
  int ndof() const { return static_cast<int>(free_.size()); }
  int nelements() const { return static_cast<int>(elements_.size()); }
  bool linear() const { return model_.transform == FrameTransform::linear; }
  const BeamElement& element(int e) const { return elements_[e]; }
  const Chord& chord(int e) const { return chords_[e]; }
  const CoordTransform& transform() const { return *transform_; }
  Vec6 element_dofs(int e, const Eigen::VectorXd& d) const;
  Vec2 axis(int e, const Eigen::VectorXd& d) const;  // e1 of the element's load and result axes at d

  const Eigen::VectorXd& free() const { return free_; }
  const Eigen::VectorXd& springs() const { return springs_; }  // support springs on free DOFs
  const SpMat& mass() const { return M_; }
  const SpMat& stiffness() const { return K0_; }
  // A copy of A with restrained rows and columns zeroed and the identity on their diagonal.
  SpMat constrained(const SpMat& A) const;

  // Internal force at d: K0 d (linear) or sum_e B^T q + springs (corotational), restrained rows included.
  void internal_force(const Eigen::VectorXd& d, Eigen::VectorXd& out) const;
  // Tangent stiffness at d (K0 for the linear transformation), unconstrained.
  SpMat tangent(const Eigen::VectorXd& d) const;
  // out = C v = alpha M v + beta K0 v.
  void damping_force(const Eigen::VectorXd& v, Eigen::VectorXd& out) const;
  bool damped() const { return model_.rayleigh_mass > 0 || model_.rayleigh_stiffness > 0; }
  // a = M^-1 r on the free DOFs (0 on restrained ones); lumped: diagonal, consistent: factorised once.
  // r is masked in place (restrained entries zeroed).
  void solve_mass(Eigen::VectorXd& r, Eigen::VectorXd& a) const;

  // Element load intensity (local, current axes at d): uniform w_local plus self-weight of model gravity.
  ElementLoad element_load(int e, const Vec2& w_local, const Eigen::VectorXd& d) const;
  // f += equivalent nodal loads of all element loads (w per element, self-weight) in the axes at d.
  void add_element_loads(const std::vector<Vec2>& w, const Eigen::VectorXd& d, Eigen::VectorXd& f) const;

  // Generalised eigenvalues omega^2 of (K0, M) on the free DOFs, ascending (dense: small frames only).
  Eigen::VectorXd eigenvalues() const;
  // omega_max^2: exact up to kDenseEigenMax free DOFs, else the element (Irons) bound plus springs.
  double max_eigenvalue() const;
  static constexpr int kDenseEigenMax = 600;

 private:
  void validate() const;
  void assemble();
  void check_mechanism() const;
  void factorise_mass();

  FrameModel model_;
  std::vector<BeamElement> elements_;
  std::vector<Chord> chords_;
  std::unique_ptr<CoordTransform> transform_;
  Eigen::VectorXd free_, springs_, inv_lumped_;
  SpMat M_, K0_;
  double element_bound_ = 0;  // max over elements of lambda_max(K_e, M_e), plus the springs' share
  Eigen::SimplicialLDLT<SpMat> mass_solver_;  // consistent mass only
};

}  // namespace dmi
