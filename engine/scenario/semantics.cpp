// The scenario's cross-references and physical sense after its keys are read (parse.cpp): every name a key refers
// to exists, the frame's geometry is connected, bodies lie inside the grid, probes and regions make sense; each error
// names the file, the key's JSON path, the value and what was expected.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include "engine/common/error.hpp"
#include "engine/common/memory.hpp"
#include "engine/scenario/scenario.hpp"
#include "engine/scenario/semantics.hpp"
#include "engine/scenario/shape_geometry.hpp"

namespace dmi {

using json = nlohmann::json;

namespace {

std::string value_text(const DVec& v) { return json(v).dump(); }
std::string value_text(double x) { return json(x).dump(); }

std::string quoted(const std::string& name) { return json(name).dump(); }

// The frame's cross-references and geometry (Lin & Yang 2024); returns the member names.
// Members meet only at shared nodes: coincident nodes, a node inside another member's span, or two
// members crossing would be silently disconnected frames (members do not join where they touch).
void check_frame_geometry(const StructureConfig& st, const std::string& file) {
  std::map<std::string, std::size_t> index;
  for (std::size_t i = 0; i < st.nodes.size(); ++i) index[st.nodes[i].name] = i;
  const std::size_t dim = st.nodes.empty() ? 2 : st.nodes[0].position.size();
  const auto sub = [dim](const DVec& a, const DVec& b) {
    DVec r(dim);
    for (std::size_t d = 0; d < dim; ++d) r[d] = a[d] - b[d];
    return r;
  };
  const auto dot = [dim](const DVec& a, const DVec& b) {
    double r = 0;
    for (std::size_t d = 0; d < dim; ++d) r += a[d] * b[d];
    return r;
  };
  const auto at = [&](std::size_t i) -> const DVec& { return st.nodes[i].position; };
  double scale = 0;
  for (const auto& n : st.nodes)
    for (double x : n.position) scale = std::max(scale, std::abs(x));
  const double tol = 1e-9 * std::max(scale, 1.0);
  for (std::size_t i = 0; i < st.nodes.size(); ++i)
    for (std::size_t j = i + 1; j < st.nodes.size(); ++j)
      if (std::sqrt(dot(sub(at(i), at(j)), sub(at(i), at(j)))) <= tol)
        throw InputError(file, "/structure/nodes/" + std::to_string(j) + "/position", value_text(st.nodes[j].position),
                         "a position apart from node '" + st.nodes[i].name + "' (coincident nodes are not joined; use one node)");
  // Closest points of segments ab and cd at parameters (s, t) (Ericson 2005, Real-Time Collision Detection, sec. 5.1.9);
  // returns their distance.
  const auto segments = [&](const DVec& a, const DVec& b, const DVec& c, const DVec& d, double& s, double& t) {
    const DVec u = sub(b, a), v = sub(d, c), w = sub(a, c);
    const double A = dot(u, u), B = dot(u, v), C = dot(v, v), Dw = dot(u, w), E = dot(v, w), den = A * C - B * B;
    s = den > 1e-14 * A * C ? std::clamp((B * E - C * Dw) / den, 0.0, 1.0) : 0.0;
    t = std::clamp((B * s + E) / C, 0.0, 1.0);
    s = std::clamp((B * t - Dw) / A, 0.0, 1.0);
    DVec q = sub(a, c);
    for (std::size_t k = 0; k < dim; ++k) q[k] += s * u[k] - t * v[k];
    return std::sqrt(dot(q, q));
  };
  for (std::size_t m = 0; m < st.members.size(); ++m) {
    const std::size_t a = index.at(st.members[m].start), b = index.at(st.members[m].end);
    const DVec ab = sub(at(b), at(a));
    const double len2 = dot(ab, ab);
    for (std::size_t i = 0; i < st.nodes.size(); ++i) {  // a node strictly inside the member's span
      if (i == a || i == b) continue;
      const double t = dot(sub(at(i), at(a)), ab) / len2;
      DVec off = sub(at(i), at(a));
      for (std::size_t k = 0; k < dim; ++k) off[k] -= t * ab[k];
      if (t > 0 && t < 1 && std::sqrt(dot(off, off)) <= tol)
        throw InputError(file, "/structure/members/" + std::to_string(m), quoted(st.members[m].name),
                         "a member whose span does not pass through other nodes (node '" + st.nodes[i].name +
                             "' lies on it; split the member there so they are joined)");
    }
    for (std::size_t k = m + 1; k < st.members.size(); ++k) {  // two spans meeting inside both
      const std::size_t c = index.at(st.members[k].start), d = index.at(st.members[k].end);
      if (c == a || c == b || d == a || d == b) continue;
      double s = 0, t = 0;
      if (segments(at(a), at(b), at(c), at(d), s, t) <= tol && s > 0 && s < 1 && t > 0 && t < 1)
        throw InputError(file, "/structure/members/" + std::to_string(k), quoted(st.members[k].name),
                         "a member that does not cross member '" + st.members[m].name +
                             "' (members join only at shared nodes; add a node at the crossing)");
    }
  }
}

// The frame's nodes: unique names, inside the grid (the members act on the grid around them). Returns name -> index.
std::map<std::string, std::size_t> check_frame_nodes(const Scenario& s, const std::string& file) {
  const StructureConfig& st = s.structure;
  const std::string base = "/structure";
  std::map<std::string, std::size_t> nodes;  // name -> index
  const auto& g = s.grid;
  for (std::size_t i = 0; i < st.nodes.size(); ++i) {
    const FrameNodeConfig& n = st.nodes[i];
    const std::string p = base + "/nodes/" + std::to_string(i);
    if (!nodes.emplace(n.name, i).second) throw InputError(file, p + "/name", quoted(n.name), "a name not used before in this list");
    // The members act on the grid nodes around them (Lin & Yang 2024), so the frame must lie on the grid.
    for (std::size_t d = 0; d < n.position.size(); ++d)
      if (n.position[d] < g.origin[d] - 1e-12 || n.position[d] > g.origin[d] + g.size[d] + 1e-12) {
        std::ostringstream os;
        os << "a position inside the grid ";
        for (std::size_t k = 0; k < n.position.size(); ++k)
          os << (k ? " x [" : "[") << g.origin[k] << ", " << g.origin[k] + g.size[k] << "]";
        os << " m (the frame acts on the grid; node '" << n.name << "' is outside along axis " << d << ")";
        throw InputError(file, p + "/position", value_text(n.position), os.str());
      }
  }
  return nodes;
}

// One member between nodes a and b (p its JSON path): a length, an orientation off its axis (3D), a material members
// may have, a pipe wall that fits its diameter.
void check_member(const Scenario& s, const std::string& file, const MemberConfig& m, const std::string& p, std::size_t a, std::size_t b,
                  const std::map<std::string, std::string>& models) {
  const StructureConfig& st = s.structure;
  const DVec &xa = st.nodes[a].position, &xb = st.nodes[b].position;
  double l2 = 0;
  for (std::size_t d = 0; d < xa.size(); ++d) l2 += (xb[d] - xa[d]) * (xb[d] - xa[d]);
  if (!(l2 > 0))
    throw InputError(file, p + "/end", quoted(m.end), "an end node away from the start node '" + m.start + "' (both are at " +
                                                           value_text(xa) + ": a zero-length member)");
  if (m.orientation.size() == 3) {  // 3D: its part normal to the member gives the section's depth direction
    double o2 = 0, od = 0;
    for (std::size_t d = 0; d < 3; ++d) o2 += m.orientation[d] * m.orientation[d], od += m.orientation[d] * (xb[d] - xa[d]);
    if (!(o2 - od * od / l2 > 1e-12 * o2) || !(o2 > 0))
      throw InputError(file, p + "/orientation", value_text(m.orientation),
                       "a vector not parallel to the member (its part normal to the member is the section's depth direction)");
  }
  const auto mat = models.find(m.material);
  if (mat == models.end()) throw InputError(file, p + "/material", quoted(m.material), "the name of one of the materials");
  if (mat->second != "linear_elastic" && mat->second != "elastic_plastic")
    throw InputError(file, p + "/material", quoted(m.material), "a linear_elastic or elastic_plastic material (beam-column members; '" +
                                                                    m.material + "' is " + mat->second + ")");
  if (mat->second == "elastic_plastic" && (m.release_start || m.release_end))
    throw InputError(file, p + (m.release_start ? "/release_start" : "/release_end"), "true",
                     "false for an elastic_plastic member (its end sections yield; a hinge is a linear_elastic member's release)");
  const SectionConfig& c = m.section;
  if (c.type == "pipe" && c.wall_thickness > 0.5 * c.diameter)
    throw InputError(file, p + "/section/wall_thickness", value_text(c.wall_thickness),
                     "a wall thickness <= diameter / 2 = " + value_text(0.5 * c.diameter) + " m");
  if (c.type == "box" && !(2 * c.wall_thickness < std::min(c.width, c.depth)))
    throw InputError(file, p + "/section/wall_thickness", value_text(c.wall_thickness),
                     "a wall thickness below half the smaller side, " + value_text(0.5 * std::min(c.width, c.depth)) + " m (else the section is solid: type rectangle)");
  if (c.type == "i_section" && !(2 * c.flange_thickness < c.depth))
    throw InputError(file, p + "/section/flange_thickness", value_text(c.flange_thickness),
                     "a flange thickness below half the depth, " + value_text(0.5 * c.depth) + " m");
  if (c.type == "i_section" && !(c.web_thickness < c.width))
    throw InputError(file, p + "/section/web_thickness", value_text(c.web_thickness),
                     "a web thinner than the flanges are wide, " + value_text(c.width) + " m");
}

std::set<std::string> check_structure(const Scenario& s, const std::string& file, const std::set<std::string>& bodies) {
  const StructureConfig& st = s.structure;
  const std::string base = "/structure";
  if (st.nodes.size() < 2)
    throw InputError(file, base + "/nodes", "", "at least two nodes (got " + std::to_string(st.nodes.size()) + ")");
  if (st.members.empty()) throw InputError(file, base + "/members", "[]", "at least one member");
  if (st.supports.empty()) throw InputError(file, base + "/supports", "[]", "at least one support (an unsupported frame is a mechanism)");
  const std::map<std::string, std::size_t> nodes = check_frame_nodes(s, file);
  std::map<std::string, std::string> models;  // material name -> model
  for (const auto& m : s.materials) models[m.name] = m.model;
  auto node_ref = [&](const std::string& name, const std::string& path) {
    const auto it = nodes.find(name);
    if (it == nodes.end()) throw InputError(file, path, quoted(name), "the name of one of the structure's nodes");
    return it->second;
  };
  std::set<std::string> members;
  std::vector<bool> connected(st.nodes.size(), false);
  for (std::size_t i = 0; i < st.members.size(); ++i) {
    const MemberConfig& m = st.members[i];
    const std::string p = base + "/members/" + std::to_string(i);
    if (!members.insert(m.name).second) throw InputError(file, p + "/name", quoted(m.name), "a name not used before in this list");
    if (bodies.count(m.name))
      throw InputError(file, p + "/name", quoted(m.name), "a name that no body has (probes refer to bodies and members by name)");
    const std::size_t a = node_ref(m.start, p + "/start"), b = node_ref(m.end, p + "/end");
    if (a == b) throw InputError(file, p + "/end", quoted(m.end), "a node other than the start node");
    connected[a] = connected[b] = true;
    check_member(s, file, m, p, a, b, models);
  }
  for (std::size_t i = 0; i < st.nodes.size(); ++i)
    if (!connected[i])
      throw InputError(file, base + "/nodes/" + std::to_string(i) + "/name", quoted(st.nodes[i].name),
                       "a node used by a member (node '" + st.nodes[i].name + "' is not connected to any member)");
  std::map<std::size_t, std::size_t> supported;  // node index -> support index
  for (std::size_t i = 0; i < st.supports.size(); ++i) {
    const SupportConfig& sp = st.supports[i];
    const std::string p = base + "/supports/" + std::to_string(i);
    const std::size_t n = node_ref(sp.node, p + "/node");
    if (const auto [it, fresh] = supported.emplace(n, i); !fresh)
      throw InputError(file, p + "/node", quoted(sp.node), "a node without another support (supports/" + std::to_string(it->second) +
                                                               " is already on '" + sp.node + "')");
    if (sp.type == "spring" && std::none_of(sp.stiffness.begin(), sp.stiffness.end(), [](double k) { return k > 0; }))
      throw InputError(file, p + "/stiffness", value_text(sp.stiffness), "at least one stiffness > 0 (a spring support with every stiffness 0 "
                                                                         "supports nothing)");
  }
  for (std::size_t i = 0; i < st.masses.size(); ++i) node_ref(st.masses[i].node, base + "/masses/" + std::to_string(i) + "/node");
  for (std::size_t i = 0; i < st.pressure_loads.size(); ++i) {
    const PressureLoadConfig& l = st.pressure_loads[i];
    const std::string p = base + "/pressure_loads/" + std::to_string(i);
    if (!members.count(l.member)) throw InputError(file, p + "/member", quoted(l.member), "the name of a member");
    const std::size_t dim = static_cast<std::size_t>(s.analysis.dimension);
    double norm = 0;
    for (double c : l.direction) norm += c * c;
    if (l.direction.size() != dim || !(norm > 0))
      throw InputError(file, p + "/direction", value_text(l.direction), dim == 3 ? "a non-zero direction [x, y, z]" : "a non-zero direction [x, y]");
  }
  check_frame_geometry(st, file);
  return members;
}

}  // namespace

void check_solid_check(const Scenario& s, const std::string& file) {
  const SolidCheckConfig& c = s.solid_check;
  if (!c.present) return;
  for (std::size_t i = 0; i < c.loads.size(); ++i) {
    const SolidLoadConfig& l = c.loads[i];
    const std::string p = "/solid_check/loads/" + std::to_string(i);
    if (l.type == "simulation") {
      if (!s.structure.present || s.bodies.empty())
        throw InputError(file, p + "/type", quoted(l.type), "point or patch without a simulated structure (type simulation takes "
                                                             "the contact loads of this run's members)");
      if (!l.member.empty() && std::none_of(s.structure.members.begin(), s.structure.members.end(),
                                            [&](const MemberConfig& m) { return m.name == l.member; }))
        throw InputError(file, p + "/member", quoted(l.member), "the name of one of the structure's members");
      continue;
    }
    if (l.height > c.height) throw InputError(file, p + "/height", value_text(l.height), "a height at most the dam height " + value_text(c.height) + " m");
    if (l.across > c.width) throw InputError(file, p + "/across", value_text(l.across), "a position within the face width " + value_text(c.width) + " m");
  }
}

// An inflow body: the last one (it grows), its driven zone and the deepest flow inside the grid. Returns the number of
// particles it will create.
namespace {

double check_inflow(const Scenario& s, const std::string& file, std::size_t i) {
  const BodyConfig& b = s.bodies[i];
  const InflowConfig& in = b.inflow;
  const std::string p = "/bodies/" + std::to_string(i) + "/inflow";
  const double h = s.grid.cell_size;
  if (i + 1 != s.bodies.size())
    throw InputError(file, p, "", "an inflow on the last body only (the body grows as debris enters; list it after the others)");
  if (in.zone > 0 && in.zone < h) throw InputError(file, p + "/zone_length", value_text(in.zone), "a driven zone at least one cell long (" + value_text(h) + " m)");
  const double zone = in.zone > 0 ? in.zone : 3 * h, depth = in.hydrograph.max_depth();
  const double t[2] = {in.direction[0], in.direction[1]}, n[2] = {-t[1], t[0]};
  for (double a : {-zone, 0.0})
    for (double d : {0.0, depth})
      for (int k = 0; k < 2; ++k) {
        const double x = in.point[k] + a * t[k] + d * n[k];
        const double lo = s.grid.origin[k] + 0.5 * h, hi = s.grid.origin[k] + s.grid.size[k] - 0.5 * h;
        if (x < lo - 1e-12 || x > hi + 1e-12) {
          std::ostringstream os;
          os << "a section whose driven zone (" << zone << " m upstream) and deepest flow (" << depth << " m) lie in the grid interior ["
             << lo << ", " << hi << "] m along axis " << k << "; a corner lies at " << x;
          throw InputError(file, p + "/point", value_text(in.point), os.str());
        }
      }
  return in.hydrograph.particle_estimate(h / b.particles_per_cell);
}

// Pressure sensors: on an existing wall (within half a cell of its surface) or member; the face profile's members exist
// and follow each other along the face.
void check_sensors(const Scenario& s, const std::string& file, const std::set<std::string>& members) {
  const double h = s.grid.cell_size;
  std::set<std::string> names;
  for (std::size_t i = 0; i < s.output.sensors.size(); ++i) {
    const SensorConfig& c = s.output.sensors[i];
    const std::string p = "/output/sensors/" + std::to_string(i);
    if (!names.insert(c.name).second) throw InputError(file, p + "/name", quoted(c.name), "a name not used before in this list");
    if (!c.member.empty()) {
      if (!members.count(c.member))
        throw InputError(file, p + "/member", quoted(c.member),
                         s.structure.present ? "the name of one of the structure's members" : "a structure member (there is no structure)");
      continue;
    }
    const auto w = std::find_if(s.walls.begin(), s.walls.end(), [&](const WallConfig& x) { return x.name == c.wall; });
    if (w == s.walls.end()) throw InputError(file, p + "/wall", quoted(c.wall), "the name of one of the walls");
    double gap = 0;  // distance from the wall's surface
    if (w->type == "plane") {
      double nn = 0;
      for (std::size_t d = 0; d < c.point.size(); ++d) gap += (c.point[d] - w->point[d]) * w->normal[d], nn += w->normal[d] * w->normal[d];
      gap = std::abs(gap) / std::sqrt(nn);
    } else {
      double out = 0, in = std::numeric_limits<double>::infinity();  // outside: distance to the box; inside: to its nearest face
      for (std::size_t d = 0; d < c.point.size(); ++d) {
        const double e = std::max({w->min[d] - c.point[d], c.point[d] - w->max[d], 0.0});
        out += e * e;
        in = std::min({in, c.point[d] - w->min[d], w->max[d] - c.point[d]});
      }
      gap = out > 0 ? std::sqrt(out) : in;
    }
    if (gap > 0.5 * h)
      throw InputError(file, p + "/point", value_text(c.point),
                       "a point on the surface of wall " + quoted(c.wall) + " (it is " + value_text(gap) + " m from it; at most half a cell)");
  }
  const FaceProfileConfig& f = s.output.face_profile;
  if (!f.present) return;
  for (std::size_t i = 0; i < f.members.size(); ++i) {
    const std::string p = "/output/face_profile/members/" + std::to_string(i);
    const auto& all = s.structure.members;
    const auto m = std::find_if(all.begin(), all.end(), [&](const MemberConfig& x) { return x.name == f.members[i]; });
    if (m == all.end()) throw InputError(file, p, quoted(f.members[i]), "the name of one of the structure's members");
    if (i == 0) continue;
    const auto prev = std::find_if(all.begin(), all.end(), [&](const MemberConfig& x) { return x.name == f.members[i - 1]; });
    if (m->start != prev->end)
      throw InputError(file, p, quoted(f.members[i]), "a member starting at the node where " + quoted(f.members[i - 1]) + " ends (" +
                                                          quoted(prev->end) + ")");
  }
  if (s.analysis.dimension == 3 && !(f.width > 0))
    throw InputError(file, "/output/face_profile/width", "(absent)", "the loaded width of the face in a 3D analysis");
}

// A name not used before in its list.
void unique(std::set<std::string>& set, const std::string& name, const std::string& file, const std::string& path) {
  if (!set.insert(name).second) throw InputError(file, path, "\"" + name + "\"", "a name not used before in this list");
}

// Each body: a unique name, a material it may use, a shape inside the grid; returns the particles they will hold.
double check_bodies(const Scenario& s, const std::string& file, const std::set<std::string>& mats, std::set<std::string>& bodies) {
  const int dim = s.analysis.dimension;
  const double h = s.grid.cell_size;
  double est = 0;
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    const BodyConfig& b = s.bodies[i];
    const std::string p = "/bodies/" + std::to_string(i);
    unique(bodies, b.name, file, p + "/name");
    if (!mats.count(b.material)) throw InputError(file, p + "/material", "\"" + b.material + "\"", "the name of one of the materials");
    for (const auto& m : s.materials) {
      if (m.name != b.material) continue;
      if ((m.model == "drucker_prager" || m.model == "mu_i" || m.model == "newtonian" || m.model == "bingham") && s.analysis.plane == Plane::stress)
        throw InputError(file, p + "/material", "\"" + b.material + "\"", "a material other than " + m.model + " in plane stress "
                                                                        "(Drucker-Prager debris and slurries need plane strain or 3D)");
      if (m.model == "elastic_plastic")
        throw InputError(file, p + "/material", "\"" + b.material + "\"", "a material for a continuum body (elastic_plastic is the steel of "
                                                                        "beam-column members only)");
      if (b.rigid_when_free && m.model != "linear_elastic")
        throw InputError(file, p + "/rigid_when_free", "true", "false, or a linear_elastic material for the body (its material is " + m.model +
                                                               ": only a linear-elastic body can be relaxed to stress-free when it turns rigid)");
    }
    if (b.inflow.present) {
      est += check_inflow(s, file, i);
      continue;
    }
    DVec lo, hi;
    shape_bounds(b.shape, dim, lo, hi);
    for (int d = 0; d < dim; ++d) {
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
  return est;
}

// The particles, cells and memory the run will need, against what it may have.
void check_resources(const Scenario& s, const std::string& file, double est) {
  const int dim = s.analysis.dimension;
  const double h = s.grid.cell_size;
  if (est > 2e8) {
    std::ostringstream os;  // a double: the estimate can exceed every integer type
    os.precision(3);
    os << "at most 2e8 particles in all (these bodies would need about " << est << "); use larger cells";
    throw InputError(file, "/bodies", "", os.str());
  }
  double cells = 1;
  for (int d = 0; d < dim; ++d) cells *= std::ceil(s.grid.size[d] / h);
  if (cells > 4e8) throw InputError(file, "/grid/cell_size", value_text(h), "a cell size giving at most 4e8 cells");
  {  // Memory the run will hold, against what it may use (engine/common/memory.hpp): refused here, not as a bad_alloc.
    double nodes = 1;
    for (int d = 0; d < dim; ++d) nodes *= std::ceil(s.grid.size[d] / h) + 1;
    const bool multi = s.contact.method == ContactMethod::multi_field && s.bodies.size() > 1;
    const double fields = multi ? static_cast<double>(s.bodies.size()) : 1.0;
    // Per node and field: m, p, f, v, v^L and the P2G record (2D: 104 B, 3D: 152 B), the contact fields (+8 + 8 D),
    // and per node the surface-detection scratch of multi-field contact (~100 B). Per particle ~400 B (arrays and
    // material history).
    const double per_field = 8.0 + 6.0 * 8 * dim + (multi ? 8.0 + 8 * dim : 0.0);
    const double grid_bytes = nodes * (fields * per_field + (multi ? 100.0 : 0.0)), particle_bytes = 400.0 * est;
    const MemoryLimit limit = memory_limit();
    if (grid_bytes + particle_bytes > limit.bytes) {
      std::ostringstream os;
      os.precision(3);
      os << "a grid and bodies that fit in memory: about " << (grid_bytes + particle_bytes) / 1073741824.0 << " GiB (grid " << grid_bytes / 1073741824.0
         << ", particles " << particle_bytes / 1073741824.0 << "), " << limit.bytes / 1073741824.0 << " GiB available (" << limit.source
         << "); use larger cells or a smaller grid";
      throw InputError(file, "/grid/cell_size", value_text(h), os.str());
    }
  }
}

// Walls and prescribed-velocity regions: unique names (one list), a normal, a box with extent, a time window.
void check_walls(const Scenario& s, const std::string& file) {
  const int dim = s.analysis.dimension;
  std::set<std::string> walls;
  for (std::size_t i = 0; i < s.walls.size(); ++i) {
    const WallConfig& w = s.walls[i];
    const std::string p = "/walls/" + std::to_string(i);
    unique(walls, w.name, file, p + "/name");
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
    unique(walls, r.name, file, p + "/name");
    for (int d = 0; d < dim; ++d)
      if (!(r.max[d] > r.min[d]))
        throw InputError(file, p + "/max", value_text(r.max), "max > min along every axis (min = " + value_text(r.min) + ")");
    if (r.end <= r.start) throw InputError(file, p + "/end", value_text(r.end), "end > start (start = " + value_text(r.start) + ")");
  }
}

// The bodies member contact names, and what one velocity field for all bodies cannot do.
void check_member_contact(const Scenario& s, const std::string& file, const std::set<std::string>& bodies) {
  for (std::size_t i = 0; i < s.member_contact.bodies.size(); ++i)
    if (!bodies.count(s.member_contact.bodies[i]))
      throw InputError(file, "/member_contact/bodies/" + std::to_string(i), quoted(s.member_contact.bodies[i]), "the name of one of the bodies");
  for (std::size_t i = 0; i < s.member_contact.bonded.size(); ++i) {
    const std::string& b = s.member_contact.bonded[i];
    const std::string p = "/member_contact/bonded/" + std::to_string(i);
    if (!bodies.count(b)) throw InputError(file, p, quoted(b), "the name of one of the bodies");
    if (!s.member_contact.bodies.empty() &&
        std::find(s.member_contact.bodies.begin(), s.member_contact.bodies.end(), b) == s.member_contact.bodies.end())
      throw InputError(file, p, quoted(b), "a body the members act on (listed in member_contact.bodies)");
  }
  if (!s.member_contact.bonded.empty() && s.member_contact.bonded.size() < s.bodies.size() && s.contact.method == ContactMethod::single_field)
    throw InputError(file, "/member_contact/bonded", json(s.member_contact.bonded).dump(),
                     "all bodies or none with contact.method single_field (the bodies share one velocity field); use multi_field");
  // A rigid body moves with its field's nodes: in a field shared with other bodies it would take their motion too.
  if (s.contact.method == ContactMethod::single_field && s.bodies.size() > 1)
    for (std::size_t i = 0; i < s.bodies.size(); ++i)
      if (s.bodies[i].rigid || s.bodies[i].rigid_when_free) {
        const char* key = s.bodies[i].rigid ? "rigid" : "rigid_when_free";
        throw InputError(file, "/bodies/" + std::to_string(i) + "/" + key, "true",
                         std::string("false with contact.method single_field and more than one body (a rigid body takes the motion of its "
                                     "velocity field's nodes, which the other bodies share); use multi_field"));
      }
  // With one velocity field for all bodies the members cannot act on only some of them.
  const std::set<std::string> listed(s.member_contact.bodies.begin(), s.member_contact.bodies.end());
  if (!listed.empty() && listed.size() < s.bodies.size() && s.contact.method == ContactMethod::single_field)
    throw InputError(file, "/member_contact/bodies", json(s.member_contact.bodies).dump(),
                     "all bodies (or none listed) with contact.method single_field: the bodies share one velocity field, so "
                     "members act on all of them; use multi_field to exempt some");
}

// Probes: unique names, on an existing body or (plane) member.
void check_probes(const Scenario& s, const std::string& file, const std::set<std::string>& bodies, const std::set<std::string>& members) {
  const int dim = s.analysis.dimension;
  std::set<std::string> probes;
  for (std::size_t i = 0; i < s.output.probes.size(); ++i) {
    const auto& pr = s.output.probes[i];
    const std::string p = "/output/probes/" + std::to_string(i);
    unique(probes, pr.name, file, p + "/name");
    if (pr.type == "member") {
      if (dim == 3)
        throw InputError(file, p + "/type", quoted(pr.type), "a body or particle probe in a 3D analysis (member probes read plane "
                                                             "members; a space frame's histories are in frame/ and supports/)");
      if (!members.count(pr.target))
        throw InputError(file, p + "/member", quoted(pr.target),
                         s.structure.present ? "the name of one of the structure's members" : "a structure member (there is no structure)");
    } else if (!bodies.count(pr.target)) {
      throw InputError(file, p + "/body", quoted(pr.target), "the name of one of the bodies");
    } else if (pr.type == "particle" && std::any_of(s.bodies.begin(), s.bodies.end(), [&](const BodyConfig& b) { return b.name == pr.target && b.inflow.present; })) {
      throw InputError(file, p + "/type", quoted(pr.type), "a body probe on an inflow body (its particles do not exist at t = 0)");
    }
  }}

// Cross-references and geometry: what a single key cannot check.
}  // namespace

void check_semantics(const Scenario& s, const std::string& file) {
  const int dim = s.analysis.dimension;
  if (s.bodies.empty() && !(s.solid_check.present && !s.structure.present))
    throw InputError(file, "/bodies", "[]", "at least one body (or a scenario with only a solid_check)");
  check_solid_check(s, file);
  std::set<std::string> mats, bodies;
  for (std::size_t i = 0; i < s.materials.size(); ++i) unique(mats, s.materials[i].name, file, "/materials/" + std::to_string(i) + "/name");
  const double h = s.grid.cell_size;
  for (int d = 0; d < dim; ++d)
    if (!(s.grid.size[d] > h))
      throw InputError(file, "/grid/cell_size", value_text(h), "a cell size smaller than the grid size along every axis (grid size " +
                                                                 value_text(s.grid.size) + ")");
  check_resources(s, file, check_bodies(s, file, mats, bodies));
  check_walls(s, file);
  std::set<std::string> members;
  if (s.structure.present) members = check_structure(s, file, bodies);
  check_member_contact(s, file, bodies);
  check_sensors(s, file, members);
  check_probes(s, file, bodies, members);
}

}  // namespace dmi
