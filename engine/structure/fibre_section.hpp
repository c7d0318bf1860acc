// Fibre discretisation of a member's cross-section (Spacone, Filippou & Taucer 1996, sec. 2): the section as fibres
// of area A_k at section coordinates (y'_k, z'_k), each with its own uniaxial law. Plane strain distribution (Navier):
// eps(y', z') = eps_0 - kappa_1 y' - kappa_2 z', section forces N = sum sigma_k A_k, M_1 = -sum sigma_k A_k y'_k,
// M_2 = -sum sigma_k A_k z'_k (M_1 + compresses the +y' fibre, the frame's convention, fibre.hpp).
// Each fibre stands for a cell of the section and sits at the root mean square of the cell's coordinate, so the
// fibres carry the section's area and second moments exactly (rectangle cells: y'^2 = y_c^2 + dy^2 / 12; pipe rings:
// r^2 = (r_a^2 + r_b^2) / 2); the plastic modulus is then within O(1/n^2) of the exact one.
#pragma once
#include <vector>

#include "engine/structure/section.hpp"

namespace dmi {

struct Fibre {
  double c[2] = {0, 0};  // y', z' (m)
  double area = 0;       // m^2
};

// The fibres of the section at the fraction s of its taper. Rectangles: layers across the depth (plane) or a grid
// (space); pipes: rings of fibres around the wall (both).
std::vector<Fibre> fibre_layout(const Section& section, double s, bool space);

}  // namespace dmi
