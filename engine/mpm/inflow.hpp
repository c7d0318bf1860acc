// Debris entering through a channel section from a hydrograph (depth h, velocity v, density rho against time).
//
// Upstream of the section lies a driven zone: while the hydrograph lasts, the grid nodes there that carry the inflow
// body's field move with the hydrograph's velocity along the bed, as the flow behind the section would push them (a
// velocity inlet). The debris is created at the zone's upstream end as slices of one particle spacing dx along the
// bed: the flow that has entered is a plug of length L(t) = int v dt, and slice k is created when L reaches
// (k + 1) dx, as a column of round(h / dx) particles over the depth h at that time, at velocity v along the bed, with
// mass rho h dx (times the thickness). The mass that enters is then the Riemann sum of int rho v h dt over the plug,
// within one slice of the hydrograph's integral. What the zone's nodes exert on the debris (the upstream thrust, and
// whatever else holds them at v) is recorded as its force, and its work enters the energy balance as a wall's does;
// the created particles bring their mass, momentum m v and kinetic energy m v^2 / 2 (the inflow's totals).
// The created particles start stress-free: the flow settles under its weight in the zone, where it is driven.
#pragma once
#include <string>

#include "engine/common/state_io.hpp"
#include "engine/common/types.hpp"
#include "core/hydrograph.hpp"

namespace dmi {

template <int D> struct Scene;

template <int D> struct Inflow {
  std::string name;
  int body = -1;                    // the body it fills (the last one: it grows)
  Vec<D> point = Vec<D>::Zero();    // the section's foot on the bed (m)
  Vec<D> along = Vec<D>::Zero();    // unit flow direction along the bed, downstream
  Vec<D> up = Vec<D>::Zero();       // unit normal to the bed, into the flow
  double zone = 0;                  // length of the driven zone upstream of the section (m)
  double spacing = 0;               // particle spacing dx (m)
  double thickness = 1;             // out-of-plane thickness of a 2D scene (m)
  double density = 0;               // the material's density, where the hydrograph gives none (kg/m^3)
  Hydrograph hydrograph;

  // State (checkpointed).
  double length = 0;                // plug length that has entered the zone, int v dt (m)
  long slices = 0;                  // slices created
  double mass = 0, energy = 0;      // created: kg, and kinetic energy J
  Vec<D> momentum = Vec<D>::Zero(); // created: kg m/s
  Vec<D> force = Vec<D>::Zero();    // force the debris exerts on the driven zone, last step (N)

  bool driving(double t) const { return !hydrograph.empty() && t >= hydrograph.start() && t <= hydrograph.end(); }
  // Whether x lies in the driven zone (within tol of it).
  bool in_zone(const Vec<D>& x, double tol) const {
    const double s = (x - point).dot(along);
    return s >= -zone - tol && s <= tol;
  }
  // The zone's velocity at time t.
  Vec<D> velocity(double t) const { return hydrograph.at(t, density).velocity * along; }
  // Mass of a full-spacing particle of the lightest debris (kg): a scale for the solver's empty-node threshold.
  double min_particle_mass() const;
  // Smallest density of the debris it creates (kg/m^3): the body's wave speed scales with 1/sqrt of it.
  double min_density() const { return hydrograph.min_density(density); }

  void save_state(StateWriter& w) const;
  void load_state(StateReader& r);
};

// Whether the debris has backed up to the section: while the zone drives, the debris within one flow depth (at least
// two cells) downstream of the section moves along the bed at less than half the hydrograph's velocity (mass
// average). The zone would then push a deposit as a piston, which the flow behind a real section cannot do (it slows
// as the bore from the dam passes it): the run must stop and the section move upstream.
template <int D> bool backed_up(const Scene<D>& s, const Inflow<D>& in, double t);

// Creates the slices whose plug length entered the zone during [t, t + dt]; extends the body's particle range and its
// material's per-particle arrays. Returns the particles created.
template <int D> Index inject(Scene<D>& s, Inflow<D>& in, double t, double dt);

}  // namespace dmi
