// The low-level scene the MPM solver advances: particles, bodies, materials, grid, boundaries
// and numerical options. Built from a Scenario by engine/sim/build_scene.
#pragma once
#include <array>
#include <limits>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "engine/materials/material.hpp"
#include "engine/mpm/grid.hpp"
#include "engine/mpm/inflow.hpp"
#include "engine/mpm/sensor.hpp"
#include "engine/common/particles.hpp"
#include "engine/mpm/touch.hpp"
#include "core/options.hpp"
#include "engine/structure/frame.hpp"
#include "engine/structure/space_frame.hpp"

namespace dmi {

struct Body {
  std::string name;
  int material = 0;     // index into Scene::materials
  int field = 0;        // velocity field (multi-field contact) this body scatters to
  Index begin = 0, end = 0;  // particle range
  bool rigid = false;   // moves as a rigid body (engine/mpm/rigid.hpp): no stress, no wave-speed step limit
  // An elastic body that moves rigidly while nothing is near it (Solver::switch_free_bodies): rigid is then its state
  // of the moment.
  bool rigid_when_free = false;
  // A rigid body's shape for its contact with plane walls, in its initial configuration: the convex hull of these
  // points (D coordinates each) swept by a ball of hull_radius (a ball: its centre and radius; a box or polygon:
  // its corners and 0).
  std::vector<double> hull_points;
  double hull_radius = 0.0;
};

// Rigid, fixed wall: a half-space behind a plane (normal n points into the free side) or a box.
// Nodes on or behind it are constrained; force is what the material exerts on the wall (N).
template <int D> struct Wall {
  std::string name;
  bool box = false;
  Vec<D> point = Vec<D>::Zero(), normal = Vec<D>::Zero(), lo = Vec<D>::Zero(), hi = Vec<D>::Zero();
  WallCondition condition = WallCondition::slip;
  double friction = 0.0;
  // For a plane on a grid line with an axis normal: that axis and the line's node index, else -1.
  // Bilateral walls (stick, roller) then mirror the velocity of free nodes onto the nodes behind the
  // wall, so the interpolated velocity vanishes on the plane itself and not a fraction of a cell
  // inside it (wide stencils: GIMP, B-splines). Keeps second-order convergence at fixed ends.
  int mirror_axis = -1;
  int mirror_index = 0;
  // Force on the wall found before the grid update (the implicit viscosity's mirrored pairs, engine/mpm/viscous.hpp):
  // the step's recorded force starts from it.
  Vec<D> carried = Vec<D>::Zero();
  // Unilateral walls (slip, friction) with surface detection hold only the nodes engaged by particles touching
  // the wall (engine/mpm/touch.hpp; wall_touch in boundary.hpp fills touch each step). Node detection: every node
  // on or behind the wall that has mass.
  bool surface_detection = true;
  TouchSet touch;
  Vec<D> force = Vec<D>::Zero();  // of the last step
  std::vector<PressurePatch<D>> sensors;  // pressure sensors on its surface: their forces of the last step
};

// Grid nodes inside [lo, hi] move with the prescribed velocity during [start, end).
template <int D> struct VelocityRegion {
  std::string name;
  Vec<D> lo, hi, velocity;
  double start = 0.0, end = std::numeric_limits<double>::infinity();
  Vec<D> force = Vec<D>::Zero();  // force the material exerts on the region (N), last step
};

struct SolverOptions {
  ShapeKind shape = ShapeKind::bspline2;
  TransferKind transfer = TransferKind::flip;
  double flip_blend = 1.0;
  StressUpdate update = StressUpdate::usl;
  double cfl = 0.5;
  bool implicit_damping = true;  // Kelvin-Voigt viscosity on the grid, backward Euler (engine/mpm/viscous.hpp)
  double dt_max = 0.0;          // 0: no user bound
  double free_dt_max = 0.0;     // the largest step while a rigid_when_free body moves rigidly (the history interval); 0: none
  double contact_friction = 0.0;
  BodyDetection contact_detection = BodyDetection::surface;
  double cell_volume = 0.0;     // h^D, times the thickness in 2D (m^3)
};

// How beam-column members act on the grid (engine/mpm/member_contact.hpp).
struct MemberCoupling {
  MemberContactMode mode = MemberContactMode::separable;
  double friction = 0.0;
  DecayKind decay = DecayKind::sharp;
  double decay_scale = 1.0;
  DistanceKind distance = DistanceKind::node;
  DetectionKind detection = DetectionKind::surface;
  std::vector<int> fields;         // velocity fields the members act on
  std::vector<int> bonded_fields;  // of those, the fields held by stick whatever the mode
};

// The beam-column frame a D-dimensional scene couples to: the plane frame in 2D, the space frame in 3D.
template <int D> using FrameOf = std::conditional_t<D == 2, Frame, SpaceFrame>;

template <int D> struct Scene {
  Particles<D> particles;
  std::vector<Body> bodies;
  std::vector<std::unique_ptr<Material<D>>> materials;
  std::unique_ptr<Grid<D>> grid;
  std::vector<Wall<D>> walls;
  std::vector<VelocityRegion<D>> regions;
  std::vector<Inflow<D>> inflows;  // at most one, feeding the last body
  Vec<D> gravity = Vec<D>::Zero();
  SolverOptions options;
  std::unique_ptr<FrameOf<D>> frame;  // beam-column members, or none
  MemberCoupling coupling;
  // Scratch of body_contact's surface detection (boundary.cpp), per node, reused every step: the pair of fields
  // with most volume (-1: no pair), three candidate axes from the first towards the second, and each field's front
  // along each axis.
  std::vector<std::array<int, 2>> body_pair;
  std::vector<std::array<Vec<D>, 3>> body_axes;
  std::vector<std::array<double, 6>> body_front;
};

}  // namespace dmi
