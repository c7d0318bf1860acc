#include "design/stability_checks.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "design/loads.hpp"
#include "design/stability.hpp"

namespace dmi::design {

using nlohmann::json;

namespace {

constexpr const char* kWho = "base joint";

// The joint loads at one sample from the base totals the supports exert on the dam (Fx, Fy, M about x0): the
// foundation's force acts where Fy (x_p - x0) = M; the weight's moment about the toe Mr is the stabilising one, and
// the rest overturns: Mo = Mr - Fy (x_toe - x_p) = Mr - Fy (x_toe - x0) + M. Round-off of the static state (a shear or
// an overturning moment below 1e-9 of the weight's) is zero.
// Uplift U (full: gamma_w h_w at the heel falling to 0 at the toe, times the limits' factor) acts at 2B/3 from the toe:
// it lightens the joint and overturns.
BaseJointLoads joint_loads(double Fx, double Fy, double M, double x0, double x_toe, double Mr, double U, double B) {
  BaseJointLoads l;
  l.N = Fy - U, l.H = -Fx, l.Mr = Mr;
  l.Mo = Mr - Fy * (x_toe - x0) + M + U * 2 * B / 3;
  if (std::abs(l.H) < 1e-9 * std::abs(Fy)) l.H = 0;
  if (std::abs(l.Mo) < 1e-9 * Mr) l.Mo = 0;
  return l;
}

struct Sample {
  BaseJointLoads l;
  ResultantLocation at;
  double resistance = 0;  // N tan(phi) + c A' (N)
  double sliding = 0;     // factor of safety
};

Sample sample(const BaseJointLoads& l, const RigidSection& s, double W, const FoundationLimits& L) {
  Sample out{l, resultant_location(l, s.base_m, W), 0, 0};
  const double area = out.at.compressed_fraction * s.base_m * W;  // A', the base in compression
  out.resistance = sliding_resistance(l, L.friction, L.cohesion, area);
  out.sliding = sliding_factor(l, L.friction, L.cohesion, area);
  return out;
}

StabilityRecord::Sample sample_record(const Sample& s, double t) {
  return {t, s.l.N, s.l.H, s.sliding, overturning_factor(s.l), s.at.x_r, s.at.eccentricity, s.at.compressed_fraction, s.at.toe_pressure,
          s.at.heel_pressure};
}

Check stability_check(const char* level, const char* id, const char* title, double demand, double capacity, const char* unit, double t,
                      const std::string& formula, const char* source) {
  Check c;
  c.level = level;
  c.id = id, c.title = title, c.member = kWho, c.material = "foundation";
  c.demand = demand, c.capacity = capacity, c.unit = unit, c.time_s = t, c.formula = formula, c.source = source;
  if (std::string(id).find("_persistent") != std::string::npos) c.situation = "persistent";
  c.finish();
  return c;
}

void persistent_checks(const Sample& s, double t0, const RigidSection& sec, const FoundationLimits& L, std::vector<Check>& checks) {
  checks.push_back(stability_check("ultimate", "stability_sliding_persistent", "sliding, persistent situation (the loads at rest)",
                                   L.sliding_factor_usual * std::abs(s.l.H), s.resistance, "N", t0, "FS_req |H| <= N tan(phi) + c A'",
                                   "EM 1110-2-2100 (2005) eq. 3-1, Table 3-3 (usual)"));
  const double e = s.l.N > 0 ? std::abs(s.at.eccentricity) : std::numeric_limits<double>::infinity();  // the joint lifts
  checks.push_back(stability_check("serviceability", "stability_resultant_persistent", "resultant in the middle third, persistent situation", e,
                                   sec.base_m / 6, "m", t0, "|e| <= B/6 (base fully in compression)", "EM 1110-2-2100 (2005) 3-9 (usual)"));
  checks.push_back(stability_check("ultimate", "stability_bearing_persistent", "bearing pressure, persistent situation",
                                   std::max(s.at.toe_pressure, s.at.heel_pressure), L.bearing_capacity, "Pa", t0,
                                   "q = N / (B W) (1 +- 6 e / B) <= q_allowable", "EM 1110-2-2100 (2005) 3-10"));
}

}  // namespace

bool stability_applies(const FrameInfo& f, const DesignBasis& b) {
  const DamBasis& d = b.dam;
  return !f.supports.empty() && d.type == DamKind::concrete_gravity && is_set(d.heel_x_m) && is_set(d.toe_x_m) &&
         is_set(d.crest_upstream_x_m) && is_set(d.crest_downstream_x_m);
}

std::optional<StabilityRecord> stability(const Results& r, const FrameInfo& f, const DesignBasis& b, const FoundationLimits& L,
                                         std::vector<Check>& checks, const std::string& where) {
  if (!stability_applies(f, b) || r.time.empty()) return std::nullopt;
  const DamBasis& d = b.dam;
  const RigidSection sec = rigid_section(d.heel_x_m, d.toe_x_m, d.crest_upstream_x_m, d.crest_downstream_x_m, d.height_m, d.width_m, d.density_kg_m3);
  const double Mr = sec.weight_N * sec.centroid_from_toe_m;
  const double U = is_set(d.water_height_m) ? L.uplift_factor * d.water_unit_weight_N_m3 * d.water_height_m * sec.base_m * d.width_m / 2 : 0.0;
  const BaseHistory h = base_history(r, f, where);
  // The elevation's base forces: 2D (Fx, Fy, Mz); 3D (x along the flow, z up) Fx, Fz and -My (a moment about +y turns
  // z towards x, the elevation's clockwise).
  const bool space = f.dim == 3;
  const std::vector<double>&Fx = h.at("Fx_N"), &Fy = h.at(space ? "Fz_N" : "Fy_N");
  std::vector<double> M = h.at(space ? "My_Nm" : "M_Nm");
  if (space)
    for (double& m : M) m = -m;
  // The rigid dam's weight is the section's; the frame must carry it at rest (self-weight on, the same section), else
  // its reactions do not describe this dam.
  if (!(std::abs(Fy[0] - sec.weight_N) <= 0.1 * sec.weight_N)) {
    StabilityRecord out;
    out.not_assessed = "the frame's vertical reaction at rest (" + std::to_string(Fy[0]) + " N) is not the dam section's weight (" +
                       std::to_string(sec.weight_N) + " N) within 10 %: self-weight off, or a frame that is not this dam";
    return out;
  }
  std::vector<Sample> s;
  std::vector<double> H(r.time.size()), R(r.time.size()), Mo(r.time.size()), Mres(r.time.size(), Mr);
  for (std::size_t k = 0; k < r.time.size(); ++k) {
    s.push_back(sample(joint_loads(Fx[k], Fy[k], M[k], h.about[0], d.toe_x_m, Mr, U, sec.base_m), sec, d.width_m, L));
    H[k] = s[k].l.H, Mo[k] = s[k].l.Mo, R[k] = s[k].resistance;
  }
  persistent_checks(s[0], r.time[0], sec, L, checks);
  // The impact: the worst instants, the time the joint opens, and the rigid-body measures of the ultimate level.
  std::size_t slide = 0, open = 0;
  double outside_third = 0, outside_base = 0;
  for (std::size_t k = 0; k < s.size(); ++k) {
    if (s[k].sliding < s[slide].sliding) slide = k;
    if (s[k].at.compressed_fraction < s[open].at.compressed_fraction) open = k;
    const double dt = k > 0 ? r.time[k] - r.time[k - 1] : 0.0;
    if (s[k].at.compressed_fraction < 1) outside_third += dt;
    if (!s[k].at.within_base) outside_base += dt;
  }
  const double displacement = newmark_sliding_displacement(r.time, H, R, sec.mass_kg);
  const double rotation = newmark_sliding_displacement(r.time, Mo, Mres, sec.inertia_about_toe_kg_m2);
  const double alpha = sec.critical_angle_rad();
  checks.push_back(stability_check("ultimate", "stability_sliding_displacement", "sliding under the impact (rigid block, Newmark)", displacement,
                                   L.sliding_displacement_limit, "m", r.time.back(), "d = double integral of (H - mu N - c A') / m while sliding",
                                   "Newmark (1965); limit: Richards & Elms (1979)"));
  checks.push_back(stability_check("ultimate", "stability_rocking", "rocking about the toe under the impact (rigid block)", L.rocking_safety_factor * rotation, alpha,
                                   "rad", r.time.back(), "SF theta_max <= alpha_c = atan(x_G / y_G), I_toe theta'' = M_o - W x_G",
                                   "Housner (1963), small rotations"));
  StabilityRecord out;
  out.model = "rigid dam on its base joint under the simulated base reactions (decoupled: the fixed-base run's reactions drive it)";
  out.dam = {sec.mass_kg, sec.weight_N, sec.base_m, d.width_m, sec.centroid_from_toe_m, sec.centroid_height_m, sec.inertia_about_toe_kg_m2, alpha};
  out.foundation = {L.friction, L.cohesion, L.bearing_capacity, L.uplift_factor, U};
  out.persistent = sample_record(s[0], r.time[0]);
  out.impact = {sample_record(s[slide], r.time[slide]), sample_record(s[open], r.time[open]), outside_third, outside_base, displacement, rotation};
  return out;
}

}  // namespace dmi::design
