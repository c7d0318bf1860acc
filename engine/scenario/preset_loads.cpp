// The presets' loads: the boulder, and the debris surge (a released block or an inflow from a hydrograph).
#include "engine/scenario/preset_builder.hpp"
#include "engine/scenario/hydrograph_io.hpp"

namespace dmi::preset_build {

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

}  // namespace dmi::preset_build
