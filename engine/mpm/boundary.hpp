// Grid boundary conditions on a nodal velocity array (all fields), and multi-velocity-field
// contact between bodies.
#pragma once
#include "engine/mpm/scene.hpp"

namespace dmi {

// Surface contact detection of unilateral walls (slip, friction) from the particle positions at the step's start
// (engine/mpm/touch.hpp): a particle touches a wall when its domain reaches it and engages its tributary nodes
// (Wall::touch); apply_boundaries then holds only engaged nodes.
template <int D> void wall_touch(Scene<D>& s);

// Walls, prescribed-velocity regions and inflows' driven zones on vel (v^L, or the MUSL remapped velocity).
// When record is true, the force on every wall/region (N) is stored and the work done by the
// boundaries on the material during this step, sum m_i (v_after - v_before) . v_after, returned (J).
//   stick:    v = 0
//   roller:   v.n = 0 (bilateral, frictionless)
//   slip:     if v.n < 0: v -= (v.n) n                      (unilateral, frictionless)
//   friction: as slip, then |v_t| reduced by mu |v.n|, to 0 at most (Coulomb)
// reset = false adds to the forces of an earlier call in the same step (the rigid bodies' constraint iterations).
// nodes: only these nodes (all fields), instead of the grid's active nodes.
template <int D>
double apply_boundaries(Scene<D>& s, std::vector<Vec<D>>& vel, double dt, double time, bool record, bool reset = true,
                        const std::vector<Index>* nodes = nullptr);

// A bilateral plane wall on a grid line (Wall::mirror_axis) gives a node behind it the velocity of its image in front,
// S v_image, S = -I (stick: the velocity is odd about the plane) or I - 2 n n^T (roller: its normal part is). False
// when node id is not behind such a wall or its image is off the grid; apply_boundaries uses it where the image has mass.
template <int D> bool wall_mirror(const Grid<D>& g, const Wall<D>& w, Index id, Index& image, Mat<D>& S);

// Particles (of deformable bodies) whose centre has passed a plane wall are put back on its plane: positions only,
// so momentum, energy and the deformation gradient are untouched. The walls act on nodes; where material presses
// into a corner, the velocity interpolated to the particles next to it kept a part into the wall and they crept
// behind it (0.55 h in a water tank at rest; 7.5 cells at the foot of a wall under a steady stream, until one left
// the grid). Rigid bodies move as a whole and meet walls at their hull (RigidBodies::wall_contact). Particles
// [i0, i1): G2P calls it chunk by chunk, on positions still in cache.
template <int D> void keep_in_front_of_walls(Scene<D>& s, Index i0, Index i1);

// Bardenhagen, Brackbill & Sulsky (2000): at nodes where several fields have mass, a field moving
// towards the others, (v_b - v_cm) . n_b > 0, loses that normal relative velocity; its tangential
// relative velocity is reduced by mu times the normal correction (Coulomb) or removed (stick); two-body
// corrections are equal and opposite (momentum to round-off). Where bodies touch:
// - surface detection (default; body_fronts in boundary.cpp): the two fields with most volume at the node touch
//   when their surfaces, located from the particles' reach in the node's column, meet along the axis of least
//   overlap (separating-axis rule). Overlapping supports alone are not contact, so a curved body meets another on
//   its contact patch, as on a wall; a third field at the node is not corrected.
// - volume detection: the bodies' particle volumes fill the node's support (>= 99 % of a cell), normal
//   n_b = (g_b - sum_{c!=b} g_c) normalised, g_b = sum_p m_p grad N_i(x_p) (outwards). Without the fill test a
//   block on a frictionless slab was braked to rest after 18 mm; with it the block slides at 0.99 g sin(theta).
//   On curved bodies the fill lags the touch and the contact is soft (docs/verification.md).
// fronts = false reuses the surface detection of an earlier call in the same step (the particles have not moved).
// nodes: only these nodes, instead of the grid's active nodes (with fronts = false).
// skip (surface detection): per field, 1 where its pairs with unflagged fields are corrected elsewhere
// (RigidBodies::body_contact: the rigid body's whole mass against the node's).
template <int D>
void body_contact(Scene<D>& s, std::vector<Vec<D>>& vel, bool fronts = true, const std::vector<Index>* nodes = nullptr,
                  const std::vector<char>* skip = nullptr);
// Surface detection at a node whose pair is set (Scene::body_pair, after body_contact's detection): false when the two
// fields do not touch, else their normal n from pair[0] towards pair[1] (the axis of least overlap).
template <int D> bool pair_normal(const Scene<D>& s, Index id, double tol, Vec<D>& n);
// Whether both fields' masses at a node count for contact (neither below 1e-6 of their sum).
bool pair_masses_count(double ma, double mb);

}  // namespace dmi
