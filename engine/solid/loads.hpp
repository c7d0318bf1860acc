// Nodal load vectors for the structured tapered block (Lin, Cheng & Tuan, Table 1): point loads, the paper's patch loads
// and a general face traction q(y, z) / pressure profile q(z) (e.g. pressures taken from a simulation).
//   Point load: a force vector added to one node.
//   Patch load on an x-face (upstream i = 0, downstream i = nx) of a hex8 block: traction t(y, z) = q(y, z) d
//   over the patch |y - y_c| <= w/2, |z - z_c| <= h/2 (z of the point on the face, so a sloped face is
//   loaded over its vertical projection), d a fixed unit direction (default +x, i.e. horizontal, from upstream):
//     uniform: q = p0;   pyramid: q = p0 (1 - max(|y - y_c| / (w/2), |z - z_c| / (h/2)))   (Lin, Cheng & Tuan: decreasing
//     linearly from the impact point to the patch edges and corners), nominal p0 = F / A and 3 F / A.
//   q is a force per unit area of the face's projection on the y-z plane (a sloped face carries the same
//   load pattern as its vertical projection). Consistent nodal forces
//   f_a = sum over face quads and n x n Gauss points of N_a q d |(x_,s x x_,t) . e_x| w_g;
//   then f is scaled by F / (sum_a f_a . d) so the resultant equals F exactly. The scale factor (the quadrature
//   error of a kinked / cut-off profile) is reported.
#pragma once
#include <Eigen/Dense>
#include <functional>
#include <vector>

#include "engine/solid/element.hpp"
#include "engine/solid/mesh.hpp"

namespace dmi::solid {

void add_point_load(const Mesh& m, int node, const Eigen::VectorXd& force_N, Eigen::VectorXd& f);

// Structured node on an x-face nearest to (y, z) in 3D (y ignored in 2D).
int nearest_face_node(const Mesh& m, Face face, double y_m, double z_m);

enum class PatchShape { uniform, pyramid };

struct PatchLoad {
  Face face = Face::upstream;
  double centre_y_m = NAN, centre_z_m = NAN;
  double width_m = NAN, height_m = NAN;  // along y and z
  double total_force_N = NAN;
  PatchShape shape = PatchShape::pyramid;
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();  // normalised internally
  int gauss_per_direction = 2;                           // 1..6 per face-quad direction
  void validate() const;
};

struct PatchLoadReport {
  double nominal_peak_pressure_Pa = NAN;  // p0 before scaling
  double integrated_force_N = NAN;        // resultant with p0 before scaling
  double scale = NAN;                     // F / integrated_force_N
  int loaded_nodes = 0;                   // nodes receiving a non-zero force
};

// Adds the patch's nodal forces to f (3D structured hex8 mesh only); throws if the patch misses all Gauss points.
// Implemented with face_load_magnitudes below (no breaks: the pyramid's diagonal kinks are not axis-aligned).
PatchLoadReport add_patch_load(const Mesh& m, const PatchLoad& p, Eigen::VectorXd& f);

// General traction on an x-face (the "load from simulation" use): t(y, z) = q(y, z) d, q in Pa per unit area
// of the face's vertical projection (3D: on the y-z plane; 2D: per unit height times the out-of-plane
// thickness, y = 0 is passed to q). Consistent nodal forces as for the patch:
//   f_a = sum over face quads (3D) / segments (2D), sub-intervals and n (x n) Gauss points of
//         N_a q d |(x_,s x x_,t) . e_x| w_g   (3D),   N_a q d |z_,t| w_g thickness   (2D).
// Each face quad/segment is split at y_breaks / z_breaks (values strictly inside it), so a q that is
// polynomial between breaks (degree <= 2n - 2 in each of y, z) is integrated exactly; z depends on t only
// and y on s only on the structured meshes' faces. In 2D, d = (d_x, d_y, d_z) must have d_y = 0.
using FaceTractionFn = std::function<double(double y_m, double z_m)>;

struct FaceTraction {
  Face face = Face::upstream;
  FaceTractionFn q_Pa;
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();  // normalised internally
  int gauss_per_direction = 2;                           // 1..6
  std::vector<double> y_breaks, z_breaks;                // where q may kink (3D y only), m
  void validate() const;
};

struct FaceLoadReport {
  double resultant_N = 0;  // sum_a f_a . d (2D: including the thickness)
  int loaded_nodes = 0;    // nodes receiving a non-zero force
};

// Sum of N_a q |J| w per node (no direction, no scaling; 2D includes thickness_m). Structured mesh only.
Eigen::VectorXd face_load_magnitudes(const Mesh& m, Face face, const FaceTractionFn& q, int gauss_per_direction,
                                     double thickness_m, const std::vector<double>& y_breaks = {},
                                     const std::vector<double>& z_breaks = {});

// Adds the traction's nodal forces to f; mat gives the dimension check and, in 2D, the thickness.
FaceLoadReport add_face_traction(const Mesh& m, const Elastic& mat, const FaceTraction& t, Eigen::VectorXd& f);

// Piecewise-linear q(z) through (z_m[i], q_Pa[i]) (z_m strictly increasing, >= 2 points), zero outside
// [z_m.front(), z_m.back()], uniform across the width. Integrated exactly (breaks at the samples).
double piecewise_linear(const std::vector<double>& z_m, const std::vector<double>& q_Pa, double z);
FaceLoadReport add_pressure_profile(const Mesh& m, const Elastic& mat, Face face, const std::vector<double>& z_m,
                                    const std::vector<double>& q_Pa, Eigen::VectorXd& f,
                                    const Eigen::Vector3d& direction = Eigen::Vector3d::UnitX());

}  // namespace dmi::solid
