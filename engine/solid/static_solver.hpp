// Assembly and linear static solution K u = f with fixed (possibly prescribed, non-zero) DOFs.
//   DOF numbering: dof = dim * node + component (component 0 = x, 1 = y in 3D or z in 2D, 2 = z).
//   Partition into free (f) and constrained (c) DOFs: K_ff u_f = f_f - K_fc u_c (SimplicialLDLT on K_ff);
//   reactions r = K u - f on the constrained DOFs (zero on free DOFs). Hughes (2000) section 1.14.
#pragma once
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <vector>

#include "engine/solid/band_cholesky.hpp"

#include "engine/solid/element.hpp"
#include "engine/solid/mesh.hpp"

namespace dmi::solid {

Eigen::SparseMatrix<double> assemble_stiffness(const Mesh& m, const Elastic& mat);
// Consistent mass; requires mat.density_kg_m3 > 0.
Eigen::SparseMatrix<double> assemble_mass(const Mesh& m, const Elastic& mat);

// All DOFs of the given nodes.
std::vector<int> node_dofs(const Mesh& m, const std::vector<int>& nodes);

struct StaticSolution {
  Eigen::VectorXd u;         // displacements, m
  Eigen::VectorXd reaction;  // K u - f on constrained DOFs, zero elsewhere; N
};

class StaticSolver {
 public:
  // Factorises K_ff once; throws if a DOF id is out of range, nothing is fixed or K_ff is singular.
  StaticSolver(const Eigen::SparseMatrix<double>& K, std::vector<int> fixed_dofs);
  // u_prescribed (full length, read on constrained DOFs only); empty means all zero.
  StaticSolution solve(const Eigen::VectorXd& f, const Eigen::VectorXd& u_prescribed = {}) const;
  int n_free() const { return static_cast<int>(free_.size()); }

 private:
  Eigen::SparseMatrix<double> K_, K_fc_;
  std::vector<int> free_, fixed_;
  // K_ff factorised within its band by dense blocks where that is cheap (the structured meshes, numbered layer by
  // layer), else by a sparse LDL^T with AMD ordering.
  bool banded_ = false;
  BandCholesky band_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt_;
};

// Sum of the reactions per component over the given nodes (dim entries), N.
Eigen::VectorXd total_reaction(const Mesh& m, const Eigen::VectorXd& reaction, const std::vector<int>& nodes);

}  // namespace dmi::solid
