// The low-level scene of the presets (layout in presets.hpp): materials, bodies, walls, the frame,
// member contact, grid, end time and probes. Every default is stated where it is chosen.
#include <sstream>

#include "engine/scenario/design_basis_json.hpp"
#include "engine/scenario/hydrograph_io.hpp"
#include "engine/scenario/preset_builder.hpp"

namespace dmi::preset_build {

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

}  // namespace dmi::preset_build

namespace dmi {

nlohmann::json build_preset_scene(const PresetScene& p, const std::string& file) { return preset_build::Builder(p, file).build(); }

}  // namespace dmi
