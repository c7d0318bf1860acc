// The tyre buffer on a concrete check dam and a rock block on a rubber pad (buffer physics against closed forms).
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "verify/cases_members.hpp"

#include "engine/sim/run.hpp"

namespace dmi {
namespace {

constexpr double pi = 3.14159265358979323846;

// Impact duration from a body's x velocity (the first column of a 2-component series, initial speed v0 > 0):
// from its first loss of frac v0 until it is within frac v0 of its final value.
double impact_duration(const std::vector<double>& t, const Series& v, double v0, double frac) {
  const double v_end = v.data[2 * (t.size() - 1)];
  double start = -1, stop = -1;
  for (std::size_t k = 0; k < t.size() && stop < 0; ++k) {
    const double vx = v.data[2 * k];
    if (start < 0 && vx < (1 - frac) * v0) start = t[k];
    if (start >= 0 && std::abs(vx - v_end) < frac * v0) stop = t[k];
  }
  return stop - start;
}

// Tyre buffer: the same 1 t boulder at 5 m/s on the concrete check dam without and with a 0.3 m
// damped rubber layer bonded to the face (examples/dam_boulder_*.json). The buffer must lower the peak base
// shear and moment and lengthen the load; neither run may create energy (balance <= +1 % of the input).
std::vector<CaseResult> tyre_buffer() {
  const CaseTimer timer;
  struct Peaks { double shear = 0, moment = 0, balance = -1e300, loaded = 0; };
  auto peaks = [](const RunOutput& out) {
    Peaks p;
    const auto& t = out.results.time;
    const Series& r = series(out.results, "supports/base/reaction");
    const Series& b = series(out.results, "energy/balance_error");
    for (std::size_t k = 0; k < t.size(); ++k) {
      p.shear = std::max(p.shear, std::abs(r.data[3 * k]));
      p.moment = std::max(p.moment, std::abs(r.data[3 * k + 2]));
      p.balance = std::max(p.balance, b.data[k]);
    }
    // The structure's free vibration after the boulder has left is not load.
    p.loaded = impact_duration(t, series(out.results, "probes/boulder/velocity"), 5.0, 0.02);
    return p;
  };
  const Peaks bare = peaks(run_quiet(example_scenario("dam_boulder_no_buffer.json")));
  const Peaks buf = peaks(run_quiet(example_scenario("dam_boulder_tyre_buffer.json")));
  const double input = 0.5 * 2650 * pi * 0.245 * 0.245 * 2.0 * 25;
  std::vector<CaseResult> r;
  auto below = [&](const std::string& m, double ratio, double limit) { r.push_back(bound_metric("tyre_buffer", m, "-", ratio, limit, false)); };
  below("peak base shear, buffer / bare (must be < 0.8)", buf.shear / bare.shear, 0.8);
  below("peak base moment, buffer / bare (must be < 0.8)", buf.moment / bare.moment, 0.8);
  below("impact duration, bare / buffer (must be < 1)", bare.loaded / buf.loaded, 1.0);
  below("energy created / input, bare (must be < 0.01)", std::max(0.0, bare.balance) / input, 0.01);
  below("energy created / input, buffer (must be < 0.01)", std::max(0.0, buf.balance) / input, 0.01);
  return stamp(r, timer.seconds());
}

// Buffer physics on a rigid wall (examples/buffer_pad_rigid_wall.json): a rock block on a rubber
// pad stuck to the wall. The pad is a rod (mass m_p, length t, modulus E' = E / (1 - nu^2), free edges in
// plane strain) carrying the block as tip mass M: beta tan(beta) = m_p / M, omega = beta c / t, contact
// time pi / omega, wall force M v omega / cos(beta) (Clough & Penzien 1993, 18-2). A damped pad returns
// the block with the restitution of a linear spring-dashpot contact that lets go when the force vanishes,
// e = exp(-zeta / sqrt(1 - zeta^2) (pi - atan(2 zeta sqrt(1 - zeta^2) / (1 - 2 zeta^2)))) (Schwager &
// Poschel 2007, Granular Matter 9, 465-469). The bare wall takes the block's elastic wave, rho c v A.
std::vector<CaseResult> buffer_pad() {
  const CaseTimer timer;
  const double v0 = 2.0, M = 2650 * 0.4 * 0.4, mp = 600 * 0.2 * 0.4, t = 0.2, A = 0.4;
  const double c = std::sqrt(5e6 / (1 - 0.09) / 600);
  double beta = std::sqrt(mp / M);
  for (int k = 0; k < 30; ++k) beta -= (beta * std::tan(beta) - mp / M) / (std::tan(beta) + beta / std::pow(std::cos(beta), 2));
  const double omega = beta * c / t, tc = pi / omega, f_pad = M * v0 * omega / std::cos(beta);
  struct Out { double peak = 0, duration = 0, e = 0, created = 0, dissipated = 0, lost = 0, impulse = 0, dp = 0; };
  auto measure = [&](const RunOutput& out) {
    Out o;
    const auto& tm = out.results.time;
    const Series& f = series(out.results, "walls/wall/force");
    const Series& v = series(out.results, "probes/block/velocity");
    const Series& bal = series(out.results, "energy/balance_error");
    const double v_end = v.data[2 * (tm.size() - 1)];
    for (std::size_t k = 0; k < tm.size(); ++k) {
      o.peak = std::max(o.peak, std::abs(f.data[2 * k]));
      o.created = std::max(o.created, bal.data[k]);
      if (k > 0) o.impulse += f.data[2 * k] * (tm[k] - tm[k - 1]);  // each step's force over that step
    }
    o.dp = M * (v0 - v_end);
    o.duration = impact_duration(tm, v, v0, 0.01);
    o.e = -v_end / v0;
    o.dissipated = series(out.results, "energy/dissipated").data.back();
    o.lost = 0.5 * M * (v0 * v0 - v_end * v_end);
    return o;
  };
  const Out pad = measure(run_quiet(example_scenario("buffer_pad_rigid_wall.json")));
  const double zeta = 0.2, s = std::sqrt(1 - zeta * zeta);
  const Out damped = measure(run_quiet(example_scenario("buffer_pad_rigid_wall.json", {{"/materials/1/damping_ratio", zeta},
                                                                                       {"/materials/1/damping_frequency", omega / (2 * pi)}})));
  const double e_sp = std::exp(-zeta / s * (pi - std::atan(2 * zeta * s / (1 - 2 * zeta * zeta))));
  nlohmann::json block = nlohmann::json::parse(embedded_examples().at("buffer_pad_rigid_wall.json"))["bodies"][1];
  block["shape"]["min"] = {-0.42, 0.0}, block["shape"]["max"] = {-0.02, 0.4};  // the same 0.02 m gap, now to the wall
  const Out bare = measure(run_quiet(example_scenario("buffer_pad_rigid_wall.json", {{"/bodies", nlohmann::json::array({block})},
                                                                                     {"/walls/0/condition", "slip"},
                                                                                     {"/analysis/end_time", 0.03}})));
  // The block made rigid: its contact with the pad sees its whole mass (RigidBodies::body_contact) and the step is the
  // pad's. Its compliance is ~2e-3 of the pad's (E A / L: 5e9 against 1e7 N/m per metre), the pad's time integration
  // at its own CFL ~1e-3: the wall force and contact time must be the elastic block's within 3 %.
  const Out rigid = measure(run_quiet(example_scenario("buffer_pad_rigid_wall.json", {{"/bodies/1/rigid", true}})));
  const double Mmod = 5e9 * 0.75 / (1.25 * 0.5);  // P-wave modulus of the block (plane strain)
  const double f_bare = 2650 * std::sqrt(Mmod / 2650) * v0 * A;
  const double input = 0.5 * M * v0 * v0;
  std::vector<CaseResult> r;
  // The pad stuck to the wall cannot bulge there, so it is stiffer than the free rod (E / (1 - nu^2)):
  // contact ~9 % shorter, force ~8 % higher at h = t / 10.
  r.push_back(metric("buffer_pad", "contact time, undamped pad", "ms", 1e3 * pad.duration, 1e3 * tc, 0.15));
  r.push_back(metric("buffer_pad", "peak wall force, undamped pad", "kN", pad.peak / 1e3, f_pad / 1e3, 0.15));
  r.push_back(bound_metric("buffer_pad", "restitution, undamped pad (must be > 0.9)", "-", pad.e, 0.9, true));
  r.push_back(metric("buffer_pad", "restitution, pad with 20 % damping", "-", damped.e, e_sp, 0.15));
  r.push_back(metric("buffer_pad", "viscous dissipation / block energy lost, damped pad", "-", damped.dissipated / damped.lost, 1.0, 0.15));
  // A square block is no bar: its free faces release the plane wave, so rho c v A (1D) bounds the peak.
  r.push_back(bound_metric("buffer_pad", "peak wall force bare / rho c v A (must be < 1.05)", "-", bare.peak / f_bare, 1.05, false));
  r.push_back(metric("buffer_pad", "wall impulse / block momentum change, bare", "-", bare.impulse / bare.dp, 1.0, 0.02));
  r.push_back(metric("buffer_pad", "wall impulse / block momentum change, undamped pad", "-", pad.impulse / pad.dp, 1.0, 0.05));
  r.push_back(bound_metric("buffer_pad", "peak force bare / pad (must be > 5)", "-", bare.peak / pad.peak, 5, true));
  r.push_back(bound_metric("buffer_pad", "contact time pad / bare (must be > 5)", "-", pad.duration / bare.duration, 5, true));
  r.push_back(metric("buffer_pad", "peak wall force, rigid block / elastic block", "-", rigid.peak / pad.peak, 1.0, 0.03));
  r.push_back(metric("buffer_pad", "contact time, rigid block / elastic block", "-", rigid.duration / pad.duration, 1.0, 0.03));
  r.push_back(metric("buffer_pad", "wall impulse / block momentum change, rigid block", "-", rigid.impulse / rigid.dp, 1.0, 0.05));
  for (const Out* o : {&pad, &damped, &bare, &rigid})
    r.push_back(bound_metric("buffer_pad", "energy created / input (must be < 0.01)", "-", std::max(0.0, o->created) / input, 0.01, false));
  return stamp(r, timer.seconds());
}

}  // namespace

std::vector<CaseResult> tyre_buffer_case() { return tyre_buffer(); }
std::vector<CaseResult> buffer_pad_case() { return buffer_pad(); }

}  // namespace dmi
