// Scenario (config structs) -> the low-level MPM scene: grid, seeded particles, materials, walls.
#pragma once
#include "engine/mpm/scene.hpp"
#include "engine/scenario/config.hpp"

namespace dmi {

// A scenario vector (its first D entries) as the engine's.
template <int D> Vec<D> vec(const DVec& v) {
  Vec<D> r;
  for (int d = 0; d < D; ++d) r[d] = v[static_cast<std::size_t>(d)];
  return r;
}

// Throws InputError (e.g. a body too small to hold a particle).
template <int D> Scene<D> build_scene(const Scenario& s);
// Builds the scene and drops it: the checks only a built scene can make (bodies overlapping each other or a member,
// a body too small for a particle, an unstable frame), for `simulate --dry-run`. Throws InputError.
void check_scene(const Scenario& s);

}  // namespace dmi
