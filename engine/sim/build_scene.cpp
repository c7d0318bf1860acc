#include "engine/sim/build_scene.hpp"

#include <cmath>
#include <limits>
#include <sstream>

#include "engine/common/error.hpp"
#include "engine/scenario/shape_geometry.hpp"
#include "engine/sim/build_frame.hpp"
#include "engine/sim/geostatic.hpp"

namespace dmi {
namespace {

// Bodies must not overlap: a particle of one body whose centre lies inside another body's shape is refused (bodies
// that only touch have their particle centres half a spacing inside their own shapes, so they pass).
template <int D> void check_overlaps(const Scenario& s, const Scene<D>& sc) {
  for (std::size_t b = sc.bodies.size(); b-- > 0;)  // the later body is named: it is the one that was added wrongly
    for (std::size_t a = 0; a < sc.bodies.size(); ++a) {
      if (a == b || s.bodies[a].inflow.present) continue;  // an inflow body has no shape
      const Body& body = sc.bodies[b];
      for (Index i = body.begin; i < body.end; ++i) {
        if (!shape_contains(s.bodies[a].shape, sc.particles.x[i].data(), D)) continue;
        std::ostringstream os;
        os << "a body that does not overlap body '" << s.bodies[a].name << "' (its particle " << i - body.begin << " at ("
           << sc.particles.x[i].transpose() << ") lies inside it); move or resize one of them";
        throw InputError(s.message_source(), "/bodies/" + std::to_string(b) + "/shape", "", os.str());
      }
    }
}

// Nor may a body start inside a member's section: a particle centre closer to an element's centre-line than the
// section's half depth there (between the element ends) is refused. Contact would otherwise start with a
// penetration and a spurious impulse (a column made deeper in a sweep reached into the boulder: 394 MN).
template <int D> void check_member_overlaps(const Scenario& s, const Scene<D>& sc) {
  const FrameOf<D>& f = *sc.frame;
  const auto& els = f.model().elements;
  for (std::size_t b = 0; b < sc.bodies.size(); ++b)
    for (Index i = sc.bodies[b].begin; i < sc.bodies[b].end; ++i) {
      const Vec<D> p = sc.particles.x[i];
      for (int e = 0; e < f.nelements(); ++e) {
        const Vec<D> A = f.node_position(els[e].i), B = f.node_position(els[e].j), AB = B - A;
        const double t = (p - A).dot(AB) / AB.squaredNorm();
        if (!(t > 0 && t < 1)) continue;
        const Vec<D> off = p - A - t * AB;
        const double d = off.norm();
        if constexpr (D == 2) {
          if (d >= f.half_depth(e, t) * (1 - 1e-9)) continue;
        } else {  // inside a round section, or inside a rectangle in its axes
          const Section& sec = els[e].section;
          const double sf = els[e].s0 + t * (els[e].s1 - els[e].s0), c = sec.half_depth(sf);
          const Eigen::Matrix3d R = f.axes(e);
          if (sec.kind() == SectionKind::pipe ? d >= c * (1 - 1e-9)
                                              : (std::abs(off.dot(R.row(1).transpose())) >= c * (1 - 1e-9) ||
                                                 std::abs(off.dot(R.row(2).transpose())) >= 0.5 * sec.width(sf) * (1 - 1e-9)))
            continue;
        }
        std::ostringstream os;
        os << "a body clear of member '" << f.model().members[els[e].member].name << "' (its particle " << i - sc.bodies[b].begin
           << " at (" << p.transpose() << ") lies inside the member's section, " << d << " m from its centre-line); move the body or the member";
        throw InputError(s.message_source(), "/bodies/" + std::to_string(b) + "/shape", "", os.str());
      }
    }
}

template <int D> bool inside(const ShapeConfig& s, const Vec<D>& x) { return shape_contains(s, x.data(), D); }

// Reach of the body from a seeded particle at x along -e_d (lo) and +e_d (hi): half the spacing dx where the
// neighbouring lattice position is in the shape too, else the distance to the shape's surface along that axis
// (bisection on membership to 1e-6 dx), so boundary particles carry the shape's curvature (engine/mpm/touch.hpp).
template <int D> void surface_reach(const ShapeConfig& s, const Vec<D>& x, double dx, Vec<D>& lo, Vec<D>& hi) {
  for (int d = 0; d < D; ++d)
    for (int side = 0; side < 2; ++side) {
      const Vec<D> e = (side ? 1.0 : -1.0) * Vec<D>::Unit(d);
      double r = 0.5 * dx;
      if (!inside<D>(s, x + dx * e)) {
        double in = 0, out = dx;
        while (out - in > 1e-6 * dx) {
          const double mid = 0.5 * (in + out);
          (inside<D>(s, x + mid * e) ? in : out) = mid;
        }
        r = in;
      }
      (side ? hi : lo)[d] = r;
    }
}

// Seeds particles on the regular sub-grid of spacing h/ppc aligned with the cells: positions
// origin + (c + (k + 1/2)/ppc) h, kept when inside the shape. Volume (h/ppc)^D (x thickness in 2D).
template <int D> void seed_body(Scene<D>& sc, const Scenario& s, const BodyConfig& b, int body, double rho) {
  const double h = s.grid.cell_size;
  const int ppc = b.particles_per_cell;
  const double dx = h / ppc;
  const Vec<D> origin = vec<D>(s.grid.origin);
  DVec blo, bhi;
  shape_bounds(b.shape, D, blo, bhi);
  const Vec<D> lo = vec<D>(blo), hi = vec<D>(bhi);
  IVec<D> first, count;
  for (int d = 0; d < D; ++d) {
    first[d] = static_cast<int>(std::floor((lo[d] - origin[d]) / dx));
    count[d] = static_cast<int>(std::ceil((hi[d] - origin[d]) / dx)) - first[d] + 1;
  }
  double volume = std::pow(dx, D);
  if (D == 2) volume *= s.analysis.thickness;
  const Vec<D> half = Vec<D>::Constant(0.5 * dx);
  const Vec<D> v0 = vec<D>(b.velocity);
  const bool sine = !b.sine_amplitude.empty();
  IVec<D> k = IVec<D>::Zero();
  while (true) {
    Vec<D> x;
    for (int d = 0; d < D; ++d) x[d] = origin[d] + (first[d] + k[d] + 0.5) * dx;
    Vec<D> v = v0;
    if (sine) v += vec<D>(b.sine_amplitude) * std::sin(vec<D>(b.sine_wavevector).dot(x - vec<D>(b.sine_origin)));
    if (inside<D>(b.shape, x)) {
      Vec<D> lo, hi;
      surface_reach<D>(b.shape, x, dx, lo, hi);
      sc.particles.push(x, v, half, rho * volume, volume, body, lo, hi);
    }
    int d = 0;
    for (; d < D; ++d) {
      if (++k[d] < count[d]) break;
      k[d] = 0;
    }
    if (d == D) break;
  }
}

template <int D> void add_inflow(Scene<D>& sc, const Scenario& s, int body, int mat) {
  const BodyConfig& bc = s.bodies[static_cast<std::size_t>(body)];
  const InflowConfig& c = bc.inflow;
  Inflow<D> in;
  in.name = bc.name;
  in.body = body;
  in.point = vec<D>(c.point);
  in.along = vec<D>(c.direction).normalized();
  if constexpr (D == 2) in.up = Vec<D>(-in.along[1], in.along[0]);  // the parser refuses 3D inflows
  in.zone = c.zone > 0 ? c.zone : 3 * s.grid.cell_size;
  in.spacing = s.grid.cell_size / bc.particles_per_cell;
  in.thickness = D == 2 ? s.analysis.thickness : 1.0;
  in.density = s.materials[static_cast<std::size_t>(mat)].density;
  in.hydrograph = c.hydrograph;
  sc.inflows.push_back(std::move(in));
}

}  // namespace

// The hull a rigid body meets plane walls with (Body::hull_points): a ball's centre and radius, a box's 2^D corners, a
// polygon's vertices (the support of a convex hull is that of its points).
static void rigid_hull(const ShapeConfig& shape, int dim, Body& body) {
  if (shape.type == "ball") {
    body.hull_points.assign(shape.center.begin(), shape.center.end());
    body.hull_radius = shape.radius;
  } else if (shape.type == "polygon") {
    for (const auto& v : shape.vertices) body.hull_points.insert(body.hull_points.end(), v.begin(), v.end());
  } else if (shape.type == "box") {
    for (int c = 0; c < (1 << dim); ++c)
      for (int d = 0; d < dim; ++d) body.hull_points.push_back((c >> d) & 1 ? shape.max[d] : shape.min[d]);
  }
}

// The pressure sensors on a wall (engine/mpm/sensor.hpp): a plane's normal, or the outward normal of the box face
// nearest the sensor's point.
template <int D> void add_wall_sensors(const Scenario& s, Wall<D>& wall) {
  for (const SensorConfig& c : s.output.sensors) {
    if (c.wall != wall.name) continue;
    Vec<D> x = vec<D>(c.point);
    Vec<D> n = wall.normal;
    if (wall.box) {  // the nearest face; the point moved onto it
      double best = std::numeric_limits<double>::infinity();
      int axis = 0, upper = 0;
      for (int d = 0; d < D; ++d)
        for (int side = 0; side < 2; ++side)
          if (const double e = std::abs(side ? x[d] - wall.hi[d] : x[d] - wall.lo[d]); e < best) best = e, axis = d, upper = side;
      n = upper ? Vec<D>(Vec<D>::Unit(axis)) : Vec<D>(-Vec<D>::Unit(axis));
      x[axis] = upper ? wall.hi[axis] : wall.lo[axis];
    } else {
      x -= (x - wall.point).dot(n) * n;  // onto the plane
    }
    wall.sensors.push_back(make_patch<D>(c.name, x, n, c.size, s.analysis.thickness));
    for (const WallConfig& o : s.walls)
      if (o.type == "plane" && o.name != wall.name) wall.sensors.back().clips.push_back({vec<D>(o.point), vec<D>(o.normal).normalized()});
  }
}

// A body that starts from its own weight's stress (engine/sim/geostatic.hpp): deformable, and a fluid with K0 = 1.
template <int D> void start_geostatic(const Scenario& s, Scene<D>& sc, const Body& body, std::size_t b) {
  const BodyConfig& bc = s.bodies[b];
  const MaterialConfig& m = s.materials[static_cast<std::size_t>(body.material)];
  const std::string path = "/bodies/" + std::to_string(b);
  if (bc.rigid) throw InputError(s.message_source(), path + "/initial_stress", "\"geostatic\"", "stress_free on a rigid body (it carries no stress)");
  if (s.analysis.plane == Plane::stress)
    throw InputError(s.message_source(), path + "/initial_stress", "\"geostatic\"",
                     "stress_free in plane stress (the geostatic state assumes no lateral strain: plane strain or 3D)");
  const bool fluid = m.model == "newtonian" || m.model == "bingham";
  if (fluid && m.volume_relaxation > 0)
    throw InputError(s.message_source(), path + "/initial_stress", "\"geostatic\"",
                     "stress_free with the material's volume_relaxation (it would relax the compressed volume, and the "
                     "hydrostatic pressure with it, back towards the space the particles fill)");
  if (fluid && bc.earth_pressure_coefficient >= 0 && bc.earth_pressure_coefficient != 1)
    throw InputError(s.message_source(), path + "/earth_pressure_coefficient", (std::ostringstream() << bc.earth_pressure_coefficient).str(),
                     "1 or nothing for a fluid (its pressure is isotropic)");
  geostatic_state<D>(sc, body, earth_pressure_at_rest(m, bc.earth_pressure_coefficient), s.message_source(), path);
}

namespace {

// The materials' constitutive models, in the scenario's order (a body's material index is its position).
template <int D> void add_materials(const Scenario& s, Scene<D>& sc) {
  MaterialRegistry<D> registry;
  register_materials(registry);
  for (const auto& m : s.materials) {
    if (m.model != "elastic_plastic") {
      sc.materials.push_back(registry.make(m, s.analysis.plane));
      continue;
    }
    MaterialConfig elastic = m;  // the members' steel: no body uses it; its slot keeps the materials' indices
    elastic.model = "linear_elastic";
    sc.materials.push_back(registry.make(elastic, s.analysis.plane));
  }

}

// The bodies: seeded particles (inside the grid by half a cell), an inflow's empty body, a geostatic start.
template <int D> void add_bodies(const Scenario& s, Scene<D>& sc, bool multi) {
  for (std::size_t b = 0; b < s.bodies.size(); ++b) {
    const BodyConfig& bc = s.bodies[b];
    int mat = 0;
    while (s.materials[mat].name != bc.material) ++mat;
    Body body;
    body.name = bc.name;
    body.material = mat;
    body.field = multi ? static_cast<int>(b) : 0;
    body.rigid = bc.rigid;
    body.rigid_when_free = bc.rigid_when_free;
    if (bc.rigid) rigid_hull(bc.shape, D, body);
    body.begin = static_cast<Index>(sc.particles.size());
    if (bc.inflow.present && bc.geostatic)
      throw InputError(s.message_source(), "/bodies/" + std::to_string(b) + "/initial_stress", "\"geostatic\"",
                       "stress_free on a body an inflow fills (its debris enters moving)");
    if (bc.inflow.present) {  // created as the debris enters (engine/mpm/inflow.hpp)
      body.end = body.begin;
      sc.bodies.push_back(body);
      add_inflow(sc, s, static_cast<int>(b), mat);
      continue;
    }
    seed_body(sc, s, bc, static_cast<int>(b), s.materials[mat].density);
    body.end = static_cast<Index>(sc.particles.size());
    for (Index i = body.begin; i < body.end; ++i) {
      if (sc.grid->interior(sc.particles.x[i])) continue;
      std::ostringstream os;
      os << "a body whose particles lie at least half a cell inside the grid; particle " << i - body.begin << " at ("
         << sc.particles.x[i].transpose() << ") does not";
      throw InputError(s.message_source(), "/bodies/" + std::to_string(b) + "/shape", "", os.str());
    }
    if (body.end == body.begin)
      throw InputError(s.message_source(), "/bodies/" + std::to_string(b) + "/shape", "",
                       "a shape that contains at least one particle position (it is smaller than the particle spacing)");
    if (bc.geostatic) start_geostatic(s, sc, body, b);
    sc.bodies.push_back(body);
  }
}

// Plane and box walls (a plane wall on a grid line mirrors the nodes across it), with their pressure sensors.
template <int D> void add_walls(const Scenario& s, Scene<D>& sc) {
  const double h = s.grid.cell_size;
  for (const auto& w : s.walls) {
    Wall<D> wall;
    wall.name = w.name;
    wall.box = w.type == "box";
    if (wall.box) {
      wall.lo = vec<D>(w.min);
      wall.hi = vec<D>(w.max);
    } else {
      wall.point = vec<D>(w.point);
      wall.normal = vec<D>(w.normal).normalized();
      for (int d = 0; d < D; ++d) {
        const double k = (wall.point[d] - s.grid.origin[d]) / h;
        if (std::abs(std::abs(wall.normal[d]) - 1) < 1e-12 && std::abs(k - std::round(k)) < 1e-9) {
          wall.mirror_axis = d;
          wall.mirror_index = static_cast<int>(std::round(k));
        }
      }
    }
    wall.condition = w.condition;
    wall.friction = w.friction;
    wall.surface_detection = w.detection == DetectionKind::surface;
    add_wall_sensors(s, wall);
    sc.walls.push_back(wall);
  }
  for (const auto& r : s.prescribed_velocity) {
    VelocityRegion<D> reg{r.name, vec<D>(r.min), vec<D>(r.max), vec<D>(r.velocity), r.start, r.end};
    sc.regions.push_back(reg);
  }
}

template <int D> void set_options(const Scenario& s, Scene<D>& sc) {
  const double h = s.grid.cell_size;
  sc.options.shape = s.mpm.shape;
  sc.options.transfer = s.mpm.transfer;
  sc.options.flip_blend = s.mpm.flip_blend;
  sc.options.update = s.mpm.update;
  sc.options.implicit_damping = s.mpm.implicit_damping;
  sc.options.cfl = s.analysis.cfl;
  sc.options.dt_max = s.analysis.dt_max;
  // While a rigid_when_free body is rigid nothing else may bound the step (a bare frame under Newmark does not): the
  // recorded histories then set it.
  sc.options.free_dt_max = s.output.history_interval > 0 ? s.output.history_interval : s.analysis.end_time / 2000;
  sc.options.contact_friction = s.contact.friction;
  sc.options.contact_detection = s.contact.detection;
  sc.options.cell_volume = std::pow(h, D) * (D == 2 ? s.analysis.thickness : 1.0);
}

// The members, standing under their own weight when built so, and their coupling to the bodies.
template <int D> void add_structure(const Scenario& s, Scene<D>& sc) {
  if (!s.structure.present) return;
  try {
    if constexpr (D == 2) sc.frame = std::make_unique<Frame>(build_frame_model(s));
    else sc.frame = std::make_unique<SpaceFrame>(build_space_frame_model(s));
    // A built structure stands in equilibrium under its own weight at t = 0.
    if (s.structure.self_weight && s.structure.initial_state == FrameInitialState::static_equilibrium) sc.frame->solve_static();
  } catch (const std::invalid_argument& e) {  // e.g. a mechanism: the parser cannot see it
    throw InputError(s.message_source(), "/structure", "", std::string("a stable frame (") + e.what() + ")");
  }
  sc.coupling = build_coupling(s, sc);
  check_member_overlaps(s, sc);
}

}  // namespace

template <int D> Scene<D> build_scene(const Scenario& s) {
  Scene<D> sc;
  const double h = s.grid.cell_size;
  IVec<D> cells;
  for (int d = 0; d < D; ++d) cells[d] = static_cast<int>(std::ceil(s.grid.size[d] / h - 1e-9));
  const bool multi = s.contact.method == ContactMethod::multi_field && s.bodies.size() > 1;
  sc.grid = std::make_unique<Grid<D>>(vec<D>(s.grid.origin), cells, h, multi ? static_cast<int>(s.bodies.size()) : 1);
  sc.gravity = vec<D>(s.analysis.gravity);
  add_materials(s, sc);
  add_bodies(s, sc, multi);
  add_walls(s, sc);
  set_options(s, sc);
  add_structure(s, sc);
  check_overlaps(s, sc);
  return sc;
}

void check_scene(const Scenario& s) {
  if (s.bodies.empty()) return;
  if (s.analysis.dimension == 2) build_scene<2>(s);
  else build_scene<3>(s);
}

template Scene<2> build_scene<2>(const Scenario&);
template Scene<3> build_scene<3>(const Scenario&);

}  // namespace dmi
