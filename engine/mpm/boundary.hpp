// Grid boundary conditions on a nodal velocity array (all fields), and multi-velocity-field
// contact between bodies.
#pragma once
#include "engine/mpm/scene.hpp"

namespace dmi {

// Walls and prescribed-velocity regions on vel (v^L, or the MUSL remapped velocity).
// When record is true, the force on every wall/region (N) is stored and the work done by the
// boundaries on the material during this step, sum m_i (v_after - v_before) . v_after, returned (J).
//   stick:    v = 0
//   roller:   v.n = 0 (bilateral, frictionless)
//   slip:     if v.n < 0: v -= (v.n) n                      (unilateral, frictionless)
//   friction: as slip, then |v_t| reduced by mu |v.n|, to 0 at most (Coulomb)
template <int D> double apply_boundaries(Scene<D>& s, std::vector<Vec<D>>& vel, double dt, double time, bool record);

// Bardenhagen, Brackbill & Sulsky (2000): at nodes where several fields have mass, a field moving
// towards the others, (v_b - v_cm) . n_b > 0, loses that normal relative velocity; its tangential
// relative velocity is reduced by mu times the normal correction (Coulomb) or removed (stick).
// n_b is the outward normal of body b from g_b = sum_p m_p grad N_i(x_p) (which points from the body's
// particles towards the node, i.e. outwards): n_b = g_b - sum_{c!=b} g_c, normalised,
// which makes two-body corrections equal and opposite (momentum conserved to round-off).
template <int D> void body_contact(Scene<D>& s, std::vector<Vec<D>>& vel);

}  // namespace dmi
