// The low-level scene of the presets (layout in presets.hpp): materials, bodies, walls, the frame,
// member contact, grid, end time and probes. Every default is stated where it is chosen.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <functional>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "engine/common/error.hpp"
#include "engine/scenario/design_basis_json.hpp"
#include "engine/scenario/hydrograph_io.hpp"
#include "engine/scenario/preset_types.hpp"

namespace dmi {

using json = nlohmann::json;

namespace {

constexpr double kPi = 3.14159265358979323846, kG = 9.81;

// x to 12 significant digits, so generated coordinates print without floating-point noise.
double clean(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.12g", x);
  return std::strtod(b, nullptr);
}

// Largest of {1, 1.5, 2, 2.5, 3, 4, 5, 6, 8} x 10^k not above x: cell sizes that print cleanly.
double nice_floor(double x) {
  const double e = std::pow(10.0, std::floor(std::log10(x)));
  for (double m : {8.0, 6.0, 5.0, 4.0, 3.0, 2.5, 2.0, 1.5, 1.0})
    if (m * e <= x * (1 + 1e-12)) return clean(m * e);
  return e;
}

// The extent of what the presets build: x along the flow, y up (the elevation), and in 3D the span across (y).
struct Box {
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  double across_lo = 0, across_hi = 0;  // 3D: y across the channel (the centre plane y = 0 always inside)
  void add(double x, double y) {
    lo[0] = std::min(lo[0], x), lo[1] = std::min(lo[1], y);
    hi[0] = std::max(hi[0], x), hi[1] = std::max(hi[1], y);
  }
  void across(double a, double b) { across_lo = std::min(across_lo, a), across_hi = std::max(across_hi, b); }
};

// Uniform cantilever first two circular frequencies (rad/s): omega_i = (beta_i L)^2 sqrt(E/rho) r / L^2,
// beta L = 1.8751, 4.6941 (Lin, Cheng & Tuan; Clough & Penzien 1993, 18-3).
std::pair<double, double> cantilever_modes(double E, double rho, double r, double L) {
  const double base = std::sqrt(E / rho) * r / (L * L);
  return {1.8751 * 1.8751 * base, 4.6941 * 4.6941 * base};
}

// Rayleigh C = a M + b K with damping ratio zeta at w1 and w2 (Chopra 2012, eq. 11.4.9); model "mass": C = a M with
// zeta at w1, a = 2 zeta w1 (eq. 11.4.3 with b = 0: zeta(w) = zeta w1 / w).
json rayleigh(double zeta, std::pair<double, double> w, const std::string& model = "rayleigh") {
  if (model == "mass") return json{{"mass", 2 * zeta * w.first}, {"stiffness", 0.0}};
  return json{{"mass", 2 * zeta * w.first * w.second / (w.first + w.second)}, {"stiffness", 2 * zeta / (w.first + w.second)}};
}

json pipe(double d, double t) { return json{{"type", "pipe"}, {"diameter", d}, {"wall_thickness", t}}; }

class Builder {
 public:
  Builder(const PresetScene& p, std::string file) : p_(p), d_(p_.dam), file_(std::move(file)) {}
  json build();

 private:
  // Upstream and downstream dam faces x(y) (concrete_gravity; steel: the upstream column's surface).
  double xu(double y) const;
  double xd(double y) const;
  // What a boulder or surge meets first at height y: the buffer's front where there is one.
  double front(double y) const;
  double bed(double x) const { return -x * std::tan(slope_); }  // ground line through the face's foot
  double front_length() const;
  double section_distance() const;
  // The features the cell must resolve: their size across, the cells across them by default, and at least.
  struct Feature {
    double size, cells, min_cells;
    const char* what;
  };
  std::vector<Feature> features() const;
  // The default cell from the features, or the user's, which must still give each its minimum.
  double choose_cell_size() const;
  void add_dam();
  void add_concrete_members();
  void add_steel_frame();
  void add_space_steel_frame();
  // The members' damping (dam.damping_ratio, dam.damping_model) into st: modal, or Rayleigh at the first two modes
  // of a uniform cantilever with radius of gyration r (m) of `material`; sets period_ (that cantilever's first
  // period), which the 3D end time uses.
  void damp(json& st, const json& material, double r);
  // A position in the elevation (x along the flow, y up) and across the channel as the scene's coordinates:
  // 2D [x, y]; 3D [x, across, y] (z up).
  json at(double x, double y, double across = 0) const { return dim_ == 3 ? json{clean(x), clean(across), clean(y)} : json{clean(x), clean(y)}; }
  // How long a boulder run goes on after the boulder arrives: 0.15 s (a buffered impact lasts a few hundredths of a
  // second; docs/verification.md); in 3D on a bare face, whose pulse lasts milliseconds and whose member peaks follow
  // within the first cantilever period, 1.5 periods (at least 0.03 s), which a 3D run cannot afford to exceed fivefold.
  double after_arrival() const { return dim_ == 3 && !p_.buffer ? std::max(0.03, 1.5 * period_) : 0.15; }
  int columns() const { return d_.columns > 0 ? d_.columns : 3; }  // 3D steel open dam: columns per row across
  void add_buffer();
  void add_boulder();
  void add_debris();
  void add_inflow();
  // With a hydrograph: its flowing time (from the first flow to its end) and the rise to its deepest flow.
  double flow_duration() const;
  double rise_time() const;
  // x of the foot of a front `gap` upstream of whatever a flow `height` high (vertically) meets first: the face or
  // the buffer (a fixed-point pass, since the bed height at the front depends on where the front is).
  double front_foot(double height, double gap) const;
  void add_grid_walls_and_time();
  void add_face_sensors();
  DesignBasis design_basis() const;
  // The diameter of the sphere of the boulder's mass (m).
  double boulder_diameter() const { return std::cbrt(6 * boulder_m_ / (p_.boulder->density * kPi)); }
  DebrisBasis debris_basis() const;
  double buffer_damping_frequency(double E, double thickness) const;
  [[noreturn]] void fail(const std::string& path, const json& value, const std::string& expected) const {
    throw InputError(file_, path, value.is_null() ? "" : value.dump(), expected);
  }

  PresetScene p_;  // a copy: the buffer's resolved top is written back
  const DamPreset& d_;
  bool rigid_boulder_ = false, free_boulder_ = false;  // rigid throughout; rigid_when_free (elastic while it can touch)
  std::string file_;
  double h_ = 0, slope_ = 0, end_time_ = 0, boulder_r_ = 0, boulder_m_ = 0, impact_y_ = 0, boulder_speed_ = 0;
  std::string width_rule_ = "given";  // how the 2D width was set
  json out_ = json::object(), materials_ = json::array(), bodies_ = json::array(), probes_ = json::array(), bonded_ = json::array();
  json face_;  // the struck face whose pressure profile is recorded (output.face_profile), or null
  json sensors_ = json::array();  // pressure sensors on the struck face (output.sensors)
  Box box_;
  bool members_ = true;
  int dim_ = 2;
  double period_ = 0;  // the dam's first cantilever period (s), for the 3D end time
};

double Builder::xu(double y) const {
  if (d_.type != "concrete_gravity" || d_.sloped_face == "downstream") return 0.0;
  const double batter = (d_.base_thickness - d_.crest) * y / d_.height;
  return d_.sloped_face == "both" ? 0.5 * batter : batter;
}

double Builder::xd(double y) const {
  if (d_.type == "steel_open") return (d_.rows - 1) * d_.row_spacing + d_.column_d;
  const double batter = (d_.base_thickness - d_.crest) * y / d_.height;
  return d_.base_thickness - (d_.sloped_face == "upstream" ? 0.0 : d_.sloped_face == "both" ? 0.5 * batter : batter);
}

double Builder::front(double y) const {
  if (!p_.buffer) return xu(y);
  const BufferPreset& b = *p_.buffer;
  if (y < b.bottom || y > b.top) return xu(y);
  return xu(y) - (b.type == "homogenised" ? b.thickness : b.tyre_diameter);
}

std::vector<Builder::Feature> Builder::features() const {
  std::vector<Feature> f;
  // A homogenised layer: 15 cells through it in 2D, from where the buffered dam's base shear converges monotonically
  // (docs/verification.md, "The buffered demo dam converges"); 5 in 3D, whose cost grows with h^-4 (the 3D loads are
  // not converged there: the report's grid study says so).
  // The bare variant of a comparison takes its buffer's default cell, without a minimum (it builds no buffer).
  const std::optional<BufferPreset>& buf = p_.buffer ? p_.buffer : p_.compared_buffer;
  const bool built = p_.buffer.has_value();
  if (buf && buf->type == "homogenised") f.push_back({buf->thickness, dim_ == 3 ? 5.0 : 15.0, built ? 2.0 : 0.0, "the buffer layer"});
  if (buf && buf->type != "homogenised") f.push_back({buf->ring_thickness, 2, built ? 1.0 : 0.0, "the tyre rings"});
  if (p_.boulder) f.push_back({2 * boulder_r_, 10, 4, dim_ == 3 ? "the boulder" : "the boulder (the cylinder of its mass)"});
  if (p_.debris) f.push_back({p_.debris->depth, 10, 3, "the surge depth"});
  if (d_.type == "concrete_gravity" && d_.model == "continuum") f.push_back({d_.crest, 8, 0, "the dam crest"});
  if (d_.type == "steel_open") f.push_back({d_.column_d, 4, 0, "the columns"});
  return f;
}

double Builder::choose_cell_size() const {
  if (p_.cell_size > 0) {  // the user's cell must still resolve what the presets build
    for (const Feature& f : features())
      if (f.min_cells > 0 && !(p_.cell_size <= f.size / f.min_cells * (1 + 1e-9))) {
        std::ostringstream os;
        os << "a cell size resolving " << f.what << ": at most " << f.size / f.min_cells << " m (" << f.min_cells << " cells across " << f.size
           << " m)";
        fail("/grid/cell_size", p_.cell_size, os.str());
      }
    return p_.cell_size;
  }
  // About 10 cells across a boulder and through a surge, 15 through a buffer layer (5 in 3D), 2 through a tyre ring, 8 through a
  // continuum crest, 4 across a column; never coarser than height / 40.
  double h = d_.height / 40;
  for (const Feature& f : features()) h = std::min(h, f.size / f.cells);
  return nice_floor(h);
}

json Builder::build() {
  dim_ = p_.dim;
  if (dim_ == 2 && p_.boulder && p_.boulder->across != 0)
    fail("/boulder/across", p_.boulder->across, "0 in 2D (the plane model has no position across the channel; analysis.dimension 3 uses it)");
  if (dim_ == 2 && d_.columns != 0)
    fail("/dam/columns", d_.columns, "no columns across the channel in 2D (the plane model stands for one bay; analysis.dimension 3 uses it)");
  members_ = !(d_.type == "concrete_gravity" && d_.model == "continuum");
  if (p_.debris && !p_.debris->hydrograph.empty()) {  // the surge's size for the cell, the grid and the estimates
    DebrisPreset& f = *p_.debris;
    f.depth = f.hydrograph.max_depth();
    f.velocity = f.hydrograph.max_velocity();
    f.length = f.velocity * flow_duration();
  }
  if (p_.debris) slope_ = p_.debris->slope * kPi / 180;
  if (p_.boulder) {
    const BoulderPreset& b = *p_.boulder;
    boulder_m_ = b.mass > 0 ? b.mass : b.density * kPi * std::pow(b.diameter, 3) / 6;  // m = rho pi D^3 / 6 (a sphere)
    if (dim_ == 2 && !d_.width_given && d_.type == "concrete_gravity") {
      // A point impact on a plane model: the width over which the boulder's load spreads through the struck section at
      // 45 degrees, its diameter plus the section's thickness at the impact height.
      const double y = std::min(b.impact_height > 0 ? b.impact_height : 0.9 * d_.height, d_.height);
      p_.dam.width = clean(boulder_diameter() + xd(y) - xu(y));
      width_rule_ = "the boulder's diameter plus the section's thickness at the impact height (a 45 degree spread)";
    }
    // The 2D model is a cylinder as long as the out-of-plane width with the boulder's mass:
    // m = rho pi r^2 W  ->  r = sqrt(m / (rho pi W)).
    boulder_r_ = dim_ == 3 ? std::cbrt(3 * boulder_m_ / (4 * kPi * b.density)) : std::sqrt(boulder_m_ / (b.density * kPi * d_.width));
  }
  h_ = choose_cell_size();
  add_dam();
  if (p_.buffer) add_buffer();
  if (p_.boulder) add_boulder();
  if (p_.debris) add_debris();
  add_face_sensors();
  add_grid_walls_and_time();
  out_["materials"] = materials_;
  out_["bodies"] = bodies_;
  out_["contact"] = json{{"method", "multi_field"}, {"friction", 0.3}};
  // A surge throws single particles into the air; landing on the pile they meet nearly empty nodes,
  // where USL blew up (a particle at 45 m/s, then off the grid) and MUSL's remap does not.
  if (p_.debris) out_["mpm"] = json{{"stress_update", "musl"}};
  if (members_) out_["member_contact"] = json{{"mode", "separable"}, {"bonded", bonded_}};
  out_["output"]["probes"] = probes_;
  if (!face_.is_null()) out_["output"]["face_profile"] = face_;
  if (!sensors_.empty()) out_["output"]["sensors"] = sensors_;
  out_["design_basis"] = design_basis_to_json(design_basis());
  return out_;
}

// Pressure sensors on the concrete dam member's upstream face, two cells across (docs/results.md, "Pressures"): at the
// boulder's impact height, or at a quarter and three quarters of a surge's depth.
void Builder::add_face_sensors() {
  if (!members_ || d_.type != "concrete_gravity") return;
  auto sensor = [&](const std::string& name, double y) {
    sensors_.push_back({{"name", name}, {"member", "dam"}, {"point", at(xu(y), y)}, {"size", clean(2 * h_)}});
  };
  if (p_.boulder) sensor("face_at_impact", std::clamp(impact_y_, h_, d_.height - h_));
  if (p_.debris) {
    sensor("face_quarter_depth", 0.25 * p_.debris->depth);
    sensor("face_three_quarter_depth", std::min(0.75 * p_.debris->depth, d_.height - h_));
  }
}

// What the design checks and closed-form estimates of design/ need (docs/design-json.md, "design basis"): the real
// (spherical) boulder, the surge, the dam and the buffer as the engineer described them.
DesignBasis Builder::design_basis() const {
  DesignBasis out;
  DamBasis& dam = out.dam;
  const bool concrete = d_.type == "concrete_gravity";
  dam.type = concrete ? DamKind::concrete_gravity : DamKind::steel_open;
  dam.height_m = d_.height, dam.width_m = d_.width, dam.width_rule = width_rule_;
  const json& m = concrete ? d_.concrete : d_.steel;
  dam.youngs_modulus_Pa = m.value("youngs_modulus", 0.0);
  dam.poisson_ratio = m.value("poisson_ratio", 0.0);
  dam.density_kg_m3 = m.value("density", 0.0);
  if (concrete) {
    dam.crest_thickness_m = d_.crest, dam.base_thickness_m = d_.base_thickness;
    dam.heel_x_m = xu(0), dam.toe_x_m = xd(0), dam.crest_upstream_x_m = xu(d_.height), dam.crest_downstream_x_m = xd(d_.height);
    if (d_.deposit_height > 0)
      dam.deposit_height_m = d_.deposit_height, dam.deposit_unit_weight_N_m3 = d_.deposit_unit_weight, dam.deposit_coefficient = d_.deposit_coefficient,
      dam.deposit_submerged = d_.deposit_submerged;
    if (d_.water_height > 0) dam.water_height_m = d_.water_height, dam.water_unit_weight_N_m3 = d_.water_unit_weight;
  } else {
    dam.column_diameter_m = d_.column_d, dam.column_wall_thickness_m = d_.column_t;
    if (d_.steel_yield > 0) dam.yield_strength_Pa = d_.steel_yield;
    dam.member_model = d_.member_model;
  }
  if (p_.boulder) {
    const BoulderPreset& b = *p_.boulder;
    BoulderBasis k;
    k.mass_kg = boulder_m_, k.diameter_m = boulder_diameter(), k.density_kg_m3 = b.density;
    k.youngs_modulus_Pa = b.youngs_modulus, k.poisson_ratio = b.poisson_ratio, k.speed_m_s = boulder_speed_, k.impact_height_m = impact_y_;
    k.model = rigid_boulder_ ? BoulderModel::rigid : free_boulder_ ? BoulderModel::elastic_when_touching : BoulderModel::elastic;
    out.boulder = k;
  }
  if (p_.debris) out.debris = debris_basis();
  if (p_.buffer) {
    const BufferPreset& b = *p_.buffer;
    const bool homog = b.type == "homogenised";
    BufferBasis t;
    t.type = b.type, t.youngs_modulus_Pa = b.material.value("youngs_modulus", 0.0), t.poisson_ratio = b.material.value("poisson_ratio", 0.0);
    t.thickness_m = homog ? b.thickness : b.tyre_diameter, t.bottom_m = b.bottom, t.top_m = b.top;
    out.buffer = t;
  }
  return out;
}

DebrisBasis Builder::debris_basis() const {
  const DebrisPreset& f = *p_.debris;
  const double rho = f.material.value("density", 2000.0);
  DebrisBasis s;
  s.density_kg_m3 = rho, s.depth_m = f.depth, s.length_m = f.length, s.speed_m_s = f.velocity, s.channel_slope_deg = f.slope;
  s.front_length_m = front_length();
  if (const Hydrograph& g = f.hydrograph; !g.empty()) {
    // The estimates take the row of the largest momentum flux at the section; the phases' passage L / v is the
    // hydrograph's flowing time; the snout is what passes the section while the depth rises to its deepest.
    const std::size_t k = g.peak_flux_row(rho);
    const double v = g.velocity[k];
    s.density_kg_m3 = g.density.empty() ? rho : g.density[k];
    s.depth_m = g.depth[k], s.speed_m_s = v, s.length_m = v * flow_duration(), s.front_length_m = v * rise_time();
    s.hydrograph = HydrographBasis{g.source, flow_duration(), g.volume_per_width(), g.mass_per_width(rho), g.time[k], section_distance()};
  }
  if (const std::string model = f.material.value("model", std::string("drucker_prager")); model == "drucker_prager" || model == "mu_i")
    s.youngs_modulus_Pa = f.material.value("youngs_modulus", 0.0), s.poisson_ratio = f.material.value("poisson_ratio", 0.0);
  else
    s.bulk_modulus_Pa = f.material.value("bulk_modulus", 0.0);
  return s;
}

void Builder::add_dam() {
  if (d_.type == "concrete_gravity") {
    json m = d_.concrete;
    m["name"] = "concrete";
    // No damping on the continuum dam: Kelvin-Voigt damping is stiffness-proportional, and for concrete at
    // the first mode it cut the explicit step 70-fold (0.05 s took 509 000 steps, 487 s); damping_ratio
    // applies to the members model (Rayleigh on the frame, which Newmark integrates implicitly).
    materials_.push_back(m);
    if (members_) return add_concrete_members();
    if (d_.deposit_height > 0 || d_.water_height > 0)
      fail("/dam/model", json("continuum"), "the members model with a deposit or water behind the dam (their pressures load the members)");
    json poly = json::array({{xu(0), 0.0}, {xd(0), 0.0}, {xd(d_.height), d_.height}, {xu(d_.height), d_.height}});
    bodies_.push_back(json{{"name", "dam"}, {"material", "concrete"}, {"shape", {{"type", "polygon"}, {"vertices", poly}}}});
    probes_.push_back(json{{"name", "dam"}, {"type", "body"}, {"body", "dam"}, {"quantities", {"displacement", "velocity"}}});
    box_.add(xu(0), 0), box_.add(xd(0), d_.height);
    return;
  }
  json m = d_.steel;
  m["name"] = "steel";
  materials_.push_back(m);
  add_steel_frame();
}

void Builder::add_concrete_members() {
  const double H = d_.height;
  const double x0 = 0.5 * (xu(0) + xd(0)), x1 = 0.5 * (xu(H) + xd(H));
  // Depth normal to the (slightly inclined) centre line: the horizontal thickness times cos(phi).
  const double c = H / std::hypot(H, x1 - x0);
  json st;
  st["integrator"] = "newmark";
  st["theory"] = d_.beam_theory;
  st["self_weight"] = true;
  st["nodes"] = json::array({{{"name", "base"}, {"position", at(x0, 0.0)}}, {{"name", "crest"}, {"position", at(x1, H)}}});
  st["members"] = json::array({{{"name", "dam"}, {"start", "base"}, {"end", "crest"}, {"material", "concrete"}, {"elements", d_.elements},
                                {"section", {{"type", "tapered_rectangle"}, {"width", d_.width}, {"depth_start", d_.base_thickness * c},
                                             {"depth_end", d_.crest * c}}}}});
  st["supports"] = json::array({{{"node", "base"}, {"type", d_.base}}});
  // What stands behind the dam: pressures on the upstream face (along the flow), over the face width.
  json pl = json::array();
  if (d_.deposit_height > 0)
    pl.push_back({{"member", "dam"}, {"direction", at(1.0, 0.0)}, {"surface", d_.deposit_height},
                  {"gradient", d_.deposit_coefficient * d_.deposit_unit_weight * d_.width}});
  if (d_.deposit_height > 0 && d_.deposit_submerged)  // the buoyancy of the submerged part: K gamma_w (min(h, h_w) - y) upstream
    pl.push_back({{"member", "dam"}, {"direction", at(-1.0, 0.0)}, {"surface", std::min(d_.deposit_height, d_.water_height)},
                  {"gradient", d_.deposit_coefficient * d_.water_unit_weight * d_.width}});
  if (d_.water_height > 0)
    pl.push_back({{"member", "dam"}, {"direction", at(1.0, 0.0)}, {"surface", d_.water_height}, {"gradient", d_.water_unit_weight * d_.width}});
  if (!pl.empty()) st["pressure_loads"] = pl;
  damp(st, d_.concrete, 0.5 * (d_.base_thickness + d_.crest) * c / std::sqrt(12.0));
  out_["structure"] = st;
  face_ = json{{"members", {"dam"}}, {"direction", at(1.0, 0.0)}};
  if (dim_ == 3) face_["width"] = d_.width;
  box_.add(xu(0), 0), box_.add(xd(0), H), box_.add(xu(H), H);
  if (dim_ == 3) return;  // member probes are plane-frame only (the space frame's histories carry every section force)
  probes_.push_back(json{{"name", "base"}, {"type", "member"}, {"member", "dam"}, {"position", 0.0}, {"quantities", {"section_forces", "fibre_stress"}}});
  probes_.push_back(json{{"name", "crest"}, {"type", "member"}, {"member", "dam"}, {"position", 1.0}, {"quantities", {"displacement"}}});
}

void Builder::add_steel_frame() {
  if (dim_ == 3) return add_space_steel_frame();
  const double H = d_.height, D = d_.column_d, s = d_.row_spacing;
  const double bd = d_.beam_d > 0 ? d_.beam_d : D, bt = d_.beam_t > 0 ? d_.beam_t : d_.column_t;
  json nodes = json::array(), members = json::array(), supports = json::array();
  auto node = [](int i, int k) { return "c" + std::to_string(i) + "_" + std::to_string(k); };
  const int secondary = std::max(2, d_.elements / 2);
  for (int i = 0; i < d_.rows; ++i) {
    const double x = 0.5 * D + i * s;  // the upstream column's upstream surface is at x = 0
    for (int k = 0; k <= d_.levels; ++k) {
      nodes.push_back({{"name", node(i, k)}, {"position", {x, H * k / d_.levels}}});
      if (k == 0) {
        supports.push_back({{"node", node(i, 0)}, {"type", d_.base}});
        continue;
      }
      const std::string tag = std::to_string(i) + "_" + std::to_string(k);
      members.push_back({{"name", "column_" + tag}, {"start", node(i, k - 1)}, {"end", node(i, k)}, {"material", "steel"},
                         {"elements", d_.elements}, {"section", pipe(D, d_.column_t)}});
      if (i + 1 == d_.rows) continue;
      members.push_back({{"name", "beam_" + tag}, {"start", node(i, k)}, {"end", node(i + 1, k)}, {"material", "steel"},
                         {"elements", secondary}, {"section", pipe(bd, bt)}});
      if (d_.bracing)
        members.push_back({{"name", "brace_" + tag}, {"start", node(i + 1, k - 1)}, {"end", node(i, k)}, {"material", "steel"},
                           {"elements", secondary}, {"section", pipe(bd, bt)}});
    }
  }
  json st{{"integrator", "newmark"}, {"theory", d_.beam_theory}, {"self_weight", true}, {"nodes", nodes}, {"members", members}, {"supports", supports}};
  damp(st, d_.steel, std::sqrt(D * D + std::pow(D - 2 * d_.column_t, 2)) / 4);  // pipe: r^2 = (D^2 + d^2) / 16
  out_["structure"] = st;
  face_ = json{{"members", json::array()}, {"direction", at(1.0, 0.0)}};  // the upstream column line
  for (int k = 1; k <= d_.levels; ++k) face_["members"].push_back("column_0_" + std::to_string(k));
  box_.add(0, 0), box_.add(xd(0), H + 0.5 * D);
  probes_.push_back(json{{"name", "base"}, {"type", "member"}, {"member", "column_0_1"}, {"position", 0.0},
                         {"quantities", {"section_forces", "fibre_stress"}}});
  probes_.push_back(json{{"name", "crest"}, {"type", "member"}, {"member", "column_0_" + std::to_string(d_.levels)}, {"position", 1.0},
                         {"quantities", {"displacement"}}});
}

// The steel open dam in 3D: `columns` pipe columns per row across the channel, `width` apart and centred on y = 0, the
// rows along the flow as in 2D; at every level beams along the flow (and one brace per panel) in each column line,
// and ties across the channel between neighbouring columns of a row.
void Builder::add_space_steel_frame() {
  const double H = d_.height, D = d_.column_d, s = d_.row_spacing;
  const double bd = d_.beam_d > 0 ? d_.beam_d : D, bt = d_.beam_t > 0 ? d_.beam_t : d_.column_t;
  const int nc = columns(), secondary = std::max(2, d_.elements / 2);
  if (nc > 1 && !(d_.width > D)) fail("/dam/width", d_.width, "a column spacing across the channel larger than the column diameter (the columns would overlap)");
  json nodes = json::array(), members = json::array(), supports = json::array();
  auto node = [](int i, int j, int k) { return "c" + std::to_string(i) + "_" + std::to_string(j) + "_" + std::to_string(k); };
  auto across = [&](int j) { return (j - 0.5 * (nc - 1)) * d_.width; };
  auto member = [&](const std::string& name, const std::string& a, const std::string& b, int elements, double d, double t) {
    members.push_back({{"name", name}, {"start", a}, {"end", b}, {"material", "steel"}, {"elements", elements}, {"section", pipe(d, t)}});
  };
  for (int i = 0; i < d_.rows; ++i)
    for (int j = 0; j < nc; ++j)
      for (int k = 0; k <= d_.levels; ++k) {
        nodes.push_back({{"name", node(i, j, k)}, {"position", at(0.5 * D + i * s, H * k / d_.levels, across(j))}});
        if (k == 0) {
          supports.push_back({{"node", node(i, j, 0)}, {"type", d_.base}});
          continue;
        }
        const std::string tag = std::to_string(i) + "_" + std::to_string(j) + "_" + std::to_string(k);
        member("column_" + tag, node(i, j, k - 1), node(i, j, k), d_.elements, D, d_.column_t);
        if (i + 1 < d_.rows) {
          member("beam_" + tag, node(i, j, k), node(i + 1, j, k), secondary, bd, bt);
          if (d_.bracing) member("brace_" + tag, node(i + 1, j, k - 1), node(i, j, k), secondary, bd, bt);
        }
        if (j + 1 < nc) member("tie_" + tag, node(i, j, k), node(i, j + 1, k), secondary, bd, bt);
      }
  json st{{"integrator", "newmark"}, {"theory", d_.beam_theory}, {"self_weight", true}, {"nodes", nodes}, {"members", members}, {"supports", supports}};
  damp(st, d_.steel, std::sqrt(D * D + std::pow(D - 2 * d_.column_t, 2)) / 4);  // pipe: r^2 = (D^2 + d^2) / 16
  out_["structure"] = st;
  box_.add(0, 0), box_.add(xd(0), H + 0.5 * D);
  box_.across(across(0) - 0.5 * D, across(nc - 1) + 0.5 * D);
}

void Builder::damp(json& st, const json& material, double r) {
  const auto modes = cantilever_modes(material["youngs_modulus"], material["density"], r, d_.height);
  period_ = 2 * kPi / modes.first;
  if (!(d_.damping_ratio > 0)) return;
  if (d_.damping_model == "modal") st["modal_damping"] = json{{"ratio", d_.damping_ratio}};
  else st["rayleigh_damping"] = rayleigh(d_.damping_ratio, modes, d_.damping_model);
}

double Builder::buffer_damping_frequency(double E, double thickness) const {
  // The buffer works as a spring k = E A / t under the boulder (A = r x W, a contact strip as wide as the
  // equivalent radius) against the boulder's mass: f = sqrt(k/m) / (2 pi). Without a boulder, the
  // layer's own quarter-wave frequency c / (4 t) (an estimate: the ratio is exact only at this frequency).
  // In 3D the sphere presses A = pi r^2 (the design basis's assumption, docs/design-checks.md).
  const double A = dim_ == 3 ? kPi * boulder_r_ * boulder_r_ : boulder_r_ * d_.width;
  if (p_.boulder) return std::sqrt(E * A / thickness / boulder_m_) / (2 * kPi);
  const double rho = p_.buffer->material.value("density", 600.0);
  return std::sqrt(E / rho) / (4 * thickness);
}

void Builder::add_buffer() {
  const BufferPreset& b = *p_.buffer;
  const double H = d_.height;
  const double top = b.top > 0 ? b.top : H;
  if (top > H) fail("/tyre_buffer/top", top, "a top at most the dam height " + std::to_string(H) + " m");
  if (top <= b.bottom) fail("/tyre_buffer/top", top, "a top above bottom = " + std::to_string(b.bottom) + " m");
  p_.buffer->top = top;  // front() reads the resolved top
  json m = b.material;
  const bool homog = b.type == "homogenised";
  m["name"] = homog ? "tyre_buffer" : "tyre_rubber";
  const double E = m["youngs_modulus"], nu = m["poisson_ratio"];
  const double f = m.contains("damping_frequency") ? m["damping_frequency"].get<double>()
                                                   : buffer_damping_frequency(E, homog ? b.thickness : b.tyre_diameter);
  if (b.viscosity > 0) {
    // Kelvin-Voigt: sigma_v = beta C:D, shear part 2 mu beta D' = 2 eta D'  ->  beta = eta / mu; zeta(f) = pi f beta.
    const double zeta = kPi * f * b.viscosity / (E / (2 * (1 + nu)));
    if (zeta > 1) fail("/tyre_buffer/viscosity", b.viscosity, "a viscosity giving a damping ratio <= 1 at " + std::to_string(f) + " Hz (it gives " +
                                                                 std::to_string(zeta) + ")");
    m["damping_ratio"] = zeta;
  }
  if (m.value("damping_ratio", 0.0) > 0 && !m.contains("damping_frequency")) m["damping_frequency"] = f;
  materials_.push_back(m);
  if (homog && dim_ == 3) {  // a box on the vertical upstream face, across the whole crest (presets.cpp allows no other)
    const double t = b.thickness, y0 = std::max(b.bottom, bed(-t)), w = 0.5 * d_.width;
    bodies_.push_back(json{{"name", "buffer"}, {"material", m["name"]}, {"shape", {{"type", "box"}, {"min", at(-t, y0, -w)}, {"max", at(0.0, top, w)}}}});
    bonded_.push_back("buffer");
    box_.add(-t, y0), box_.add(-t, top), box_.across(-w, w);
    return;
  }
  if (homog) {
    const double t = b.thickness;
    const double y0 = std::max(b.bottom, bed(xu(b.bottom) - t));
    json poly = json::array({{xu(y0) - t, y0}, {xu(y0), y0}, {xu(top), top}, {xu(top) - t, top}});
    bodies_.push_back(json{{"name", "buffer"}, {"material", m["name"]}, {"shape", {{"type", "polygon"}, {"vertices", poly}}}});
    bonded_.push_back("buffer");
    box_.add(xu(y0) - t, y0), box_.add(xu(top) - t, top);
    return;
  }
  const double R = 0.5 * b.tyre_diameter, inner = R - b.ring_thickness;
  if (inner <= 0) fail("/tyre_buffer/ring_thickness", b.ring_thickness, "a ring thickness below the tyre radius " + std::to_string(R) + " m");
  if (b.fill != "none") {
    const bool sand = b.fill == "sand";
    materials_.push_back(json{{"name", "tyre_fill"}, {"model", "drucker_prager"}, {"density", sand ? 1800 : 2000},
                              {"youngs_modulus", sand ? 30e6 : 80e6}, {"poisson_ratio", 0.3}, {"friction_angle", sand ? 35 : 40}});
  }
  int n = 0;
  for (double y = std::max(b.bottom, 0.0) + R; y + R <= top + 1e-9; y += 2 * R, ++n) {
    const std::string name = "tyre_" + std::to_string(n + 1);
    const double x = xu(y) - R;
    bodies_.push_back(json{{"name", name}, {"material", "tyre_rubber"},
                           {"shape", {{"type", "ball"}, {"center", {x, y}}, {"radius", R}, {"inner_radius", inner}}}});
    bonded_.push_back(name);
    if (b.fill != "none")
      bodies_.push_back(json{{"name", name + "_fill"}, {"material", "tyre_fill"},
                             {"shape", {{"type", "ball"}, {"center", {x, y}}, {"radius", inner * (1 - 1e-9)}}}});
    box_.add(x - R, y - R), box_.add(x + R, y + R);
  }
  if (n == 0) fail("/tyre_buffer/tyre_diameter", b.tyre_diameter, "tyres that fit between bottom and top (" + std::to_string(top - b.bottom) + " m)");
}

void Builder::add_boulder() {
  const BoulderPreset& b = *p_.boulder;
  materials_.push_back(json{{"name", "rock"}, {"model", "linear_elastic"}, {"density", b.density}, {"youngs_modulus", b.youngs_modulus},
                            {"poisson_ratio", b.poisson_ratio}});
  // The velocity in the elevation (vx along the flow, vy up) and, in 3D, across the channel (va): [vx, va, vy] there.
  const bool space = dim_ == 3;
  double vx = b.velocity.empty() ? std::sqrt(2 * kG * b.release_height) : b.velocity[0];
  double vy = b.velocity.empty() ? 0.0 : b.velocity[space ? 2 : 1];
  const double va = b.velocity.empty() || !space ? 0.0 : b.velocity[1];
  boulder_speed_ = std::sqrt(vx * vx + vy * vy + va * va);
  if (!(vx > 0)) fail("/boulder/velocity", b.velocity, "a velocity with a positive x component (towards the dam, downstream)");
  const double r = boulder_r_, gap = b.gap >= 0 ? b.gap : 2 * h_;
  impact_y_ = b.impact_height > 0 ? b.impact_height : 0.9 * d_.height;
  double cx, cy, ca = b.across;
  if (!b.position.empty()) {
    cx = b.position[0], cy = b.position[space ? 2 : 1], ca = space ? b.position[1] : 0.0;
    impact_y_ = cy;
  } else {
    // Touching point (centre r upstream of the face at the impact height), moved back by gap along the path.
    cx = front(impact_y_) - r - gap * vx / boulder_speed_;
    cy = impact_y_ - gap * vy / boulder_speed_;
    ca = b.across - gap * va / boulder_speed_;
  }
  if (space) {  // the impact point must lie on the dam across the channel: the crest's length, or the outer columns
    const double half = d_.type == "steel_open" ? 0.5 * (columns() - 1) * d_.width + 0.5 * d_.column_d : 0.5 * d_.width;
    if (std::abs(b.across) > half)
      fail("/boulder/across", b.across, "an impact point on the dam across the channel: |across| <= " + std::to_string(half) + " m");
    box_.across(ca - r, ca + r);
  }
  // The boulder must strike the dam (or its buffer): a centre above the crest passes over it and loads nothing, and
  // a design check of that run would read as a safe impact.
  if (cy > d_.height)
    fail(b.position.empty() ? "/boulder/impact_height" : "/boulder/position", b.position.empty() ? json(impact_y_) : json(b.position),
         "an impact point on the dam: the boulder's centre at most the dam height " + std::to_string(d_.height) + " m (above it, it passes over the crest)");
  if (cy - r < bed(cx) + 0.5 * h_)
    fail(b.position.empty() ? "/boulder/impact_height" : "/boulder/position", b.position.empty() ? json(impact_y_) : json(b.position),
         "a boulder above the ground: its centre at least the equivalent radius " + std::to_string(r) + " m (+ half a cell) above the bed");
  if (cx + r > front(cy) + 1e-9)
    fail("/boulder/position", b.position, "a boulder upstream of the dam face or buffer (it overlaps them)");
  rigid_boulder_ = b.model == "rigid" || (b.model == "auto" && p_.buffer);
  // On a bare face (auto) the rock is elastic while it can touch something and rigid in free flight, before and
  // after the strike: its waves then set the step only around the impact.
  free_boulder_ = b.model == "auto" && !p_.buffer;
  bodies_.push_back(json{{"name", "boulder"}, {"material", "rock"}, {"shape", {{"type", "ball"}, {"center", at(cx, cy, ca)}, {"radius", clean(r)}}},
                         {"velocity", space ? json{vx, va, vy} : json{vx, vy}}, {"rigid", rigid_boulder_}});
  if (free_boulder_) bodies_.back()["rigid_when_free"] = true;
  probes_.push_back(json{{"name", "boulder"}, {"type", "body"}, {"body", "boulder"}, {"quantities", {"velocity", "kinetic_energy", "position"}}});
  box_.add(cx - r, cy - r), box_.add(cx + r, cy + r);
  // End: arrival plus after_arrival() (0.15 s, or 1.5 cantilever periods on a bare face in 3D).
  const double travel = std::max(0.0, front(cy) - r - cx) / vx;
  end_time_ = std::max(end_time_, travel + after_arrival());
  if (members_ && !space) {
    const double y = std::clamp(impact_y_ / d_.height, 0.0, 1.0);
    if (d_.type == "concrete_gravity") {
      probes_.push_back(json{{"name", "impact"}, {"type", "member"}, {"member", "dam"}, {"position", y},
                             {"quantities", {"section_forces", "fibre_stress", "displacement"}}});
    } else {
      const int k = std::clamp(static_cast<int>(std::ceil(y * d_.levels)), 1, d_.levels);
      const double pos = std::clamp(y * d_.levels - (k - 1), 0.0, 1.0);
      probes_.push_back(json{{"name", "impact"}, {"type", "member"}, {"member", "column_0_" + std::to_string(k)}, {"position", pos},
                             {"quantities", {"section_forces", "fibre_stress", "displacement"}}});
    }
  }
}

// A blunt, full-depth surge front strikes like a rigid block: its peak is the elastic wave rho c v h w, set by
// the debris modulus (docs/verification.md, "Debris surge: the front"). A cohesionless front steeper than its
// angle of repose slumps before it arrives, so by default the snout's surface stands at the friction angle to
// the horizontal: at phi - theta to a bed falling at theta towards the dam, front_length = depth / tan(phi - theta),
// at most half the surge (mu_i: phi = atan mu_s). Slurries have no friction angle: their snout is taken at 45 degrees
// to the bed.
double Builder::front_length() const {
  const DebrisPreset& f = *p_.debris;
  if (f.front_length >= 0) return f.front_length;
  const std::string model = f.material.value("model", std::string("drucker_prager"));
  const double phi = model == "drucker_prager" ? f.material.value("friction_angle", 30.0) * kPi / 180
                     : model == "mu_i"         ? std::atan(f.material.value("mu_s", 0.0))  // the static friction of mu(I)
                                               : -1.0;
  const double beta = phi >= 0 ? phi - slope_ : kPi / 4;
  const double most = 0.5 * f.length;
  return beta <= 0 ? most : std::min(most, f.depth / std::tan(beta));
}

double Builder::flow_duration() const {
  const Hydrograph& g = p_.debris->hydrograph;
  return g.end() - g.time[g.first_flow_row()];
}

double Builder::rise_time() const {
  const Hydrograph& g = p_.debris->hydrograph;
  std::size_t k = 0;
  while (g.depth[k] < g.max_depth()) ++k;
  return std::max(0.0, g.time[k] - g.time[g.first_flow_row()]);
}

double Builder::front_foot(double height, double gap) const {
  double x = -gap;
  for (int pass = 0; pass < 3; ++pass) {
    const double y0 = bed(x);
    double face = 1e300;
    for (int k = 0; k <= 50; ++k) face = std::min(face, front(std::min(y0 + height * k / 50, d_.height)));
    x = face - gap;
  }
  return x;
}

double Builder::section_distance() const {
  const DebrisPreset& f = *p_.debris;
  // By default the deposit should not reach the section while debris still enters (the run stops if it does): the
  // hydrograph's volume V (per metre) held in a triangle as high as the dam at its face, 2 V / H long, plus two depths.
  return f.section_distance > 0 ? f.section_distance : std::max(1.0, 2 * f.hydrograph.volume_per_width() / d_.height + 2 * f.depth);
}

// A surge from a hydrograph enters through a section section_distance upstream of the dam, perpendicular to the bed
// (engine/mpm/inflow.hpp); its driven zone, 3 cells long, lies upstream of the section. The run lasts until the
// hydrograph's end, plus the time its last debris needs to reach the dam at half the fastest velocity, plus 0.5 s of
// pile-up.
void Builder::add_inflow() {
  const DebrisPreset& f = *p_.debris;
  const double c = std::cos(slope_), s = std::sin(slope_);
  const double x = front_foot(f.depth / c, 0.0);  // where the flow meets the face (or buffer) at the bed
  const double dist = section_distance(), xs = x - dist * c, zone = 3 * h_;
  bodies_.push_back(json{{"name", "debris"}, {"material", "debris"},
                         {"inflow", {{"point", {clean(xs), clean(bed(xs))}}, {"direction", {clean(c), clean(-s)}}, {"hydrograph", hydrograph_json(f.hydrograph)}}}});
  probes_.push_back(json{{"name", "debris"}, {"type", "body"}, {"body", "debris"}, {"quantities", {"velocity", "kinetic_energy", "position", "volume"}}});
  const double xz = xs - zone * c;
  box_.add(xz, bed(xz)), box_.add(xz + f.depth * s, bed(xz) + f.depth * c), box_.add(xs + f.depth * s, bed(xs) + f.depth * c);
  end_time_ = std::max(end_time_, f.hydrograph.end() + dist / (0.5 * f.velocity) + 0.5);
}

void Builder::add_debris() {
  const DebrisPreset& f = *p_.debris;
  json m = f.material;
  m["name"] = "debris";
  materials_.push_back(m);
  if (!f.hydrograph.empty()) return add_inflow();
  const double c = std::cos(slope_), gap = f.gap >= 0 ? f.gap : 2 * h_, height = f.depth / c;  // vertical flow height
  const double x = front_foot(height, gap);  // the front's foot, gap upstream of what it meets first
  const double xb = x - f.length * c;  // back edge: the surge is `length` long along the bed
  // The snout: the depth rises from nothing at the front to the full depth over front_length() along the bed.
  json poly = json::array({{xb, bed(xb)}, {x, bed(x)}});
  const double lf = front_length(), xf = x - lf * c;
  poly.push_back({xf, bed(xf) + height});
  if (lf < f.length) poly.push_back({xb, bed(xb) + height});
  const double vx = f.velocity * c, vy = -f.velocity * std::sin(slope_);
  bodies_.push_back(json{{"name", "debris"}, {"material", "debris"}, {"shape", {{"type", "polygon"}, {"vertices", poly}}}, {"velocity", {vx, vy}}});
  probes_.push_back(json{{"name", "debris"}, {"type", "body"}, {"body", "debris"}, {"quantities", {"velocity", "kinetic_energy", "position", "volume"}}});
  box_.add(xb, bed(x)), box_.add(x, bed(xb) + height);
  // End: the whole surge has arrived, plus 0.5 s of pile-up.
  end_time_ = std::max(end_time_, (gap + f.length) / f.velocity + 0.5);
}

void Builder::add_grid_walls_and_time() {
  const double h = h_, H = d_.height;
  // Room: 4 cells round everything; above, the boulder's possible rebound height v^2 / 2g (at most H)
  // and for a surge its depth plus twice its run-up (a slurry splashed 1.3 m above the flow); downstream,
  // a quarter of the height (half with a surge).
  double top = std::max(box_.hi[1], H) + 4 * h;
  if (p_.boulder) top += std::min(boulder_speed_ * boulder_speed_ / (2 * kG), H);
  if (p_.debris) top += p_.debris->depth + p_.debris->velocity * p_.debris->velocity / kG;  // twice the run-up v^2/2g
  const double right = box_.hi[0] + std::max(4 * h, (p_.debris ? 0.5 : 0.25) * H);
  // Upstream, room for a rebounding boulder to fly freely until the end (at most its impact speed for the
  // 0.15 s after arrival): with 4 cells it struck the upstream end wall and came back for a second impact.
  const double left = box_.lo[0] - 4 * h - (p_.boulder ? boulder_speed_ * after_arrival() : 0.0);
  const double bottom = std::min(0.0, bed(right)) - 4 * h;
  const double ox = std::floor(left / h) * h, oy = std::floor(bottom / h) * h;
  const double sx = std::ceil((right - ox) / h) * h, sy = std::ceil((top - oy) / h) * h;
  if (dim_ == 3) {  // across: 4 cells round the members and the boulder, the centre plane y = 0 inside
    const double a0 = std::floor((box_.across_lo - 4 * h) / h) * h, a1 = std::ceil((box_.across_hi + 4 * h) / h) * h;
    out_["grid"] = json{{"origin", at(ox, oy, a0)}, {"size", at(sx, sy, a1 - a0)}, {"cell_size", h}};
    out_["analysis"] = json{{"dimension", 3}, {"end_time", clean(end_time_)}, {"gravity", {0.0, 0.0, -kG}}};
  } else {
    out_["grid"] = json{{"origin", {clean(ox), clean(oy)}}, {"size", {clean(sx), clean(sy)}}, {"cell_size", h}};
    out_["analysis"] = json{{"dimension", 2}, {"plane", "strain"}, {"thickness", d_.width}, {"end_time", clean(end_time_)}};
  }
  // A rigid boulder leaves the step to the buffer's rubber. The step's error on the buffered dam's peaks is first
  // order and grows as h falls at a fixed cfl; at 0.25 it stays within a few per cent of the small-step limit
  // (docs/verification.md, "Rigid boulder").
  if (rigid_boulder_) out_["analysis"]["cfl"] = 0.25;
  out_["output"] = json{{"history_interval", clean(std::min(1e-4, end_time_ / 2000))}, {"snapshot_interval", clean(end_time_ / 50)}};
  json walls = json::array();
  const double bed_mu = p_.debris ? p_.debris->bed_friction : 0.4;
  walls.push_back({{"name", "ground"}, {"type", "plane"}, {"point", at(0.0, 0.0)}, {"normal", at(std::sin(slope_), std::cos(slope_))},
                   {"condition", "friction"}, {"friction", bed_mu}});
  walls.push_back({{"name", "upstream_end"}, {"type", "plane"}, {"point", at(ox + 2 * h, 0.0)}, {"normal", at(1.0, 0.0)}, {"condition", "slip"}});
  walls.push_back({{"name", "downstream_end"}, {"type", "plane"}, {"point", at(ox + sx - 2 * h, 0.0)}, {"normal", at(-1.0, 0.0)}, {"condition", "slip"}});
  // Surges throw single particles far above any run-up (a Bingham slurry flung one 5.8 m up at 0.4 s); a
  // slip ceiling keeps such ejecta in the grid instead of stopping the run. It carries no load worth noting.
  if (p_.debris)
    walls.push_back({{"name", "ceiling"}, {"type", "plane"}, {"point", {0.0, oy + sy - 2 * h}}, {"normal", {0.0, -1.0}}, {"condition", "slip"}});
  if (!members_)  // the continuum dam is stuck to its foundation along its base
    walls.push_back({{"name", "dam_base"}, {"type", "box"}, {"min", {xu(0), oy}}, {"max", {xd(0), 1e-9 * H}}, {"condition", "stick"}});
  out_["walls"] = walls;
}

}  // namespace

json build_preset_scene(const PresetScene& p, const std::string& file) { return Builder(p, file).build(); }

}  // namespace dmi
