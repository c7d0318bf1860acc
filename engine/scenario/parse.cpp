// The scenario schema, version 1: every key declared once here (default, unit, doc, validation).
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "engine/common/error.hpp"
#include "engine/common/json_input.hpp"
#include "engine/common/memory.hpp"
#include "engine/scenario/design_basis_json.hpp"
#include "engine/scenario/hydrograph_io.hpp"
#include "engine/scenario/presets.hpp"
#include "engine/scenario/scenario.hpp"
#include "engine/scenario/parse_output.hpp"
#include "engine/scenario/parse_structure.hpp"
#include "engine/scenario/schema.hpp"
#include "engine/scenario/semantics.hpp"
#include "engine/scenario/shape_geometry.hpp"

namespace dmi {

using schema::Obj;
using schema::Spec;
using json = nlohmann::json;

namespace {

using schema::any;
using schema::positive;
using schema::nonneg;
using schema::when_any;

void read_analysis(Obj o, AnalysisConfig& a) {
  o.integer("dimension", a.dimension, Spec{.doc = "2 (plane strain or plane stress) or 3", .min = 2, .max = 3});
  o.context().dim = a.dimension;
  a.gravity.assign(a.dimension, 0.0);
  a.gravity.back() = -9.81;
  o.choice<Plane>("plane", a.plane, {{"strain", Plane::strain}, {"stress", Plane::stress}},
                  Spec{.doc = "2D kinematics: plane strain (thick bodies, dams) or plane stress (thin plates, beams); ignored in 3D"});
  o.number("thickness", a.thickness, positive("m", "out-of-plane thickness of every 2D body; masses, forces and energies include it"));
  o.number("end_time", a.end_time, positive("s", "simulated duration", true));
  o.number("dt_max", a.dt_max, Spec{.unit = "s", .doc = "upper bound on the time step; 0 = only the automatic CFL step", .min = 0});
  o.number("cfl", a.cfl, Spec{.doc = "fraction of the CFL limit h/(c + |v|) used as the time step", .min = 0, .max = 1, .min_open = true});
  o.vector("gravity", a.gravity, any("m/s^2", "gravitational acceleration; default points down the last axis (y in 2D, z in 3D)"));
  o.number("max_steps", a.max_steps, Spec{.doc = "a run whose estimated step count (end_time over the first step) exceeds this is refused "
                                                 "before it starts; raise it for a run that is meant to be that long",
                                          .min = 1, .max = 1e15});
  o.number("max_wall_hours", a.max_wall_hours, Spec{.unit = "h", .doc = "a run whose estimated wall time on one core (the dry run's first "
                                                                        "guess, docs/performance.md) exceeds this is refused before it starts; "
                                                                        "raise it for a run meant to be that long",
                                                     .min = 0, .max = 1e9, .min_open = true});
  o.finish();
  if (a.dimension == 3) a.plane = Plane::none;
}

void read_mpm(Obj o, MpmConfig& m) {
  o.choice<ShapeKind>("shape_function", m.shape,
                      {{"linear", ShapeKind::linear}, {"gimp", ShapeKind::gimp}, {"bspline2", ShapeKind::bspline2}},
                      Spec{.doc = "grid shape functions: linear (Sulsky 1994), uGIMP (Bardenhagen & Kober 2004), quadratic B-spline"});
  o.choice<TransferKind>("transfer", m.transfer, {{"flip", TransferKind::flip}, {"apic", TransferKind::apic}},
                         Spec{.doc = "particle velocity update: FLIP/PIC blend (Lin & Yang 2024 eq. 13) or APIC (Jiang et al. 2015)"});
  o.number("flip_blend", m.flip_blend, Spec{.doc = "FLIP fraction of the FLIP/PIC blend: 1 = pure FLIP, 0 = pure PIC (transfer = flip only)", .min = 0, .max = 1});
  // Linear shape functions with USL are unstable when a particle barely touches a node (tiny nodal
  // mass, full force gradient): MUSL's remapped velocities avoid it, so it is their default.
  m.update = m.shape == ShapeKind::linear ? StressUpdate::musl : StressUpdate::usl;
  o.choice<StressUpdate>("stress_update", m.update, {{"usl", StressUpdate::usl}, {"musl", StressUpdate::musl}},
                         Spec{.doc = "update stress last (USL, Lin & Yang 2024) or modified USL with a momentum remap (MUSL); "
                                     "default usl, but musl for linear shape functions (USL with linear shapes is unstable at nearly empty nodes)"});
  o.choice<bool>("damping", m.implicit_damping, {{"implicit", true}, {"explicit", false}},
                 Spec{.doc = "integration of the Kelvin-Voigt viscous stress of damped linear_elastic and neo_hookean materials: implicit "
                             "(a viscous sub-step on the grid by damped Chebyshev stages, about 2 sqrt(dt lambda_max) operator passes; "
                             "the step stays the elastic CFL step) or explicit "
                             "(the step shrinks to (2/w)(sqrt(1 + zeta^2) - zeta), as h^2 for strong damping). The fluids' viscosity is explicit"});
  if (!o.documenting() && m.shape == ShapeKind::linear && m.transfer == TransferKind::apic)
    o.fail("transfer", nullptr, "flip with shape_function linear (APIC with linear shape functions is unstable at nearly empty nodes; use gimp or bspline2 for APIC)");
  o.finish();
}

void read_grid(Obj o, GridConfig& g) {
  o.vector("origin", g.origin, any("m", "lower corner of the background grid", true));
  o.vector("size", g.size, Spec{.unit = "m", .doc = "extent of the grid along each axis", .min = 0, .min_open = true, .required = true});
  o.number("cell_size", g.cell_size, positive("m", "edge length of the square/cubic grid cells", true));
  o.finish();
}

// Newtonian and Bingham fluids: weak compressibility, viscosity, volume relaxation.
void read_fluid(Obj& o, MaterialConfig& m) {
  o.number("bulk_modulus", m.bulk_modulus, positive("Pa", "bulk modulus K of the weakly compressible fluid: p = K (1/J - 1) >= 0, "
                                                          "J = V/V0 (Monaghan 1994, gamma = 1); sound speed c = sqrt(K/density) "
                                                          "sets the time step; take c >= 10x the fastest flow speed (about 1 % density error)", true));
  o.number("viscosity", m.viscosity, positive("Pa s", "dynamic (plastic, for bingham) viscosity mu: deviatoric stress s = 2 mu D'; "
                                                     "a large viscosity lowers the time step to about cfl h^2 density / (8/3 d mu) in d dimensions", true));
  o.number("volume_relaxation", m.volume_relaxation,
           Spec{.doc = "0 (default): the volume ratio J follows the velocity gradient alone. n > 0: each step J also relaxes "
                       "towards the space the particles fill on the grid (their reference volumes at the nodes against the "
                       "nodes' space in front of the walls) over n transits of sound across a cell (100 is a fair choice): a "
                       "stopped or splashing stream then cannot pack more mass than its space holds (without it, 1.3-2.8x "
                       "near a wall), but the fluid reads its density low within a cell or two of a free surface or of "
                       "another body and carries less pressure there (docs/verification.md)",
                .min = 0});
}

// Members' steel: yield strength and hardening.
void read_member_steel(Obj& o, MaterialConfig& m) {
  o.number("yield_strength", m.yield_strength,
           Spec{.unit = "Pa", .doc = "yield strength f_y of the steel (S235: 235e6, S355: 355e6; EN 10025-2)", .min = 1e8, .max = 2e9,
                .required = true});
  o.number("hardening_ratio", m.hardening_ratio,
           Spec{.doc = "post-yield modulus over E (linear kinematic hardening); the default 0.01 is the E/100 strain-hardening slope "
                       "of EN 1993-1-5 Annex C.6(2); 0 = perfectly plastic", .min = 0, .max = 0.5});
  o.choice<SteelCurve>("steel_curve", m.steel_curve, {{"bilinear", SteelCurve::bilinear}, {"menegotto_pinto", SteelCurve::menegotto_pinto}},
                       Spec{.doc = "the steel under load reversals: bilinear (the default: a sharp yield, reversed yielding after a stress "
                                   "change of 2 f_y) or menegotto_pinto (Menegotto & Pinto 1973 with Filippou, Popov & Bertero 1983: a smooth "
                                   "knee whose curvature falls with each plastic excursion, so a reversal yields gradually, the Bauschinger "
                                   "effect of structural steel; it changes the rebound and the residual drift, little the first peak)"});
  o.number("transition_r0", m.transition_r0,
           Spec{.doc = "menegotto_pinto: R0, the sharpness of the first knee (20 for mild steel, Filippou et al. 1983; larger is "
                       "sharper, towards the bilinear curve)", .min = 2, .max = 100});
  o.number("transition_a1", m.transition_a1,
           Spec{.doc = "menegotto_pinto: a1 in R = R0 - a1 xi / (a2 + xi), how much the knee softens with the plastic excursion xi "
                       "(18.5, Filippou et al. 1983)", .min = 0, .max = 100});
  o.number("transition_a2", m.transition_a2,
           Spec{.doc = "menegotto_pinto: a2 in R = R0 - a1 xi / (a2 + xi) (0.15, Filippou et al. 1983)", .min = 1e-3, .max = 10});
  if (!o.documenting() && m.steel_curve == SteelCurve::menegotto_pinto && m.transition_a1 >= m.transition_r0) {
    const nlohmann::json v = m.transition_a1;
    o.fail("transition_a1", &v, "less than transition_r0 (R = R0 - a1 xi / (a2 + xi) must stay above 0 at large excursions)");
  }
}

// Bingham fluids: yield stress and its regularisation.
void read_bingham(Obj& o, MaterialConfig& m) {
  o.number("yield_stress", m.yield_stress, Spec{.unit = "Pa", .doc = "Bingham yield stress tau_y: shear stress tau = tau_y + mu gamma_dot "
                                                                      "in flow", .min = 0, .required = true});
  o.number("regularisation_rate", m.regularisation_rate,
           positive("1/s", "Papanastasiou (1987) regularisation, 1/m: tau = mu gamma_dot + tau_y (1 - exp(-gamma_dot / rate)); below "
                           "yield the material creeps at about this shear rate, as a fluid of viscosity mu + tau_y / rate, which "
                           "also bounds the time step to about cfl h^2 density / (8/3 d (mu + tau_y / rate)) in d dimensions: a "
                           "larger rate runs faster but creeps more"));
}

// Elastic solids' Kelvin-Voigt damping.
void read_solid_damping(Obj& o, MaterialConfig& m) {
  o.number("damping_ratio", m.damping_ratio, Spec{.doc = "viscous (Kelvin-Voigt, stiffness-proportional) damping ratio zeta reached "
                                                          "at damping_frequency: sigma_v = beta C:D, beta = zeta / (pi f); 0 = elastic",
                                                  .min = 0, .max = 1});
  o.number("damping_frequency", m.damping_frequency, Spec{.unit = "Hz", .doc = "frequency f at which the damping ratio holds (zeta grows "
                                                                               "with frequency as in Rayleigh beta damping); required with a damping ratio",
                                                          .min = 0, .min_open = true});
  if (!o.documenting() && m.damping_ratio > 0 && !(m.damping_frequency > 0))
    o.fail("damping_frequency", nullptr, "a frequency > 0 (Hz) with damping_ratio " + std::to_string(m.damping_ratio));
}

// Drucker-Prager: Mohr-Coulomb strength and dilation.
void read_drucker_prager(Obj& o, MaterialConfig& m) {
  o.number("cohesion", m.cohesion, Spec{.unit = "Pa", .doc = "cohesion c (Mohr-Coulomb)", .min = 0});
  o.number("friction_angle", m.friction_angle, Spec{.unit = "deg", .doc = "internal friction angle phi", .min = 0, .max = 70, .required = true});
  o.number("dilation_angle", m.dilation_angle, Spec{.unit = "deg", .doc = "dilation angle psi (0: no plastic volume change), at most phi",
                                                    .min = 0, .max = 70});
  if (!o.documenting() && m.dilation_angle > m.friction_angle)
    o.fail("dilation_angle", nullptr, "a dilation angle <= friction_angle (" + std::to_string(m.friction_angle) + " deg)");
}

// mu(I) dense granular flow.
void read_mu_i(Obj& o, MaterialConfig& m) {
  o.number("mu_s", m.mu_s, Spec{.doc = "static friction coefficient mu_s = tan(theta_1): q = mu(I) p with q = sqrt(J2)", .min = 0, .min_open = true, .required = true});
  o.number("mu_2", m.mu_2, Spec{.doc = "limiting friction coefficient mu_2 = tan(theta_2) at large I, greater than mu_s", .min = 0, .min_open = true, .required = true});
  o.number("I0", m.inertial_I0, Spec{.doc = "inertial number scale I0 of mu(I) = mu_s + (mu_2 - mu_s) / (I0 / I + 1)", .min = 0, .min_open = true, .required = true});
  o.number("grain_diameter", m.grain_diameter, positive("m", "grain diameter d in I = gamma_dot d / sqrt(p / grain_density)", true));
  o.number("grain_density", m.grain_density, positive("kg/m^3", "density of the grains rho_s in I (default 2650)"));
  o.number("regularisation_alpha", m.regularisation_alpha,
           Spec{.doc = "alpha of Barker & Gray's (2017) partial regularisation: below I_N1, where mu(I) is ill posed, mu = sqrt(alpha / "
                       "ln(A / I)), joined continuously at I_N1; the material then creeps below mu_s instead of standing rigid "
                       "(default 1.9; 0 = Jop's law unregularised)",
                .min = 0});
  if (!o.documenting() && !(m.mu_2 > m.mu_s)) {
    const nlohmann::json v = m.mu_2;
    o.fail("mu_2", &v, "a limiting friction mu_2 greater than mu_s (" + std::to_string(m.mu_s) + ")");
  }
}

void read_material(Obj& o, MaterialConfig& m) {
  o.string("name", m.name, Spec{.doc = "name that bodies refer to", .required = true});
  m.model = "linear_elastic";
  o.string("model", m.model, Spec{.doc = "material law: linear_elastic (small strain, Jaumann rate) | neo_hookean (compressible, "
                                         "large strain; rubber, tyre buffers) | drucker_prager (elastic-perfectly plastic "
                                         "Drucker-Prager matched to Mohr-Coulomb in plane strain; granular debris) | newtonian "
                                         "(weakly compressible viscous fluid; slurry) | bingham (weakly compressible Bingham fluid, "
                                         "Papanastasiou-regularised; mud and debris slurry) | mu_i (elastic-viscoplastic dense granular "
                                         "flow, the mu(I) rheology of Jop, Forterre & Pouliquen 2006) | elastic_plastic (steel of "
                                         "beam-column members only: linear elastic to yield_strength, then bilinear with kinematic "
                                         "hardening in each fibre of the section). The fluids, drucker_prager and mu_i need plane strain "
                                         "or 3D"});
  if (!o.documenting() && m.model != "linear_elastic" && m.model != "neo_hookean" && m.model != "drucker_prager" &&
      m.model != "newtonian" && m.model != "bingham" && m.model != "mu_i" && m.model != "elastic_plastic")
    o.fail("model", nullptr, "linear_elastic, neo_hookean, drucker_prager, newtonian, bingham, mu_i or elastic_plastic (got '" + m.model + "')");
  o.number("density", m.density, positive("kg/m^3", "mass density", true));
  if (when_any(o, "model", m.model, {"linear_elastic", "neo_hookean", "drucker_prager", "mu_i", "elastic_plastic"})) {
    o.number("youngs_modulus", m.youngs_modulus, positive("Pa", "Young's modulus E", true));
    o.number("poisson_ratio", m.poisson_ratio, Spec{.doc = "Poisson's ratio", .min = -1, .max = 0.5, .min_open = true, .max_open = true, .required = true});
  }
  o.end_when();
  if (when_any(o, "model", m.model, {"newtonian", "bingham"})) read_fluid(o, m);
  o.end_when();
  if (o.when("model", m.model, "elastic_plastic")) read_member_steel(o, m);
  o.end_when();
  if (o.when("model", m.model, "bingham")) read_bingham(o, m);
  o.end_when();
  if (when_any(o, "model", m.model, {"linear_elastic", "neo_hookean"})) read_solid_damping(o, m);
  o.end_when();
  if (o.when("model", m.model, "drucker_prager")) read_drucker_prager(o, m);
  o.end_when();
  if (o.when("model", m.model, "mu_i")) read_mu_i(o, m);
  o.end_when();
}

void read_shape(Obj o, ShapeConfig& s) {
  o.string("type", s.type, Spec{.doc = "box (rectangle in 2D) | ball (disk in 2D, sphere in 3D; with inner_radius a ring or hollow sphere) | "
                                       "polygon (2D only: a simple polygon, e.g. a trapezoidal dam or an inclined debris body)", .required = true});
  if (o.when("type", s.type, "box")) {
    o.vector("min", s.min, any("m", "lower corner", true));
    o.vector("max", s.max, any("m", "upper corner", true));
  }
  o.end_when();
  if (o.when("type", s.type, "ball")) {
    o.vector("center", s.center, any("m", "centre", true));
    o.number("radius", s.radius, positive("m", "radius", true));
    o.number("inner_radius", s.inner_radius, Spec{.unit = "m", .doc = "radius of the hole: a ring in 2D (e.g. a tyre), a hollow sphere in 3D; 0 = solid",
                                                  .min = 0});
    if (!o.documenting() && s.inner_radius >= s.radius)
      o.fail("inner_radius", nullptr, "an inner radius below radius = " + std::to_string(s.radius) + " m");
  }
  o.end_when();
  if (o.when("type", s.type, "polygon")) {
    if (!o.documenting() && o.context().dim != 2) o.fail("type", nullptr, "box or ball in 3D (polygon is 2D only)");
    o.vectors("vertices", s.vertices, any("m", "corners in order (either orientation); edges must not cross", true), 3);
    if (!o.documenting() && polygon_self_intersects(s.vertices))
      o.fail("vertices", nullptr, "a simple polygon (two of its edges cross)");
    if (!o.documenting() && !(std::abs(polygon_area(s.vertices)) > 0)) o.fail("vertices", nullptr, "a polygon with a non-zero area");
  }
  o.end_when();
  if (!o.documenting() && s.type != "box" && s.type != "ball" && s.type != "polygon")
    o.fail("type", nullptr, "box, ball or polygon (got '" + s.type + "')");
  o.finish();
}

void read_inflow(Obj o, InflowConfig& in) {
  in.present = true;
  if (!o.documenting() && o.context().dim != 2) o.fail("point", nullptr, "a 2D scenario (the inflow section is a line across a 2D channel)");
  o.vector("point", in.point, any("m", "the section's foot on the bed: where the inflowing debris leaves the driven zone", true));
  o.vector("direction", in.direction, any("", "flow direction along the bed, downstream (normalised); the depth is measured normal to it, "
                                              "on its left (counter-clockwise)", true));
  o.number("zone_length", in.zone, nonneg("m", "length along the bed of the driven zone upstream of the section, where the debris is created "
                                               "and moves with the hydrograph's velocity; 0 = 3 cells"));
  const json* h = o.raw("hydrograph", Spec{.doc = "depth (m, normal to the bed), velocity (m/s, along the bed) and optionally density "
                                                  "(kg/m^3; default the material's) against time (s): a CSV file name (relative to the "
                                                  "scenario's folder; a header row names the columns time, depth, velocity, density) or "
                                                  "an object of equal-length arrays {\"time\": [...], \"depth\": [...], \"velocity\": [...]}",
                                           .required = true},
                        "string or object", "");
  if (h) in.hydrograph = read_hydrograph(*h, o.context().file, o.path() + "/hydrograph");
  if (o.documenting()) return;
  double n2 = 0;
  for (double x : in.direction) n2 += x * x;
  if (!(n2 > 0)) o.fail("direction", nullptr, "a non-zero direction vector");
  for (double& x : in.direction) x /= std::sqrt(n2);
  o.finish();
}

void read_body(Obj& o, BodyConfig& b) {
  o.string("name", b.name, Spec{.doc = "body name, used by probes and in messages", .required = true});
  o.string("material", b.material, Spec{.doc = "name of an entry in materials", .required = true});
  Obj in = o.object("inflow", "debris entering through a channel section from a hydrograph (2D; the body grows as it enters): give this "
                              "or shape. Only the last body may have one");
  if (in.present()) read_inflow(in, b.inflow);
  if (!o.documenting() && b.inflow.present) {
    if (const json* sh = o.raw("shape", Spec{}, "object", ""))
      o.fail("shape", sh, "no shape on a body that an inflow fills (give either shape or inflow)");
  } else {
    read_shape(o.object("shape", "region the body fills; particles are seeded on a regular sub-grid of every cell inside it"), b.shape);
  }
  o.integer("particles_per_cell", b.particles_per_cell, Spec{.doc = "particles per cell along each axis", .min = 1, .max = 8});
  std::string init = "stress_free";
  o.string("initial_stress", init, Spec{.doc = "stress_free | geostatic: the stress of the body's own weight above each particle, "
                                               "sigma_v = -rho g d (d: depth below the body's top in the particle's column), "
                                               "sigma_h = K0 sigma_v, so that a body at rest under gravity starts at rest instead of "
                                               "ringing (a fluid: hydrostatic pressure, its volume compressed to match)"});
  if (!o.documenting() && init != "stress_free" && init != "geostatic") o.fail("initial_stress", o.given("initial_stress"), "stress_free or geostatic");
  b.geostatic = init == "geostatic";
  o.number("earth_pressure_coefficient", b.earth_pressure_coefficient,
           Spec{.doc = "K0 = sigma_h / sigma_v of the geostatic state; default: 1 for fluids, 1 - sin(friction_angle) for "
                       "drucker_prager (Jaky 1944), nu / (1 - nu) for linear_elastic (no lateral strain); fluids take 1 only",
                .min = 0, .max = 3});
  o.boolean("rigid", b.rigid, Spec{.doc = "move as a rigid body: translation and rotation from the particles' momentum and angular momentum "
                                          "after each grid update, no stress, no step limit from the material's stiffness (its density "
                                          "gives the mass); contacts act on it as on any body. For a boulder whose deformation does not "
                                          "matter (against a soft buffer), not for a hard impact whose peak the boulder's elasticity sets"});
  if (!o.documenting() && b.rigid && b.inflow.present)
    o.fail("rigid", o.raw("rigid", Spec{}, "boolean", ""), "false on a body that an inflow fills (debris is not rigid)");
  o.boolean("rigid_when_free", b.rigid_when_free,
            Spec{.doc = "a linear-elastic body that is elastic while anything is near it (another body, a wall, a region or a "
                        "member within a few cells) and moves as a rigid body while nothing is, or while it is leaving whatever "
                        "is near (apart by more than both half a cell and its particles' reach, and moving further apart; "
                        "members under the default touch-detected contact only): its waves then no longer set the step. On "
                        "becoming rigid its vibration (the kinetic energy the rigid projection removes) and its strain energy "
                        "are given up (counted as dissipated) and it is stress-free when it turns elastic again. For a boulder "
                        "that rebounds from a hard impact and flies on"});
  if (!o.documenting() && b.rigid_when_free && (b.rigid || b.inflow.present))
    o.fail("rigid_when_free", o.raw("rigid_when_free", Spec{}, "boolean", ""), "false on a rigid body or one that an inflow fills");
  b.velocity.assign(o.context().dim, 0.0);
  o.vector("velocity", b.velocity, any("m/s", "initial velocity"));
  Obj m = o.object("velocity_sine", "optional sine mode added to the initial velocity, v += amplitude sin(wavevector . (x - origin)); "
                                    "e.g. a bar's first axial mode");
  if (!m.present()) return;
  m.vector("amplitude", b.sine_amplitude, any("m/s", "velocity amplitude", true));
  m.vector("wavevector", b.sine_wavevector, any("rad/m", "wave vector", true));
  b.sine_origin.assign(o.context().dim, 0.0);
  m.vector("origin", b.sine_origin, any("m", "phase origin"));
  m.finish();
}

void read_contact(Obj o, ContactConfig& c) {
  o.choice<ContactMethod>("method", c.method, {{"multi_field", ContactMethod::multi_field}, {"single_field", ContactMethod::single_field}},
                          Spec{.doc = "multi_field: one velocity field per body with Bardenhagen et al. (2000) contact, bodies can separate and slide; "
                                      "single_field: all bodies share one field (no-slip, they stick on touching)"});
  o.number("friction", c.friction, Spec{.doc = "Coulomb friction coefficient between bodies (multi_field)", .min = 0});
  o.choice<BodyDetection>("detection", c.detection, {{"surface", BodyDetection::surface}, {"volume", BodyDetection::volume}},
                          Spec{.doc = "how two bodies are found touching at a grid node (multi_field): surface = their surfaces, located "
                                      "from the particles in the node's column, meet (default); volume = their particle volumes fill the "
                                      "node's support (late and soft on curved bodies: docs/verification.md)"});
  o.finish();
}

void read_wall(Obj& o, WallConfig& w) {
  o.string("name", w.name, Spec{.doc = "wall name; its force history is stored as walls/<name>/force", .required = true});
  o.string("type", w.type, Spec{.doc = "plane (grid nodes on or behind it) | box (grid nodes inside it)", .required = true});
  if (o.when("type", w.type, "plane")) {
    o.vector("point", w.point, any("m", "a point on the wall plane", true));
    o.vector("normal", w.normal, any("", "normal pointing to the free side (need not be unit length)", true));
  }
  o.end_when();
  if (o.when("type", w.type, "box")) {
    o.vector("min", w.min, any("m", "lower corner", true));
    o.vector("max", w.max, any("m", "upper corner", true));
  }
  o.end_when();
  if (!o.documenting() && w.type != "plane" && w.type != "box") o.fail("type", nullptr, "plane or box (got '" + w.type + "')");
  o.choice<WallCondition>("condition", w.condition,
                          {{"stick", WallCondition::stick}, {"roller", WallCondition::roller}, {"slip", WallCondition::slip}, {"friction", WallCondition::friction}},
                          Spec{.doc = "stick: v = 0; roller: no normal velocity (bilateral); slip: frictionless contact, separable; friction: Coulomb contact, separable"});
  o.number("friction", w.friction, Spec{.doc = "Coulomb coefficient (condition = friction)", .min = 0});
  o.choice<DetectionKind>("detection", w.detection, {{"surface", DetectionKind::surface}, {"node", DetectionKind::node}},
                          Spec{.doc = "contact detection of a unilateral boundary: surface (default) = a grid node is held only where the particles whose "
                                        "domains touch it carry at least half the node's mass; node = every node on or behind the wall with mass is held, "
                                        "which engages the stencil's reach (1.5 h) ahead of the body and makes a hard impact's peak "
                                        "cell-dependent (docs/verification.md, hard impact)"});
}

void read_region(Obj& o, PrescribedVelocityConfig& r) {
  o.string("name", r.name, Spec{.doc = "region name; its force history is stored as regions/<name>/force", .required = true});
  o.vector("min", r.min, any("m", "lower corner of the region of grid nodes", true));
  o.vector("max", r.max, any("m", "upper corner", true));
  o.vector("velocity", r.velocity, any("m/s", "prescribed nodal velocity", true));
  o.number("start", r.start, Spec{.unit = "s", .doc = "active from this time", .min = 0});
  o.number("end", r.end, Spec{.unit = "s", .doc = "active until this time (default: always)", .min = 0});
}

void read_header(Obj& o, Scenario& s) {
  o.integer("schema_version", s.schema_version, Spec{.doc = "scenario format version; must be 1", .min = 1, .max = 1, .required = true});
  o.string("name", s.name, Spec{.doc = "scenario name, shown in outputs and reports", .required = true});
  o.string("description", s.description, Spec{.doc = "free text"});
}

void read_scenario(Obj& o, Scenario& s) {
  read_header(o, s);
  read_analysis(o.object("analysis", "dimension, kinematics, duration, time step and gravity"), s.analysis);
  read_mpm(o.object("mpm", "material point method options"), s.mpm);
  read_grid(o.object("grid", "the background grid"), s.grid);
  o.array<MaterialConfig>("materials", s.materials, Spec{.doc = "material laws"}, read_material);
  o.array<BodyConfig>("bodies", s.bodies, Spec{.doc = "continuum bodies discretised by particles; at least one, unless the scenario is "
                                                      "only a solid_check"}, read_body);
  read_contact(o.object("contact", "contact between bodies"), s.contact);
  o.array<WallConfig>("walls", s.walls, Spec{.doc = "rigid fixed walls acting on grid nodes"}, read_wall);
  o.array<PrescribedVelocityConfig>("prescribed_velocity", s.prescribed_velocity, Spec{.doc = "regions of grid nodes moving with a given velocity"}, read_region);
  read_structure(o.object("structure", "beam-column frame (plane in 2D, space frame in 3D) whose members act on the bodies (Lin & Yang "
                                       "2024); absent: no frame"), s.structure);
  read_member_contact(o.object("member_contact", "how the structure's members act on the bodies (Lin & Yang 2024); only with a structure"),
                      s.member_contact, s.structure.present);
  read_output(o.object("output", "what is recorded"), s.output);
  read_solid_check(o.object("solid_check", "a linear solid-FE check of a concrete dam body (Lin, Cheng & Tuan, Table 1): static load cases, "
                                           "given or taken from this run's contact loads; absent: none"), s.solid_check);
  if (const json* b = o.raw("design_basis", Spec{.doc = "what the design checks and closed-form estimates need (dam, boulder, "
                                                        "debris_surge, tyre_buffer; docs/design-json.md); the presets write it"}, "object", ""))
    s.design_basis = design_basis_from_json(*b, o.context().file, "/design_basis");
  o.finish();
}

}  // namespace

namespace detail {
void read_material_object(const json& j, const std::string& path, const std::string& file, MaterialConfig& out) {
  schema::Context ctx{.file = file, .dim = 2};
  if (!j.is_object()) throw InputError(file, path, schema::short_dump(j), "an object (a material: model, density, ...)");
  Obj o(&j, path, ctx);
  read_material(o, out);
  o.finish();
}
}  // namespace detail

const std::vector<std::string>& particle_probe_quantities() {
  static const std::vector<std::string> q = {"displacement", "position", "velocity", "stress", "von_mises"};
  return q;
}
const std::vector<std::string>& body_probe_quantities() {
  static const std::vector<std::string> q = {"position", "displacement", "velocity", "kinetic_energy", "volume"};
  return q;
}
const std::vector<std::string>& member_probe_quantities() {
  static const std::vector<std::string> q = {"displacement", "top_displacement", "rotation", "section_forces", "fibre_stress"};
  return q;
}

namespace {

Scenario parse_low_level(const json& j, const std::string& file) {
  Scenario s;
  schema::Context ctx{.file = file};
  if (!j.is_object()) throw InputError(file, "/", schema::short_dump(j), "a JSON object (a scenario)");
  if (j.contains("accept_unusual")) {
    if (!j["accept_unusual"].is_boolean()) throw InputError(file, "/accept_unusual", schema::short_dump(j["accept_unusual"]), "true or false");
    ctx.accept_unusual = j["accept_unusual"].get<bool>();
  }
  Obj o(&j, "", ctx);
  bool unusual = false;
  o.boolean("accept_unusual", unusual, Spec{.doc = "accept values outside their plausible ranges (a laboratory model)"});
  if (j.contains("solid_check") && !j.contains("bodies") && !j.contains("structure")) {
    // A solid-FE check on its own (e.g. Lin, Cheng & Tuan's Table 1): no grid, bodies or time stepping.
    read_header(o, s);
    read_solid_check(o.object("solid_check", ""), s.solid_check);
    o.finish();
    check_solid_check(s, file);
    s.source_file = file;
    return s;
  }
  read_scenario(o, s);
  check_semantics(s, file);
  s.source_file = file;
  return s;
}

json parse_json_text(const std::string& text, const std::string& file) {
  check_json_structure(text, file);
  try {
    return json::parse(text);
  } catch (const json::out_of_range& e) {
    // e.g. a number too large for a double; the JSON library gives no position for it.
    std::string what = e.what();
    const auto k = what.find("] ");
    throw InputError(file + ": invalid JSON (" + (k == std::string::npos ? what : what.substr(k + 2)) +
                     "; numbers must fit a double)");
  } catch (const json::parse_error& e) {
    // Turn the byte offset into line:column.
    std::size_t line = 1, col = 1;
    for (std::size_t i = 0; i + 1 < e.byte && i < text.size(); ++i) {
      if (text[i] == '\n') { ++line; col = 1; } else { ++col; }
    }
    std::string what = e.what();
    const auto k = what.find("syntax error");
    throw InputError(file + ":" + std::to_string(line) + ":" + std::to_string(col) + ": invalid JSON (" +
                     (k == std::string::npos ? what : what.substr(k)) + ")");
  }
}

// One variant: presets expanded first (their own keys validated at their own paths), then the
// low-level scene parsed; an error in a generated key names the expansion (see --dry-run).
Scenario parse_variant(const json& j, const std::string& file, const std::string& variant) {
  if (!has_presets(j)) return parse_low_level(j, file);
  const json low = expand_presets(j, file, variant);
  Scenario s = parse_low_level(low, file + " (expanded presets)");
  s.source_file = file;
  s.expanded_text = low.dump(1);
  s.variant = variant;
  return s;
}

std::string read_file_text(const std::string& path) { return read_json_file(path, "scenario"); }

// An input error is one line (README; the CLI prints it as one): keys and names taken from the input may hold
// control characters (a JSON "\n" in a key or a name), which messages show escaped, as JSON writes them.
template <class F>
auto one_line_errors(F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const InputError& e) {
    const std::string m = e.what();
    auto control = [](unsigned char c) { return c < 0x20; };
    if (std::none_of(m.begin(), m.end(), control)) throw;
    std::string r;
    for (const char c : m) {
      if (!control(static_cast<unsigned char>(c))) {
        r += c;
        continue;
      }
      const std::string esc = json(std::string(1, c)).dump();  // "\n", "\t", "\u001f", ...
      r += esc.substr(1, esc.size() - 2);
    }
    throw InputError(r);
  }
}

}  // namespace

Scenario parse_scenario(const json& j, const std::string& file) {
  return one_line_errors([&] { return parse_variant(j, file, preset_variants(j, file).front()); });
}

Scenario parse_scenario(const std::string& text, const std::string& file) {
  Scenario s = parse_scenario(parse_json_text(text, file), file);
  s.source_text = text;
  return s;
}

Scenario load_scenario(const std::string& path) { return parse_scenario(read_file_text(path), path); }

std::vector<ScenarioVariant> parse_scenario_variants(const std::string& text, const std::string& file) {
  const json j = parse_json_text(text, file);
  return one_line_errors([&] {
    std::vector<ScenarioVariant> out;
    for (const auto& v : preset_variants(j, file)) {
      out.push_back({v, parse_variant(j, file, v)});
      out.back().scenario.source_text = text;
    }
    return out;
  });
}

std::vector<ScenarioVariant> load_scenario_variants(const std::string& path) { return parse_scenario_variants(read_file_text(path), path); }

double common_cell_size(const std::vector<ScenarioVariant>& variants, const std::string& file) {
  for (const auto& v : variants)
    if (is_space_variant(v.label))
      throw InputError(file, "/compare_3d", "true", "false for a grid study (it refines the plane model; run the 3D comparison on its own)");
  const double h = variants.front().scenario.grid.cell_size;
  for (const auto& v : variants)
    if (std::abs(v.scenario.grid.cell_size - h) > 1e-12 * h)
      throw InputError(file + ": the variants have different cell sizes; a grid study needs one");
  return h;
}

std::string scenario_reference_markdown() {
  std::vector<schema::Row> rows;
  schema::Context ctx{.doc = &rows};
  Scenario s;
  Obj o(nullptr, "", ctx);
  read_scenario(o, s);
  document_presets(o);
  return schema::markdown(rows);
}

}  // namespace dmi
