// The solid check's field for the pictures: the dam body's mesh (node coordinates, VTK-ordered element corners) and
// per load case the nodal von Mises stress, largest principal stress and displacement, to 6 significant digits.
// results.h5 carries it (/documents/solid_field, docs/results.md).
#pragma once
#include <string>
#include <vector>

namespace dmi {

struct SolidFieldCase {
  std::string name;
  std::vector<double> von_mises_Pa, max_principal_Pa;  // per node
  std::vector<double> displacement_m;                  // per node and direction
};

struct SolidFieldRecord {
  int dim = 3, nodes_per_element = 8;  // hex8 in 3D, quad4 in 2D
  std::string axes;                    // the mesh's axes in words
  std::vector<double> nodes_m;         // node coordinates, dim per node
  std::vector<long> elements;          // nodes_per_element node indices per element
  std::vector<SolidFieldCase> cases;
  std::size_t nodes() const { return dim > 0 ? nodes_m.size() / static_cast<std::size_t>(dim) : 0; }
};

}  // namespace dmi
