// The builder of the presets' low-level scene (engine/scenario/preset_scene.cpp, preset_structure.cpp,
// preset_loads.cpp): one class whose parts live in three files. Internal to engine/scenario.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/common/error.hpp"
#include "engine/scenario/preset_types.hpp"

namespace dmi::preset_build {

using json = nlohmann::json;

inline constexpr double kPi = 3.14159265358979323846, kG = 9.81;

// x to 12 significant digits, so generated coordinates print without floating-point noise.
inline double clean(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.12g", x);
  return std::strtod(b, nullptr);
}

// Largest of {1, 1.5, 2, 2.5, 3, 4, 5, 6, 8} x 10^k not above x: cell sizes that print cleanly.
inline double nice_floor(double x) {
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
inline std::pair<double, double> cantilever_modes(double E, double rho, double r, double L) {
  const double base = std::sqrt(E / rho) * r / (L * L);
  return {1.8751 * 1.8751 * base, 4.6941 * 4.6941 * base};
}

// Rayleigh C = a M + b K with damping ratio zeta at w1 and w2 (Chopra 2012, eq. 11.4.9); model "mass": C = a M with
// zeta at w1, a = 2 zeta w1 (eq. 11.4.3 with b = 0: zeta(w) = zeta w1 / w).
inline json rayleigh(double zeta, std::pair<double, double> w, const std::string& model = "rayleigh") {
  if (model == "mass") return json{{"mass", 2 * zeta * w.first}, {"stiffness", 0.0}};
  return json{{"mass", 2 * zeta * w.first * w.second / (w.first + w.second)}, {"stiffness", 2 * zeta / (w.first + w.second)}};
}

inline json pipe(double d, double t) { return json{{"type", "pipe"}, {"diameter", d}, {"wall_thickness", t}}; }

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

}  // namespace dmi::preset_build
