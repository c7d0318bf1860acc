// The dry run's estimate of a run's step count and its wall time on one core (docs/performance.md, "Before a run"),
// from the scene at t = 0. A first guess calibrated on the bundled examples, not a bound.
#pragma once
#include "engine/mpm/solver.hpp"
#include "engine/scenario/config.hpp"
#include "engine/sim/run.hpp"

namespace dmi {

// Steps: end_time over the first step, except for a body that is rigid while nothing is near it (rigid_when_free), which
// bounds the step by its waves only while it is within three cells of something: for 6 h / |v| (its approach and
// departure), the rest of the run at the step the other bodies allow (the history interval when they are rigid).
// Cost per step: each body's particles times a cost per particle-step by dimension and material (fluid, granular,
// elastic; half for a rigid body, four times for a Kelvin-Voigt damped solid, whose viscosity takes sub-steps), each
// member element at 0.5 us in a linear frame (one factorisation) and, in a corotational or plastic one, 5 us (2D) or
// 12 us (3D), six times that for an elasto-plastic element; and 5 us.
// dt0: the solver's first stable step.
template <int D> RunEstimate estimate_run(const Solver<D>& solver, const Scenario& s, double dt0, double particles_at_end);

}  // namespace dmi
