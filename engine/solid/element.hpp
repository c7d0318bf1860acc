// Isoparametric quad4 (bilinear) and hex8 (trilinear) continuum elements, isotropic linear elasticity.
//   Shape functions (tensor product, corner signs s_a of mesh.hpp): N_a(xi) = prod_d (1 + s_ad xi_d) / 2^dim.
//   Strain (Voigt, engineering shear): 3D [exx, eyy, ezz, gyz, gxz, gxy]; 2D (x-z plane) [exx, ezz, gxz].
//   sigma = D B u_e; K_e = sum_g B^T D B det J w_g (x thickness in 2D), full 2^dim Gauss (2 points per
//   direction, +-1/sqrt 3, w = 1); consistent mass M_e = sum_g rho N^T N det J w_g (x thickness in 2D).
//   Units: Pa, m, kg/m^3. Hughes, The Finite Element Method (2000), sections 3.5-3.8.
//   Note: full integration locks in bending (parasitic shear); refine through the depth.
#pragma once
#include <Eigen/Dense>

namespace dmi::solid {

// Plane strain: eyy = 0; plane stress: syy = 0. Solid3d requires a hex8 mesh; the others quad4.
enum class Analysis { solid3d, plane_strain, plane_stress };

struct Elastic {
  double E_Pa = NAN;
  double nu = NAN;
  Analysis analysis = Analysis::solid3d;
  double thickness_m = 1.0;  // out-of-plane thickness, 2D only
  double density_kg_m3 = 0;  // mass matrix only
  int dim() const { return analysis == Analysis::solid3d ? 3 : 2; }
  void validate() const;     // E > 0, -1 < nu < 0.5, thickness > 0, density >= 0; throws
};

// Full stress tensor in 3D Voigt order [sxx, syy, szz, syz, sxz, sxy], Pa; 2D sections fill syy
// (nu (sxx + szz) in plane strain, 0 in plane stress) and leave syz = sxy = 0.
using Stress6 = Eigen::Matrix<double, 6, 1>;

// Corner signs s_a (n_corners x dim).
const Eigen::MatrixXd& corner_signs(int dim);
// N (2^dim) and dN/dxi (2^dim x dim) at natural coordinates xi.
void shape_functions(int dim, const Eigen::VectorXd& xi, Eigen::VectorXd& N, Eigen::MatrixXd& dN);
// Gauss points of the 2^dim rule in corner order: xi_g = s_g / sqrt 3 (rows), all weights 1.
Eigen::MatrixXd gauss_points(int dim);
// Elasticity matrix D (6x6 in 3D, 3x3 in 2D).
Eigen::MatrixXd elasticity_matrix(const Elastic& mat);
// B (n_strain x dim*nen) at xi for corner coordinates X (nen x dim); det J returned through detJ.
Eigen::MatrixXd strain_displacement(const Eigen::MatrixXd& X, const Eigen::VectorXd& xi, double* detJ);
Eigen::MatrixXd element_stiffness(const Eigen::MatrixXd& X, const Elastic& mat);
Eigen::MatrixXd element_mass(const Eigen::MatrixXd& X, const Elastic& mat);
// Stress at xi from element displacements ue (dim*nen, node-major).
Stress6 element_stress(const Eigen::MatrixXd& X, const Eigen::VectorXd& ue, const Eigen::VectorXd& xi,
                       const Elastic& mat);

}  // namespace dmi::solid
