// Elasto-plastic members against closed forms (verify/plastic_models.hpp): a fibre section's plastic moment, plastic
// collapse loads (Neal 1977) at several refinements, and an elastic-perfectly-plastic SDOF under a rectangular pulse
// (Biggs 1964) at three time steps.
#include <cmath>
#include <string>
#include <vector>

#include "verify/plastic_models.hpp"
#include "verify/validate.hpp"

namespace dmi {
namespace {

// A fibre section's plastic modulus: 48 layers (rectangle) or 2 rings x 32 fibres (CHS), each at its cell's rms
// coordinate, carry the plastic modulus within 0.1 % (the layers' offset: (8.9/6)/48^2 = 0.06 %); 0.2 % with the
// last 0.1 % of M_p the elastic core still leaves at 50 times the yield curvature.
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

}  // namespace

std::vector<ValidationCase> plastic_validation_cases() {
  return {{"plastic_collapse", "plastic members: fibre section plastic moment; collapse loads of a fixed-end beam and a portal frame (Neal)",
           plastic_collapse},
          {"plastic_sdof", "plastic members: bar with a tip mass vs the exact elastic-perfectly-plastic SDOF under a rectangular pulse",
           plastic_sdof}};
}

}  // namespace dmi
