// The beam-column frame's keys (`structure`) and the member contact's (`member_contact`) of the scenario schema,
// declared once here with their defaults, units, docs and validation (the rest of the schema: parse.cpp).
#include <algorithm>
#include <cmath>
#include <set>

#include "engine/common/error.hpp"
#include "engine/scenario/parse_structure.hpp"

namespace dmi {

using schema::Obj;
using schema::Spec;
using json = nlohmann::json;

namespace {

using schema::any;
using schema::positive;
using schema::nonneg;

// --- Beam-column frame (2D; Lin & Yang 2024) -----------------------------------------------------

void read_section(Obj o, SectionConfig& c) {
  o.string("type", c.type, Spec{.doc = "rectangle (solid, width x depth) | pipe (circular hollow section) | "
                                       "tapered_rectangle (solid, depth linear from the start to the end node) | box (rectangular hollow "
                                       "section) | i_section (I or H section, its web in the plane of bending)", .required = true});
  if (!o.documenting() && c.type != "rectangle" && c.type != "pipe" && c.type != "tapered_rectangle" && c.type != "box" && c.type != "i_section")
    o.fail("type", nullptr, "rectangle, pipe, tapered_rectangle, box or i_section (got '" + c.type + "')");
  if (o.when("type", c.type, "rectangle")) {
    o.number("width", c.width, positive("m", "out-of-plane width b", true));
    o.number("depth", c.depth, positive("m", "in-plane depth h; the member surfaces are h/2 from the centre line (Lin & Yang 2024 eq. 23)", true));
  }
  o.end_when();
  if (o.when("type", c.type, "pipe")) {
    o.number("diameter", c.diameter, positive("m", "outer diameter D", true));
    o.number("wall_thickness", c.wall_thickness, positive("m", "wall thickness t, at most D/2 (t = D/2: a solid circle)", true));
  }
  o.end_when();
  if (o.when("type", c.type, "tapered_rectangle")) {
    o.number("width", c.width, positive("m", "out-of-plane width b (constant)", true));
    o.number("depth_start", c.depth_start, positive("m", "in-plane depth at the start node", true));
    o.number("depth_end", c.depth_end, positive("m", "in-plane depth at the end node", true));
  }
  o.end_when();
  if (o.when("type", c.type, "box")) {
    o.number("width", c.width, positive("m", "outer width b (out of plane; 3D: along e3)", true));
    o.number("depth", c.depth, positive("m", "outer depth h (in-plane; 3D: along e2)", true));
    o.number("wall_thickness", c.wall_thickness, positive("m", "wall thickness t, the same all round, below half the width and the depth", true));
  }
  o.end_when();
  if (o.when("type", c.type, "i_section")) {
    o.number("width", c.width, positive("m", "flange width b (out of plane; 3D: along e3)", true));
    o.number("depth", c.depth, positive("m", "overall depth h (in-plane, along the web; 3D: along e2)", true));
    o.number("flange_thickness", c.flange_thickness, positive("m", "flange thickness t_f, below half the depth", true));
    o.number("web_thickness", c.web_thickness, positive("m", "web thickness t_w, below the flange width", true));
  }
  o.end_when();
  o.finish();
}

void read_frame_node(Obj& o, FrameNodeConfig& n) {
  o.string("name", n.name, Spec{.doc = "node name that members, supports and masses refer to", .required = true});
  o.vector("position", n.position, any("m", "position, inside the grid (2 or 3 coordinates, as analysis.dimension)", true), o.context().dim);
}

void read_member(Obj& o, MemberConfig& m) {
  o.string("name", m.name, Spec{.doc = "member name, used by probes and in results; unique, and not the name of a body", .required = true});
  o.string("start", m.start, Spec{.doc = "start node; the member axis e1 points from start to end, e2 is e1 turned 90 degrees "
                                         "counter-clockwise (the top side; 3D: the section's depth direction, see orientation)",
                                  .required = true});
  o.string("end", m.end, Spec{.doc = "end node", .required = true});
  o.string("material", m.material, Spec{.doc = "name of an entry in materials, of model linear_elastic", .required = true});
  read_section(o.object("section", "cross-section; its type is required"), m.section);
  o.integer("elements", m.elements, Spec{.doc = "beam-column elements along the member", .min = 1, .max = 10000});
  if (o.documenting() || o.context().dim == 3)
    o.vector("orientation", m.orientation,
             any("-", "3D only: a vector giving the section's depth direction e2 (its part normal to the member); default the vertical "
                      "(global z), or global x (the flow) for a vertical member. The section's width lies along e3 = e1 x e2"),
             3);
  o.boolean("release_start", m.release_start, Spec{.doc = "moment release (hinge) at the start: the member carries no moment there "
                                                          "(3D: neither bending moment; a ball joint)"});
  o.boolean("release_end", m.release_end, Spec{.doc = "moment release (hinge) at the end"});
}

void read_support(Obj& o, SupportConfig& s) {
  o.string("node", s.node, Spec{.doc = "supported node", .required = true});
  const bool space = o.context().dim == 3;
  o.string("type", s.type, Spec{.doc = "fixed (translations and rotations restrained) | pinned (translations) | roller (one translation) | "
                                       "spring (elastic in every translation and rotation)", .required = true});
  if (!o.documenting() && s.type != "fixed" && s.type != "pinned" && s.type != "roller" && s.type != "spring")
    o.fail("type", nullptr, "fixed, pinned, roller or spring (got '" + s.type + "')");
  if (o.when("type", s.type, "roller")) {
    if (space)
      o.choice<std::string>("restrained", s.restrained, {{"x", "x"}, {"y", "y"}, {"z", "z"}},
                            Spec{.doc = "the restrained translation (global axis); the others and the rotations are free"});
    else
      o.choice<std::string>("restrained", s.restrained, {{"x", "x"}, {"y", "y"}},
                            Spec{.doc = "the restrained translation (global axis); the other one and the rotation are free"});
  }
  o.end_when();
  if (o.when("type", s.type, "spring"))
    o.vector("stiffness", s.stiffness,
             Spec{.unit = space ? "N/m, N m/rad" : "N/m, N/m, N m/rad",
                  .doc = space ? "[kx, ky, kz, krx, kry, krz]: stiffness along and about x, y, z; 0 = free; at least one > 0"
                               : "[kx, ky, kr]: stiffness along x, along y and in rotation; 0 = free; at least one > 0",
                  .min = 0, .required = true},
             space ? 6 : 3);
  o.end_when();
}

void read_nodal_mass(Obj& o, NodalMassConfig& m) {
  o.string("node", m.node, Spec{.doc = "node carrying the mass", .required = true});
  o.number("mass", m.mass, Spec{.unit = "kg", .doc = "point mass added to both translations", .min = 0});
  o.number("rotary_inertia", m.rotary_inertia, Spec{.unit = "kg m^2", .doc = "rotary inertia added to the rotation", .min = 0});
}

void read_pressure_load(Obj& o, PressureLoadConfig& l) {
  o.string("member", l.member, Spec{.doc = "the member loaded", .required = true});
  o.vector("direction", l.direction, Spec{.doc = "direction of the pressure's force (normalised), e.g. [1, 0] (3D [1, 0, 0]) downstream",
                                          .required = true});
  o.number("surface", l.surface, Spec{.unit = "m", .doc = "height of the free surface (y; 3D z); the pressure is zero above it", .required = true});
  o.number("gradient", l.gradient, Spec{.unit = "N/m^2", .doc = "increase of the load per unit height (N/m) with depth below the surface: "
                                                                    "unit weight x pressure coefficient x loaded width", .min = 0,
                                        .min_open = true, .required = true});
}

}  // namespace

void read_structure(Obj o, StructureConfig& st) {
  if (!o.present()) return;
  st.present = true;
  o.choice<BeamTheoryKind>("theory", st.theory, {{"euler_bernoulli", BeamTheoryKind::euler_bernoulli}, {"timoshenko", BeamTheoryKind::timoshenko}},
                           Spec{.doc = "beam theory: euler_bernoulli (no shear deformation) or timoshenko (shear deformation; deep members)"});
  o.choice<FrameTransformKind>("transformation", st.transformation,
                               {{"linear", FrameTransformKind::linear}, {"corotational", FrameTransformKind::corotational}},
                               Spec{.doc = "geometric transformation: linear (small displacement, M and K formed once) or corotational "
                                           "(large displacement and rotation: internal forces and tangent from the current chords; "
                                           "the mass matrix stays the initial one; Lin & Yang 2024)"});
  o.choice<FrameMassKind>("mass", st.mass, {{"lumped", FrameMassKind::lumped}, {"consistent", FrameMassKind::consistent}},
                          Spec{.doc = "element mass matrix: lumped (diagonal) or consistent"});
  o.choice<FrameIntegratorKind>("integrator", st.integrator,
                                {{"explicit", FrameIntegratorKind::explicit_euler}, {"newmark", FrameIntegratorKind::newmark}},
                                Spec{.doc = "frame time integration: explicit (Lin & Yang 2024 eqs. 27-29; its stable step limits the global "
                                            "time step) or newmark (implicit, HHT-alpha form; does not limit the step)"});
  if (o.when("integrator", st.integrator == FrameIntegratorKind::newmark ? "newmark" : "", "newmark"))
    o.number("hht_alpha", st.hht_alpha,
             Spec{.doc = "HHT alpha of the newmark integrator, in [-1/3, 0]: 0 = average acceleration (no numerical damping); "
                         "the default -0.1 damps frame modes far above the time step's resolution, which stick contact "
                         "otherwise pumps (docs/verification.md)", .min = -1.0 / 3, .max = 0});
  o.end_when();
  o.integer("integration_points", st.integration_points,
            Spec{.doc = "Gauss-Lobatto sections along each element of an elastic_plastic member (3 to 5; the end sections, where "
                        "plastic hinges form, are always among them)", .min = 3, .max = 5});
  o.boolean("self_weight", st.self_weight, Spec{.doc = "apply analysis.gravity to the members' own mass"});
  if (o.when("self_weight", st.self_weight ? "true" : "", "true"))
    o.choice<FrameInitialState>("initial_state", st.initial_state,
                                {{"static", FrameInitialState::static_equilibrium}, {"unloaded", FrameInitialState::unloaded}},
                                Spec{.doc = "frame state at t = 0: static (in equilibrium under its self-weight, linear static "
                                            "solution; the default, as a built structure stands) or unloaded (undeformed, so it "
                                            "oscillates about its static sag)"});
  o.end_when();
  Obj r = o.object("rayleigh_damping", "Rayleigh damping of the frame, C = alpha M + beta K; absent: undamped");
  r.number("mass", st.rayleigh_mass, Spec{.unit = "1/s", .doc = "mass-proportional coefficient alpha", .min = 0});
  r.number("stiffness", st.rayleigh_stiffness, Spec{.unit = "s", .doc = "stiffness-proportional coefficient beta "
                                                                         "(linear transformation only: with corotational members the initial "
                                                                         "stiffness would damp rigid rotation)", .min = 0});
  if (!o.documenting() && st.rayleigh_stiffness > 0 && st.transformation == FrameTransformKind::corotational)
    r.fail("stiffness", nullptr, "0 with transformation corotational (beta K0 damps rigid-body rotation of the members; "
                                 "use the mass-proportional term or HHT damping)");
  r.finish();
  Obj md = o.object("modal_damping", "modal damping of the frame: every mode computed from the frame up to max_frequency damped at one "
                                     "ratio (C = sum 2 zeta omega_i M phi_i phi_i^T M), the ratio a hard impact's kHz modes see too; "
                                     "absent: none");
  md.number("ratio", st.modal_damping_ratio, Spec{.doc = "damping ratio zeta of each mode", .min = 0, .max = 1, .max_open = true,
                                                  .required = md.present()});
  md.number("max_frequency", st.modal_damping_max_frequency, Spec{.unit = "Hz", .doc = "modes above it are left undamped; absent: every mode",
                                                                  .min = 0, .min_open = true});
  if (!o.documenting() && st.modal_damping_ratio > 0 && st.transformation == FrameTransformKind::corotational)
    md.fail("ratio", nullptr, "no modal damping with transformation corotational (the modes of the initial stiffness damp rigid-body "
                              "rotation of the members; use the mass-proportional Rayleigh term or HHT damping)");
  md.finish();
  o.array<FrameNodeConfig>("nodes", st.nodes, Spec{.doc = "frame nodes (at least 2), inside the grid", .required = true}, read_frame_node);
  o.array<MemberConfig>("members", st.members, Spec{.doc = "members (at least 1), each a straight beam-column between two nodes", .required = true},
                        read_member);
  o.array<SupportConfig>("supports", st.supports, Spec{.doc = "supports (at least 1, at most one per node)", .required = true}, read_support);
  o.array<NodalMassConfig>("masses", st.masses, Spec{.doc = "point masses and rotary inertias added at nodes"}, read_nodal_mass);
  o.array<PressureLoadConfig>("pressure_loads", st.pressure_loads,
                              Spec{.doc = "permanent linearly increasing pressures on members (earth and water behind a dam), held from "
                                          "t = 0 with the self-weight (the frame starts in equilibrium under both)"},
                              read_pressure_load);
  o.finish();
}

// Members as velocity boundaries of the continua (Yang 2016; Lin & Yang 2024).
void read_member_contact(Obj o, MemberContactConfig& c, bool structure) {
  if (!o.documenting() && o.present() && !structure)
    throw InputError(o.context().file, o.path(), "", "a \"structure\" section as well (member_contact says how the structure's members "
                                                     "act on the bodies, and there is no structure)");
  o.choice<MemberContactMode>("mode", c.mode,
                              {{"stick", MemberContactMode::stick},
                               {"separable", MemberContactMode::separable},
                               {"friction", MemberContactMode::friction}},
                              Spec{.doc = "stick: prescribed member velocity (Lin & Yang 2024 eq. 20), the material sticks; separable: "
                                          "smooth boundary applied only while a node approaches the member (eq. 21); friction: "
                                          "separable plus Coulomb friction"});
  if (o.when("mode", c.mode == MemberContactMode::friction ? "friction" : "", "friction"))
    o.number("friction", c.friction, Spec{.doc = "Coulomb friction coefficient between members and bodies", .min = 0});
  o.end_when();
  o.choice<DecayKind>("decay", c.decay, {{"sharp", DecayKind::sharp}, {"linear", DecayKind::linear}, {"cosine", DecayKind::cosine}},
                      Spec{.doc = "weight q of the boundary force across the decay layer l_n (Lin & Yang 2024, eq. 16): sharp (default) "
                                  "= a node is held fully (q = 1) once on or inside the member surface (within l_n / 2 of it for members "
                                  "thinner than l_n) and stays held while within l_n / 2 more and the material presses (stick: "
                                  "while within l_n, pressing or not), else q = 0; linear 1 - r / l_n or cosine (1 + cos(pi r / l_n)) / 2 hold nodes partly, "
                                  "which acts as a dashpot of impedance ~ q (1 - q) rho c and absorbs a hard elastic impact "
                                  "(docs/verification.md, member contact)"});
  o.number("decay_scale", c.decay_scale, positive("", "multiplies the decay-layer thickness l_n of Lin & Yang 2024 eq. (18)"));
  o.choice<DistanceKind>("distance", c.distance, {{"node", DistanceKind::node}, {"material", DistanceKind::material}},
                         Spec{.doc = "signed distance r that sets q: node (default) = from the grid node itself (Lin & Yang 2024, "
                                     "eq. 23), the node set a rigid wall holds; material = from the mass-weighted particle "
                                     "position the node sees (eq. 25), which engages when the material, not its grid support, "
                                     "reaches the member (docs/verification.md)"});
  o.choice<DetectionKind>("detection", c.detection, {{"surface", DetectionKind::surface}, {"node", DetectionKind::node}},
                          Spec{.doc = "contact detection (sharp decay): surface (default) = a grid node is taken only where the particles whose "
                                        "domains touch the member carry at least half the node's mass (unilateral contact holds it while "
                                        "touched, stick while it stays in its band); node = every node on or inside the member surface with mass is held, "
                                        "which engages the stencil's reach (1.5 h) ahead of the body and makes a hard impact's peak "
                                        "cell-dependent (docs/verification.md, hard impact)"});
  o.strings("bodies", c.bodies, {}, Spec{.doc = "names of the bodies the members act on; empty: all bodies"});
  o.strings("bonded", c.bonded, {}, Spec{.doc = "names of bodies bonded to the members: held by stick contact whatever the mode "
                                                "(a tyre buffer fixed on the dam face, while a boulder meets the dam separably); "
                                                "needs multi_field contact unless every body is bonded"});
  o.finish();
}

}  // namespace dmi
