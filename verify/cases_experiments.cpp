// Loads against measured experiments and at rest: the wall pressures of a water dam break (Lobovsky et al. 2014)
// refined three times, and water and sand started at rest from their geostatic state (hydrostatic pressure; earth
// pressure between the active and at-rest coefficients), without ringing.
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "verify/validate.hpp"

namespace dmi {
namespace {

// Trapezoid mean of a piecewise-linear record (T, p) over [a, b], from its points inside the window.
double record_mean(const std::vector<std::pair<double, double>>& pts, double a, double b) {
  double area = 0, span = 0;
  for (std::size_t k = 1; k < pts.size(); ++k) {
    const auto [t0, p0] = pts[k - 1];
    const auto [t1, p1] = pts[k];
    if (t0 < a || t1 > b) continue;
    area += 0.5 * (p0 + p1) * (t1 - t0), span += t1 - t0;
  }
  return area / span;
}

// The mean of a sensor's history over T = t sqrt(g/H) in [a, b], as p / (rho g H).
double sensor_mean(const Results& r, const std::string& name, double scale_t, double scale_p, double a, double b) {
  return time_mean(r.time, series(r, "sensors/" + name + "/pressure"), 0, a / scale_t, b / scale_t) / scale_p;
}

// examples/dam_break_lobovsky.json at H/h = 12, 24, 48, to T = 5.5. Lobovsky, Botia-Vera, Castellana, Mas-Soler &
// Souto-Iglesias (2014), J. Fluids Struct. 48, 407-434: sensor 4, 80 mm above the floor of the struck wall, in one
// run as digitised from the paper by the PySPH project (the points of T 4.0-5.5 below). The metric is the mean over
// T 4.0-5.5, the quasi-static load after the impact and before the backward-breaking wave returns; the sensor is
// the 20 mm one (two to eight cells) centred where the transducer sat: the pressure is nearly hydrostatic there and
// then, so the mean over 20 mm is the value at its centre. Tolerance 0.12 rho g H: the half-width of the 95 % band of
// the repeated runs in this window (sensor 2, the only one whose band is published with the paper's data; assumed to
// hold at sensor 4). What the case does not claim (the impact peak, the sensors nearer the floor, the arrival) is in
// docs/verification.md with its figures.
std::vector<CaseResult> lobovsky() {
  const CaseTimer timer;
  const std::vector<std::pair<double, double>> p4 = {{4.047, 0.562}, {4.213, 0.567}, {4.379, 0.576}, {4.464, 0.555},
                                                     {4.543, 0.509}, {4.609, 0.481}, {4.709, 0.482}, {4.875, 0.485},
                                                     {5.041, 0.481}, {5.206, 0.464}, {5.372, 0.465}};
  const double H = 0.3, g = 9.81, rho = 997, L = 1.61, scale_t = std::sqrt(g / H), scale_p = rho * g * H;
  const double ref = record_mean(p4, 4.0, 5.5);
  std::vector<CaseResult> r;
  for (int n : {12, 24, 48}) {
    const double h = H / n;
    const int k = static_cast<int>(std::lround(L / h)) + 3;  // the struck wall on a grid line, three cells of margin
    const Scenario s = example_scenario("dam_break_lobovsky.json", {{"/grid/origin", {L - k * h, -3 * h}},
                                                                     {"/grid/size", {(k + 3) * h, 0.6 + 6 * h}},
                                                                     {"/grid/cell_size", h},
                                                                     {"/analysis/end_time", 5.5 / scale_t},
                                                                     {"/output/snapshot_interval", 0.0}});
    const Results res = run_quiet(s).results;
    const double v = sensor_mean(res, "W80", scale_t, scale_p, 4.0, 5.5);
    r.push_back(metric("lobovsky", "sensor at 80 mm, mean p/(rho g H) over T 4.0-5.5, H/h = " + std::to_string(n) +
                                       " (Lobovsky 2014; tolerance: the repeated runs' 95 % band)",
                       "-", v, ref, 0.12, false));
  }
  return stamp(r, timer.seconds());
}

// examples/dam_break_kleefsman_3d.json at H/h = 10, 15, 20 to T = 4.5 (a long case: run by name).
// Kleefsman, Fekken, Veldman, Iwanowski & Buchner (2005), J. Comput. Phys. 206, 363-393 (MARIN, SPHERIC test 2): the
// pressure on the block's water-facing face at 0.021 m (P1) and 0.101 m (P3), one record as digitised by the PySPH
// project. Metric: the mean over T 2.5-4.5, the load after the impact, on the 80 mm sensors, at the finest grid; the
// difference must fall at each refinement. The experiment publishes no repeats; the tolerance is Lobovsky et al.'s
// 95 % band of the same phase of a dam break, 0.12 rho g H.
std::vector<CaseResult> kleefsman() {
  const CaseTimer timer;
  const std::vector<std::pair<double, double>> p1 = {{2.308, 1.08}, {2.733, 0.776}, {3.157, 0.686}, {3.581, 0.641}, {4.006, 0.586}, {4.43, 0.556},
                                                     {4.854, 0.538}},
                                               p3 = {{2.338, 0.92}, {2.531, 0.776}, {2.84, 0.684}, {3.265, 0.693}, {3.69, 0.677}, {4.115, 0.61},
                                                     {4.54, 0.579}};
  const double H = 0.55, g = 9.81, rho = 1000, scale_t = std::sqrt(g / H), scale_p = rho * g * H, x = 0.8245;
  auto window = [](const std::vector<std::pair<double, double>>& pts) {  // the record, cut at T 2.5 and 4.5
    std::vector<std::pair<double, double>> w;
    for (std::size_t k = 1; k < pts.size(); ++k) {
      const auto [t0, v0] = pts[k - 1];
      const auto [t1, v1] = pts[k];
      for (double t : {2.5, 4.5})
        if (t0 < t && t1 > t) w.push_back({t, v0 + (t - t0) / (t1 - t0) * (v1 - v0)});
      if (t1 > 2.5 && t1 < 4.5) w.push_back(pts[k]);
    }
    std::sort(w.begin(), w.end());
    return w;
  };
  const double ref1 = record_mean(window(p1), 2.5, 4.5), ref3 = record_mean(window(p3), 2.5, 4.5);
  std::vector<CaseResult> r;
  std::vector<double> e1, e3;  // |simulated - measured| at each grid
  const std::vector<int> grids{10, 15, 20};
  for (int n : grids) {
    const double h = H / n;
    const int k = static_cast<int>(std::lround(x / h)) + 3, nx = static_cast<int>((3.22 - (x - k * h)) / h) + 4;
    const Scenario s = example_scenario("dam_break_kleefsman_3d.json", {{"/grid/origin", {x - k * h, -2 * h, -2 * h}},
                                                                         {"/grid/size", {nx * h, 1 + 4 * h, 1 + 4 * h}},
                                                                         {"/grid/cell_size", h},
                                                                         {"/analysis/end_time", 4.5 / scale_t},
                                                                         {"/output/snapshot_interval", 0.0}});
    const Results res = run_quiet(s).results;
    const double v1 = sensor_mean(res, "P1w", scale_t, scale_p, 2.5, 4.5), v3 = sensor_mean(res, "P3w", scale_t, scale_p, 2.5, 4.5);
    e1.push_back(std::abs(v1 - ref1)), e3.push_back(std::abs(v3 - ref3));
    if (n != grids.back()) continue;
    const std::string at = ", H/h = " + std::to_string(n) + " (Kleefsman 2005; tolerance: a dam break's 95 % band, Lobovsky 2014)";
    r.push_back(metric("kleefsman", "block face at 0.021 m, mean p/(rho g H) over T 2.5-4.5" + at, "-", v1, ref1, 0.12, false));
    r.push_back(metric("kleefsman", "block face at 0.101 m, mean p/(rho g H) over T 2.5-4.5" + at, "-", v3, ref3, 0.12, false));
  }
  for (std::size_t k = 1; k < grids.size(); ++k) {  // the differences from the experiment fall at each refinement
    const std::string step = ", H/h " + std::to_string(grids[k - 1]) + " -> " + std::to_string(grids[k]) + ": falls";
    r.push_back(bound_metric("kleefsman", "0.021 m: difference from the experiment" + step, "-", e1[k - 1] - e1[k], 0.0, true));
    r.push_back(bound_metric("kleefsman", "0.101 m: difference from the experiment" + step, "-", e3[k - 1] - e3[k], 0.0, true));
  }
  return stamp(r, timer.seconds());
}

// The largest departure of a history from its mean after the first sample, as a fraction of the mean.
double ringing(const Series& s, std::size_t comp) {
  double lo = INFINITY, hi = -INFINITY, sum = 0;
  const std::size_t n = s.samples(), nc = s.components.size();
  for (std::size_t k = 1; k < n; ++k) lo = std::min(lo, s.data[k * nc + comp]), hi = std::max(hi, s.data[k * nc + comp]), sum += s.data[k * nc + comp];
  const double mean = sum / static_cast<double>(n - 1);
  return std::max(hi - mean, mean - lo) / std::abs(mean);
}

// examples/water_tank_at_rest.json and sand_at_rest.json, started geostatic. Water: each wall sensor's mean against
// rho g d, within one cell of depth, h / d (the nodal forces locate the pressure to within a node spacing); the
// wall's force within 10 % of rho g D^2 / 2 at every sample ("no ringing": a stress-free start swings +-70 %).
// Sand: the wall's mean force as a coefficient K = F / (gamma D^2 / 2) between Rankine's active Ka and K0 (1 + h/D),
// and within 10 % of its mean at every sample.
std::vector<CaseResult> at_rest() {
  const CaseTimer timer;
  std::vector<CaseResult> r;
  const Scenario w = example_scenario("water_tank_at_rest.json");
  const Results rw = run_quiet(w).results;
  const double rho = 997, g = 9.81, D = 0.3, h = w.grid.cell_size, end = w.analysis.end_time, dt = w.output.history_interval;
  for (const auto& [name, d] : std::vector<std::pair<std::string, double>>{{"d250", 0.25}, {"d150", 0.15}, {"d050", 0.05}, {"floor", 0.3}}) {
    const double v = time_mean(rw.time, series(rw, "sensors/" + name + "/pressure"), 0, dt, end) / (rho * g * d);
    r.push_back(metric("at_rest", "still water: sensor " + name + ", mean p / (rho g d) (tolerance h/d)", "-", v, 1.0, h / d, false));
  }
  const Series& fw = series(rw, "walls/right/force");
  r.push_back(metric("at_rest", "still water: wall force, mean / (rho g D^2 / 2)", "-", time_mean(rw.time, fw, 0, dt, end) / (0.5 * rho * g * D * D),
                     1.0, h / D, false));
  r.push_back(bound_metric("at_rest", "still water: wall force, largest departure from its mean (no ringing, < 10 %)", "-", ringing(fw, 0), 0.10, false));
  const Scenario s = example_scenario("sand_at_rest.json");
  const Results rs = run_quiet(s).results;
  const double gamma = 1800 * g, Ds = 0.5, phi = 30 * M_PI / 180, hs = s.grid.cell_size;
  const Series& fs = series(rs, "walls/right/force");
  const double K = time_mean(rs.time, fs, 0, dt, s.analysis.end_time) / (0.5 * gamma * Ds * Ds);
  const double Ka = (1 - std::sin(phi)) / (1 + std::sin(phi)), K0 = 1 - std::sin(phi);
  r.push_back(bound_metric("at_rest", "sand: wall force coefficient K above the active Ka = 1/3 (Rankine)", "-", K, Ka, true));
  r.push_back(bound_metric("at_rest", "sand: wall force coefficient K below K0 (1 + h/D), K0 = 1 - sin(phi) = 0.5 (Jaky)", "-", K, K0 * (1 + hs / Ds), false));
  r.push_back(bound_metric("at_rest", "sand: wall force, largest departure from its mean (no ringing, < 10 %)", "-", ringing(fs, 0), 0.10, false));
  return stamp(r, timer.seconds());
}

}  // namespace

std::vector<ValidationCase> experiment_validation_cases() {
  return {{"lobovsky", "water dam break on a wall (Lobovsky et al. 2014): the quasi-static pressure at 80 mm, three grids", lobovsky},
          {"at_rest", "water and sand started geostatic: hydrostatic wall pressure, earth pressure between Ka and K0, no ringing", at_rest},
          {"kleefsman", "water dam break on a block in a 3D tank (Kleefsman et al. 2005): the face pressures after the impact, three grids (long)",
           kleefsman, false}};
}

}  // namespace dmi
