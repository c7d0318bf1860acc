// Lin, Cheng & Tuan's closed-form tools: the single-degree-of-freedom oscillator, its
// free and impulse responses, the boulder-on-dam peak base force, a buffer in series, and three
// design-practice impact loads (GEO/Kwan 2012 Hertz, full Hertz after Johnson 1985, EN 1991-1-7 Annex C).
// Pure functions, SI units throughout (kg, m, s, N, Pa, rad/s); displacement u is positive in the
// direction of the initial velocity / impulse. Every function validates its arguments and throws
// std::invalid_argument naming the function, the argument and its value.
#pragma once
#include <vector>

namespace dmi::sdof {

// ---------------------------------------------------------------------------------------------------
// SDOF theory (Lin, Cheng & Tuan eqs. 9–20): m u'' + c u' + k u = 0
// ---------------------------------------------------------------------------------------------------

// omega_n = sqrt(k/m) (rad/s), Lin, Cheng & Tuan eq. (9).
double natural_frequency(double mass_kg, double stiffness_N_per_m);

// c_c = 2 m omega_n = 2 sqrt(k m) (N s/m), Lin, Cheng & Tuan eq. (14).
double critical_damping(double mass_kg, double stiffness_N_per_m);

// omega_D = omega_n sqrt(1 - zeta^2) (rad/s), Lin, Cheng & Tuan eq. (14); requires 0 <= zeta < 1.
double damped_frequency(double natural_frequency_rad_per_s, double damping_ratio);

// An oscillator: mass m (kg), stiffness k (N/m), damping ratio zeta = c/c_c (-), zeta >= 0 (zeta < 1
// underdamped, = 1 critically damped, > 1 overdamped).
struct Oscillator {
  double mass_kg;
  double stiffness_N_per_m;
  double damping_ratio = 0.0;

  double natural_frequency_rad_per_s() const;   // omega_n = sqrt(k/m)
  double damping_coefficient_N_s_per_m() const; // c = zeta c_c = 2 zeta sqrt(k m)
};

// The oscillator with viscous damping coefficient c (N s/m): zeta = c / (2 sqrt(k m)), Lin, Cheng & Tuan eq. (14).
Oscillator oscillator_from_damping_coefficient(double mass_kg, double stiffness_N_per_m,
                                               double damping_N_s_per_m);

// Free vibration u(t) (m) from u(0) = u0 (m), u'(0) = v0 (m/s), t >= 0 (s):
//   zeta = 0    u = u0 cos(wn t) + (v0/wn) sin(wn t)                                   eq. (9)
//   zeta < 1    u = e^{-zeta wn t} [u0 cos(wD t) + ((v0 + zeta wn u0)/wD) sin(wD t)]     eq. (14)
//   zeta = 1    u = e^{-wn t} [u0 + (v0 + wn u0) t]                       (critical; standard result)
//   zeta > 1    u = e^{-zeta wn t} [u0 cosh(w* t) + ((v0 + zeta wn u0)/w*) sinh(w* t)],
//               w* = wn sqrt(zeta^2 - 1)                                  (overdamped; standard result)
double free_vibration(const Oscillator& o, double u0_m, double v0_m_per_s, double t_s);

// Unit-impulse response h(t - tau) (m per N s): zero before tau, else the free vibration from rest with
// v0 = 1/m, i.e. sin(wn (t-tau)) / (m wn) undamped, eq. (18), and
// e^{-zeta wn (t-tau)} sin(wD (t-tau)) / (m wD) damped, eq. (19) (and the zeta >= 1 forms above).
double unit_impulse_response(const Oscillator& o, double t_s, double tau_s);

// Response (m) to an impulse I (N s) applied at tau: I h(t - tau), Lin, Cheng & Tuan eqs. (18)-(19), (21).
double impulse_response(const Oscillator& o, double impulse_N_s, double t_s, double tau_s);

// Peak of the unit-impulse response and its time after the impulse.
struct ImpulsePeak {
  double displacement_m_per_N_s;  // u_max per unit impulse (m/(N s))
  double time_s;                  // t_peak - tau (s)
};

// Peak of h, Lin, Cheng & Tuan eq. (20), from h' = 0 <=> tan(wD t) = sqrt(1-zeta^2)/zeta:
//   t_peak = atan2(sqrt(1-zeta^2), zeta) / wD,
//   u_max  = (1/(m wn)) exp(-(zeta/sqrt(1-zeta^2)) atan(sqrt(1-zeta^2)/zeta))        (0 <= zeta < 1)
// zeta = 0 gives 1/(m wn) at t = pi/(2 wn). Same derivation with tanh for zeta > 1:
//   t_peak = atanh(sqrt(zeta^2-1)/zeta) / w*, u_max = (1/(m wn)) exp(-(zeta/sqrt(zeta^2-1)) atanh(...)),
// and zeta = 1: t_peak = 1/wn, u_max = 1/(e m wn). u_max decreases with zeta (Lin, Cheng & Tuan).
ImpulsePeak unit_impulse_peak(const Oscillator& o);

// ---------------------------------------------------------------------------------------------------
// Boulder on a dam (Lin, Cheng & Tuan eqs. 21–23): dam = SDOF (M, k), impulse I = m v0, damping neglected
// ---------------------------------------------------------------------------------------------------

struct BoulderImpact {
  double impulse_N_s;                 // I = m v0, eq. (21)
  double natural_frequency_rad_per_s; // omega_n = sqrt(k/M) of the dam
  double peak_displacement_m;         // u_max = I / (M omega_n), eq. (22)
  double peak_base_force_N;           // F_T,max = k u_max = I omega_n = m v0 omega_n, eq. (23)
};

// Lin, Cheng & Tuan eqs. (21)-(23): boulder mass m (kg) at speed v0 (m/s) on a dam of effective mass M (kg)
// and stiffness k (N/m). u(t) ~ (I/(M wn)) sin(wn t); eq. (23) as written (the impulse goes entirely
// into the dam's effective mass M; the boulder mass enters only through I).
BoulderImpact boulder_on_dam(double boulder_mass_kg, double boulder_speed_m_per_s,
                             double dam_mass_kg, double dam_stiffness_N_per_m);

// A prismatic section: area A (m^2), second moment I (m^4) about the bending axis.
struct Section {
  double area_m2;
  double second_moment_m4;
  double radius_of_gyration_m() const;  // r = sqrt(I/A)
};

// Rectangle of width b (m, along the bending axis, e.g. the 2 m dam face) and depth h (m, in the
// direction of the impact): A = b h, I = b h^3 / 12, r = h / sqrt(12).
Section rectangular_section(double width_m, double depth_m);

// Tapered rectangle (depth varying linearly from crest to base) approximated by the rectangle of the
// mean depth (h_crest + h_base)/2 -- an approximation, not an exact tapered-beam stiffness.
Section tapered_rectangular_section(double width_m, double crest_depth_m, double base_depth_m);

struct CantileverSdof {
  double stiffness_N_per_m;            // k = 3 E I / L^3 (tip load)
  double effective_mass_kg;            // M = rho A L / 2
  double natural_frequency_rad_per_s;  // omega_n = sqrt(k/M) = sqrt(6E/rho) r / L^2
  double first_mode_rad_per_s;         // omega_1 = (beta_1 L)^2 sqrt(E/rho) r / L^2, beta_1 L = 1.8751
};

// Uniform cantilever column of height L (m), Young's modulus E (Pa), density rho (kg/m^3), Lin, Cheng & Tuan.
// beta_1 L = 1.87510407 is the first root of 1 + cos x cosh x = 0 (the paper's 1.875).
CantileverSdof cantilever_sdof(double youngs_modulus_Pa, double density_kg_per_m3,
                               const Section& section, double height_m);

// ---------------------------------------------------------------------------------------------------
// Buffer in series (Lin, Cheng & Tuan, last line)
// ---------------------------------------------------------------------------------------------------

// Springs in series: k_eff = 1 / (1/k_dam + 1/k_buffer) (N/m).
double series_stiffness(double dam_stiffness_N_per_m, double buffer_stiffness_N_per_m);

// Buffer layer in compression: k_buffer = E_buffer A_contact / t_buffer (N/m).
double buffer_layer_stiffness(double buffer_modulus_Pa, double contact_area_m2, double thickness_m);

// boulder_on_dam with the dam stiffness replaced by k_eff = series_stiffness(k_dam, k_buffer), same M:
// omega and F_T,max = I omega both drop by sqrt(k_eff / k_dam); u_max grows by sqrt(k_dam / k_eff).
BoulderImpact buffered_boulder_on_dam(double boulder_mass_kg, double boulder_speed_m_per_s,
                                      double dam_mass_kg, double dam_stiffness_N_per_m,
                                      double buffer_stiffness_N_per_m);

// ---------------------------------------------------------------------------------------------------
// Hertz impact (the design-practice formulas: engine/sdof/practice_loads.hpp)
// ---------------------------------------------------------------------------------------------------

// E* = 1 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2) (Pa), Johnson (1985) Contact Mechanics, Hertz theory (ch. 4).
double hertz_effective_modulus(double youngs_modulus_1_Pa, double poisson_ratio_1,
                               double youngs_modulus_2_Pa, double poisson_ratio_2);

struct HertzImpact {
  double effective_modulus_Pa;  // E*
  double max_indentation_m;     // delta_max = (15 m v^2 / (16 E* R^{1/2}))^{2/5}
  double peak_force_N;          // F_max = (4/3) E* R^{1/2} delta_max^{3/2}
  double contact_duration_s;    // t_c = 2.94 delta_max / v
};

// Elastic sphere (mass m, radius R, E1, nu1) on a massive elastic half-space (E2, nu2) at normal speed
// v, Johnson (1985) ch. 11: R* = R; F = (4/3) E* R^{1/2} delta^{3/2}; energy 1/2 m v^2 =
// (8/15) E* R^{1/2} delta_max^{5/2} gives delta_max; t_c = 2.94 delta_max / v (Johnson's 2.94; exact 2.9432).
HertzImpact hertz_sphere_impact(double boulder_mass_kg, double boulder_speed_m_per_s,
                                double boulder_radius_m, double boulder_modulus_Pa,
                                double boulder_poisson_ratio, double barrier_modulus_Pa,
                                double barrier_poisson_ratio);

// ---------------------------------------------------------------------------------------------------
// Continuous cantilever under a force history (beyond Lin, Cheng & Tuan's single mode)
// ---------------------------------------------------------------------------------------------------

// Base shear V(t_k) (N) of a uniform, undamped Euler-Bernoulli cantilever (fixed at x = 0, free at L) under a
// transverse force history at height a: force[k] is the mean force over (t[k-1], t[k]] (force[0] is ignored, the
// beam starts at rest). Modal superposition of the exact continuous modes phi_j(x) = cosh b x - cos b x
// - s_j (sinh b x - sin b x), 1 + cos(b_j L) cosh(b_j L) = 0, omega_j = b_j^2 sqrt(EI / m), each modal
// coordinate integrated exactly for a piecewise-constant force; the modes above the first `modes` enter
// statically (mode-acceleration method, Chopra 2017, Dynamics of Structures, section 12.12):
//   V = F (1 - sum_j L_j phi_j(a) / M_j) + sum_j L_j omega_j^2 q_j,  L_j = int m phi_j, M_j = int m phi_j^2.
// Requires 1 <= modes <= 8, 0 < a <= L, t increasing.
std::vector<double> cantilever_base_shear(double bending_stiffness_N_m2, double mass_per_length_kg_per_m, double length_m,
                                          double load_height_m, const std::vector<double>& t, const std::vector<double>& force,
                                          int modes);

}  // namespace dmi::sdof
