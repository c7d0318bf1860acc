// Verification cases with their closed forms. Each returns one CaseResult per metric.
#include <algorithm>
#include <chrono>
#include <cmath>

#include "verify/cases_members.hpp"
#include "verify/validate.hpp"
#include "engine/sdof/sdof.hpp"

namespace dmi {
namespace {

constexpr double pi = 3.14159265358979323846;

using Timer = CaseTimer;

}  // namespace

// 1. Fixed-free bar, first axial mode: u(x,t) = (v0/w) sin(beta x) sin(w t), beta = pi/(2L), w = beta c,
//    c = sqrt(E/rho) (nu = 0). Period T = 4L/c; centroid displacement amplitude (v0/w)(2/pi).
//    The period error is measured for h = 1, 1/2, 1/4, 1/8 m; the order is the log2 ratio of the last two.
BarResult bar_vibration_run(double h, ShapeKind shape, TransferKind transfer) {
  const double L = 25, E = 100, rho = 1, v0 = 0.1;
  const double c = std::sqrt(E / rho), beta = pi / (2 * L), w = beta * c;
  Scenario s = example_scenario("bar_vibration.json", {{"/grid/cell_size", h}});
  s.mpm.shape = shape;
  s.mpm.transfer = transfer;
  const RunOutput out = run_quiet(s);
  const auto& t = out.results.time;
  const auto z = zero_crossings(t, series(out.results, "probes/bar/velocity"), 0);
  BarResult r;
  r.period = z.size() >= 3 ? z[2] - z[0] : std::numeric_limits<double>::quiet_NaN();
  r.period_exact = 2 * pi / w;
  r.amplitude = column_max(series(out.results, "probes/bar/displacement"), 0, true);
  r.amplitude_exact = v0 / w * 2 / pi;
  r.wall = out.results.info.stats.wall_seconds.value();
  return r;
}

namespace {

std::vector<CaseResult> bar_vibration() {
  Timer timer;
  std::vector<double> err;
  BarResult fine;
  for (double h : {1.0, 0.5, 0.25, 0.125}) {
    fine = bar_vibration_run(h, ShapeKind::bspline2, TransferKind::flip);
    err.push_back(std::abs(fine.period - fine.period_exact) / fine.period_exact);
  }
  std::vector<CaseResult> r;
  r.push_back(metric("bar_vibration", "period (h = 1/8 m)", "s", fine.period, fine.period_exact, 2e-3));
  r.push_back(metric("bar_vibration", "amplitude (h = 1/8 m)", "m", fine.amplitude, fine.amplitude_exact, 5e-3));
  // The fixed end limits B-splines to first order (the support truncates the stencil); >= 0.8 required.
  r.push_back(metric("bar_vibration", "period order, fixed end", "-", std::log2(err[2] / err[3]), 1.0, 0.2, false));
  return stamp(r, timer.seconds());
}

// 1b. Free-free bar of length 2L in its first mode v0 cos(pi x / 2L): same period 4L/c; no support,
//     so the interior order of the scheme shows: 2 for quadratic B-splines.
std::vector<CaseResult> bar_free_free() {
  Timer timer;
  const double T = 10.0;
  std::vector<double> err;
  double period = 0;
  for (double h : {1.0, 0.5, 0.25}) {
    const RunOutput out = run_quiet(example_scenario("bar_free_free.json", {{"/grid/cell_size", h}}));
    const auto z = zero_crossings(out.results.time, series(out.results, "probes/end/velocity"), 0);
    period = z.size() >= 3 ? z[2] - z[0] : std::numeric_limits<double>::quiet_NaN();
    err.push_back(std::abs(period - T) / T);
  }
  std::vector<CaseResult> r;
  r.push_back(metric("bar_free_free", "period (h = 1/4 m)", "s", period, T, 2e-4));
  r.push_back(metric("bar_free_free", "period convergence order", "-", std::log2(err[1] / err[2]), 2.0, 0.3, false));
  return stamp(r, timer.seconds());
}

// 2. Sulsky et al. (1995) colliding disks: no external force, so total momentum is conserved to
//    round-off; the total energy drift (E_end - E_0)/E_0 is reported and bounded.
std::vector<CaseResult> colliding_disks() {
  Timer timer;
  struct Run { double momentum, drift, rebound; };
  auto run = [](double h, const char* method) {
    const RunOutput out = run_quiet(example_scenario("colliding_disks.json", {{"/grid/cell_size", h}, {"/contact/method", method}}));
    const auto& p = series(out.results, "momentum");
    const auto& ke = series(out.results, "energy/kinetic");
    const auto& se = series(out.results, "energy/strain");
    const auto& v1 = series(out.results, "probes/disk1/velocity");
    const double m_disk = 1000 * pi * 0.2 * 0.2 * 1.0;
    const double scale = 2 * m_disk * 0.1 * std::sqrt(2.0);  // sum m |v| at the start
    const std::size_t n = ke.samples();
    const double e0 = ke.data[0] + se.data[0], e1 = ke.data[n - 1] + se.data[n - 1];
    return Run{std::max(column_max(p, 0, true), column_max(p, 1, true)) / scale, (e1 - e0) / e0, -v1.data[(n - 1) * 2] / 0.1};
  };
  const Run coarse = run(0.025, "multi_field"), fine = run(0.0125, "multi_field"), sulsky = run(0.0125, "single_field");
  std::vector<CaseResult> r;
  r.push_back(metric("colliding_disks", "momentum / sum m|v|", "-", std::max(fine.momentum, sulsky.momentum), 0.0, 1e-12, false));
  r.push_back(metric("colliding_disks", "energy drift, multi-field h=1/80", "-", fine.drift, 0.0, 0.08, false));
  r.push_back(metric("colliding_disks", "energy drift ratio h=1/40 : 1/80", "-", coarse.drift / fine.drift, 2.0, 1.0, false));
  r.push_back(metric("colliding_disks", "energy drift, single-field h=1/80", "-", sulsky.drift, 0.0, 0.03, false));
  r.push_back(metric("colliding_disks", "rebound speed / approach speed", "-", fine.rebound, 1.0, 0.15));
  return stamp(r, timer.seconds());
}

// 3. Block on an incline (gravity rotated by theta): a = g (sin theta - mu cos theta) when
//    tan theta > mu; it sticks (a = 0) when tan theta < mu.
std::vector<CaseResult> incline() {
  Timer timer;
  const double g = 9.81, th = pi / 6;
  std::vector<CaseResult> r;
  {
    const RunOutput out = run_quiet(example_scenario("incline_sliding.json"));
    const double a = slope(out.results.time, series(out.results, "probes/block/velocity"), 0, 0.2, 1.0);
    r.push_back(metric("incline", "sliding acceleration mu=0.3", "m/s^2", a, g * (std::sin(th) - 0.3 * std::cos(th)), 0.02));
  }
  {
    // mu = 1 > tan 30 = 0.577. (Within ~20 % of tan theta, the vibration of the suddenly loaded block
    // makes it creep; measured in docs/verification.md.)
    const RunOutput out = run_quiet(example_scenario("incline_sliding.json", {{"/walls/0/friction", 1.0}}));
    const double u = series(out.results, "probes/block/displacement").data.end()[-2];
    // Sliding distance over 1 s relative to a frictionless block's (g sin theta t^2 / 2).
    r.push_back(metric("incline", "sticking: slip / frictionless slip (mu=1)", "-", u / (0.5 * g * std::sin(th)), 0.0, 0.005, false));
  }
  return stamp(r, timer.seconds());
}

// 3b. The same block on a second elastic body (multi-field contact, Bardenhagen 2000) instead of a
//     wall: a = g (sin theta - mu cos theta) with mu = 0.3, and g sin theta without friction.
std::vector<CaseResult> slab_friction() {
  Timer timer;
  const double g = 9.81, th = pi / 6;
  std::vector<CaseResult> r;
  for (double mu : {0.3, 0.0}) {
    const RunOutput out = run_quiet(example_scenario("block_on_slab.json", {{"/contact/friction", mu}}));
    const double a = slope(out.results.time, series(out.results, "probes/block/velocity"), 0, 0.2, 1.0);
    r.push_back(metric("slab_friction", mu > 0 ? "sliding acceleration mu=0.3" : "sliding acceleration mu=0", "m/s^2", a,
                       g * (std::sin(th) - mu * std::cos(th)), 0.05));
  }
  return stamp(r, timer.seconds());
}

// 4. Elastic bar onto a rigid frictionless wall (1D wave, nu = 0): contact stress rho c v,
//    contact time 2L/c.
std::vector<CaseResult> wall_impact() {
  Timer timer;
  const double rho = 1000, E = 1e7, v = 1, L = 1, A = 0.2 * 1.0;
  const double c = std::sqrt(E / rho), T = 2 * L / c;
  const RunOutput out = run_quiet(example_scenario("wall_impact.json"));
  const auto& t = out.results.time;
  const auto& f = series(out.results, "walls/wall/force");
  const double stress = -time_mean(t, f, 0, 0.2 * T, 0.8 * T) / A;  // force on the wall points along -x
  double t_end = 0;
  const double fpeak = rho * c * v * A;
  for (std::size_t i = 0; i < f.samples(); ++i)
    if (std::abs(f.data[i * 2]) > 0.05 * fpeak) t_end = t[i];
  std::vector<CaseResult> r;
  r.push_back(metric("wall_impact", "contact stress", "Pa", stress, rho * c * v, 0.03));
  r.push_back(metric("wall_impact", "contact time", "s", t_end, T, 0.05));
  return stamp(r, timer.seconds());
}

// Elastic sphere on a rigid frictionless wall (examples/hertz_sphere_on_wall.json) at h = R/5 and R/10. The wall's
// impulse equals the sphere's momentum change m v0 (1 + e) to 1 % (two independent measures: wall reactions, particle
// velocities); the energy lost by the held nodes' plastic engagement falls with h (order > 0.5). Peak force and
// contact time are checked at R/10 within 5 % against the quasi-static impact of the finite sphere: Hertz's law
// (Johnson 1985, sec. 4.2 and 11.4) assumes half-spaces, so its approach is that of points far from a contact
// much smaller than R; here a/R = 0.17 and the centre of mass of a sphere held by its own inertia approaches the wall
// less, by O(a/R). An axisymmetric finite-element model of the sphere on the flat under a uniform body force
// (bench/hertz_axisym.cpp, mesh-converged to 0.01 %) gives a force-approach law 5 % stiffer than Hertz at a/R = 0.055
// and 18 % at 0.17; integrated over the impact it gives the peak and duration below, +8.9 % and -6.4 % from Hertz.
// Hertz's own error at this a/R exceeds 5 %, so it is not the gate (docs/verification.md gives both). The sphere
// meeting its mirror image through multi-field contact is the same problem by symmetry: the same gates at R/10.
constexpr double kFiniteSpherePeakN = 7871.0;       // bench/hertz_axisym: 13k and 47k elements agree to 0.01 %
constexpr double kFiniteSphereTime1pcS = 3.866e-3;  // time with the force above 1 % of its peak
std::vector<CaseResult> hertz_sphere() {
  Timer timer;
  const double R = 0.1, v0 = 2.0, m = 1000.0 * 4.0 / 3.0 * 3.14159265358979323846 * R * R * R;
  struct Run { double peak, duration, impulse, e; };
  auto run = [&](double h) {
    const RunOutput out = run_quiet(example_scenario("hertz_sphere_on_wall.json", {{"/grid/cell_size", h}}));
    const auto& t = out.results.time;
    const Series& f = series(out.results, "walls/wall/force");
    const Series& v = series(out.results, "probes/ball/velocity");
    Run r{0, 0, 0, v.data.back() / v0};
    for (std::size_t k = 1; k < t.size(); ++k) r.peak = std::max(r.peak, -f.data[3 * k + 2]);
    double t0 = -1, t1 = 0;
    for (std::size_t k = 1; k < t.size(); ++k) {
      const double fz = -f.data[3 * k + 2];
      r.impulse += fz * (t[k] - t[k - 1]);  // interval means: the exact impulse
      if (fz > 0.01 * r.peak) {
        if (t0 < 0) t0 = t[k - 1];
        t1 = t[k];
      }
    }
    r.duration = t1 - t0;
    return r;
  };
  const Run a = run(2 * R / 10), b = run(R / 10);
  // The sphere meeting its mirror image head-on through multi-field contact (mu = 0, walls removed) is, by symmetry,
  // the sphere on a frictionless wall: force from the momentum rate over 0.02 ms windows (contact ~3.9 ms).
  Run mirror{0, 0, 0, 0};
  {
    using J = nlohmann::json;
    J ball = J::parse(embedded_examples().at("hertz_sphere_on_wall.json"))["bodies"][0];
    J image = ball;
    image["name"] = "image";
    image["shape"]["center"] = J::array({0.0, 0.0, -0.105});
    image["velocity"] = J::array({0.0, 0.0, v0});
    const RunOutput out = run_quiet(example_scenario("hertz_sphere_on_wall.json", {{"/grid/cell_size", R / 10},
                                                                                   {"/grid/origin/2", -0.29},
                                                                                   {"/grid/size/2", 0.58},
                                                                                   {"/bodies", J::array({ball, image})},
                                                                                   {"/walls", J::array()},
                                                                                   {"/contact", {{"method", "multi_field"}, {"friction", 0.0}}}}));
    const auto& t = out.results.time;
    const Series& v = series(out.results, "probes/ball/velocity");
    const double w = 2e-5;
    const std::vector<double> a = windowed_rate(t, v, 3, 2, w);
    for (double x : a) mirror.peak = std::max(mirror.peak, m * x);
    int on = 0;
    for (double x : a) on += m * x > 0.01 * mirror.peak;
    mirror.duration = on * w;
    mirror.e = v.data.back() / v0;
  }
  std::vector<CaseResult> r;
  for (const Run* x : {&a, &b}) {
    const std::string tag = x == &a ? " (h = R/5)" : " (h = R/10)";
    r.push_back(metric("hertz_sphere", "wall impulse / m v0 (1 + e)" + tag, "-", x->impulse / (m * v0 * (1 + x->e)), 1.0, 0.01));
  }
  r.push_back(metric("hertz_sphere", "peak force vs the finite sphere (h = R/10)", "N", b.peak, kFiniteSpherePeakN, 0.05));
  r.push_back(metric("hertz_sphere", "contact time (force above 1 % of its peak) vs the finite sphere (h = R/10)", "s",
                     b.duration, kFiniteSphereTime1pcS, 0.05));
  r.push_back(metric("hertz_sphere", "mirror sphere (multi-field) peak force vs the finite sphere (h = R/10)", "N", mirror.peak,
                     kFiniteSpherePeakN, 0.05));
  r.push_back(metric("hertz_sphere", "mirror sphere (multi-field) contact time vs the finite sphere (h = R/10)", "s", mirror.duration,
                     kFiniteSphereTime1pcS, 0.05));
  r.push_back(metric("hertz_sphere", "mirror sphere rebound vs the wall's (h = R/10)", "-", mirror.e, b.e, 0.02));
  r.push_back(bound_metric("hertz_sphere", "order of the energy lost, 1 - e^2, R/5 -> R/10 (> 0.5)", "-",
                           std::log2((1 - a.e * a.e) / (1 - b.e * b.e)), 0.5, true));
  return stamp(r, timer.seconds());
}

// 5a. Free fall: y = y0 - g t^2/2 (the explicit update adds g dt t/2, i.e. a relative error dt/t);
//     a uniformly accelerating body stays stress free.
std::vector<CaseResult> free_fall() {
  Timer timer;
  const RunOutput out = run_quiet(example_scenario("free_fall.json"));
  const double t = out.results.time.back(), g = 9.81;
  const double u = series(out.results, "probes/disk/displacement").data.back();
  std::vector<CaseResult> r;
  r.push_back(metric("free_fall", "centroid drop", "m", -u, 0.5 * g * t * t, 0.003));
  r.push_back(metric("free_fall", "max von Mises", "Pa", column_max(series(out.results, "probes/centre/von_mises"), 0), 0.0, 1e-6, false));
  return stamp(r, timer.seconds());
}

// 5b. Block resting on a frictionless floor under gravity (nu = 0, 1D): the centroid settles by
//     rho g H^2 / (3E) (time mean over many periods of the start-up oscillation, which PIC damps);
//     no horizontal drift; no creep: the mean does not move between the 2nd and 3rd second.
std::vector<CaseResult> rest_on_wall() {
  Timer timer;
  const double rho = 1000, g = 10, H = 1, E = 1e6, settle_exact = rho * g * H * H / (3 * E);
  const RunOutput out = run_quiet(example_scenario("rest_on_wall.json"));
  const auto& t = out.results.time;
  const auto& u = series(out.results, "probes/block/displacement");
  const double settle = -time_mean(t, u, 1, 1.0, 3.0);
  const double creep = std::abs(time_mean(t, u, 1, 2.0, 3.0) - time_mean(t, u, 1, 1.0, 2.0)) / settle_exact;
  std::vector<CaseResult> r;
  r.push_back(metric("rest_on_wall", "centroid settlement", "m", settle, settle_exact, 0.05));
  r.push_back(metric("rest_on_wall", "horizontal drift", "m", column_max(u, 0, true), 0.0, 1e-9, false));
  r.push_back(metric("rest_on_wall", "creep: mean shift 2nd->3rd s / settlement", "-", creep, 0.0, 0.01, false));
  return stamp(r, timer.seconds());
}

// 6. The fixed-free bar of case 1 with Kelvin-Voigt damping zeta = 0.05 at its own frequency 0.1 Hz (tyre-
//    rubber model): successive velocity peaks decay by exp(2 pi zeta / sqrt(1 - zeta^2)) per period, and the
//    energy balance closes with the dissipated energy counted.
std::vector<CaseResult> damped_bar() {
  Timer timer;
  const double zeta = 0.05;
  const RunOutput out = run_quiet(example_scenario("bar_vibration.json", {{"/materials/0/damping_ratio", zeta},
                                                                          {"/materials/0/damping_frequency", 0.1},
                                                                          {"/analysis/end_time", 30.0},
                                                                          {"/output/history_interval", 0.01}}));
  const auto& t = out.results.time;
  const Series& v = series(out.results, "probes/bar/velocity");
  std::vector<double> peaks;
  for (std::size_t k = 1; k + 1 < t.size(); ++k)
    if (v.data[2 * k] > 0 && v.data[2 * k] > v.data[2 * (k - 1)] && v.data[2 * k] >= v.data[2 * (k + 1)]) peaks.push_back(v.data[2 * k]);
  const double delta = peaks.size() >= 2 ? std::log(peaks[0] / peaks[1]) : 0.0;
  const double measured = delta / std::sqrt(4 * pi * pi + delta * delta);
  const double e0 = series(out.results, "energy/kinetic").data.front();
  const double bal = series(out.results, "energy/balance_error").data.back();
  const double lost = series(out.results, "energy/dissipated").data.back();
  std::vector<CaseResult> r;
  r.push_back(metric("damped_bar", "damping ratio from the logarithmic decrement", "-", measured, zeta, 0.02));
  r.push_back(metric("damped_bar", "dissipated energy / initial energy (30 s)", "-", lost / e0, 1 - std::exp(-2 * zeta * 2 * pi * 0.1 * 30), 0.05));
  r.push_back(metric("damped_bar", "energy balance error / initial energy", "-", bal / e0, 0.0, 0.02, false));
  return stamp(r, timer.seconds());
}

}  // namespace

const std::vector<ValidationCase>& validation_cases() {
  static const std::vector<ValidationCase> cases = [] {
    std::vector<ValidationCase> c = {
      {"bar_vibration", "axial vibration of a fixed-free bar: period, amplitude, convergence order", bar_vibration},
      {"bar_free_free", "axial vibration of a free-free bar: period and interior convergence order", bar_free_free},
      {"colliding_disks", "two elastic disks (Sulsky 1995): momentum, energy drift, rebound", colliding_disks},
      {"incline", "block on a 30 deg incline with Coulomb friction: sliding and sticking", incline},
      {"slab_friction", "block sliding on a second body: multi-field contact with and without friction", slab_friction},
      {"wall_impact", "elastic bar onto a rigid wall: contact stress rho c v and time 2L/c", wall_impact},
      {"hertz_sphere", "3D elastic sphere on a rigid wall and on its mirror image (multi-field) vs the finite sphere (Hertz corrected by FE)", hertz_sphere},
      {"free_fall", "free fall: drop g t^2/2, no stress", free_fall},
      {"rest_on_wall", "block at rest on a wall: settlement rho g H^2/3E, no drift or creep", rest_on_wall},
      {"damped_bar", "bar with Kelvin-Voigt damping: logarithmic decrement and dissipated energy", damped_bar},
    };
    for (auto& m : member_validation_cases()) c.push_back(std::move(m));
    for (auto& m : debris_validation_cases()) c.push_back(std::move(m));
    for (auto& m : dam_validation_cases()) c.push_back(std::move(m));
    for (auto& m : plastic_validation_cases()) c.push_back(std::move(m));
    for (auto& m : experiment_validation_cases()) c.push_back(std::move(m));
    return c;
  }();
  return cases;
}

}  // namespace dmi
