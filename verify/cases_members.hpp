// Runs and closed forms for the beam-column verification cases (Lin & Yang 2024, verifications 1-2), shared by
// `damimpact validate`, the tests and the benchmarks.
#pragma once
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "verify/validate.hpp"

namespace dmi {

// Mid-span deflection (m, downwards negative) of eq. (30), t from the instant of impact (s).
double paper_a5_eq30(double t);

// Independent reference for eq. (30) without its one-mode truncation: the beam as `elements`
// Euler-Bernoulli elements (consistent mass), the block as a 3 kg point mass at mid-span that
// sticks at t = 0 with the free-fall speed sqrt(2 g d) (plastic impact as a one-step impulse) and
// its weight. Returns mid-span deflection sampled every `sample` s from the impact to t_end.
void paper_a5_point_mass_reference(int elements, double dt, double t_end, double sample, std::vector<double>& t,
                                   std::vector<double>& u);

struct A5Run {
  std::vector<double> time, midspan;  // s, m (vertical displacement of the centre-line)
  std::vector<double> block;          // m, the block's mean vertical displacement
  std::vector<double> contact;        // N, the vertical contact force on the beam
  double t_impact = 0;                // first sample with a contact force on the beam (s)
  double wall = 0;                    // s
  long steps = 0;
};
A5Run paper_a5_run(int elements, const std::vector<std::pair<std::string, nlohmann::json>>& overrides = {});

// The paper's verification 2 peaks (m) for depths 0.5, 0.25, 0.125, 0.0625 m (NaN: dropped by the paper);
// also in tests/data/paper_a/paper_numbers.json with their source.
constexpr double kPaperA6Depth[4] = {0.5, 0.25, 0.125, 0.0625};
constexpr double kPaperA6PeakParticles[4] = {0.075, 0.18, 0.29, 0.28};
constexpr double kPaperA6PeakBeamColumn[3] = {0.056, 0.19, 0.58};

// Lin & Yang verification 2 at beam depth h (m): the beam as 4 beam-column elements or as particles.
struct A6Run {
  std::vector<double> time, top_uy, von_mises;  // top-surface mid-span: vertical displacement (m), von Mises (Pa)
  double peak_displacement = 0;                 // max downward top-surface displacement (m)
  double peak_von_mises = 0;                    // Pa
  double min_gap = 0;                           // min over time of disc-centroid gap to the beam top minus r (m)
  double min_bottom_gap = 0;                    // min over time of the disc bottom's gap to the beam top (m), if probed
  double disc_final_vy = 0;                     // disc centroid vertical velocity at the end (m/s, + up)
  double projection_iterations_max = 0, projection_iterations_mean = 0;
  double wall = 0;                              // s
  long steps = 0;
};
A6Run paper_a6_run(double depth, bool beam_column, const std::vector<std::pair<std::string, nlohmann::json>>& overrides = {});
// Override adding a particle probe "bottom" at the disc's lowest point (A6Run::min_bottom_gap measures penetration).
std::pair<std::string, nlohmann::json> a6_bottom_probe(double depth);

struct ErrorPair {
  double nrms = 0;  // RMS(u - ref) / max |ref|
  double peak = 0;  // (max |u| - max |ref|) / max |ref|
};
// u(x) by linear interpolation of samples (t, u), clamped at the ends.
double interpolate(const std::vector<double>& t, const std::vector<double>& u, double x);
// Rate of change of component `comp` of a recorded vector series (`dims` components per row) over consecutive
// windows of `window` s from t = 0, the history linearly interpolated: a body's momentum rate over m gives the force
// on it where no wall or member records one (body-body contact).
std::vector<double> windowed_rate(const std::vector<double>& t, const Series& s, int dims, int comp, double window);

ErrorPair compare_history(const std::vector<double>& t, const std::vector<double>& u, double t0,
                          const std::function<double(double)>& ref);

// Cases in their own files: cases_impact.cpp, cases_buffer.cpp.
std::vector<CaseResult> impact_contact();
std::vector<CaseResult> tyre_buffer_case();
std::vector<CaseResult> buffer_pad_case();

}  // namespace dmi
