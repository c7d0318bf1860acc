// Whether a body is clear of everything it could touch within the next step: the test that lets an elastic body move
// rigidly while it is free (Body::rigid_when_free, Solver::switch_free_bodies).
#pragma once
#include <algorithm>
#include <array>
#include <vector>

#include "engine/mpm/scene.hpp"

namespace dmi {

// Distances (m) a body's particles must keep, box to box, from what it could meet. Particles reach nodes 1.5 h away
// (quadratic B-splines, GIMP and linear hats reach less), so two bodies share a node below 3 h; each side moves at most
// cfl h < h per step. Walls act on nodes behind them (on nodes a particle reaches), members on nodes within their
// contact reach ln of their surface.
struct Clearance {
  double bodies = 0, walls = 0, members = 0;
  static Clearance of(double h, double member_reach) { return {4.5 * h, 3.0 * h, 3.0 * h + member_reach}; }
};

// One thing a body could meet: the separation (m) of the body's particle box from it along each axis (negative where
// they overlap; plane walls: the distance along the normal per unit of its 1-norm, in sep[0]), and the distance at
// which the body is clear of it. Nodes are shared per axis: the gap is the largest separation (the max norm).
struct Gap {
  enum Kind { body, wall, region, member };
  std::array<double, 3> sep;
  double clear;
  Kind kind;
  double gap() const { return std::max({sep[0], sep[1], sep[2]}); }
};

// The gaps of body k to every other body (their particle boxes; +inf for an empty one), every wall, every velocity
// region and every member element (its deformed shape's bounding box), in that order, a fixed count for a scene.
// Empty (and false) when body k has no particles.
template <int D> bool body_gaps(const Scene<D>& s, int k, const Clearance& c, std::vector<Gap>& out);

// True when body k's particles lie, in a box sense, at least c.bodies from every other body's, c.walls in front of every
// wall, c.walls from every velocity region and c.members from every member element.
template <int D> bool body_is_clear(const Scene<D>& s, int k, const Clearance& c);

}  // namespace dmi
