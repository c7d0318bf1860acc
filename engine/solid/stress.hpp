// Stress recovery and stress measures.
//   Gauss points: sigma = D B u_e at the 2^dim points of the stiffness rule (corner order, xi = s / sqrt 3).
//   Centroids: at xi = 0. Nodes: Gauss values extrapolated to the corners with the bilinear/trilinear field
//   through the Gauss points, sigma_a = sum_g N_g(sqrt 3 s_a) sigma_g, then averaged over the elements
//   sharing the node (Hinton & Campbell 1974; Cook et al., Concepts and Applications of FEA, section 6.14).
//   Measures: von Mises sqrt(((s1-s2)^2 + (s2-s3)^2 + (s3-s1)^2) / 2), principal s1 >= s2 >= s3,
//   max shear (s1 - s3) / 2, components; tension positive, Pa.
#pragma once
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "engine/solid/element.hpp"
#include "engine/solid/mesh.hpp"

namespace dmi::solid {

enum class Measure { von_mises, max_principal, min_principal, max_shear, sxx, syy, szz, syz, sxz, sxy };
const char* to_string(Measure m);
double measure(const Stress6& s, Measure m);
// Principal stresses, descending.
Eigen::Vector3d principal_stresses(const Stress6& s);

enum class Location { gauss, centroid, node };
const char* to_string(Location l);

struct StressField {
  std::vector<Stress6> gauss;     // n_elements * 2^dim, element-major, corner order
  std::vector<Stress6> centroid;  // n_elements
  std::vector<Stress6> nodal;     // n_nodes (averaged; zero at nodes of no element)
  const std::vector<Stress6>& at(Location l) const;
};

StressField recover_stress(const Mesh& m, const Elastic& mat, const Eigen::VectorXd& u);

// The point index and coordinates (dim) of a stress point of a recovered field.
Eigen::VectorXd point_coordinates(const Mesh& m, Location l, int index);

struct Peak {
  double value = NAN;  // max |measure| (von Mises, shear, components, min principal), max s1 for max_principal
  int index = -1;      // into StressField::at(location)
};
Peak peak(const StressField& s, Measure m, Location l);
// The peaks of several measures at one location in one pass (principal stresses once per point).
std::vector<Peak> peaks(const StressField& s, const std::vector<Measure>& ms, Location l);

}  // namespace dmi::solid
