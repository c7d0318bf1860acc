// Closed-form SDOF and impact tools (engine/sdof/sdof.hpp, Lin, Cheng & Tuan): identities (the
// equation of motion by finite differences, eq. (20) against the sampled maximum, Hertz closed forms
// against an RK4 integration of the contact ODE) and worked examples with their hand calculations.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/sdof/practice_loads.hpp"
#include "engine/sdof/sdof.hpp"

namespace dmi::sdof {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(SdofFrequencies, HandValues) {
  // m = 100 kg, k = 1e6 N/m: omega_n = sqrt(1e4) = 100 rad/s; c_c = 2 * 100 * 100 = 2e4 N s/m;
  // zeta = 0.1: omega_D = 100 sqrt(0.99) = 99.498744 rad/s.
  EXPECT_DOUBLE_EQ(natural_frequency(100.0, 1e6), 100.0);
  EXPECT_DOUBLE_EQ(critical_damping(100.0, 1e6), 2e4);
  EXPECT_NEAR(damped_frequency(100.0, 0.1), 99.498743710662, 1e-9);
  // c = 2000 N s/m -> zeta = 2000 / 2e4 = 0.1, and back.
  const Oscillator o = oscillator_from_damping_coefficient(100.0, 1e6, 2000.0);
  EXPECT_DOUBLE_EQ(o.damping_ratio, 0.1);
  EXPECT_DOUBLE_EQ(o.damping_coefficient_N_s_per_m(), 2000.0);
  EXPECT_DOUBLE_EQ(o.natural_frequency_rad_per_s(), 100.0);
}

TEST(SdofFreeVibration, UndampedHandValueEq9) {
  // m = 2, k = 8 -> omega_n = 2; u0 = 0.1, v0 = 0.4: u = 0.1 cos 2t + 0.2 sin 2t.
  const Oscillator o{2.0, 8.0, 0.0};
  EXPECT_NEAR(free_vibration(o, 0.1, 0.4, kPi / 4), 0.2, 1e-15);   // cos = 0, sin = 1
  EXPECT_NEAR(free_vibration(o, 0.1, 0.4, kPi / 2), -0.1, 1e-15);  // cos = -1, sin = 0
  EXPECT_NEAR(free_vibration(o, 0.1, 0.4, 0.3), 0.1 * std::cos(0.6) + 0.2 * std::sin(0.6), 1e-15);
}

TEST(SdofFreeVibration, DampedHandValueEq14) {
  // m = 1, k = 100 (omega_n = 10), zeta = 0.2: omega_D = 10 sqrt(0.96) = 9.797959; u0 = 0.01, v0 = 0:
  // u(0.1) = e^{-0.2} [0.01 cos(0.9797959) + (0.2*10*0.01 / 9.797959) sin(0.9797959)]
  //        = 0.8187308 * [0.01 * 0.5571920 + 0.0020412 * 0.8303837] = 0.0059497
  const Oscillator o{1.0, 100.0, 0.2};
  EXPECT_NEAR(free_vibration(o, 0.01, 0.0, 0.1), 0.0059497, 1e-7);
}

// m u'' + c u' + k u = 0 by central differences, for under-, critically and overdamped oscillators;
// and the initial conditions u(0) = u0, u'(0) = v0.
TEST(SdofFreeVibration, SatisfiesEquationOfMotionAndInitialConditions) {
  const double m = 2.0, k = 800.0, u0 = 0.03, v0 = -0.5, h = 1e-5;  // omega_n = 20 rad/s
  const double scale = k * std::max(std::abs(u0), std::abs(v0) / 20.0);
  for (double zeta : {0.0, 0.05, 0.3, 0.99, 1.0, 2.0}) {
    SCOPED_TRACE(zeta);
    const Oscillator o{m, k, zeta};
    const double c = o.damping_coefficient_N_s_per_m();
    auto u = [&](double t) { return free_vibration(o, u0, v0, t); };
    EXPECT_DOUBLE_EQ(u(0.0), u0);
    EXPECT_NEAR((-3 * u(0.0) + 4 * u(h) - u(2 * h)) / (2 * h), v0, 1e-6);
    double worst = 0;
    for (double t = 0.01; t < 0.6; t += 0.0137) {
      const double a = (u(t + h) - 2 * u(t) + u(t - h)) / (h * h), v = (u(t + h) - u(t - h)) / (2 * h);
      worst = std::max(worst, std::abs(m * a + c * v + k * u(t)));
    }
    EXPECT_LT(worst, 1e-5 * scale);
  }
}

TEST(SdofImpulse, UnitResponseIsEq18And19) {
  const double m = 50.0, k = 2e5, tau = 0.05;  // omega_n = 63.245553 rad/s
  const double wn = std::sqrt(k / m);
  const Oscillator undamped{m, k, 0.0}, damped{m, k, 0.08};
  const double wd = wn * std::sqrt(1 - 0.08 * 0.08);
  EXPECT_EQ(unit_impulse_response(damped, 0.0499, tau), 0.0);  // nothing before the impulse
  for (double t = tau; t < 0.5; t += 0.013) {
    EXPECT_NEAR(unit_impulse_response(undamped, t, tau), std::sin(wn * (t - tau)) / (m * wn), 1e-15);
    EXPECT_NEAR(unit_impulse_response(damped, t, tau),
                std::exp(-0.08 * wn * (t - tau)) * std::sin(wd * (t - tau)) / (m * wd), 1e-15);
    // response to I = 300 N s is I times the unit response
    EXPECT_DOUBLE_EQ(impulse_response(damped, 300.0, t, tau), 300.0 * unit_impulse_response(damped, t, tau));
  }
}

// Eq. (20) and its peak time equal the maximum of the unit-impulse response sampled finely
// (10^6 samples over one undamped period), for under-, critically and overdamped oscillators.
TEST(SdofImpulse, PeakEq20MatchesSampledMaximum) {
  const double m = 3.0, k = 1200.0, wn = 20.0, period = 2 * kPi / wn;
  const int n = 1000000;
  for (double zeta : {0.0, 0.01, 0.05, 0.1, 0.3, 0.7, 0.95, 1.0, 1.5}) {
    SCOPED_TRACE(zeta);
    const Oscillator o{m, k, zeta};
    double best = -1, t_best = 0;
    for (int i = 0; i <= n; ++i) {
      const double t = period * i / n, u = unit_impulse_response(o, t, 0.0);
      if (u > best) { best = u; t_best = t; }
    }
    const ImpulsePeak p = unit_impulse_peak(o);
    EXPECT_NEAR(p.displacement_m_per_N_s, best, 1e-9 * best);
    EXPECT_NEAR(p.time_s, t_best, 2 * period / n);
    EXPECT_NEAR(unit_impulse_response(o, p.time_s, 0.0), p.displacement_m_per_N_s, 1e-14 * best);
  }
}

TEST(SdofImpulse, PeakHandValueAndUndampedLimit) {
  const double m = 3.0, k = 1200.0, undamped = 1.0 / (m * 20.0);  // 1/(m omega_n) = 1/60
  // zeta = 0: exactly 1/(m omega_n) at a quarter period pi/(2 omega_n) = 0.0785398 s.
  EXPECT_DOUBLE_EQ(unit_impulse_peak({m, k, 0.0}).displacement_m_per_N_s, undamped);
  EXPECT_DOUBLE_EQ(unit_impulse_peak({m, k, 0.0}).time_s, kPi / 40.0);
  // zeta = 0.05: exponent (0.05/sqrt(0.9975)) atan(sqrt(0.9975)/0.05) = 0.0500626 * 1.5207755
  // = 0.0761340 -> factor e^{-0.0761340} = 0.9266920.
  EXPECT_NEAR(unit_impulse_peak({m, k, 0.05}).displacement_m_per_N_s / undamped, 0.9266920, 1e-7);
  // zeta = 1: 1/(e m omega_n) at t = 1/omega_n.
  EXPECT_DOUBLE_EQ(unit_impulse_peak({m, k, 1.0}).displacement_m_per_N_s, undamped / std::numbers::e);
  // zeta -> 0: exponent ~ zeta pi/2, so 1 - ratio ~ 1.5708e-6 at zeta = 1e-6.
  const double ratio = unit_impulse_peak({m, k, 1e-6}).displacement_m_per_N_s / undamped;
  EXPECT_NEAR(1.0 - ratio, 1e-6 * kPi / 2, 1e-9);
  // Lin, Cheng & Tuan eq. (20): more damping, lower peak; continuous through zeta = 1.
  double previous = 2 * undamped;
  for (double zeta : {0.0, 0.05, 0.1, 0.2, 0.5, 0.9, 0.999999, 1.0, 1.000001, 1.5, 3.0}) {
    const double u = unit_impulse_peak({m, k, zeta}).displacement_m_per_N_s;
    EXPECT_LT(u, previous) << zeta;
    previous = u;
  }
  for (double zeta : {0.999999, 1.000001})  // d u_max / d zeta is finite: a 1e-6 step moves it ~1e-6
    EXPECT_NEAR(unit_impulse_peak({m, k, zeta}).displacement_m_per_N_s, undamped / std::numbers::e, 1e-5 * undamped);
}

// Lin, Cheng & Tuan's concrete column (Lin, Cheng & Tuan, Table 1) as a cantilever SDOF, hit by a 1 t boulder at 5 m/s:
//   section: b = 2 m, depth 1.0 (crest) .. 1.6 m (base), mean 1.3 m: A = 2.6 m^2,
//   I = 2 * 1.3^3 / 12 = 0.3661667 m^4, r = 1.3/sqrt(12) = 0.3752777 m
//   k = 3 * 25e9 * 0.3661667 / 4^3 = 4.29101562e8 N/m;  M = 2300 * 2.6 * 4 / 2 = 11 960 kg
//   omega_n = sqrt(k/M) = sqrt(35 878.06) = 189.41504 rad/s = sqrt(6 * 25e9 / 2300) * 0.3752777 / 16
//   omega_1 = 1.8751041^2 * sqrt(25e9/2300) * 0.3752777 / 16 = 271.88772 rad/s
//   I = 1000 * 5 = 5000 N s; u_max = 5000 / (11 960 * 189.41504) = 2.2071120 mm
//   F_T,max = k u_max = m v0 omega_n = 5000 * 189.41504 = 947.0752 kN
TEST(ImpactBoulderOnDam, PaperBColumnWorkedExample) {
  const Section s = tapered_rectangular_section(2.0, 1.0, 1.6);
  EXPECT_DOUBLE_EQ(s.area_m2, 2.6);
  EXPECT_NEAR(s.second_moment_m4, 0.3661667, 1e-7);
  EXPECT_NEAR(s.radius_of_gyration_m(), 0.3752777, 1e-7);
  const CantileverSdof c = cantilever_sdof(25e9, 2300.0, s, 4.0);
  EXPECT_NEAR(c.stiffness_N_per_m, 4.29101562e8, 1.0);
  EXPECT_DOUBLE_EQ(c.effective_mass_kg, 11960.0);
  EXPECT_NEAR(c.natural_frequency_rad_per_s, 189.41504, 1e-5);
  EXPECT_NEAR(c.natural_frequency_rad_per_s, std::sqrt(6 * 25e9 / 2300.0) * s.radius_of_gyration_m() / 16.0, 1e-9);
  EXPECT_NEAR(c.first_mode_rad_per_s, 271.88772, 1e-4);
  // omega_1 / omega_n = 1.8751^2 / sqrt(6) = 1.4354: the lumped SDOF (M = rho A L / 2) is softer.
  EXPECT_NEAR(c.first_mode_rad_per_s / c.natural_frequency_rad_per_s, 1.8751040687 * 1.8751040687 / std::sqrt(6.0), 1e-9);

  const BoulderImpact b = boulder_on_dam(1000.0, 5.0, c.effective_mass_kg, c.stiffness_N_per_m);
  EXPECT_DOUBLE_EQ(b.impulse_N_s, 5000.0);
  EXPECT_NEAR(b.natural_frequency_rad_per_s, 189.41504, 1e-5);
  EXPECT_NEAR(b.peak_displacement_m, 2.2071120e-3, 1e-10);
  EXPECT_NEAR(b.peak_base_force_N, 947075.2, 0.1);
  EXPECT_NEAR(b.peak_base_force_N, 1000.0 * 5.0 * b.natural_frequency_rad_per_s, 1e-6);  // eq. (23)
  // Eq. (21) is the undamped impulse response: its sampled peak is u_max.
  const Oscillator dam{c.effective_mass_kg, c.stiffness_N_per_m, 0.0};
  EXPECT_NEAR(impulse_response(dam, b.impulse_N_s, kPi / (2 * b.natural_frequency_rad_per_s), 0.0),
              b.peak_displacement_m, 1e-15);
}

TEST(ImpactBoulderOnDam, RectangularAndTaperedSections) {
  const Section r = rectangular_section(0.5, 0.2);  // A = 0.1, I = 0.5 * 0.008 / 12 = 3.3333e-4
  EXPECT_DOUBLE_EQ(r.area_m2, 0.1);
  EXPECT_NEAR(r.second_moment_m4, 3.3333333e-4, 1e-11);
  EXPECT_NEAR(r.radius_of_gyration_m(), 0.2 / std::sqrt(12.0), 1e-15);
  const Section t = tapered_rectangular_section(0.5, 0.1, 0.3);  // mean depth 0.2
  EXPECT_DOUBLE_EQ(t.area_m2, r.area_m2);
  EXPECT_DOUBLE_EQ(t.second_moment_m4, r.second_moment_m4);
}

// A rubber-like buffer (E = 50 MPa, 0.4 x 0.4 m contact, 0.3 m thick) in front of the Lin, Cheng & Tuan column:
//   k_buffer = 50e6 * 0.16 / 0.3 = 2.6666667e7 N/m
//   k_eff = 1 / (1/4.2910156e8 + 1/2.6666667e7) = 2.5106419e7 N/m; sqrt(k_eff/k) = 0.2418869
//   F_T,max = 947.0752 kN * 0.2418869 = 229.0851 kN
TEST(ImpactBuffer, SeriesSpringLowersPeakForceBySqrtStiffnessRatio) {
  EXPECT_DOUBLE_EQ(series_stiffness(3e6, 3e6), 1.5e6);  // equal springs: half
  const double kb = buffer_layer_stiffness(50e6, 0.16, 0.3);
  EXPECT_NEAR(kb, 2.6666667e7, 1.0);
  const CantileverSdof c = cantilever_sdof(25e9, 2300.0, rectangular_section(2.0, 1.3), 4.0);
  const double k_eff = series_stiffness(c.stiffness_N_per_m, kb);
  EXPECT_NEAR(k_eff, 2.5106419e7, 1.0);
  EXPECT_LT(k_eff, std::min(kb, c.stiffness_N_per_m));
  const BoulderImpact bare = boulder_on_dam(1000.0, 5.0, c.effective_mass_kg, c.stiffness_N_per_m);
  const BoulderImpact buffered = buffered_boulder_on_dam(1000.0, 5.0, c.effective_mass_kg, c.stiffness_N_per_m, kb);
  const double ratio = std::sqrt(k_eff / c.stiffness_N_per_m);
  EXPECT_NEAR(ratio, 0.2418869, 1e-7);
  EXPECT_NEAR(buffered.natural_frequency_rad_per_s / bare.natural_frequency_rad_per_s, ratio, 1e-12);
  EXPECT_NEAR(buffered.peak_base_force_N / bare.peak_base_force_N, ratio, 1e-12);
  EXPECT_NEAR(buffered.peak_base_force_N, 229085.08, 0.05);
  EXPECT_NEAR(buffered.peak_displacement_m / bare.peak_displacement_m, 1.0 / ratio, 1e-12);
  EXPECT_DOUBLE_EQ(buffered.impulse_N_s, bare.impulse_N_s);
}

// GEO Report 270 (Kwan 2012): r = 0.5 m, v = 5 m/s, K_c = 0.1:
//   5^1.2 = e^{1.2 ln 5} = e^{1.9313255} = 6.8986483; F = 0.1 * 4000 * 6.8986483 * 0.25 = 689.86483 kN
TEST(ImpactGeoHertz, HandValue) {
  EXPECT_NEAR(geo_hertz_impact_force_N(5.0, 0.5), 689864.83, 0.01);
  EXPECT_NEAR(geo_hertz_impact_force_N(5.0, 0.5, 0.1), 689864.83, 0.01);
  EXPECT_NEAR(geo_hertz_impact_force_N(5.0, 0.5, 1.0), 6898648.3, 0.1);  // linear in K_c
  EXPECT_NEAR(geo_hertz_impact_force_N(1.0, 1.0, 1.0), 4.0e6, 1e-6);     // 4000 kN at v = r = 1
  EXPECT_EQ(geo_hertz_impact_force_N(0.0, 0.5), 0.0);
}

// Granite sphere (E1 = 50 GPa, nu1 = 0.25), 1 t, R = 0.5 m, 5 m/s on concrete (E2 = 25 GPa, nu2 = 0.2):
//   E* = 1 / (0.9375/50e9 + 0.96/25e9) = 1 / (1.875e-11 + 3.84e-11) = 1.749781277e10 Pa
//   delta_max = (15 * 1000 * 25 / (16 * 1.74978128e10 * 0.7071068))^0.4 = (1.8942728e-6)^0.4 = 5.140164 mm
//   F_max = 4/3 * 1.74978128e10 * 0.7071068 * 0.005140164^1.5 = 6.079572 MN; t_c = 2.94 * 0.005140164 / 5 = 3.02242 ms
TEST(ImpactHertz, HandValue) {
  const HertzImpact h = hertz_sphere_impact(1000.0, 5.0, 0.5, 50e9, 0.25, 25e9, 0.2);
  EXPECT_NEAR(h.effective_modulus_Pa, 1.749781277e10, 10.0);
  EXPECT_NEAR(h.max_indentation_m, 5.140164e-3, 1e-9);
  EXPECT_NEAR(h.peak_force_N, 6.079572e6, 1.0);
  EXPECT_NEAR(h.contact_duration_s, 3.02242e-3, 1e-8);
  EXPECT_DOUBLE_EQ(hertz_effective_modulus(2e11, 0.0, 2e11, 0.0), 1e11);  // identical rigid-ish bodies: E/2
}

// m x'' = -(4/3) E* sqrt(R) x^1.5 (x > 0) integrated by RK4 with 2e5 steps per contact: peak force and
// contact duration match the closed forms (< 1 %; 2.94 vs the exact 2.9433 is 0.1 %), the boulder leaves
// at -v (elastic) and the contact impulse is 2 m v (momentum check).
TEST(ImpactHertz, ClosedFormsMatchRk4IntegrationOfContactOde) {
  const double m = 1000.0, v0 = 5.0, R = 0.5;
  const HertzImpact h = hertz_sphere_impact(m, v0, R, 50e9, 0.25, 25e9, 0.2);
  const double kh = 4.0 / 3.0 * h.effective_modulus_Pa * std::sqrt(R);
  auto force = [&](double x) { return x > 0 ? kh * std::pow(x, 1.5) : 0.0; };
  auto accel = [&](double x) { return -force(x) / m; };
  const double dt = h.contact_duration_s / 2e5;
  double x = 0, v = v0, t = 0, f_max = 0, impulse = 0, t_c = std::numeric_limits<double>::quiet_NaN();
  for (int i = 0; i < 1000000; ++i) {
    const double k1x = v, k1v = accel(x);
    const double k2x = v + 0.5 * dt * k1v, k2v = accel(x + 0.5 * dt * k1x);
    const double k3x = v + 0.5 * dt * k2v, k3v = accel(x + 0.5 * dt * k2x);
    const double k4x = v + dt * k3v, k4v = accel(x + dt * k3x);
    const double x_new = x + dt / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
    const double v_new = v + dt / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    impulse += 0.5 * dt * (force(x) + force(std::max(x_new, 0.0)));
    f_max = std::max(f_max, force(x_new));
    if (x_new <= 0 && i > 0) {  // left the surface: interpolate the zero crossing
      t_c = t + dt * x / (x - x_new);
      v = v_new;
      break;
    }
    x = x_new, v = v_new, t += dt;
  }
  ASSERT_TRUE(std::isfinite(t_c));
  EXPECT_NEAR(f_max / h.peak_force_N, 1.0, 1e-6);
  EXPECT_NEAR(t_c / h.contact_duration_s, 1.0, 0.01);
  EXPECT_NEAR(t_c * v0 / h.max_indentation_m, 2.943275, 1e-4);  // 2 Gamma(1.4) Gamma(0.5) / Gamma(0.9)
  EXPECT_NEAR(v, -v0, 1e-6 * v0);
  EXPECT_NEAR(impulse / (2 * m * v0), 1.0, 1e-4);
}

// EN 1991-1-7 Annex C hard impact, m = 1000 kg, v_r = 5 m/s, k = 1e8 N/m:
//   F = 5 * sqrt(1e8 * 1000) = 5 * 316 227.77 = 1.5811388 MN; delta_t = sqrt(1000/1e8) = 3.1622777 ms
TEST(ImpactEurocodeHard, HandValue) {
  const HardImpact e = en1991_hard_impact(5.0, 1000.0, 1e8);
  EXPECT_NEAR(e.peak_force_N, 1581138.83, 0.01);
  EXPECT_NEAR(e.duration_s, 3.1622777e-3, 1e-10);
  EXPECT_NEAR(e.peak_force_N * e.duration_s, 1000.0 * 5.0, 1e-9);  // F delta_t = m v_r
  // same form as eq. (23) with the impacting mass: m v sqrt(k/m)
  EXPECT_NEAR(e.peak_force_N, boulder_on_dam(1000.0, 5.0, 1000.0, 1e8).peak_base_force_N, 1e-6);
}

TEST(SdofInvalidArguments, Throw) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(natural_frequency(0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(natural_frequency(1.0, -1.0), std::invalid_argument);
  EXPECT_THROW(natural_frequency(nan, 1.0), std::invalid_argument);
  EXPECT_THROW(critical_damping(1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(damped_frequency(10.0, 1.0), std::invalid_argument);
  EXPECT_THROW(damped_frequency(10.0, -0.1), std::invalid_argument);
  EXPECT_THROW(oscillator_from_damping_coefficient(1.0, 1.0, -1.0), std::invalid_argument);
  EXPECT_THROW(free_vibration({1.0, 1.0, -0.1}, 0.0, 1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(free_vibration({1.0, 1.0, 0.1}, 0.0, 1.0, -1.0), std::invalid_argument);
  EXPECT_THROW(free_vibration({1.0, 1.0, 0.1}, nan, 1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(unit_impulse_response({-1.0, 1.0, 0.1}, 1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(unit_impulse_peak({1.0, 0.0, 0.1}), std::invalid_argument);
  try {
    natural_frequency(-1.5, 1.0);
    FAIL() << "no throw";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("natural_frequency"), std::string::npos) << what;
    EXPECT_NE(what.find("mass_kg = -1.5"), std::string::npos) << what;
  }
}

TEST(ImpactInvalidArguments, Throw) {
  EXPECT_THROW(boulder_on_dam(0.0, 5.0, 1e4, 1e8), std::invalid_argument);
  EXPECT_THROW(boulder_on_dam(1e3, 5.0, 1e4, -1e8), std::invalid_argument);
  EXPECT_THROW(rectangular_section(0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(tapered_rectangular_section(1.0, 1.0, -1.0), std::invalid_argument);
  EXPECT_THROW(cantilever_sdof(25e9, 2300.0, {2.6, 0.0}, 4.0), std::invalid_argument);
  EXPECT_THROW(cantilever_sdof(25e9, 2300.0, rectangular_section(2, 1), 0.0), std::invalid_argument);
  EXPECT_THROW(series_stiffness(1e8, 0.0), std::invalid_argument);
  EXPECT_THROW(buffer_layer_stiffness(50e6, 0.16, 0.0), std::invalid_argument);
  EXPECT_THROW(geo_hertz_impact_force_N(-1.0, 0.5), std::invalid_argument);
  EXPECT_THROW(geo_hertz_impact_force_N(5.0, 0.0), std::invalid_argument);
  EXPECT_THROW(geo_hertz_impact_force_N(5.0, 0.5, 0.0), std::invalid_argument);
  EXPECT_THROW(hertz_effective_modulus(50e9, 0.5, 25e9, 0.2), std::invalid_argument);
  EXPECT_THROW(hertz_sphere_impact(1000.0, 0.0, 0.5, 50e9, 0.25, 25e9, 0.2), std::invalid_argument);
  EXPECT_THROW(hertz_sphere_impact(1000.0, 5.0, 0.5, 50e9, 0.25, -25e9, 0.2), std::invalid_argument);
  EXPECT_THROW(en1991_hard_impact(5.0, 1000.0, 0.0), std::invalid_argument);
  EXPECT_THROW(en1991_hard_impact(5.0, -1.0, 1e8), std::invalid_argument);
}

}  // namespace
}  // namespace dmi::sdof

// A load ramped over many first periods is carried statically: V(t) -> F(t) (error ~ 1 / (omega_1 T)).
TEST(CantileverBaseShear, QuasiStaticRampIsCarriedStatically) {
  const double EI = 1e9, m = 1000, L = 4, w1 = 1.8751040687 * 1.8751040687 / (L * L) * std::sqrt(EI / m);
  const double T = 2000 * 2 * 3.14159265358979 / w1;
  std::vector<double> t, f;
  for (int k = 0; k <= 20000; ++k) t.push_back(T * k / 20000), f.push_back(1e5 * (T * (k - 0.5) / 20000) / T);
  const std::vector<double> v = dmi::sdof::cantilever_base_shear(EI, m, L, 3.0, t, f, 4);
  EXPECT_NEAR(v.back(), 1e5, 1e5 * 2e-3);
}

// A constant force applied suddenly: the base shear oscillates about F, and with one mode its extremes are the
// single-mode closed form F (1 - r) + r F (1 - cos omega_1 t), r = L_1 phi_1(a) / M_1, i.e. peak F (1 + r).
TEST(CantileverBaseShear, SuddenLoadOneModePeakMatchesClosedForm) {
  const double EI = 2e9, m = 800, L = 5, a = L;
  std::vector<double> t, f;
  for (int k = 0; k <= 200000; ++k) t.push_back(1e-5 * k), f.push_back(k == 0 ? 0.0 : 1e4);
  const std::vector<double> v = dmi::sdof::cantilever_base_shear(EI, m, L, a, t, f, 1);
  double vmax = 0;
  for (double x : v) vmax = std::max(vmax, x);
  // Tip load, first mode of a cantilever: L_1 phi_1(L) / M_1 = 2 * 0.7830 / 1 ... computed here by the
  // textbook values int phi_1 = 0.7830 L (phi_1(L) = 2), int phi_1^2 = L: r = 0.7830 * 2 = 1.5660.
  EXPECT_NEAR(vmax, 1e4 * (1 + 1.5660), 1e4 * 2.566 * 2e-3);
}

TEST(CantileverBaseShear, RefusesBadArguments) {
  const std::vector<double> t{0, 1}, f{0, 1};
  EXPECT_THROW(dmi::sdof::cantilever_base_shear(1e9, 1000, 4, 5, t, f, 4), std::invalid_argument);
  EXPECT_THROW(dmi::sdof::cantilever_base_shear(1e9, 1000, 4, 3, t, f, 0), std::invalid_argument);
  EXPECT_THROW(dmi::sdof::cantilever_base_shear(1e9, 1000, 4, 3, t, {0.0}, 4), std::invalid_argument);
}
