// Whether a body is clear of everything it could touch within the next step: the test that lets an elastic body move
// rigidly while it is free (Body::rigid_when_free, Solver::switch_free_bodies).
#pragma once
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

// True when body k's particles lie, in a box sense, at least c.bodies from every other body's, c.walls in front of every
// wall, c.walls from every velocity region and c.members from every member element (its deformed shape's bounding box).
template <int D> bool body_is_clear(const Scene<D>& s, int k, const Clearance& c);

}  // namespace dmi
