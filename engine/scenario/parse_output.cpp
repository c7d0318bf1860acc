// The scenario reader's output section (probes, pressure sensors, the face profile) and the solid-FE check's section.
#include "engine/scenario/parse_output.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "engine/common/error.hpp"
#include "engine/scenario/scenario.hpp"

namespace dmi {

using schema::Obj;
using schema::Spec;
using schema::any;
using schema::positive;
using schema::nonneg;
using schema::when_any;
using json = nlohmann::json;

namespace {

void read_probe(Obj& o, ProbeConfig& p) {
  o.string("name", p.name, Spec{.doc = "probe name; series are stored as probes/<name>/<quantity>", .required = true});
  o.string("type", p.type, Spec{.doc = "particle (the particle nearest to point) | body (centroid and mean values of a body) | "
                                       "member (a point of a structure member)", .required = true});
  const bool particle = p.type == "particle", member = p.type == "member";
  if (!o.documenting() && !particle && !member && p.type != "body")
    o.fail("type", nullptr, "particle, body or member (got '" + p.type + "')");
  if (when_any(o, "type", p.type, {"particle", "body"})) o.string("body", p.target, Spec{.doc = "body the probe looks at", .required = true});
  o.end_when();
  if (o.when("type", p.type, "particle")) o.vector("point", p.point, any("m", "initial position; the nearest particle of the body is tracked", true));
  o.end_when();
  if (o.when("type", p.type, "member")) {
    o.string("member", p.target, Spec{.doc = "structure member the probe looks at", .required = true});
    o.number("position", p.position, Spec{.doc = "point of the member as a fraction of its length from its start node", .min = 0, .max = 1});
  }
  o.end_when();
  std::vector<std::string> all;
  for (const auto* list : {&particle_probe_quantities(), &body_probe_quantities(), &member_probe_quantities()})
    for (const auto& q : *list) if (std::find(all.begin(), all.end(), q) == all.end()) all.push_back(q);
  const auto& allowed = o.documenting() ? all
                        : particle      ? particle_probe_quantities()
                        : member        ? member_probe_quantities()
                                        : body_probe_quantities();
  o.strings("quantities", p.quantities, allowed,
            Spec{.doc = "quantities to record (default: all); particle: displacement position velocity stress von_mises; "
                        "body: position displacement velocity kinetic_energy volume (its particles' volumes summed, now and as created); member: displacement (centre line, x y), "
                        "top_displacement (the point on the top surface, the +e2 side, e2 = the start-to-end axis e1 turned "
                        "90 degrees counter-clockwise), rotation, section_forces (N V M), fibre_stress (sigma_top sigma_bottom "
                        "tau_max von_mises_top von_mises_bottom von_mises_max)"});
  if (p.quantities.empty()) p.quantities = allowed;
}

void read_sensor(Obj& o, SensorConfig& c) {
  o.string("name", c.name, Spec{.doc = "sensor name; its history is stored as sensors/<name>/pressure", .required = true});
  o.string("wall", c.wall, Spec{.doc = "the wall (plane or box) the sensor sits on; give wall or member"});
  o.string("member", c.member, Spec{.doc = "the structure member whose face the sensor sits on; give wall or member"});
  if (!o.documenting() && c.wall.empty() == c.member.empty()) o.fail("wall", o.given("wall"), "exactly one of wall and member");
  o.vector("point", c.point, any("m", "centre of the sensor, on the wall's surface or the member's face", true));
  o.number("size", c.size, Spec{.unit = "m", .doc = "side of the square the normal traction is averaged over (its length along the "
                                                    "face in 2D), as a transducer's face; at least the cell size is advised",
                                .min = 0, .min_open = true, .required = true});
}

void read_face_profile(Obj o, FaceProfileConfig& f) {
  if (!o.present()) return;
  f.present = true;
  o.strings("members", f.members, {}, Spec{.doc = "the members that make the face, in order, each starting where the last ended", .required = true});
  o.vector("direction", f.direction, any("-", "direction into the face: the normal contact force along it is the pressure", true));
  o.number("width", f.width, Spec{.unit = "m", .doc = "loaded width of the face (3D; required there); a 2D face has the analysis thickness",
                                  .min = 0, .min_open = true});
  o.finish();
  if (o.documenting()) return;
  if (f.members.empty()) o.fail("members", o.given("members"), "at least one member");
  double n = 0;
  for (double v : f.direction) n += v * v;
  if (!(n > 0)) o.fail("direction", o.given("direction"), "a nonzero vector");
  for (double& v : f.direction) v /= std::sqrt(n);
}

void read_solid_load(Obj& o, SolidLoadConfig& l) {
  o.string("name", l.name, Spec{.doc = "load case name, used in results and reports", .required = true});
  o.string("type", l.type, Spec{.doc = "point (one node of the upstream face) | patch (spread over a rectangle of the upstream face) | "
                                       "simulation (the contact loads on a dam member at the instant of the largest contact force "
                                       "of this run, as a pressure on the upstream face)", .required = true});
  if (!o.documenting() && l.type != "point" && l.type != "patch" && l.type != "simulation")
    o.fail("type", nullptr, "point, patch or simulation (got '" + l.type + "')");
  if (when_any(o, "type", l.type, {"point", "patch"})) {
    o.number("force", l.force, positive("N", "horizontal force towards downstream (Lin, Cheng & Tuan: 980 kN)", true));
    // An impact force on a check dam: 10 kN to 1 GN in N (a value in kN is the usual slip).
    if (!o.documenting() && !o.context().accept_unusual && l.force > 0 && (l.force < 1e4 || l.force > 1e9))
    {
      char b[200];
      std::snprintf(b, sizeof b, "a force in N between 1e4 and 1e9 (%g kN is %g N; \"accept_unusual\": true for a laboratory model)", l.force, l.force * 1e3);
      o.fail("force", o.given("force"), b);
    }
    o.number("height", l.height, positive("m", "height of the load (patch centre) above the base", true));
    o.number("across", l.across, Spec{.unit = "m", .doc = "position across the face width from its side edge (hex8); default mid-width"});
  }
  o.end_when();
  if (o.when("type", l.type, "patch")) {
    o.number("patch_width", l.patch_width, positive("m", "patch extent across the face", true));
    o.number("patch_height", l.patch_height, positive("m", "patch extent up the face", true));
    o.choice<std::string>("shape", l.shape, {{"pyramid", "pyramid"}, {"uniform", "uniform"}},
                          Spec{.doc = "pressure decreasing linearly from the centre to the patch edges and corners (Lin, Cheng & Tuan), or uniform"});
  }
  o.end_when();
  if (o.when("type", l.type, "simulation")) {
    o.string("member", l.member, Spec{.doc = "the dam member whose contact loads are taken; default the first member"});
    o.choice<std::string>("spread", l.spread, {{"uniform", "uniform"}, {"axisymmetric", "axisymmetric"}},
                          Spec{.doc = "across the face width (hex8): uniform (the plane-strain model's assumption) or axisymmetric "
                                      "(the vertical profile turned about its centroid: a round contact patch, same resultant)"});
  }
  o.end_when();
}

}  // namespace

void read_output(Obj o, OutputConfig& out) {
  o.number("snapshot_interval", out.snapshot_interval, Spec{.unit = "s", .doc = "time between particle field snapshots; 0 = initial and final state only", .min = 0});
  o.number("history_interval", out.history_interval, Spec{.unit = "s", .doc = "time between history samples (energies, probes, wall forces); 0 = every step", .min = 0});
  o.boolean("vtk", out.vtk, Spec{.doc = "also write ParaView files fields/particles_NNNN.vtu and fields/particles.pvd"});
  o.array<ProbeConfig>("probes", out.probes, Spec{.doc = "named points and quantities recorded as histories"}, read_probe);
  o.array<SensorConfig>("sensors", out.sensors, Spec{.doc = "pressure sensors on walls and member faces, recorded as sensors/<name>/pressure"}, read_sensor);
  read_face_profile(o.object("face_profile", "the pressure profile along a struck face made of members (face/ in results.h5)"), out.face_profile);
  o.finish();
}

void read_solid_check(Obj o, SolidCheckConfig& c) {
  if (!o.present()) return;
  c.present = true;
  o.number("height", c.height, positive("m", "dam height (with a concrete_gravity dam preset: taken from it)", true));
  o.number("crest_thickness", c.crest_thickness, positive("m", "thickness at the crest", true));
  o.number("base_thickness", c.base_thickness, positive("m", "thickness at the base", true));
  o.number("width", c.width, positive("m", "face width across the channel (hex8); 2D quad4: the plane-strain thickness", true));
  o.choice<std::string>("sloped_face", c.sloped_face, {{"downstream", "downstream"}, {"upstream", "upstream"}, {"both", "both"}},
                        Spec{.doc = "which face is battered"});
  o.choice<std::string>("element", c.element, {{"hex8", "hex8"}, {"quad4", "quad4"}},
                        Spec{.doc = "hex8: 3D block (Lin, Cheng & Tuan); quad4: 2D plane-strain section (loads per unit width x width)"});
  DVec cells{8, 10, 20};
  o.vector("cells", cells, Spec{.doc = "elements through the thickness, across the width (hex8 only) and up the height (Lin, Cheng & Tuan: 8 x 10 x 20)",
                                .min = 1, .max = 400}, 3);
  c.cells = {static_cast<int>(cells[0]), static_cast<int>(cells[1]), static_cast<int>(cells[2])};
  o.number("max_dofs", c.max_dofs, Spec{.doc = "meshes with more degrees of freedom are refused before they are solved (8 x 10 x 20 hex8: "
                                               "6 237 DOFs, 0.7 s; 16 x 20 x 40: 43 911, 70 s and 0.8 GB; the cost grows ~ DOFs^2); raise "
                                               "it for a finer mesh on purpose", .min = 1, .max = 1e9});
  o.number("youngs_modulus", c.youngs_modulus, positive("Pa", "concrete Young's modulus"));
  o.number("poisson_ratio", c.poisson_ratio, Spec{.doc = "concrete Poisson's ratio", .min = 0, .max = 0.5, .max_open = true});
  o.array<SolidLoadConfig>("loads", c.loads, Spec{.doc = "load cases, each solved statically (linear elastic, base fixed)", .required = true},
                           read_solid_load);
  o.finish();
  if (o.documenting()) return;
  if (c.loads.empty()) o.fail("loads", nullptr, "at least one load case");
  if (c.base_thickness < c.crest_thickness)
    o.fail("base_thickness", nullptr, "a base thickness >= crest_thickness = " + std::to_string(c.crest_thickness) + " m");
  for (double x : cells)
    if (x != std::floor(x)) o.fail("cells", nullptr, "whole numbers of elements");
  const bool hex = c.element == "hex8";
  const double dofs = hex ? 3.0 * (cells[0] + 1) * (cells[1] + 1) * (cells[2] + 1) : 2.0 * (cells[0] + 1) * (cells[2] + 1);
  if (dofs > c.max_dofs) {
    std::ostringstream os;
    os.precision(3);
    os << "a mesh of at most /solid_check/max_dofs = " << c.max_dofs << " degrees of freedom (this one has " << dofs
       << "; at ~0.7 s x (DOFs / 6 237)^2 it would take about " << 0.7 * (dofs / 6237) * (dofs / 6237) / 60
       << " min); use fewer cells or raise /solid_check/max_dofs";
    const json v = json::array({cells[0], cells[1], cells[2]});
    o.fail("cells", &v, os.str());
  }
}

}  // namespace dmi
