// The geostatic initial state of a body at rest under gravity: each particle starts from the stress of the body's
// weight above it, so that a deposit or a still water body is in equilibrium at t = 0 instead of falling onto
// itself and ringing. Vertical stress sigma_v = -rho g d, d the depth below the body's top in the particle's column
// (columns one cell wide across the gravity direction; the top is the highest particle's upper edge); horizontal
// stress sigma_h = K0 sigma_v (the earth-pressure coefficient at rest; 1 for a fluid: hydrostatic). The weight of
// other bodies above is not included.
#pragma once
#include "engine/mpm/scene.hpp"
#include "engine/scenario/config.hpp"

namespace dmi {

// K0 of a material: the body's own value when given (>= 0); else 1 for fluids, 1 - sin(phi) for granular laws
// (Jaky 1944; phi the friction angle, or atan(mu_s) for mu_i), nu / (1 - nu) for linear elastic solids (no lateral
// strain under their weight).
double earth_pressure_at_rest(const MaterialConfig& m, double given);

// Sets the geostatic stress of body b's particles through its material (Material::prestress); before the solver
// attaches the materials. Throws InputError naming body_path when the law cannot start from a stress.
template <int D> void geostatic_state(Scene<D>& sc, const Body& b, double K0, const std::string& file, const std::string& body_path);

}  // namespace dmi
