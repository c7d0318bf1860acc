// Stability stress suite (`damimpact validate --stress`, docs/reliability.md "Stability stress suite").
// Every run is attempted: a RunError (NaN/Inf, a particle leaving the grid) becomes a failed metric carrying
// its message instead of ending the suite.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "engine/common/error.hpp"
#include "verify/cases_members.hpp"
#include "verify/validate.hpp"

namespace dmi {
namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double nan_v = std::numeric_limits<double>::quiet_NaN();
using J = nlohmann::json;
using Overrides = std::vector<std::pair<std::string, J>>;

// A run that may fail: ok = false with the RunError's message.
struct Attempt {
  bool ok = false;
  std::string error;
  RunOutput out;
};
Attempt attempt(const Scenario& s) {
  Attempt a;
  try {
    a.out = run_quiet(s);
    a.ok = true;
  } catch (const RunError& e) {
    a.error = e.what();
  }
  return a;
}

void detail(const char* fmt, auto... args) {
  if (!validate_verbose()) return;
  std::fprintf(stderr, fmt, args...);
}

// The metric of a run that stopped: value NaN, failed, its message in the metric text.
CaseResult run_failed(const std::string& c, const std::string& what, const std::string& message) {
  CaseResult r = metric(c, what + " completes: " + message, "-", nan_v, 0.0, 0.0, false);
  r.passed = false;
  return r;
}

// value >= limit passes (CFL limits on the sweep's grid of factors).
CaseResult at_least(const std::string& c, const std::string& m, const std::string& unit, double value, double limit) {
  CaseResult r = metric(c, m, unit, value, limit, 0.0, false);
  r.error = std::max(0.0, limit - value);
  r.passed = std::isfinite(value) && value >= limit;
  return r;
}

double last(const Series& s, std::size_t comp = 0) { return s.data[(s.samples() - 1) * s.components.size() + comp]; }

bool all_finite(const Results& r) {
  for (const auto& s : r.series)
    for (double x : s.data)
      if (!std::isfinite(x)) return false;
  return true;
}

// Largest |component| of a vector series (any component), relative to `scale`.
double max_norm(const Series& s, double scale) {
  double m = 0;
  const std::size_t nc = s.components.size();
  for (std::size_t i = 0; i < s.samples(); ++i) {
    double n = 0;
    for (std::size_t c = 0; c < nc; ++c) n += s.data[i * nc + c] * s.data[i * nc + c];
    m = std::max(m, std::sqrt(n));
  }
  return m / scale;
}

// Period from the zero crossings of comp: mean spacing of the last `n` full periods (2 crossings each).
double period_from(const std::vector<double>& z, bool at_end, int n = 2) {
  if (z.size() < static_cast<std::size_t>(2 * n + 1)) return nan_v;
  return at_end ? (z[z.size() - 1] - z[z.size() - 1 - 2 * n]) / n : (z[2 * n] - z[0]) / n;
}

// ---------------------------------------------------------------------------------------------------------------
// long_run: the free-free bar (examples/bar_free_free.json, first mode, period 4L/c = 10 s) at h = 1 m, 2 x 2
// particles per cell, B-spline FLIP, CFL 0.5, for 50 000 s (> 1e6 steps). No external force or support: the
// energy balance error is E(t) - E0; its least-squares slope against the step count gives the drift per 1e5 steps.
// Bound 1 % of E0 per 1e5 steps: a design run is well under 1e5 steps (the dam + boulder example: 2.9e4), so a
// drift within it keeps a design run's created energy under the 1 % the design cases allow (tyre_buffer).
// long_run_energy (not run by default: fails, see docs/reliability.md): the same run with the two-sided bound
// |drift| <= 1 % of E0 per 1e5 steps and the energy left after 1e6 steps; long_run bounds only energy creation.
std::vector<CaseResult> long_run_impl(bool energy) {
  const CaseTimer timer;
  const std::string c = energy ? "long_run_energy" : "long_run";
  // Rollers on y = 0 and y = 1 (grid lines) keep the bar axial. Its 1 % strain amplitude is 30 times the Euler
  // buckling strain of a 50 m x 1 m bar (pi^2 h^2 / 12 L^2 = 3.3e-4), so without them it buckles dynamically once
  // round-off seeds a transverse motion: seen after ~2e4 s, at a time that moves with the last bit of the arithmetic
  // (a particle then left the grid). The axial problem is the one this case is about.
  const nlohmann::json rollers = nlohmann::json::parse(R"([
      {"name": "below", "type": "plane", "point": [0, 0], "normal": [0, 1], "condition": "roller"},
      {"name": "above", "type": "plane", "point": [0, 1], "normal": [0, -1], "condition": "roller"}])");
  const Attempt a = attempt(example_scenario("bar_free_free.json", {{"/grid/cell_size", 1.0},
                                                                    {"/analysis/end_time", 50000.0},
                                                                    {"/output/history_interval", 0.25},
                                                                    {"/output/snapshot_interval", 0.0},
                                                                    {"/walls", rollers}}));
  std::vector<CaseResult> r;
  if (!a.ok) return stamp({run_failed(c, "bar, 50 000 s", a.error)}, timer.seconds());
  const Results& res = a.out.results;
  const double steps = res.info.stats.steps.value();
  const Series& ke = series(res, "energy/kinetic");
  const Series& se = series(res, "energy/strain");
  const Series& bal = series(res, "energy/balance_error");
  const Series& st = series(res, "step");
  const double e0 = ke.data[0] + se.data[0];
  // Drift: slope of the balance error against the step number (both as series over the samples).
  std::vector<double> step(st.data.begin(), st.data.end());
  const double drift = slope(step, bal, 0, 0, steps) * 1e5 / e0;
  const double gain = column_max(bal, 0) / e0, left = (last(ke) + last(se)) / e0;
  // Momentum: the first mode has none; scale by sum m |v| at the start (rho A L 2 v0 / pi).
  const double mv = 1.0 * 1.0 * 50.0 * 0.1 * 2 / pi;
  const auto z = zero_crossings(res.time, series(res, "probes/end/velocity"), 0);
  // Mean over 10 periods at each end: a single crossing of the noisy FLIP signal moves a 2-period mean by ~0.2 %.
  const double t_first = period_from(z, false, 10), t_last = period_from(z, true, 10);
  detail("  %s: %.0f steps, E0 %.6g J, drift/1e5 steps %.3g, largest gain/E0 %.3g, energy left/E0 %.3g, period first %.6f last %.6f s\n",
         c.c_str(), steps, e0, drift, gain, left, t_first, t_last);
  r.push_back(bound_metric(c, "steps (must exceed 1e6)", "-", steps, 1e6, true));
  if (energy) {
    r.push_back(metric(c, "energy drift per 1e5 steps / E0 (fit over the run, two-sided)", "-", drift, 0.0, 0.01, false));
    r.push_back(metric(c, "energy after 1e6 steps / E0", "-", left, 1.0, 0.1));
    return stamp(r, timer.seconds());
  }
  r.push_back(bound_metric(c, "energy drift per 1e5 steps / E0 (fit; must be < +0.01: no creation)", "-", drift, 0.01, false));
  r.push_back(bound_metric(c, "largest energy gain / E0 (must be < 0.05)", "-", gain, 0.05, false));
  r.push_back(metric(c, "largest |momentum| / sum m|v|", "-", max_norm(series(res, "momentum"), mv), 0.0, 1e-9, false));
  r.push_back(metric(c, "period over the first 10 periods", "s", t_first, 10.0, 2e-3));
  // After 5000 periods FLIP has disordered the particles, and the axial bar's period is 0.24 % short (9.976 s,
  // measured with the rollers; any arithmetic gives the same here): bound 0.5 %.
  r.push_back(metric(c, "period over the last 10 periods (after 1e6 steps)", "s", t_last, 10.0, 5e-3));
  r.push_back(bound_metric(c, "all histories finite (1 = yes)", "-", all_finite(res) ? 1.0 : 0.0, 0.5, true));
  return stamp(r, timer.seconds());
}
std::vector<CaseResult> long_run() { return long_run_impl(false); }
std::vector<CaseResult> long_run_energy() { return long_run_impl(true); }

// ---------------------------------------------------------------------------------------------------------------
// Dam + boulder runs (examples/dam_boulder_tyre_buffer.json, dam_boulder_no_buffer.json): the concrete member
// (E 25 GPa), the granite boulder (E 50 GPa) and, with a buffer, a rubber layer bonded to the face.
struct DamRun {
  bool ok = false;
  std::string error;
  double input = 0;           // boulder kinetic energy at the start (J)
  double created = 0;         // largest energy balance error (J, > 0: energy created)
  double lost = 0;            // -smallest energy balance error (J, > 0: lost by contact and numerics)
  double contact = 0;         // peak |contact force of the material on the member| (N)
  double shear = 0, moment = 0;  // peak |base reaction| Fx (N) and M (N m)
  double j_min = 1, steps = 0;
  bool finite = false;
};
DamRun dam_run(const std::string& file, const Overrides& ov) {
  DamRun d;
  const Attempt a = attempt(example_scenario(file, ov));
  d.ok = a.ok;
  d.error = a.error;
  if (!a.ok) return d;
  const Results& res = a.out.results;
  const Series& bal = series(res, "energy/balance_error");
  const Series& cf = series(res, "frame/contact_force");
  const Series& base = series(res, "supports/base/reaction");
  d.input = series(res, "probes/boulder/kinetic_energy").data.front();
  d.created = column_max(bal, 0);
  d.lost = -*std::min_element(bal.data.begin(), bal.data.end());
  for (std::size_t k = 0; k < res.time.size(); ++k) d.contact = std::max(d.contact, std::hypot(cf.data[2 * k], cf.data[2 * k + 1]));
  d.shear = column_max(base, 0, true);
  d.moment = column_max(base, 2, true);
  d.j_min = res.info.stats.jacobian_min.value();
  d.steps = res.info.stats.steps.value();
  d.finite = all_finite(res);
  return d;
}

// Energy created < 1 % of the impact energy (the design cases' bound), energy lost <= the impact energy (a run
// cannot lose more than was put in), contact force and base reactions finite and > 0, particle J > 0.
void dam_metrics(std::vector<CaseResult>& r, const std::string& c, const std::string& tag, const DamRun& d) {
  detail("  %s %s: %s steps %.0f, input %.4g J, created %.3g, lost %.3g, contact %.4g N, shear %.4g N, moment %.4g N m, J_min %.3g\n",
         c.c_str(), tag.c_str(), d.ok ? "ok" : d.error.c_str(), d.steps, d.input, d.created / d.input, d.lost / d.input, d.contact,
         d.shear, d.moment, d.j_min);
  if (!d.ok) {
    r.push_back(run_failed(c, tag, d.error));
    return;
  }
  r.push_back(bound_metric(c, tag + ": histories finite (1 = yes)", "-", d.finite ? 1.0 : 0.0, 0.5, true));
  r.push_back(bound_metric(c, tag + ": energy created / impact energy (must be < 0.01)", "-", std::max(0.0, d.created) / d.input, 0.01, false));
  r.push_back(bound_metric(c, tag + ": energy lost / impact energy (must be < 1)", "-", std::max(0.0, d.lost) / d.input, 1.0, false));
  r.push_back(bound_metric(c, tag + ": peak contact force (must be > 0)", "N", d.contact, 0.0, true));
  r.push_back(bound_metric(c, tag + ": peak base shear (must be > 0)", "N", d.shear, 0.0, true));
  r.push_back(bound_metric(c, tag + ": peak base moment (must be > 0)", "N m", d.moment, 0.0, true));
  r.push_back(bound_metric(c, tag + ": smallest particle J (must be > 0)", "-", d.j_min, 0.0, true));
}

// stiffness_contrast: the buffer's modulus overridden to 1 MPa and 10 MPa (the example has 5 MPa): stiffness
// ratios concrete / rubber 2.5e4 and 2.5e3, granite / rubber 5e4 and 5e3, in one explicit step.
std::vector<CaseResult> stiffness_contrast() {
  const CaseTimer timer;
  std::vector<CaseResult> r;
  for (double e : {1e6, 1e7}) {
    const DamRun d = dam_run("dam_boulder_tyre_buffer.json", {{"/materials/2/youngs_modulus", e}});
    dam_metrics(r, "stiffness_contrast", "buffer E " + std::to_string(static_cast<int>(e / 1e6)) + " MPa", d);
  }
  return stamp(r, timer.seconds());
}

// high_speed: the boulder at 30 m/s (6 x the example's 5 m/s; the presets' boulder.velocity becomes the
// body's velocity) with and without the buffer, 0.04 s (the boulder must not reach the grid's upstream edge
// on its rebound). The buffer must lower the peak contact force.
std::vector<CaseResult> high_speed() {
  const CaseTimer timer;
  std::vector<CaseResult> r;
  const Overrides ov = {{"/bodies/0/velocity", J::array({30.0, 0.0})}, {"/analysis/end_time", 0.04}};
  const DamRun buf = dam_run("dam_boulder_tyre_buffer.json", ov);
  const DamRun bare = dam_run("dam_boulder_no_buffer.json", ov);
  dam_metrics(r, "high_speed", "30 m/s, buffer", buf);
  dam_metrics(r, "high_speed", "30 m/s, no buffer", bare);
  if (buf.ok && bare.ok)
    r.push_back(bound_metric("high_speed", "peak contact force buffer / bare (must be < 1)", "-", buf.contact / bare.contact, 1.0, false));
  return stamp(r, timer.seconds());
}

// ---------------------------------------------------------------------------------------------------------------
// cfl_sweep: the CFL factor 0.3 ... 1.0 for each scheme on the free-free bar (h = 0.5 m as in the example, 20 s)
// and the colliding disks (h = 1/40 m as in the example, 3 s). A run is stable when it completes (finite, no
// particle lost) and:
//   bar:   the period error against 4L/c = 10 s is <= 1 % (stable runs: <= 1e-3; broken ones 0.5-1) and the
//          energy never exceeds E0 by more than 5 % (the energy of accurate runs, taken at staggered time levels,
//          swings above E0 by 0.6 % at CFL 0.3 to 1.5 % at 0.9; growing runs reach 60 % to 100 x);
//   disks: the energy never exceeds E0 by more than 1 % (growth is the instability; APIC and USL dissipate, up to
//          30 % at this h, docs/performance.md), loses at most 50 %, and momentum stays at round-off (1e-10).
// Criterion of the suite: every run at or below the schema's default CFL (0.5) is stable. The largest factor up to
// which every run is stable is recorded per scheme and problem.
struct Scheme {
  const char *shape, *transfer, *update;
};
// The schema's stress update for each shape (usl; musl for linear). Linear + APIC is refused by the schema.
const std::vector<Scheme> kSchemes = {{"gimp", "flip", "usl"}, {"gimp", "apic", "usl"}, {"bspline2", "flip", "usl"}, {"bspline2", "apic", "usl"}};
// cfl_sweep_linear (not run by default: fails at every CFL on the bar): linear FLIP with its default MUSL and
// with USL (the examples name usl explicitly, so overriding only the shape gives linear + USL).
const std::vector<Scheme> kLinearSchemes = {{"linear", "flip", "musl"}, {"linear", "flip", "usl"}};
const double kCfls[] = {0.3, 0.5, 0.7, 0.8, 0.9, 1.0};
constexpr double kDefaultCfl = 0.5;  // engine/scenario/config.hpp AnalysisConfig::cfl

std::string scheme_name(const Scheme& s) { return std::string(s.shape) + " " + s.transfer + " " + s.update; }

// One sweep run: stable or not, and why.
struct SweepRun {
  bool stable = false;
  std::string why;
  double measure = nan_v;  // bar: period error; disks: energy change E_end/E0 - 1
};
// raw: the factor as given (allow_unstable_cfl), else reduced to the scheme's limit as every user run is.
SweepRun sweep_run(bool bar, const Scheme& sc, double cfl, bool raw = true) {
  const Overrides ov = {{"/mpm/shape_function", sc.shape}, {"/mpm/transfer", sc.transfer}, {"/mpm/stress_update", sc.update},
                        {"/analysis/cfl", cfl}, {"/output/snapshot_interval", 0.0}};
  Scenario scen = example_scenario(bar ? "bar_free_free.json" : "colliding_disks.json", ov);
  scen.mpm.allow_unstable_cfl = raw;
  const Attempt a = attempt(scen);
  SweepRun s;
  if (!a.ok) {
    s.why = a.error;
    return s;
  }
  const Results& res = a.out.results;
  if (!all_finite(res)) {
    s.why = "non-finite history";
    return s;
  }
  const Series& ke = series(res, "energy/kinetic");
  const Series& se = series(res, "energy/strain");
  const double e0 = ke.data[0] + se.data[0];
  const double gain = column_max(series(res, "energy/balance_error"), 0) / e0;
  char buf[160];
  if (bar) {
    const auto z = zero_crossings(res.time, series(res, "probes/end/velocity"), 0);
    const double period = z.size() >= 3 ? z[2] - z[0] : nan_v;
    s.measure = std::abs(period - 10.0) / 10.0;
    s.stable = s.measure <= 0.01 && gain <= 0.05;
    std::snprintf(buf, sizeof buf, "period error %.3g, energy gain %.3g", s.measure, gain);
  } else {
    const double m_disk = 1000 * pi * 0.2 * 0.2 * 1.0, scale = 2 * m_disk * 0.1 * std::sqrt(2.0);
    const double p = max_norm(series(res, "momentum"), scale);
    s.measure = (last(ke) + last(se)) / e0 - 1;
    s.stable = gain <= 0.01 && s.measure >= -0.5 && p <= 1e-10;
    std::snprintf(buf, sizeof buf, "energy change %.3g, gain %.3g, momentum %.2g", s.measure, gain, p);
  }
  s.why = buf;
  return s;
}

std::vector<CaseResult> cfl_sweep_impl(const std::string& c, const std::vector<Scheme>& schemes) {
  const CaseTimer timer;
  std::vector<CaseResult> r;
  for (bool bar : {true, false}) {
    const char* problem = bar ? "bar" : "disks";
    for (const Scheme& sc : schemes) {
      double limit = 0;  // largest factor up to which every run is stable
      double first_unstable = nan_v;
      std::string why_default;  // a failure at or below the default
      for (double cfl : kCfls) {
        const SweepRun s = sweep_run(bar, sc, cfl);
        detail("  %s %-5s %-18s cfl %.1f: %-8s %s\n", c.c_str(), problem, scheme_name(sc).c_str(), cfl, s.stable ? "stable" : "UNSTABLE",
               s.why.c_str());
        if (s.stable && std::isnan(first_unstable)) limit = cfl;
        if (!s.stable && std::isnan(first_unstable)) first_unstable = cfl;
        if (!s.stable && cfl <= kDefaultCfl && why_default.empty()) why_default = "cfl " + std::to_string(cfl).substr(0, 3) + ": " + s.why;
      }
      std::string m = std::string(problem) + ", " + scheme_name(sc) + ": largest stable CFL (must be >= 0.5)";
      if (!why_default.empty()) m += " [" + why_default + "]";
      r.push_back(at_least(c, m, "-", limit, kDefaultCfl));
      // What a user gets: CFL 1.0 asked for, reduced to the scheme's limit by the run (engine/sim/run.cpp).
      const SweepRun user = sweep_run(bar, sc, 1.0, false);
      detail("  %s %-5s %-18s cfl 1.0 reduced to the limit: %-8s %s\n", c.c_str(), problem, scheme_name(sc).c_str(),
             user.stable ? "stable" : "UNSTABLE", user.why.c_str());
      if (std::string(sc.shape) != "linear")
        r.push_back(at_least(c, std::string(problem) + ", " + scheme_name(sc) + ": cfl 1.0 asked, reduced to the limit: stable (1 = yes)", "-",
                             user.stable ? 1.0 : 0.0, 1.0));
    }
  }
  return stamp(r, timer.seconds());
}
std::vector<CaseResult> cfl_sweep() { return cfl_sweep_impl("cfl_sweep", kSchemes); }
std::vector<CaseResult> cfl_sweep_linear() { return cfl_sweep_impl("cfl_sweep_linear", kLinearSchemes); }

// ---------------------------------------------------------------------------------------------------------------
// thin_member: Lin & Yang verification 2 at h/L = 0.025 (beam depth 0.0625 m) as 4 corotational beam-columns, on the example's
// grid (h = 0.25 m; regression 0.474 m as in paper_a6_large) and on a grid 4 x finer (h = 0.0625 m, the disc's
// particle spacing kept at 1/32 m), where the member's deflection sweeps the beam through ~8 cells.
std::vector<CaseResult> thin_member() {
  const CaseTimer timer;
  const std::string c = "thin_member";
  std::vector<CaseResult> r;
  auto one = [&](const std::string& tag, const Overrides& extra) -> A6Run {
    Overrides ov = {{"/structure/transformation", "corotational"}, a6_bottom_probe(0.0625)};
    ov.insert(ov.end(), extra.begin(), extra.end());
    try {
      return paper_a6_run(0.0625, true, ov);
    } catch (const RunError& e) {
      r.push_back(run_failed(c, tag, e.what()));
      A6Run bad;
      bad.steps = -1;
      return bad;
    }
  };
  const A6Run coarse = one("h/L 0.025, grid 0.25 m", {});
  const A6Run fine = one("h/L 0.025, grid 0.0625 m", {{"/grid/cell_size", 0.0625}, {"/bodies/0/particles_per_cell", 2}});
  for (const auto* run : {&coarse, &fine}) {
    if (run->steps < 0) continue;
    const bool is_fine = run == &fine;
    const std::string tag = is_fine ? "grid 0.0625 m" : "grid 0.25 m";
    bool finite = std::isfinite(run->peak_displacement) && std::isfinite(run->peak_von_mises);
    for (double u : run->top_uy) finite = finite && std::isfinite(u);
    detail("  thin_member %s: steps %ld, peak deflection %.4f m (%.1f cells), min gap %.4f m, disc final vy %.3f m/s, wall %.2f s\n",
           tag.c_str(), run->steps, run->peak_displacement, run->peak_displacement / (is_fine ? 0.0625 : 0.25), run->min_gap,
           run->disc_final_vy, run->wall);
    r.push_back(bound_metric(c, tag + ": deflection history finite (1 = yes)", "-", finite ? 1.0 : 0.0, 0.5, true));
    if (!is_fine)
      r.push_back(metric(c, tag + ": peak deflection, regression as paper_a6_large (c07f3eb)", "m", run->peak_displacement, 0.474, 0.05));
    // At the disc's bottom, not its centroid: the soft disc flattens (paper_a6_large).
    r.push_back(metric(c, tag + ": disc bottom below the beam top, worst (penetration)", "m", std::max(0.0, -run->min_bottom_gap), 0.0, 0.05, false));
    r.push_back(metric(c, tag + ": rebound speed short of upward (max(0, -v_final))", "m/s", std::max(0.0, -run->disc_final_vy), 0.0, 0.5, false));
  }
  if (coarse.steps >= 0 && fine.steps >= 0) {
    const double cells = fine.peak_displacement / 0.0625;
    r.push_back(bound_metric(c, "grid 0.0625 m: peak deflection in cells (must exceed 4)", "-", cells, 4.0, true));
    r.push_back(metric(c, "peak deflection, grid 0.0625 m / grid 0.25 m", "-", fine.peak_displacement / coarse.peak_displacement, 1.0, 0.15));
  }
  return stamp(r, timer.seconds());
}

// ---------------------------------------------------------------------------------------------------------------
// grid_edges
//  a) particles on grid lines: particles are seeded at (k + 1/2)/ppc of a cell, so they are put on the lines by
//     the motion: a box (1 particle per cell) translating diagonally by h/4 per step (h = 1/8 m, dt = 2^-10 s,
//     v = 32 m/s, all exact in binary) sits on grid lines - and grid nodes - every second step, for 48 cells.
//     Rigid translation: displacement v t, no stress, momentum conserved.
//  b) free fall across 98 cells (free_fall.json, 1 s, grid 6 m deep): drop g t^2/2 (error dt/t, bound 0.003).
//  c) a body one cell from every grid edge: the free-free bar on a grid with a one-cell margin; the period is that
//     on the example's roomy grid.
//  d) near-empty cells: one lone particle thrown across the grid under gravity (velocity v0 + g t, no stress),
//     and the colliding disks at 1 particle per cell on a coarse grid (h = 1/20 m): momentum at round-off.
const Scheme kLoneSchemes[] = {{"linear", "flip", "musl"}, {"gimp", "flip", "usl"}, {"gimp", "apic", "usl"},
                               {"bspline2", "flip", "usl"}, {"bspline2", "apic", "usl"}};

void on_grid_lines(std::vector<CaseResult>& r, const std::string& c, const std::vector<Scheme>& schemes) {
  const J soft = J::array({J{{"name", "soft"}, {"model", "linear_elastic"}, {"density", 1000.0}, {"youngs_modulus", 1e5}, {"poisson_ratio", 0.25}}});
  for (const Scheme& sc : schemes) {
    const double h = 0.125, dt = 1.0 / 1024, v = h / 4 / dt, t_end = 192 * dt;
    const Overrides ov = {{"/mpm", J{{"shape_function", sc.shape}, {"transfer", sc.transfer}, {"stress_update", sc.update}}},
                          {"/analysis/gravity", J::array({0.0, 0.0})}, {"/analysis/dt_max", dt}, {"/analysis/end_time", t_end},
                          {"/grid", J{{"origin", J::array({0.0, 0.0})}, {"size", J::array({8.0, 8.0})}, {"cell_size", h}}},
                          {"/materials", soft},
                          {"/bodies/0", J{{"name", "disk"}, {"material", "soft"}, {"particles_per_cell", 1},
                                          {"shape", J{{"type", "box"}, {"min", J::array({0.5, 0.5})}, {"max", J::array({1.0, 1.0})}}},
                                          {"velocity", J::array({v, v})}}},
                          {"/output/probes/1/point", J::array({0.5625, 0.5625})}};
    const std::string tag = "on grid lines, " + scheme_name(sc);
    const Attempt a = attempt(example_scenario("free_fall.json", ov));
    if (!a.ok) {
      r.push_back(run_failed(c, tag, a.error));
      continue;
    }
    const Results& res = a.out.results;
    const double t = res.time.back();
    const Series& u = series(res, "probes/disk/displacement");
    const double err = std::max(std::abs(last(u, 0) - v * t), std::abs(last(u, 1) - v * t)) / (v * t);
    const double vm = column_max(series(res, "probes/centre/von_mises"), 0);
    const Series& p = series(res, "momentum");
    const double dp = std::hypot(last(p, 0) - p.data[0], last(p, 1) - p.data[1]) / std::hypot(p.data[0], p.data[1]);
    detail("  %s %s: %.0f steps, displacement error %.3g, max von Mises %.3g Pa, momentum change %.3g\n", c.c_str(), tag.c_str(),
           res.info.stats.steps.value(), err, vm, dp);
    r.push_back(metric(c, tag + ": displacement / v t (48 cells)", "-", err, 0.0, 1e-9, false));
    r.push_back(metric(c, tag + ": max von Mises (rigid translation)", "Pa", vm, 0.0, 1e-6, false));
    r.push_back(metric(c, tag + ": momentum change / m|v|", "-", dp, 0.0, 1e-12, false));
  }
}

// grid_lines_linear (not run by default: fails): a) with linear shape functions. A particle exactly on a grid
// line has weight 0 but slope 1/h on the node beyond it; at the body's leading face that node has no mass
// (velocity 0), so the particle sees a velocity gradient -v/h and a rigid translation builds stress.
std::vector<CaseResult> grid_lines_linear() {
  const CaseTimer timer;
  std::vector<CaseResult> r;
  on_grid_lines(r, "grid_lines_linear", {{"linear", "flip", "musl"}, {"linear", "flip", "usl"}});
  return stamp(r, timer.seconds());
}

// b) free fall across many cells.
void free_fall_across_cells(const std::string& c, std::vector<CaseResult>& r) {
  const Attempt a = attempt(example_scenario("free_fall.json", {{"/grid/origin", J::array({0.0, -5.0})}, {"/grid/size", J::array({1.0, 6.0})},
                                                                {"/analysis/end_time", 1.0}}));
  if (!a.ok) {
    r.push_back(run_failed(c, "free fall 1 s", a.error));
  } else {
    const double t = a.out.results.time.back(), g = 9.81;
    const double drop = -last(series(a.out.results, "probes/disk/displacement"), 1);
    detail("  grid_edges free fall: drop %.6f m (%.1f cells) vs %.6f m\n", drop, drop / 0.05, 0.5 * g * t * t);
    r.push_back(metric(c, "free fall across 98 cells: centroid drop", "m", drop, 0.5 * g * t * t, 0.003));
  }
}

// c) one cell from every grid edge.
void bar_one_cell_from_edges(const std::string& c, std::vector<CaseResult>& r) {
  auto period = [&](const Overrides& ov, const std::string& tag) {
    const Attempt a = attempt(example_scenario("bar_free_free.json", ov));
    if (!a.ok) {
      r.push_back(run_failed(c, tag, a.error));
      return nan_v;
    }
    const auto z = zero_crossings(a.out.results.time, series(a.out.results, "probes/end/velocity"), 0);
    return z.size() >= 3 ? z[2] - z[0] : nan_v;
  };
  const double roomy = period({}, "bar, example grid");
  const double tight = period({{"/grid/origin", J::array({-0.5, -0.5})}, {"/grid/size", J::array({51.0, 2.0})}}, "bar, one-cell margin");
  detail("  grid_edges bar: period %.9f s (one-cell margin) vs %.9f s (example grid)\n", tight, roomy);
  r.push_back(metric(c, "bar one cell from every edge: period", "s", tight, 10.0, 1e-3));
  r.push_back(metric(c, "bar one cell from every edge: period / period on the example grid", "-", tight, roomy, 1e-9));
}

// d) a lone particle in free flight.
void lone_particles(const std::string& c, std::vector<CaseResult>& r) {
  for (const Scheme& sc : kLoneSchemes) {
    const J v0 = J::array({3.0, 5.0});
    const Overrides ov = {{"/mpm", J{{"shape_function", sc.shape}, {"transfer", sc.transfer}, {"stress_update", sc.update}}},
                          {"/analysis/end_time", 0.8},
                          {"/grid", J{{"origin", J::array({0.0, 0.0})}, {"size", J::array({4.0, 4.0})}, {"cell_size", 0.1}}},
                          {"/bodies/0", J{{"name", "disk"}, {"material", "rock"}, {"particles_per_cell", 1},
                                          {"shape", J{{"type", "box"}, {"min", J::array({0.5, 0.5})}, {"max", J::array({0.6, 0.6})}}},
                                          {"velocity", v0}}},
                          {"/output/probes/1/point", J::array({0.55, 0.55})}};
    const std::string tag = "lone particle, " + scheme_name(sc);
    const Attempt a = attempt(example_scenario("free_fall.json", ov));
    if (!a.ok) {
      r.push_back(run_failed(c, tag, a.error));
      continue;
    }
    const Results& res = a.out.results;
    const double t = res.time.back(), g = 9.81;
    const Series& v = series(res, "probes/disk/velocity");
    const double verr = std::hypot(last(v, 0) - 3.0, last(v, 1) - (5.0 - g * t)) / std::hypot(3.0, 5.0);
    const double xerr = std::abs(last(series(res, "probes/disk/displacement"), 0) - 3.0 * t) / (3.0 * t);
    const double vm = column_max(series(res, "probes/centre/von_mises"), 0);
    detail("  grid_edges %s: %.0f particle(s), %.0f steps, velocity error %.3g, x error %.3g, max von Mises %.3g Pa\n", tag.c_str(),
           res.info.stats.particles.value(), res.info.stats.steps.value(), verr, xerr, vm);
    r.push_back(metric(c, tag + ": particles", "-", res.info.stats.particles.value(), 1.0, 0.0, false));
    r.push_back(metric(c, tag + ": velocity / (v0 + g t)", "-", verr, 0.0, 1e-9, false));
    r.push_back(metric(c, tag + ": horizontal travel / v0x t (24 cells)", "-", xerr, 0.0, 1e-9, false));
    r.push_back(metric(c, tag + ": max von Mises (free flight)", "Pa", vm, 0.0, 1e-3, false));
  }
}

// d) sparse disks colliding: momentum and energy at one particle per cell.
void sparse_disks(const std::string& c, std::vector<CaseResult>& r) {
  for (const Scheme& sc : kLoneSchemes) {
    const std::string tag = "disks at 1 particle per cell, h 1/20 m, " + scheme_name(sc);
    const Attempt a = attempt(example_scenario("colliding_disks.json", {{"/mpm/shape_function", sc.shape}, {"/mpm/transfer", sc.transfer},
                                                                       {"/mpm/stress_update", sc.update}, {"/grid/cell_size", 0.05},
                                                                       {"/bodies/0/particles_per_cell", 1}, {"/bodies/1/particles_per_cell", 1},
                                                                       {"/output/snapshot_interval", 0.0}}));
    if (!a.ok) {
      r.push_back(run_failed(c, tag, a.error));
      continue;
    }
    const Results& res = a.out.results;
    const double per_disk = res.info.stats.particles.value() / 2;
    const Series& ke = series(res, "energy/kinetic");
    const double e0 = ke.data[0] + series(res, "energy/strain").data[0];
    const double gain = column_max(series(res, "energy/balance_error"), 0) / e0;
    // sum m|v| at the start: the kinetic energy gives m v^2 / 2 per disk with |v| = 0.1 sqrt 2.
    const double scale = 2 * e0 / (0.1 * std::sqrt(2.0));
    const double p = max_norm(series(res, "momentum"), scale);
    detail("  grid_edges %s: %.0f particles per disk, momentum %.3g, energy gain %.3g, finite %d\n", tag.c_str(), per_disk, p, gain,
           all_finite(res));
    r.push_back(metric(c, tag + ": momentum / sum m|v|", "-", p, 0.0, 1e-12, false));
    r.push_back(bound_metric(c, tag + ": energy gain / E0 (must be < 0.01)", "-", gain, 0.01, false));
  }
}

std::vector<CaseResult> grid_edges() {
  const CaseTimer timer;
  const std::string c = "grid_edges";
  std::vector<CaseResult> r;
  // a) translation on grid lines (linear shapes: grid_lines_linear).
  on_grid_lines(r, c, {{"gimp", "flip", "usl"}, {"gimp", "apic", "usl"}, {"bspline2", "flip", "usl"}, {"bspline2", "apic", "usl"}});
  free_fall_across_cells(c, r);
  bar_one_cell_from_edges(c, r);
  lone_particles(c, r);
  sparse_disks(c, r);
  return stamp(r, timer.seconds());
}

}  // namespace

std::vector<ValidationCase> stress_cases() {
  return {
      {"long_run", "free-free bar for > 1e6 steps: energy drift per 1e5 steps, momentum, period at the end", long_run},
      {"stiffness_contrast", "concrete dam, granite boulder, rubber buffer of 1 and 10 MPa: completes, energy, forces", stiffness_contrast},
      {"high_speed", "boulder at 30 m/s with and without buffer: completes, energy, the buffer lowers the contact force", high_speed},
      {"cfl_sweep", "CFL 0.3-1.0 x shape x transfer on the free-free bar and the colliding disks: stable at the default 0.5", cfl_sweep},
      {"thin_member", "Lin & Yang verification 2 at h/L = 0.025 (corotational), and on a grid where the member sweeps ~8 cells", thin_member},
      {"grid_edges", "particles on grid lines, free fall across cells, a body one cell from the edges, lone particles", grid_edges},
      // Known defects (docs/reliability.md): run only when named.
      {"long_run_energy", "long_run with a two-sided energy drift bound: FLIP loses most of the bar's energy over 1e6 steps", long_run_energy, false},
      {"cfl_sweep_linear", "cfl_sweep for linear shapes (FLIP with MUSL and USL): unstable at every CFL on the bar", cfl_sweep_linear, false},
      {"grid_lines_linear", "grid_edges a) with linear shapes: a translating body on grid lines builds stress", grid_lines_linear},
  };
}

}  // namespace dmi
