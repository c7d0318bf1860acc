// Capacity formulas of the design checks (docs/design-checks.md), pure functions in SI units so each
// can be checked by hand, and the record of one check (demand, capacity, utilisation, where, when).
#pragma once
#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/structure/section.hpp"

namespace dmi::design {

// One check. utilisation = demand / capacity; passed when utilisation <= 1.
struct Check {
  std::string id;        // stable key, e.g. "concrete_flexural_tension" (docs/design-json.md)
  std::string title;     // readable
  std::string member;    // member name, or "solid: <case>" / "" for whole-structure checks
  std::string material;  // concrete | steel
  double demand = 0, capacity = 0;
  std::string unit;      // of demand and capacity
  double utilisation = 0;
  bool passed = true;
  double position = -1;  // fraction of the member length from its start (-1: not on a member)
  double s_m = -1;       // distance from the member start (m)
  double x_m = 0, y_m = 0, z_m = 0;  // global location (m)
  bool space = false;       // a 3D location: location_m has z
  double time_s = -1;    // instant of the governing demand (-1: not time-dependent)
  std::string formula, source;
  // What the check says about the design (docs/design-checks.md, "Two levels"): serviceability (elastic stresses within
  // strengths, no joint opening at rest), ultimate (stability, local damage short of perforation, sliding and rocking
  // under the impact), or information (reported, never judged: e.g. a linear stress under a point load).
  std::string level = "serviceability";
  // The design situation (EN 1990 3.2): persistent (the loads at rest: self-weight, deposit, water, with their partial
  // factors) or accidental (the impact, EN 1990 6.4.3.3: the actions unfactored).
  std::string situation = "accidental";
  // Strain-rate effects on the capacity (design/strain_rate_checks): the factor applied and the strain rate it was
  // taken at (1/s; 0: a static strength).
  double dynamic_factor = 1, strain_rate = 0;
  // The demand at the first history sample where the check governs: the static state the run starts from (members).
  double static_demand = 0;
  // An unbounded demand (a dam that does not stop sliding, a block that topples, a resultant outside the base) is held
  // as 1e300, as is the utilisation of a demand on no capacity: results files hold no infinities (JSON would null them).
  void finish() {
    if (std::isinf(demand)) demand = demand > 0 ? 1e300 : -1e300;
    if (capacity > 0 && std::abs(demand) < 1e-9 * capacity) demand = 0;  // round-off of a zero demand (e.g. 4.7e-10 Pa)
    utilisation = capacity > 0 ? demand / capacity : (demand > 0 ? 1e300 : 0.0);
    passed = utilisation <= 1.0;
  }
  nlohmann::json to_json() const;
};

// --- Concrete (plain, ACI 318-19 chapter 14; SI: f'c in Pa, results in N or Pa) --------------------------
// Sqrt of f'c in MPa, returned in Pa: lambda sqrt(f'c[MPa]) * 1e6.
double sqrt_fc_Pa(double fc_Pa, double lambda = 1.0);
// One-way shear, ACI 318-19 Table 14.5.5.1(a): V_n = (4/3) lambda sqrt(f'c) b_w h [psi] = 0.11 lambda sqrt(f'c) b_w h [MPa];
// returns phi V_n (N).
double concrete_one_way_shear_capacity(double fc_Pa, double lambda, double width_m, double depth_m, double phi);
// Two-way (punching) shear, ACI 318-19 Table 14.5.5.1(b): V_n = min((4/3 + 8/(3 beta)), 2.66) lambda sqrt(f'c) b_o h [psi]
// = min(0.11 (1 + 2/beta), 0.22) lambda sqrt(f'c) b_o h [MPa], beta = long/short side of the patch, b_o the perimeter
// at h/2 from the patch (ACI 318-19 22.6.4.1): b_o = 2 (c1 + h) + 2 (c2 + h). Returns phi V_n (N).
double concrete_punching_capacity(double fc_Pa, double lambda, double patch_w_m, double patch_h_m, double depth_m, double phi);

// --- Steel circular hollow sections (EN 1993-1-1) -----------------------------------------------------------
double chs_area(double D, double t);               // pi (D^2 - d^2) / 4, d = D - 2t
double chs_elastic_modulus(double D, double t);    // W_el = I / (D/2), I = pi (D^4 - d^4) / 64
double chs_plastic_modulus(double D, double t);    // W_pl = (D^3 - d^3) / 6
double chs_shear_area(double D, double t);         // A_v = 2 A / pi (EN 1993-1-1 6.2.6(3)(g))
// Section class in bending and/or compression from D/t, EN 1993-1-1 Table 5.2 (sheet 3):
// eps^2 = 235 / f_y[MPa]; class 1: D/t <= 50 eps^2, 2: <= 70 eps^2, 3: <= 90 eps^2, else 4.
int chs_class(double D, double t, double fy_Pa);
double chs_class3_limit(double fy_Pa);             // 90 eps^2 (the largest D/t this check accepts)
// Plastic shear resistance V_pl,Rd = A_v (f_y / sqrt 3) / gamma_M0 (EN 1993-1-1 eq. 6.18), N.
double chs_shear_resistance(double D, double t, double fy_Pa, double gamma_M0);
// Linear interaction N_Ed / N_Rd + M_Ed / M_Rd (EN 1993-1-1 6.2.1(7) eq. 6.2), N_Rd = A f_y / gamma_M0,
// M_Rd = W f_y / gamma_M0 with W = W_pl for class 1-2, W_el for class 3 (6.2.5(2) eqs. 6.13-6.14).
double chs_interaction(double N, double M, double D, double t, double fy_Pa, double gamma_M0);
// Torsion of a CHS, EN 1993-1-1 6.2.7(1) eq. 6.23 with the elastic St Venant resistance T_Rd = W_t f_y / (sqrt 3 gamma_M0),
// W_t = J / (D/2) = 2 I / (D/2): returns T_Rd (N m).
double chs_torsion_resistance(double D, double t, double fy_Pa, double gamma_M0);
// Shear resistance of a structural hollow section under torsion, EN 1993-1-1 6.2.7(9) eq. 6.28:
// V_pl,T,Rd = [1 - tau_t,Ed / (f_y / (sqrt 3 gamma_M0))] V_pl,Rd, tau_t,Ed = |T| / W_t (not below 0), N.
double chs_shear_resistance_with_torsion(double T, double D, double t, double fy_Pa, double gamma_M0);

// --- Steel box and I sections (EN 1993-1-1; square corners, no root fillets) ------------------------------------------
// The section's plates against the class-3 limits of Table 5.2 (eps = sqrt(235 / f_y[MPa])), the flanges in compression
// and the webs in bending: a box's walls as internal parts, c = b - 3t and h - 3t (the Table's note for RHS), 42 eps and
// 124 eps; an I's outstand flanges c = (b - t_w) / 2 over t_f, 14 eps, and its web c = h - 2 t_f over t_w, 124 eps. The
// largest ratio of a plate's c/t to its limit for class `cls` (1, 2 or 3; <= 1: that class or better), the limits of
// classes 1 and 2 box 33 / 38 eps and 72 / 83 eps, I 9 / 10 eps and 72 / 83 eps; and the class (1 to 4).
double flanged_class_ratio(const Section& s, double fy_Pa, int cls);
int flanged_class(const Section& s, double fy_Pa);
// Linear interaction N_Ed / N_Rd + M_y'Ed / M_y',Rd + M_z'Ed / M_z',Rd (EN 1993-1-1 6.2.1(7) eq. 6.2), the moment
// resistances plastic for class 1-2 and elastic for class 3 (6.2.5(2)): `in_plane` the moment in the plane of the web(s),
// `out_of_plane` the other (0 in a plane frame).
double flanged_interaction(double N, double in_plane, double out_of_plane, const Section& s, double fy_Pa, double gamma_M0);
// Plastic shear resistance A_v f_y / (sqrt 3 gamma_M0) (eq. 6.18), A_v along the web(s) A h / (b + h) (box, 6.2.6(3)(c))
// or h_w t_w (I, (d)), across them A b / (b + h) (box) or the flanges 2 b t_f (I), N.
double flanged_shear_resistance(const Section& s, bool along_web, double fy_Pa, double gamma_M0);
// St Venant torsional resistance W_t f_y / (sqrt 3 gamma_M0) (6.2.7, elastic), W_t of the section (Bredt's for a box), N m.
double flanged_torsion_resistance(const Section& s, double fy_Pa, double gamma_M0);

// --- Steel members that yield (EN 1993-1-1 6.3; DNV-RP-C204) -------------------------------------------------------
// Imperfection factor alpha of a buckling curve a0, a, b, c, d (EN 1993-1-1 Table 6.1: 0.13, 0.21, 0.34, 0.49, 0.76).
double buckling_imperfection(const std::string& curve);
// Flexural buckling resistance N_b,Rd = chi A f_y / gamma_M1 (EN 1993-1-1 eq. 6.47), chi = 1 / (Phi + sqrt(Phi^2 -
// lambda^2)) <= 1, Phi = 0.5 (1 + alpha (lambda - 0.2) + lambda^2) (eq. 6.49), lambda = sqrt(A f_y / N_cr) (eq. 6.50),
// N_cr = pi^2 E I / L_cr^2. Returns N (class 1-3 sections: A, not A_eff).
double flexural_buckling_resistance(double A, double I, double L_cr, double E, double fy, double alpha, double gamma_M1);
// Local denting of a tube of diameter D and wall t struck over a width b (DNV-RP-C204 (2010) sec. 3.10; NORSOK N-004
// Annex A): R / R_c = c1 (w/D)^c2, R_c = f_y t^2 / 4 sqrt(D/t), c1 = 22 + 1.2 b/D, c2 = 1.925 / (3.5 + b/D); the energy
// to a dent w is E = c1 R_c D (w/D)^(c2 + 1) / (c2 + 1). The dent depth (m) at a force F (N), and under an energy E (J).
double dent_depth_at_force(double F, double D, double t, double fy, double b);
double dent_depth_for_energy(double E, double D, double t, double fy, double b);

}  // namespace dmi::design
