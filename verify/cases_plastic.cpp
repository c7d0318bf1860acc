// Elasto-plastic members against closed forms (verify/plastic_models.hpp): a fibre section's plastic moment, plastic
// collapse loads (Neal 1977) at several refinements, and an elastic-perfectly-plastic SDOF under a rectangular pulse
// (Biggs 1964) at three time steps.
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

#include "engine/convergence/grid_convergence.hpp"
#include "verify/calculix.hpp"
#include "verify/plastic_models.hpp"
#include "verify/validate.hpp"

namespace dmi {
namespace {

// A fibre section's plastic modulus: 48 layers (rectangle; a box's or I's web, its flanges in 4) or 2 rings x 32 fibres
// (CHS), each at its cell's rms coordinate, carry the plastic modulus within 0.1 % (the layers' offset: (8.9/6)/48^2 =
// 0.06 %); 0.2 % with the last 0.1 % of M_p the elastic core still leaves at 50 times the yield curvature.
constexpr double kSectionTolerance = 2e-3;
// Collapse loads: the section's 0.2 %, and (portal) 0.14 % for the columns' axial force plus the bisection's 0.3 %.
constexpr double kCollapseTolerance = 2e-3, kPortalTolerance = 6e-3;
// The SDOF peak: average acceleration converges at second order; at 2 000 steps per period (omega dt)^2 / 12 ~ 1e-6,
// the yield event inside a step costs O(dt): 0.2 %.
constexpr double kSdofTolerance = 2e-3;

std::vector<CaseResult> plastic_collapse() {
  CaseTimer timer;
  std::vector<CaseResult> r;
  r.push_back(metric("plastic_collapse", "rectangle 0.1 x 0.2: M / M_p at 50 kappa_y", "-", rectangle_moment_ratio(0.1, 0.2, 50), 1.0, kSectionTolerance));
  r.push_back(metric("plastic_collapse", "CHS 0.5 x 0.016: M / M_p at 50 kappa_y", "-", pipe_moment_ratio(0.5, 0.016, 50), 1.0, kSectionTolerance));
  r.push_back(metric("plastic_collapse", "box 0.2 x 0.3 x 0.01: M / M_p at 50 kappa_y", "-", section_moment_ratio(Section::box(0.2, 0.3, 0.01), 50), 1.0,
                     kSectionTolerance));
  r.push_back(metric("plastic_collapse", "I 0.4 deep, flanges 0.2 x 0.016, web 0.01: M / M_p at 50 kappa_y", "-",
                     section_moment_ratio(Section::i_section(0.2, 0.4, 0.016, 0.01), 50), 1.0, kSectionTolerance));
  for (int n : {2, 4, 8})
    r.push_back(metric("plastic_collapse", "fixed-end beam, " + std::to_string(n) + " elements: P / (8 M_p / L)", "-", fixed_beam_collapse_ratio(n), 1.0,
                       kCollapseTolerance));
  r.push_back(metric("plastic_collapse", "portal frame: lambda_c / (6 M_p / (h + L))", "-", portal_collapse_ratio(), 1.0, kPortalTolerance));
  return stamp(r, timer.seconds());
}

std::vector<CaseResult> plastic_sdof() {
  CaseTimer timer;
  std::vector<CaseResult> r;
  for (double ratio : {1.2, 1.5}) {
    std::vector<double> err;
    SdofPeak fine;
    for (int steps : {500, 1000, 2000}) {
      fine = epp_bar_peak(ratio, steps);
      err.push_back(std::abs(fine.computed / fine.exact - 1));
    }
    const std::string tag = "F0/R_y " + std::to_string(ratio).substr(0, 3) + ": ";
    r.push_back(metric("plastic_sdof", tag + "peak displacement, 2000 steps per period", "m", fine.computed, fine.exact, kSdofTolerance));
    r.push_back(bound_metric("plastic_sdof", tag + "error falls from 500 to 2000 steps per period", "-", err.front() - err.back(), 0, true));
  }
  return stamp(r, timer.seconds());
}

// Parkes' cantilever (gamma 1, kinetic energy 30 times the elastic capacity at first yield) at 4, 8 and 16 elements:
// the permanent tip deflection's Richardson value against the rigid-plastic theory (Parkes 1955; Jones 1989,
// sec. 3.8). The theory leaves out the elastic energy, M_p^2 L / (6 E I) at collapse: its share of the kinetic energy (7.5 %)
// is the reference's own uncertainty and the tolerance.
std::vector<CaseResult> parkes() {
  CaseTimer timer;
  std::vector<CaseResult> r;
  const double gamma = 1, energy_ratio = 30, hardening = 1e-4;
  std::array<double, 3> w{};
  ParkesResult fine;
  const std::array<int, 3> n = {16, 8, 4};
  for (int k = 0; k < 3; ++k) {
    const ParkesResult p = parkes_cantilever(gamma, energy_ratio, n[k], hardening);
    w[k] = p.computed;
    if (k == 0) fine = p;
  }
  const GridConvergence c = grid_convergence({1.0 / n[0], 1.0 / n[1], 1.0 / n[2]}, w);
  const double tolerance = fine.elastic_at_collapse / fine.kinetic;
  char levels[96];
  std::snprintf(levels, sizeof levels, "%.4f / %.4f / %.4f m at 16 / 8 / 4 elements", w[0], w[1], w[2]);
  r.push_back(metric("parkes", "permanent tip deflection, Richardson value of " + std::string(levels) + " (" + describe(c) + ")", "m",
                     c.extrapolated, fine.rigid_plastic, tolerance));
  r.push_back(bound_metric("parkes", "difference between levels falls (16-8 against 8-4 elements)", "m", std::abs(w[1] - w[2]) - std::abs(w[0] - w[1]), 0, true));
  return stamp(r, timer.seconds());
}

// The cantilever pushed by a pulse (verify/plastic_models.hpp) against the same cantilever in CalculiX bricks
// (verify/calculix.hpp), each at three meshes: the peak and the residual sway of its end. Tolerance, the sum of: the
// grid uncertainty (GCI) of each code's three meshes at its finest; the time step's, the change of our finest result
// when the step is halved, at our step and at CalculiX's largest increment (the same average-acceleration rule); and
// the shear flexibility the Euler-Bernoulli member leaves out and the bricks hold, 3 E I / (kappa G A L^2) (kappa 5/6).
std::vector<CaseResult> calculix_cantilever() {
  CaseTimer timer;
  std::vector<CaseResult> r;
  const CantileverPulse p;
  const std::array<int, 3> ours = {16, 8, 4}, along = {30, 20, 10}, across = {6, 4, 2};
  std::array<SwayHistory, 3> a, b;
  const std::string dir = (std::filesystem::temp_directory_path() / ("damimpact-calculix-" + std::to_string(::getpid()))).string();
  for (int k = 0; k < 3; ++k) a[k] = cantilever_pulse_sway(p, ours[k]), b[k] = calculix_cantilever_sway(p, along[k], across[k], dir);
  std::filesystem::remove_all(dir);
  const auto at_step = [&](double dt) {
    CantileverPulse q = p;
    q.dt = dt;
    return cantilever_pulse_sway(q, ours[0]);
  };
  const std::array<SwayHistory, 3> steps = {at_step(0.5 * p.dt), at_step(p.max_increment), at_step(0.5 * p.max_increment)};
  const double G = p.E / (2 * (1 + p.nu)), shear = 3 * p.E * (p.b * p.d * p.d * p.d / 12) / (5.0 / 6 * G * p.b * p.d * p.L * p.L);
  const double period = a[0].period;
  using Get = double (*)(const SwayHistory&, double);
  const std::vector<std::pair<std::string, Get>> qs = {
      {"peak sway", [](const SwayHistory& s, double) { return s.peak(); }},
      {"residual sway (centre of the ringing over the last 1.5 elastic periods)", [](const SwayHistory& s, double T) { return s.residual(T); }}};
  for (const auto& [name, get] : qs) {
    const GridConvergence ca = grid_convergence({1.0 / ours[0], 1.0 / ours[1], 1.0 / ours[2]}, {get(a[0], period), get(a[1], period), get(a[2], period)});
    const GridConvergence cb = grid_convergence({1.0 / along[0], 1.0 / along[1], 1.0 / along[2]}, {get(b[0], period), get(b[1], period), get(b[2], period)});
    const double ours_step = std::abs(get(a[0], period) - get(steps[0], period)) / std::abs(ca.f[0]);
    const double their_step = std::abs(get(steps[1], period) - get(steps[2], period)) / std::abs(ca.f[0]);
    char text[320];
    std::snprintf(text, sizeof text, "%s: %.4f / %.4f / %.4f m at 16 / 8 / 4 elements against CalculiX %.4f / %.4f / %.4f m at 30x6 / 20x4 / 10x2 C3D20R "
                  "(time steps %.2f %% and %.2f %%)", name.c_str(), ca.f[0], ca.f[1], ca.f[2], cb.f[0], cb.f[1], cb.f[2], 100 * ours_step, 100 * their_step);
    r.push_back(metric("calculix_cantilever", text, "m", ca.f[0], cb.f[0], ca.gci + cb.gci + ours_step + their_step + shear));
  }
  return stamp(r, timer.seconds());
}

}  // namespace

std::vector<ValidationCase> plastic_validation_cases() {
  return {{"plastic_collapse", "plastic members: fibre section plastic moment; collapse loads of a fixed-end beam and a portal frame (Neal)",
           plastic_collapse},
          {"plastic_sdof", "plastic members: bar with a tip mass vs the exact elastic-perfectly-plastic SDOF under a rectangular pulse",
           plastic_sdof},
          {"parkes", "plastic members: a cantilever struck at its tip by a mass (Parkes), permanent deflection at three meshes vs rigid-plastic theory",
           parkes},
          {"calculix_cantilever", "plastic members: a cantilever with a tip block pushed by a pulse against the same cantilever in CalculiX bricks (needs ccx; long)",
           calculix_cantilever, false}};
}

}  // namespace dmi
