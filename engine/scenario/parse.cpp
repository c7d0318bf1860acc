// The scenario schema, version 1: every key declared once here (default, unit, doc, validation).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "engine/common/error.hpp"
#include "engine/scenario/scenario.hpp"
#include "engine/scenario/schema.hpp"

namespace dmi {

using schema::Obj;
using schema::Spec;
using json = nlohmann::json;

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();
Spec positive(const std::string& unit, const std::string& doc, bool required = false) {
  return Spec{.unit = unit, .doc = doc, .min = 0, .min_open = true, .required = required};
}
Spec any(const std::string& unit, const std::string& doc, bool required = false) {
  return Spec{.unit = unit, .doc = doc, .required = required};
}

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
  o.finish();
  if (a.dimension == 3) a.plane = Plane::none;
}

void read_mpm(Obj o, MpmConfig& m) {
  o.choice<ShapeKind>("shape_function", m.shape,
                      {{"linear", ShapeKind::linear}, {"gimp", ShapeKind::gimp}, {"bspline2", ShapeKind::bspline2}},
                      Spec{.doc = "grid shape functions: linear (Sulsky 1994), uGIMP (Bardenhagen & Kober 2004), quadratic B-spline"});
  o.choice<TransferKind>("transfer", m.transfer, {{"flip", TransferKind::flip}, {"apic", TransferKind::apic}},
                         Spec{.doc = "particle velocity update: FLIP/PIC blend (SEEDS.md A.1 eq. 13) or APIC (Jiang et al. 2015)"});
  o.number("flip_blend", m.flip_blend, Spec{.doc = "FLIP fraction of the FLIP/PIC blend: 1 = pure FLIP, 0 = pure PIC (transfer = flip only)", .min = 0, .max = 1});
  // Linear shape functions with USL are unstable when a particle barely touches a node (tiny nodal
  // mass, full force gradient): MUSL's remapped velocities avoid it, so it is their default.
  m.update = m.shape == ShapeKind::linear ? StressUpdate::musl : StressUpdate::usl;
  o.choice<StressUpdate>("stress_update", m.update, {{"usl", StressUpdate::usl}, {"musl", StressUpdate::musl}},
                         Spec{.doc = "update stress last (USL, SEEDS.md A.1) or modified USL with a momentum remap (MUSL); "
                                     "default usl, but musl for linear shape functions (USL with linear shapes is unstable at nearly empty nodes)"});
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

void read_material(Obj& o, MaterialConfig& m) {
  o.string("name", m.name, Spec{.doc = "name that bodies refer to", .required = true});
  m.model = "linear_elastic";
  o.string("model", m.model, Spec{.doc = "material law: linear_elastic (small strain, Jaumann rate) | neo_hookean (compressible, large strain)"});
  if (!o.documenting() && m.model != "linear_elastic" && m.model != "neo_hookean")
    o.fail("model", nullptr, "linear_elastic or neo_hookean (got '" + m.model + "')");
  o.number("density", m.density, positive("kg/m^3", "mass density", true));
  o.number("youngs_modulus", m.youngs_modulus, positive("Pa", "Young's modulus E", true));
  o.number("poisson_ratio", m.poisson_ratio, Spec{.doc = "Poisson's ratio", .min = -1, .max = 0.5, .min_open = true, .max_open = true, .required = true});
}

void read_shape(Obj o, ShapeConfig& s) {
  o.string("type", s.type, Spec{.doc = "box (rectangle in 2D) | ball (disk in 2D, sphere in 3D)", .required = true});
  if (o.when("type", s.type, "box")) {
    o.vector("min", s.min, any("m", "lower corner", true));
    o.vector("max", s.max, any("m", "upper corner", true));
  }
  o.end_when();
  if (o.when("type", s.type, "ball")) {
    o.vector("center", s.center, any("m", "centre", true));
    o.number("radius", s.radius, positive("m", "radius", true));
  }
  o.end_when();
  if (!o.documenting() && s.type != "box" && s.type != "ball") o.fail("type", nullptr, "box or ball (got '" + s.type + "')");
  o.finish();
}

void read_body(Obj& o, BodyConfig& b) {
  o.string("name", b.name, Spec{.doc = "body name, used by probes and in messages", .required = true});
  o.string("material", b.material, Spec{.doc = "name of an entry in materials", .required = true});
  read_shape(o.object("shape", "region the body fills; particles are seeded on a regular sub-grid of every cell inside it"), b.shape);
  o.integer("particles_per_cell", b.particles_per_cell, Spec{.doc = "particles per cell along each axis", .min = 1, .max = 8});
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
                          Spec{.doc = "multi_field: one velocity field per body with Bardenhagen (2000) contact, bodies can separate and slide; "
                                      "single_field: all bodies share one field (no-slip, they stick on touching)"});
  o.number("friction", c.friction, Spec{.doc = "Coulomb friction coefficient between bodies (multi_field)", .min = 0});
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
}

void read_region(Obj& o, PrescribedVelocityConfig& r) {
  o.string("name", r.name, Spec{.doc = "region name; its force history is stored as regions/<name>/force", .required = true});
  o.vector("min", r.min, any("m", "lower corner of the region of grid nodes", true));
  o.vector("max", r.max, any("m", "upper corner", true));
  o.vector("velocity", r.velocity, any("m/s", "prescribed nodal velocity", true));
  o.number("start", r.start, Spec{.unit = "s", .doc = "active from this time", .min = 0});
  o.number("end", r.end, Spec{.unit = "s", .doc = "active until this time (default: always)", .min = 0});
}

void read_probe(Obj& o, ProbeConfig& p) {
  o.string("name", p.name, Spec{.doc = "probe name; series are stored as probes/<name>/<quantity>", .required = true});
  o.string("type", p.type, Spec{.doc = "particle (the particle nearest to point) | body (centroid and mean values of a body)", .required = true});
  o.string("body", p.target, Spec{.doc = "body the probe looks at", .required = true});
  if (o.when("type", p.type, "particle")) o.vector("point", p.point, any("m", "initial position; the nearest particle of the body is tracked", true));
  o.end_when();
  const bool particle = p.type == "particle";
  if (!o.documenting() && !particle && p.type != "body") o.fail("type", nullptr, "particle or body (got '" + p.type + "')");
  std::vector<std::string> all = particle_probe_quantities();
  if (o.documenting() || !particle) for (const auto& q : body_probe_quantities()) if (std::find(all.begin(), all.end(), q) == all.end()) all.push_back(q);
  const auto& allowed = o.documenting() ? all : (particle ? particle_probe_quantities() : body_probe_quantities());
  o.strings("quantities", p.quantities, allowed,
            Spec{.doc = "quantities to record (default: all); particle: displacement position velocity stress von_mises; body: position displacement velocity kinetic_energy"});
  if (p.quantities.empty()) p.quantities = allowed;
}

void read_output(Obj o, OutputConfig& out) {
  o.number("snapshot_interval", out.snapshot_interval, Spec{.unit = "s", .doc = "time between particle field snapshots; 0 = initial and final state only", .min = 0});
  o.number("history_interval", out.history_interval, Spec{.unit = "s", .doc = "time between history samples (energies, probes, wall forces); 0 = every step", .min = 0});
  o.boolean("vtk", out.vtk, Spec{.doc = "also write ParaView files fields/particles_NNNN.vtu and fields/particles.pvd"});
  o.array<ProbeConfig>("probes", out.probes, Spec{.doc = "named points and quantities recorded as histories"}, read_probe);
  o.finish();
}

void read_scenario(Obj& o, Scenario& s) {
  o.integer("schema_version", s.schema_version, Spec{.doc = "scenario format version; must be 1", .min = 1, .max = 1, .required = true});
  o.string("name", s.name, Spec{.doc = "scenario name, shown in outputs and reports", .required = true});
  o.string("description", s.description, Spec{.doc = "free text"});
  read_analysis(o.object("analysis", "dimension, kinematics, duration, time step and gravity"), s.analysis);
  read_mpm(o.object("mpm", "material point method options"), s.mpm);
  read_grid(o.object("grid", "the background grid"), s.grid);
  o.array<MaterialConfig>("materials", s.materials, Spec{.doc = "material laws", .required = true}, read_material);
  o.array<BodyConfig>("bodies", s.bodies, Spec{.doc = "continuum bodies discretised by particles", .required = true}, read_body);
  read_contact(o.object("contact", "contact between bodies"), s.contact);
  o.array<WallConfig>("walls", s.walls, Spec{.doc = "rigid fixed walls acting on grid nodes"}, read_wall);
  o.array<PrescribedVelocityConfig>("prescribed_velocity", s.prescribed_velocity, Spec{.doc = "regions of grid nodes moving with a given velocity"}, read_region);
  read_output(o.object("output", "what is recorded"), s.output);
  o.finish();
}

std::string value_text(const DVec& v) { return json(v).dump(); }
std::string value_text(double x) { return json(x).dump(); }

// Cross-references and geometry: what a single key cannot check.
void check_semantics(const Scenario& s, const std::string& file) {
  const int dim = s.analysis.dimension;
  if (s.bodies.empty()) throw InputError(file, "/bodies", "[]", "at least one body");
  std::set<std::string> mats, bodies, walls;
  auto dup = [&](std::set<std::string>& set, const std::string& name, const std::string& path) {
    if (!set.insert(name).second) throw InputError(file, path, "\"" + name + "\"", "a name not used before in this list");
  };
  for (std::size_t i = 0; i < s.materials.size(); ++i) dup(mats, s.materials[i].name, "/materials/" + std::to_string(i) + "/name");
  const double h = s.grid.cell_size;
  for (int d = 0; d < dim; ++d)
    if (!(s.grid.size[d] > h))
      throw InputError(file, "/grid/cell_size", value_text(h), "a cell size smaller than the grid size along every axis (grid size " +
                                                                 value_text(s.grid.size) + ")");
  double est = 0;
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    const BodyConfig& b = s.bodies[i];
    const std::string p = "/bodies/" + std::to_string(i);
    dup(bodies, b.name, p + "/name");
    if (!mats.count(b.material)) throw InputError(file, p + "/material", "\"" + b.material + "\"", "the name of one of the materials");
    DVec lo(dim), hi(dim);
    for (int d = 0; d < dim; ++d) {
      lo[d] = b.shape.type == "box" ? b.shape.min[d] : b.shape.center[d] - b.shape.radius;
      hi[d] = b.shape.type == "box" ? b.shape.max[d] : b.shape.center[d] + b.shape.radius;
      if (b.shape.type == "box" && !(hi[d] > lo[d]))
        throw InputError(file, p + "/shape/max", value_text(b.shape.max), "max > min along every axis (min = " + value_text(b.shape.min) + ")");
      // Every particle must lie at least half a cell inside the grid (shape function support).
      const double glo = s.grid.origin[d] + 0.5 * h, ghi = s.grid.origin[d] + s.grid.size[d] - 0.5 * h;
      if (lo[d] < glo - 1e-12 || hi[d] > ghi + 1e-12) {
        std::ostringstream os;
        os << "a body inside the grid interior [" << glo << ", " << ghi << "] m along axis " << d
           << " (half a cell from the grid edge); it spans [" << lo[d] << ", " << hi[d] << "]";
        throw InputError(file, p + "/shape", "", os.str());
      }
    }
    double vol = 1;
    for (int d = 0; d < dim; ++d) vol *= (hi[d] - lo[d]) / h;
    est += vol * std::pow(b.particles_per_cell, dim);
  }
  if (est > 2e8)
    throw InputError(file, "/bodies", "", "at most 2e8 particles in all (these bodies would need about " +
                                              std::to_string(static_cast<long long>(est)) + "); use larger cells");
  double cells = 1;
  for (int d = 0; d < dim; ++d) cells *= std::ceil(s.grid.size[d] / h);
  if (cells > 4e8) throw InputError(file, "/grid/cell_size", value_text(h), "a cell size giving at most 4e8 cells");
  for (std::size_t i = 0; i < s.walls.size(); ++i) {
    const WallConfig& w = s.walls[i];
    const std::string p = "/walls/" + std::to_string(i);
    dup(walls, w.name, p + "/name");
    if (w.type == "plane") {
      double n2 = 0;
      for (double x : w.normal) n2 += x * x;
      if (!(n2 > 0)) throw InputError(file, p + "/normal", value_text(w.normal), "a non-zero normal vector");
    } else {
      for (int d = 0; d < dim; ++d)
        if (!(w.max[d] > w.min[d]))
          throw InputError(file, p + "/max", value_text(w.max), "max > min along every axis (min = " + value_text(w.min) + ")");
    }
  }
  for (std::size_t i = 0; i < s.prescribed_velocity.size(); ++i) {
    const auto& r = s.prescribed_velocity[i];
    const std::string p = "/prescribed_velocity/" + std::to_string(i);
    dup(walls, r.name, p + "/name");
    for (int d = 0; d < dim; ++d)
      if (!(r.max[d] > r.min[d]))
        throw InputError(file, p + "/max", value_text(r.max), "max > min along every axis (min = " + value_text(r.min) + ")");
    if (r.end <= r.start) throw InputError(file, p + "/end", value_text(r.end), "end > start (start = " + value_text(r.start) + ")");
  }
  std::set<std::string> probes;
  for (std::size_t i = 0; i < s.output.probes.size(); ++i) {
    const auto& pr = s.output.probes[i];
    const std::string p = "/output/probes/" + std::to_string(i);
    dup(probes, pr.name, p + "/name");
    if (!bodies.count(pr.target)) throw InputError(file, p + "/body", "\"" + pr.target + "\"", "the name of one of the bodies");
  }
}

}  // namespace

const std::vector<std::string>& particle_probe_quantities() {
  static const std::vector<std::string> q = {"displacement", "position", "velocity", "stress", "von_mises"};
  return q;
}
const std::vector<std::string>& body_probe_quantities() {
  static const std::vector<std::string> q = {"position", "displacement", "velocity", "kinetic_energy"};
  return q;
}

Scenario parse_scenario(const json& j, const std::string& file) {
  Scenario s;
  schema::Context ctx{.file = file};
  if (!j.is_object()) throw InputError(file, "/", schema::short_dump(j), "a JSON object (a scenario)");
  Obj o(&j, "", ctx);
  read_scenario(o, s);
  check_semantics(s, file);
  s.source_file = file;
  return s;
}

Scenario parse_scenario(const std::string& text, const std::string& file) {
  json j;
  try {
    j = json::parse(text);
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
  Scenario s = parse_scenario(j, file);
  s.source_text = text;
  return s;
}

Scenario load_scenario(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(path + ": is a directory, not a scenario file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the scenario file (does it exist and is it readable?)");
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_scenario(ss.str(), path);
}

std::string scenario_reference_markdown() {
  std::vector<schema::Row> rows;
  schema::Context ctx{.doc = &rows};
  Scenario s;
  Obj o(nullptr, "", ctx);
  read_scenario(o, s);
  return schema::markdown(rows);
}

}  // namespace dmi
