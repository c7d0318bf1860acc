// Nodal load vectors for the structured tapered block (SEEDS.md B.3).
//   Point load: a force vector added to one node.
//   Patch load on an x-face (upstream i = 0, downstream i = nx) of a hex8 block: traction t(y, z) = q(y, z) d
//   over the patch |y - y_c| <= w/2, |z - z_c| <= h/2 (z of the point on the face, so a sloped face is
//   loaded over its vertical projection), d a fixed unit direction (default +x, i.e. horizontal, from upstream):
//     uniform: q = p0;   pyramid: q = p0 (1 - max(|y - y_c| / (w/2), |z - z_c| / (h/2)))   (paper B: decreasing
//     linearly from the impact point to the patch edges and corners), nominal p0 = F / A and 3 F / A.
//   q is a force per unit area of the face's projection on the y-z plane (a sloped face carries the same
//   load pattern as its vertical projection). Consistent nodal forces
//   f_a = sum over face quads and n x n Gauss points of N_a q d |(x_,s x x_,t) . e_x| w_g;
//   then f is scaled by F / (sum_a f_a . d) so the resultant equals F exactly. The scale factor (the quadrature
//   error of a kinked / cut-off profile) is reported.
#pragma once
#include <Eigen/Dense>

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
PatchLoadReport add_patch_load(const Mesh& m, const PatchLoad& p, Eigen::VectorXd& f);

}  // namespace dmi::solid
