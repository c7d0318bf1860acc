#include "engine/sim/run_estimate.hpp"

#include <algorithm>
#include <cmath>

namespace dmi {
namespace {

// Seconds per particle-step on one core, by material law (measured on the bundled examples: docs/performance.md).
double particle_cost(const MaterialConfig& m, int dim) {
  const bool fluid = m.model == "newtonian" || m.model == "bingham", granular = m.model == "drucker_prager" || m.model == "mu_i";
  if (dim == 2) return fluid ? 100e-9 : granular ? 130e-9 : 80e-9;
  return fluid || granular ? 500e-9 : 350e-9;
}

}  // namespace

template <int D> RunEstimate estimate_run(const Solver<D>& solver, const Scenario& s, double dt0, double particles_at_end) {
  const Scene<D>& sc = solver.scene();
  const double end = s.analysis.end_time;
  // Steps.
  bool free_body = false, others_rigid = true;
  double near = 0;
  for (std::size_t b = 0; b < sc.bodies.size(); ++b) {
    const Body& body = sc.bodies[b];
    if (!body.rigid_when_free) {
      others_rigid = others_rigid && body.rigid;
      continue;
    }
    free_body = true;
    Vec<D> v = Vec<D>::Zero();
    double m = 0;
    for (Index i = body.begin; i < body.end; ++i) v += sc.particles.mass[i] * sc.particles.v[i], m += sc.particles.mass[i];
    const double speed = m > 0 ? (v / m).norm() : 0.0;
    near = std::max(near, speed > 0 ? std::min(end, 6 * sc.grid->h() / speed) : end);
  }
  double steps = end / dt0;
  if (free_body && others_rigid && sc.options.free_dt_max > dt0) steps = near / dt0 + (end - near) / sc.options.free_dt_max;
  // Cost per step.
  double cost = 5e-6, built = 0;
  for (const Body& body : sc.bodies) {
    const MaterialConfig& m = s.materials[static_cast<std::size_t>(body.material)];
    double c = particle_cost(m, D);
    if (body.rigid) c *= 0.5;
    if (!body.rigid && (m.model == "linear_elastic" || m.model == "neo_hookean") && m.damping_ratio > 0) c *= 4;  // Kelvin-Voigt
    cost += c * static_cast<double>(body.end - body.begin);
    built += static_cast<double>(body.end - body.begin);
  }
  if (particles_at_end > built && !sc.bodies.empty())  // an inflow's debris, at the last body's cost
    cost += (particles_at_end - built) * particle_cost(s.materials[static_cast<std::size_t>(sc.bodies.back().material)], D);
  if (const auto* f = sc.frame.get()) {
    // A linear frame solves with one factorisation; a corotational or plastic one assembles and iterates every step.
    const bool linear = f->model().transform == FrameTransform::linear && !f->plastic();
    for (int e = 0; e < f->nelements(); ++e) cost += linear ? 0.5e-6 : (D == 2 ? 5e-6 : 12e-6) * (f->plastic_record(e) ? 6 : 1);
  }
  return {steps, steps * cost};
}

template RunEstimate estimate_run<2>(const Solver<2>&, const Scenario&, double, double);
template RunEstimate estimate_run<3>(const Solver<3>&, const Scenario&, double, double);

}  // namespace dmi
