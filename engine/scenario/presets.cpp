// Preset keys (declared once, with defaults, units and docs) and their expansion into the
// low-level scene. Geometry conventions: presets.hpp.
#include "engine/scenario/presets.hpp"

#include <sstream>

#include <algorithm>
#include <cmath>

#include "engine/common/error.hpp"
#include "engine/scenario/hydrograph_io.hpp"
#include "engine/scenario/preset_types.hpp"

namespace dmi {

using json = nlohmann::json;
using schema::Obj;
using schema::Spec;

namespace {

const char* const kPresetKeys[] = {"dam", "boulder", "debris_surge", "tyre_buffer", "compare", "compare_3d", "accept_unusual"};

using schema::nonneg;
using schema::positive;

// A material object: defaults overlaid by the user's keys, validated as a materials[] entry at its
// own JSON path (so a wrong key names /dam/concrete/..., not the generated list).
// `derived` holds keys the expansion fills in later (e.g. a damping frequency), used for the check only.
json material_object(Obj& o, const char* key, const json& defaults, const std::string& doc, const std::string& name,
                     const json& derived = json::object()) {
  const json* v = o.raw(key, Spec{.doc = doc + "; the keys of a materials[] entry without name (docs: materials)"}, "object",
                        defaults.dump());
  json m = defaults;
  if (v) {
    if (!v->is_object()) o.fail(key, v, "an object (a material: model, density, youngs_modulus, ...)");
    if (v->contains("name")) o.fail(std::string(key) + "/name", &v->at("name"), "no name (the preset names its materials)");
    if (v->contains("model") && v->at("model") != defaults.value("model", "")) {
      // Another law: keep only the density default, the rest must come from the user.
      m = json::object();
      if (defaults.contains("density")) m["density"] = defaults["density"];
    }
    m.update(*v);
  }
  if (!o.documenting()) {
    json named = m;
    named["name"] = name;
    for (auto it = derived.begin(); it != derived.end(); ++it)
      if (!named.contains(it.key())) named[it.key()] = it.value();
    MaterialConfig unused;
    detail::read_material_object(named, o.path() + "/" + key, o.context().file, unused);
  }
  return m;
}

// Plausibility of a preset material's modulus and density (SI units): E = 25 for concrete is 25 Pa, not 25 GPa. The
// ranges are wide (any real concrete, steel, rock or tyre stack lies inside); a lab-scale or scaled model can use the
// low-level scenario, which has no such check.
void plausible(Obj& o, const std::string& key, const json& m, const char* what, double e_lo, double e_hi, double rho_lo, double rho_hi) {
  if (o.documenting() || o.context().accept_unusual) return;
  const double E = m.value("youngs_modulus", 0.0), rho = m.value("density", 0.0);
  char buf[256];
  if (m.contains("youngs_modulus") && !(E >= e_lo && E <= e_hi)) {
    std::snprintf(buf, sizeof buf, "a Young's modulus in Pa between %.0e and %.0e for %s (units: Pa, e.g. 25e9 for 25 GPa)", e_lo, e_hi, what);
    o.fail(key.empty() ? "youngs_modulus" : key + "/youngs_modulus", &m.at("youngs_modulus"), buf);
  }
  if (m.contains("density") && !(rho >= rho_lo && rho <= rho_hi)) {
    std::snprintf(buf, sizeof buf, "a density in kg/m^3 between %.0f and %.0f for %s", rho_lo, rho_hi, what);
    o.fail(key.empty() ? "density" : key + "/density", &m.at("density"), buf);
  }
}

// A unit weight in N/m^3 (a value in kN/m^3 is the usual slip: refused with the conversion).
void unit_weight(Obj& o, const char* key, double& v, const char* what, double lo, double hi) {
  o.number(key, v, Spec{.unit = "N/m^3", .doc = what});
  if (o.documenting() || o.context().accept_unusual || (v >= lo && v <= hi)) return;
  char buf[200];
  if (v < lo) std::snprintf(buf, sizeof buf, "a unit weight in N/m^3 between %.0f and %.0f (%g kN/m^3 is %g N/m^3)", lo, hi, v, v * 1e3);
  else std::snprintf(buf, sizeof buf, "a unit weight in N/m^3 between %.0f and %.0f", lo, hi);
  o.fail(key, o.given(key), buf);
}

// What stands behind the dam when the impact arrives: a deposit and water, permanent pressures on the upstream face
// from t = 0 (the accidental combination's permanent part; docs/presets.md).
void read_standing_loads(Obj& o, DamPreset& d) {
  Obj dep = o.object("deposit", "sediment or debris deposited behind the dam when the impact arrives: an earth pressure K gamma (h - y) on "
                                "the upstream face, held from t = 0 with the self-weight; absent: none");
  if (dep.present()) {
    dep.number("height", d.deposit_height, positive("m", "height of the deposit's surface above the base", true));
    unit_weight(dep, "unit_weight", d.deposit_unit_weight, "unit weight gamma of the deposit (saturated, when submerged)", 5e3, 2.6e4);
    dep.number("pressure_coefficient", d.deposit_coefficient,
               Spec{.doc = "earth-pressure coefficient K (at rest 1 - sin phi = 0.5 at phi = 30 deg; active 0.33)", .min = 0, .max = 1,
                  .min_open = true});
    dep.boolean("submerged", d.deposit_submerged,
                Spec{.doc = "true: below the water surface (dam.water, required) the deposit weighs its buoyant unit weight gamma - gamma_w, "
                            "the water's own pressure acting besides: K (gamma (h - y) - gamma_w (min(h, h_w) - y)) below min(h, h_w)"});
    dep.finish();
  }
  Obj w = o.object("water", "water standing behind the dam when the impact arrives: a hydrostatic pressure gamma_w (h - y) on the upstream "
                            "face from t = 0, and its uplift on the base joint in the stability checks; absent: none");
  if (w.present()) {
    w.number("height", d.water_height, positive("m", "height of the water surface above the base", true));
    unit_weight(w, "unit_weight", d.water_unit_weight, "unit weight (muddy water up to about 12 kN/m^3)", 9e3, 1.4e4);
    w.finish();
  }
  if (!o.documenting() && d.deposit_height > d.height) o.fail("deposit/height", nullptr, "a deposit no higher than the dam (" + std::to_string(d.height) + " m)");
  if (!o.documenting() && d.deposit_submerged && !(d.water_height > 0))
    o.fail("deposit/submerged", nullptr, "false without water behind the dam (dam.water gives the water surface the deposit is submerged below)");
  if (!o.documenting() && d.deposit_submerged && !(d.deposit_unit_weight > d.water_unit_weight))
    o.fail("deposit/unit_weight", nullptr, "a saturated unit weight above the water's (" + std::to_string(d.water_unit_weight) + " N/m^3) for a submerged deposit");
  if (!o.documenting() && d.water_height > d.height) o.fail("water/height", nullptr, "water no higher than the dam crest (" + std::to_string(d.height) + " m)");
}

// A concrete gravity dam: its section, the model, the concrete and what stands behind it.
void read_concrete_dam(Obj& o, DamPreset& d) {
  o.number("crest_thickness", d.crest, positive("m", "thickness at the crest, along the flow", true));
  o.number("base_thickness", d.base_thickness, positive("m", "thickness at the base, >= crest_thickness", true));
  o.choice<std::string>("sloped_face", d.sloped_face, {{"downstream", "downstream"}, {"upstream", "upstream"}, {"both", "both"}},
                        Spec{.doc = "which face is battered: downstream (vertical upstream face), upstream, or both (symmetric)"});
  o.choice<std::string>("model", d.model, {{"members", "members"}, {"continuum", "continuum"}},
                        Spec{.doc = "members: one tapered beam-column member fixed at the base (Lin & Yang 2024; stresses from N and M); "
                                    "continuum: an MPM body stuck to the ground along its base (for comparison)"});
  d.concrete = material_object(o, "concrete", json{{"model", "linear_elastic"}, {"density", 2400}, {"youngs_modulus", 25e9}, {"poisson_ratio", 0.2}},
                               "concrete (Lin, Cheng & Tuan use E 25 GPa, rho 2300)", "concrete");
  plausible(o, "concrete", d.concrete, "concrete", 5e9, 1e11, 1500, 3500);
  if (!o.documenting() && d.base_thickness < d.crest)
    o.fail("base_thickness", nullptr, "a base thickness >= crest_thickness = " + std::to_string(d.crest) + " m");
  read_standing_loads(o, d);
}

// A steel open dam: rows, levels and bracing of pipes, the member model and the steel.
void read_steel_dam(Obj& o, DamPreset& d) {
  o.integer("rows", d.rows, Spec{.doc = "rows of columns along the flow (the upstream row is hit)", .min = 1, .max = 10});
  o.number("row_spacing", d.row_spacing, positive("m", "distance between rows along the flow; default height / 2"));
  o.integer("levels", d.levels, Spec{.doc = "beam levels between the rows, evenly spaced up to the crest", .min = 1, .max = 20});
  o.boolean("bracing", d.bracing, Spec{.doc = "one diagonal per panel, from the foot of the downstream column to the head of the upstream one"});
  o.integer("columns", d.columns, Spec{.doc = "3D (analysis.dimension 3): columns in each row across the channel, `width` apart, tied by beams "
                                              "across at every level; default 3", .min = 1, .max = 20});
  Obj c = o.object("column", "column pipe section");
  c.number("diameter", d.column_d, positive("m", "outer diameter D", true));
  c.number("wall_thickness", d.column_t, positive("m", "wall thickness t <= D/2", true));
  c.finish();
  Obj b = o.object("beam", "beam and brace pipe section; default: the column's");
  b.number("diameter", d.beam_d, positive("m", "outer diameter D"));
  b.number("wall_thickness", d.beam_t, positive("m", "wall thickness t <= D/2"));
  b.finish();
  // Checked here, at the key the user wrote (the member sections the presets build check it again, at their paths).
  auto pipe_wall = [](Obj& sec, double D, double t) {
    if (sec.documenting() || !(D > 0) || !(t > 0.5 * D)) return;
    std::ostringstream half;
    half << 0.5 * D;
    const json v = t;
    sec.fail("wall_thickness", &v, "a wall thickness <= diameter / 2 = " + half.str() + " m");
  };
  pipe_wall(c, d.column_d, d.column_t);
  if (!o.documenting() && d.row_spacing > 0 && d.column_d > 0 && d.rows > 1 && !(d.row_spacing > d.column_d)) {
    const json v = d.row_spacing;
    o.fail("row_spacing", &v, "a row spacing larger than the column diameter " + json(d.column_d).dump() + " m (the rows would overlap)");
  }
  if (d.beam_t > 0) pipe_wall(b, d.beam_d > 0 ? d.beam_d : d.column_d, d.beam_t);
  o.choice<std::string>("member_model", d.member_model, {{"plastic", "plastic"}, {"elastic", "elastic"}},
                        Spec{.doc = "the members: plastic (the default: elastic_plastic steel, force-based fibre beam-columns that yield "
                                    "and absorb the boulder's energy; a slit dam is sized to) or elastic (linear elastic members: the "
                                    "serviceability level, or a comparison)"});
  d.steel = material_object(o, "steel", json{{"model", "elastic_plastic"}, {"density", 7850}, {"youngs_modulus", 205e9}, {"poisson_ratio", 0.3},
                                             {"yield_strength", 355e6}, {"hardening_ratio", 0.01}},
                            "steel (S355 by default: f_y 355 MPa, EN 10025-2; the design checks take this f_y)", "steel");
  plausible(o, "steel", d.steel, "steel", 1e11, 3e11, 7000, 8500);
  if (d.member_model == "plastic" && !o.documenting() && !o.given("damping_model")) d.damping_model = "mass";
  if (d.member_model == "elastic" && d.steel.value("model", "") == "elastic_plastic") {
    d.steel["model"] = "linear_elastic";
    d.steel.erase("hardening_ratio");
    d.steel_yield = d.steel.value("yield_strength", 355e6);
    d.steel.erase("yield_strength");
  } else {
    d.steel_yield = d.steel.value("yield_strength", 0.0);
  }
}

void read_dam(Obj o, DamPreset& d) {
  o.string("type", d.type, Spec{.doc = "concrete_gravity (a tapered concrete wall) | steel_open (a frame of steel pipes: columns in rows "
                                       "along the flow, beams between them)", .required = true});
  if (!o.documenting() && d.type != "concrete_gravity" && d.type != "steel_open")
    o.fail("type", nullptr, "concrete_gravity or steel_open (got '" + d.type + "')");
  o.number("height", d.height, positive("m", "height above the ground at the upstream face", true));
  o.number("width", d.width, positive("m", "out-of-plane width the 2D model stands for (analysis.thickness): the face width of a concrete dam, "
                                           "(absent, a boulder on a concrete dam in 2D: the impact's effective width, the boulder's diameter plus "
                                           "the section's thickness at the impact height, a 45 degree spread through the struck section; else 1 m) "
                                           "the column spacing across the channel of a steel dam"));
  d.width_given = o.documenting() || o.given("width") != nullptr;
  o.choice<std::string>("base", d.base, {{"fixed", "fixed"}, {"pinned", "pinned"}}, Spec{.doc = "support at the foundation"});
  o.number("damping_ratio", d.damping_ratio, Spec{.doc = "structural damping ratio of the members (concrete 5-10 %, steel 2-5 %)",
                                                  .min = 0, .max = 0.5});
  o.choice<std::string>("damping_model", d.damping_model, {{"modal", "modal"}, {"rayleigh", "rayleigh"}, {"mass", "mass"}},
                        Spec{.doc = "how damping_ratio damps the members: modal = every mode of the assembled frame at damping_ratio "
                                    "(computed modes; the kHz modes a hard impact excites get the same ratio as the first); "
                                    "rayleigh = C = alpha M + beta K fitted at the first two modes of the dam as a uniform "
                                    "cantilever (zeta grows with frequency above the second and damps a hard impact's kHz modes "
                                    "heavily); mass = C = alpha M with zeta at the first mode (zeta falls above it). Default modal; mass for a "
                                    "steel_open dam with plastic members (damping built on the initial stiffness puts spurious "
                                    "moments on yielding hinges, which then dissipate what the steel should; Charney 2008)"});
  // A short hard impact excites the dam's higher modes, which the members must resolve (docs/verification.md).
  if (d.type == "concrete_gravity") d.elements = 16;
  o.integer("elements", d.elements, Spec{.doc = "beam-column elements per member (members model); default 16 for concrete_gravity "
                                                "(a bare impact's peak base shear as with 32; docs/verification.md), 8 for steel_open",
                                         .min = 1, .max = 1000});
  d.beam_theory = d.type == "concrete_gravity" ? "timoshenko" : "euler_bernoulli";
  o.choice<std::string>("beam_theory", d.beam_theory, {{"timoshenko", "timoshenko"}, {"euler_bernoulli", "euler_bernoulli"}},
                        Spec{.doc = "the members' beam theory: timoshenko (shear deformation and rotary inertia; the default for "
                                    "concrete_gravity, whose section is a sizeable fraction of its height) or euler_bernoulli (the "
                                    "default for steel_open's slender pipes)"});
  if (o.when("type", d.type, "concrete_gravity")) read_concrete_dam(o, d);
  o.end_when();
  if (o.when("type", d.type, "steel_open")) read_steel_dam(o, d);
  o.end_when();
  o.finish();
}

void read_boulder(Obj o, BoulderPreset& b) {
  o.number("diameter", b.diameter, positive("m", "diameter of the (spherical) boulder; give this or mass"));
  o.number("mass", b.mass, positive("kg", "boulder mass; give this or diameter"));
  o.number("density", b.density, positive("kg/m^3", "rock density"));
  o.number("youngs_modulus", b.youngs_modulus, positive("Pa", "rock Young's modulus (stiffness)"));
  if (!o.documenting()) plausible(o, "", json{{"youngs_modulus", b.youngs_modulus}, {"density", b.density}}, "rock", 1e9, 2e11, 1500, 4000);
  o.number("poisson_ratio", b.poisson_ratio, Spec{.doc = "rock Poisson's ratio", .min = 0, .max = 0.5, .max_open = true});
  o.vector("velocity", b.velocity, Spec{.unit = "m/s", .doc = "velocity at release; give this or release_height"});
  o.number("release_height", b.release_height, positive("m", "drop height converted to a horizontal speed sqrt(2 g h) towards the dam"));
  o.number("impact_height", b.impact_height, positive("m", "height of the boulder's centre where it meets the dam (or buffer); default 0.9 x dam height"));
  o.vector("position", b.position, Spec{.unit = "m", .doc = "centre at release (overrides impact_height and gap)"});
  o.number("gap", b.gap, nonneg("m", "clearance to the face at release along the path; default 2 cells"));
  o.number("across", b.across, Spec{.unit = "m", .doc = "3D (analysis.dimension 3): where the boulder strikes across the channel, y from the "
                                                        "middle of the dam (0: the middle of the crest, or the middle column)"});
  o.choice<std::string>("model", b.model, {{"auto", "auto"}, {"rigid", "rigid"}, {"elastic", "elastic"}},
                        Spec{.doc = "auto: rigid when it strikes a tyre buffer (its deformation does not matter against rubber thousands of "
                                    "times softer, and the step is then the buffer's, not the rock's); on a bare face elastic while it can "
                                    "touch the dam (the rock's elasticity sets a hard impact's peak) and rigid in free flight before and "
                                    "after the strike (bodies[].rigid_when_free); rigid or elastic (throughout) to choose. A rigid boulder "
                                    "that reaches a member stops the run"});
  o.finish();
  if (o.documenting()) return;
  if ((b.diameter > 0) == (b.mass > 0)) o.fail("diameter", nullptr, "either diameter or mass (exactly one of them)");
  if (!o.context().accept_unusual) {  // a boulder that check dams are designed for, in SI (accept_unusual: a model scale)
    char buf[200];
    if (b.mass > 0 && !(b.mass >= 50 && b.mass <= 5e5)) {
      if (b.mass < 50)
        std::snprintf(buf, sizeof buf, "a boulder mass in kg between 50 and 500000 (%g t is %g kg; a weight of %g kN is a mass of %.0f kg)",
                      b.mass, b.mass * 1e3, b.mass, b.mass * 1e3 / 9.81);
      else
        std::snprintf(buf, sizeof buf, "a boulder mass in kg between 50 and 500000");
      o.fail("mass", o.given("mass"), buf);
    }
    if (b.diameter > 0 && !(b.diameter >= 0.2 && b.diameter <= 10)) {
      o.fail("diameter", o.given("diameter"), "a boulder diameter in m between 0.2 and 10 (cm or mm given?)");
    }
  }
  if (b.velocity.empty() == !(b.release_height > 0)) o.fail("velocity", nullptr, "either velocity or release_height (exactly one of them)");
}

void read_debris(Obj o, DebrisPreset& d) {
  const json* hg = o.raw("hydrograph", Spec{.doc = "instead of depth, length and velocity: the flow entering the channel through a section "
                                                   "section_distance upstream of the dam, as depth (m, normal to the bed), velocity (m/s, along "
                                                   "the bed) and optionally density (kg/m^3) against time (s) from a run-out model: a CSV file "
                                                   "(relative to the scenario's folder; header row time, depth, velocity[, density]) or an object "
                                                   "of equal-length arrays {\"time\": [...], \"depth\": [...], \"velocity\": [...]}"},
                         "string or object", "");
  if (hg) d.hydrograph = read_hydrograph(*hg, o.context().file, o.path() + "/hydrograph");
  const bool given = !d.hydrograph.empty();
  if (!o.documenting() && given)
    for (const char* k : {"depth", "length", "velocity", "gap", "front_length"})
      if (const json* v = o.raw(k, Spec{}, "number", "")) o.fail(k, v, "no " + std::string(k) + " with a hydrograph (the hydrograph gives the flow)");
  o.number("depth", d.depth, positive("m", "flow depth, normal to the bed (without a hydrograph)", !given));
  o.number("length", d.length, positive("m", "surge length along the bed (without a hydrograph)", !given));
  o.number("velocity", d.velocity, positive("m/s", "front speed along the bed, towards the dam (without a hydrograph)", !given));
  o.number("section_distance", d.section_distance, positive("m", "with a hydrograph: distance along the bed from the dam face (or buffer) "
                                                                 "to the inflow section; default 2 V / H + 2 h_max (V the hydrograph's volume per metre, H the dam height: its deposit "
                                                                 "as a triangle as high as the dam), at least 1 m. The run stops if the deposit reaches the section"));
  o.number("channel_slope", d.slope, Spec{.unit = "deg", .doc = "bed inclination (rising upstream)", .min = 0, .max = 45, .max_open = true});
  o.number("gap", d.gap, nonneg("m", "distance from the surge front to the dam face (or buffer) at t = 0; default 2 cells"));
  o.number("bed_friction", d.bed_friction, nonneg("", "Coulomb friction coefficient of the bed"));
  o.number("front_length", d.front_length, nonneg("m", "length along the bed over which the depth rises from nothing at the front "
                                                       "to the full depth (a wedge-shaped snout); 0 is a blunt, vertical front. Default: the "
                                                       "Coulomb wedge depth / (bed_friction - tan(channel_slope)), at least the depth and at most "
                                                       "half the length"));
  if (!o.documenting() && d.front_length > d.length) {
    const json v = d.front_length;
    char buf[96];
    std::snprintf(buf, sizeof buf, "at most the surge length (%g m)", d.length);
    o.fail("front_length", &v, buf);
  }
  if (!o.documenting() && !given && d.section_distance > 0) o.fail("section_distance", nullptr, "a hydrograph to go with section_distance");
  d.material = material_object(o, "material", json{{"model", "drucker_prager"}, {"density", 2000}, {"youngs_modulus", 20e6}, {"poisson_ratio", 0.3},
                                                   {"cohesion", 0}, {"friction_angle", 30}},
                               "debris law: drucker_prager (granular, default), mu_i (dense granular flow) or a slurry (bingham, newtonian)", "debris");
  if (!o.documenting() && !o.context().accept_unusual && d.material.contains("density")) {
    const double rho = d.material.value("density", 0.0);
    if (!(rho >= 900 && rho <= 2700)) {
      char buf[200];
      std::snprintf(buf, sizeof buf, "a density in kg/m^3 between 900 and 2700 for debris (a unit weight of %g kN/m^3 is a density of %.0f kg/m^3)",
                    rho, rho * 1e3 / 9.81);
      o.fail("material/density", &d.material.at("density"), buf);
    }
  }
  o.finish();
}

void read_buffer(Obj o, BufferPreset& b) {
  o.choice<std::string>("type", b.type, {{"homogenised", "homogenised"}, {"discrete", "discrete"}},
                        Spec{.doc = "homogenised: one rubber layer bonded to the upstream face; discrete: a column of tyres (rubber "
                                    "rings, axis across the channel) bonded to the face, optionally filled"});
  o.number("bottom", b.bottom, nonneg("m", "lowest point of the buffer above the ground"));
  o.number("top", b.top, positive("m", "highest point; default the dam height"));
  o.number("viscosity", b.viscosity, positive("Pa s", "instead of material.damping_ratio: Kelvin-Voigt shear viscosity eta; the "
                                                      "stiffness-proportional time beta = eta / mu (mu the shear modulus)"));
  if (o.when("type", b.type, "homogenised")) {
    o.number("thickness", b.thickness, positive("m", "layer thickness (horizontal)", true));
    b.material = material_object(o, "material", json{{"model", "neo_hookean"}, {"density", 600}, {"youngs_modulus", 2e6}, {"poisson_ratio", 0.3},
                                                     {"damping_ratio", 0.15}},
                                 "homogenised tyre layer (effective modulus of the stack; damping_frequency defaults to the "
                                 "boulder-on-buffer frequency)", "tyre_buffer", json{{"damping_frequency", 1.0}});
  }
  o.end_when();
  if (o.when("type", b.type, "discrete")) {
    o.number("tyre_diameter", b.tyre_diameter, positive("m", "outer diameter of a tyre"));
    o.number("ring_thickness", b.ring_thickness, positive("m", "rubber ring thickness in the section (tread and sidewalls homogenised)"));
    o.choice<std::string>("fill", b.fill, {{"none", "none"}, {"sand", "sand"}, {"gravel", "gravel"}},
                          Spec{.doc = "filling of the tyres: none, sand or gravel (Drucker-Prager)"});
    b.material = material_object(o, "material", json{{"model", "neo_hookean"}, {"density", 1100}, {"youngs_modulus", 10e6}, {"poisson_ratio", 0.4},
                                                     {"damping_ratio", 0.1}},
                                 "tyre rubber (damping_frequency defaults to the boulder-on-buffer frequency)", "tyre_rubber",
                                 json{{"damping_frequency", 1.0}});
  }
  o.end_when();
  o.finish();
}

}  // namespace

bool has_presets(const json& j) {
  if (!j.is_object()) return false;
  for (const char* k : kPresetKeys)
    if (j.contains(k) && std::string(k) != "accept_unusual") return true;  // accept_unusual alone: a low-level scenario's
  return false;
}

namespace {

// The variants of the compare key alone: {""} or the buffer pair.
std::vector<std::string> buffer_variants(const json& j, const std::string& file) {
  if (!j.contains("compare")) return {""};
  const json& c = j["compare"];
  if (c != "with_and_without_buffer" && c != "none")
    throw InputError(file, "/compare", schema::short_dump(c), "with_and_without_buffer or none");
  if (c == "none") return {""};
  if (!j.contains("tyre_buffer"))
    throw InputError(file, "/compare", schema::short_dump(c), "a tyre_buffer to compare with (there is none)");
  return {"with_buffer", "without_buffer"};
}

// compare_3d: true asks for the 3D model of a plane boulder scenario beside it.
bool wants_3d(const json& j, const std::string& file) {
  if (!j.contains("compare_3d")) return false;
  const json& c = j["compare_3d"];
  if (!c.is_boolean()) throw InputError(file, "/compare_3d", schema::short_dump(c), "true or false");
  if (!c.get<bool>()) return false;
  if (j.contains("analysis") && j["analysis"].is_object() && j["analysis"].value("dimension", 2) == 3)
    throw InputError(file, "/compare_3d", "true", "a plane scenario (analysis.dimension 2) to set beside its 3D model");
  if (!j.contains("boulder") || j.contains("debris_surge"))
    throw InputError(file, "/compare_3d", "true", "a boulder on the dam (the 3D presets build no debris surge)");
  if (!j.contains("dam") || !j["dam"].is_object() || !j["dam"].contains("width"))
    throw InputError(file, "/dam/width", "", "the dam's width (a concrete dam's crest length, a steel dam's column spacing) for the 3D "
                                             "model of compare_3d");
  if (j.contains("grid") && j["grid"].is_object() && (j["grid"].contains("origin") || j["grid"].contains("size")))
    throw InputError(file, "/grid", "", "only grid.cell_size with compare_3d (the 3D model builds its own grid)");
  return true;
}

}  // namespace

std::vector<std::string> preset_variants(const json& j, const std::string& file) {
  if (!j.is_object()) return {""};
  std::vector<std::string> v = buffer_variants(j, file);
  if (wants_3d(j, file)) {
    const std::size_t n = v.size();
    for (std::size_t k = 0; k < n; ++k) v.push_back(space_variant(v[k]));
  }
  return v;
}

void document_presets(Obj& o) {
  DamPreset d;
  BoulderPreset b;
  DebrisPreset f;
  BufferPreset t;
  read_dam(o.object("dam", "preset: the check dam (expanded into a structure or a body; docs/presets.md)"), d);
  read_boulder(o.object("boulder", "preset: a boulder thrown at the dam's upstream face"), b);
  read_debris(o.object("debris_surge", "preset: a debris surge running down the channel into the dam"), f);
  read_buffer(o.object("tyre_buffer", "preset: waste tyres on the upstream face"), t);
  std::string c;
  o.string("compare", c, Spec{.doc = "with_and_without_buffer: run the scenario with and without its tyre_buffer (OUT/with_buffer, "
                                     "OUT/without_buffer) | none"});
  bool space = false;
  o.boolean("compare_3d", space, Spec{.doc = "also run the 3D model of this plane boulder scenario (OUT/3d, or OUT/with_buffer_3d and "
                                             "OUT/without_buffer_3d): the boulder a sphere, the dam's crest length its width, and the "
                                             "report sets the plane model's governing numbers beside the 3D ones (both are judged)"});
  bool unusual = false;
  o.boolean("accept_unusual", unusual, Spec{.doc = "accept preset values outside their plausible ranges (materials, boulder, debris and "
                                                    "deposit unit weights: docs/presets.md), for scaled or laboratory models"});
}

namespace {

// The plane preset keys as the 3D model reads them: vectors [x, y] become [x, 0, y] (the elevation is the plane
// y = 0, z up), analysis.dimension 3; the solid check (a plane-run feature) is left to the plane variant.
json space_presets(const json& j) {
  json s = j;
  auto lift = [](json& v) {
    if (v.is_array() && v.size() == 2) v = json::array({v[0], 0.0, v[1]});
  };
  s["analysis"]["dimension"] = 3;
  if (s["analysis"].contains("gravity")) lift(s["analysis"]["gravity"]);
  if (s.contains("boulder") && s["boulder"].is_object())
    for (const char* k : {"velocity", "position"})
      if (s["boulder"].contains(k)) lift(s["boulder"][k]);
  s.erase("solid_check");
  s.erase("compare_3d");
  return s;
}

}  // namespace

json expand_presets(const json& j0, const std::string& file, const std::string& variant0) {
  const bool space = is_space_variant(variant0);
  const json j = space ? space_presets(j0) : j0;
  const std::string variant = plane_variant(variant0);
  PresetScene p;
  if (j.contains("analysis") && j["analysis"].is_object() && j["analysis"].contains("dimension")) {
    const json& d = j["analysis"]["dimension"];
    if (d != 2 && d != 3) throw InputError(file, "/analysis/dimension", schema::short_dump(d), "2 (an elevation, plane strain) or 3 with presets");
    p.dim = d.get<int>();
  }
  if (p.dim == 3) {  // what the 3D presets build (docs/presets.md, "In three dimensions")
    for (const char* k : {"debris_surge", "solid_check"})
      if (j.contains(k))
        throw InputError(file, "/" + std::string(k), "", std::string("no ") + k + " with analysis.dimension 3: the 3D presets build a concrete_gravity "
                         "(members) or steel_open dam struck by a boulder, with a homogenised tyre buffer on a concrete dam; surges and the "
                         "solid check are 2D presets for now");
    if (j.contains("tyre_buffer") && j["tyre_buffer"].is_object()) {
      const json& t = j["tyre_buffer"];
      if (t.value("type", std::string("homogenised")) != "homogenised")
        throw InputError(file, "/tyre_buffer/type", schema::short_dump(t["type"]), "homogenised with analysis.dimension 3 (discrete tyres are 2D for now)");
      const json& dam = j.contains("dam") && j["dam"].is_object() ? j["dam"] : json::object();
      if (dam.value("type", std::string()) != "concrete_gravity")
        throw InputError(file, "/tyre_buffer", "", "a tyre buffer on a concrete_gravity dam with analysis.dimension 3 (a slit dam's buffer is 2D for now)");
      if (dam.value("sloped_face", std::string("downstream")) != "downstream")
        throw InputError(file, "/dam/sloped_face", schema::short_dump(dam["sloped_face"]),
                         "downstream (a vertical upstream face) under a 3D tyre buffer: the layer is a box on the face");
    }
  }
  if (p.dim == 3 && j.contains("dam") && j["dam"].is_object() && j["dam"].value("model", std::string("members")) != "members")
    throw InputError(file, "/dam/model", schema::short_dump(j["dam"]["model"]), "members with analysis.dimension 3 (the continuum dam is 2D for now)");
  schema::Context ctx{.file = file, .dim = p.dim};
  if (j.contains("accept_unusual")) {
    if (!j["accept_unusual"].is_boolean()) throw InputError(file, "/accept_unusual", schema::short_dump(j["accept_unusual"]), "true or false");
    ctx.accept_unusual = j["accept_unusual"].get<bool>();
  }
  Obj root(&j, "", ctx);
  if (!j.contains("dam")) throw InputError(file, "/dam", "", "a dam preset with the other presets (boulder, debris_surge and tyre_buffer act on it)");
  read_dam(root.object("dam", ""), p.dam);
  if (j.contains("boulder")) read_boulder(root.object("boulder", ""), p.boulder.emplace());
  if (j.contains("debris_surge")) read_debris(root.object("debris_surge", ""), p.debris.emplace());
  if (j.contains("tyre_buffer")) read_buffer(root.object("tyre_buffer", ""), (variant == "without_buffer" ? p.compared_buffer : p.buffer).emplace());
  if (!p.boulder && !p.debris) {
    std::vector<std::string> present;
    for (auto it = j.begin(); it != j.end(); ++it) present.push_back(it.key());
    std::string near = schema::closest_key("boulder", present);
    if (near.empty()) near = schema::closest_key("debris_surge", present);
    throw InputError(file, "/boulder", "", std::string("a boulder or a debris_surge hitting the dam") +
                                               (near.empty() ? "" : " ('" + near + "' is there instead: misspelled?)"));
  }
  if (j.contains("grid") && j["grid"].is_object() && j["grid"].contains("cell_size") && j["grid"]["cell_size"].is_number())
    p.cell_size = j["grid"]["cell_size"].get<double>();
  if (j.contains("analysis") && j["analysis"].is_object() && j["analysis"].contains("gravity")) p.gravity_given = true;
  json low = build_preset_scene(p, file);
  if (j.contains("solid_check") && p.dam.type == "concrete_gravity")  // the dam body's geometry and concrete by default
    low["solid_check"] = json{{"height", p.dam.height}, {"crest_thickness", p.dam.crest}, {"base_thickness", p.dam.base_thickness},
                              {"width", p.dam.width}, {"sloped_face", p.dam.sloped_face},
                              {"youngs_modulus", p.dam.concrete.value("youngs_modulus", 25e9)},
                              {"poisson_ratio", p.dam.concrete.value("poisson_ratio", 0.2)}};
  // Merge the user's low-level keys: objects key by key (user wins), arrays appended.
  for (auto it = j.begin(); it != j.end(); ++it) {
    if (std::find(std::begin(kPresetKeys), std::end(kPresetKeys), it.key()) != std::end(kPresetKeys)) continue;
    merge_json(low[it.key()], it.value());
  }
  if (!variant.empty()) low["name"] = low.value("name", std::string()) + (variant == "with_buffer" ? " (with buffer)" : " (without buffer)");
  if (space) low["name"] = low.value("name", std::string()) + " (3D)";
  if (ctx.accept_unusual) low["accept_unusual"] = true;  // the low-level keys' own ranges (e.g. a solid check's force)
  return low;
}

void merge_json(json& into, const json& from) {
  if (into.is_object() && from.is_object()) {
    for (auto it = from.begin(); it != from.end(); ++it) merge_json(into[it.key()], it.value());
  } else if (into.is_array() && from.is_array()) {
    for (const auto& e : from) into.push_back(e);
  } else {
    into = from;
  }
}

}  // namespace dmi
