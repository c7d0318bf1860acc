#include "verify/plastic_models.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "engine/structure/fibre_beam.hpp"
#include "engine/structure/frame.hpp"

namespace dmi {
namespace {

constexpr double kE = 200e9;

FrameElementDef element(int i, int j, const Section& s, double fy, int member = 0, double hardening = 0) {
  FrameElementDef e;
  e.i = i, e.j = j, e.section = s, e.E = kE, e.nu = 0.3, e.rho = 7850, e.member = member;
  e.steel = SteelLaw{kE, fy, hardening};
  return e;
}

void fix(FrameModel& m, int node, bool ux, bool uy, bool rz) {
  FrameSupportDef s;
  s.node = node, s.fixed[0] = ux, s.fixed[1] = uy, s.fixed[2] = rz;
  m.supports.push_back(s);
}

double moment_ratio(const Section& s, double kappa_y, double Mp, double kappa_over_yield) {
  FibreBeam<1> b(s, 0, 1, 1.0, SteelLaw{kE, 355e6, 0.0}, 3);
  const double kappa = kappa_over_yield * kappa_y;
  FibreBeam<1>::VecV v(0, -0.5 * kappa, 0.5 * kappa), q;  // uniform curvature kappa = (theta_j - theta_i) / L
  b.respond(v, q, nullptr);
  return q(2) / Mp;
}

// The exact EPP SDOF (m, k, R_y) at rest under F0 for td: elastic arcs and plastic parabolas, marched by a step far
// below the period (closed forms within each step; the events found to that step).
double epp_exact_peak(double m, double k, double Ry, double F0, double td) {
  const double w = std::sqrt(k / m), dt = 1e-6 / w;
  double t = 0, x = 0, v = 0, xp = 0, peak = 0;
  bool plastic = false;
  while (t < td + 40 / w) {
    const double F = t < td ? F0 : 0.0;
    if (!plastic) {
      const double x0 = x - xp - F / k, c = std::cos(w * dt), s = std::sin(w * dt);
      const double vn = -x0 * w * s + v * c;
      x = xp + F / k + x0 * c + v / w * s, v = vn;
      if (k * (x - xp) > Ry && v > 0) plastic = true, xp = x - Ry / k;
    } else {
      const double a = (F - Ry) / m;
      x += v * dt + 0.5 * a * dt * dt, v += a * dt;
      xp = x - Ry / k;
      if (v <= 0) plastic = false;
    }
    t += dt;
    peak = std::max(peak, x);
    if (t > td && !plastic && v < 0 && x < peak) break;
  }
  return peak;
}

}  // namespace

double rectangle_moment_ratio(double b, double h, double r) {
  return moment_ratio(Section::rectangle(b, h), 355e6 / (kE * 0.5 * h), 355e6 * b * h * h / 4, r);
}

double section_moment_ratio(const Section& s, double r) {
  return moment_ratio(s, 355e6 / (kE * s.half_depth(0)), 355e6 * s.plastic_modulus(0), r);
}

double pipe_moment_ratio(double D, double t, double r) {
  const double d = D - 2 * t;
  return moment_ratio(Section::pipe(D, t), 355e6 / (kE * 0.5 * D), 355e6 * (D * D * D - d * d * d) / 6, r);
}

double fixed_beam_collapse_ratio(int n) {
  const double L = 2, fy = 355e6;
  const Section s = Section::rectangle(0.1, 0.2);
  FrameModel fm;
  for (int k = 0; k <= n; ++k) fm.nodes.push_back(Vec2(L * k / n, 0));
  for (int k = 0; k < n; ++k) fm.elements.push_back(element(k, k + 1, s, fy));
  fm.members = {{"beam", 0, n}};
  fix(fm, 0, true, true, true);
  fix(fm, n, true, true, true);
  const double ks = 192 * kE * s.inertia(0) / (L * L * L), Pc = 8 * fy * 0.1 * 0.04 / 4 / L;
  FrameSupportDef spring;
  spring.node = n / 2, spring.spring[1] = ks;
  fm.supports.push_back(spring);
  Frame f(fm);
  const double P = 21 * Pc;  // the spring takes 20 P_c: the centre deflects ~20 times the collapse deflection
  f.add_nodal_load(n / 2, Vec3(0, -P, 0));
  f.solve_static(400);
  return (P + ks * f.displacement()(3 * (n / 2) + 1)) / Pc;
}

namespace {
// The portal's sway at a load factor lambda / lambda_c, or +inf when no equilibrium is found.
double portal_sway(double ratio) {
  const double h = 4, L = 4, fy = 355e6, Mp = fy * 0.1 * 0.04 / 4, P = 0.75 * Mp * ratio;
  const Section s = Section::rectangle(0.1, 0.2);
  FrameModel fm;
  fm.nodes = {Vec2(0, 0), Vec2(0, h / 2), Vec2(0, h), Vec2(L / 2, h), Vec2(L, h), Vec2(L, h / 2), Vec2(L, 0)};
  for (int k = 0; k + 1 < 7; ++k) fm.elements.push_back(element(k, k + 1, s, fy, k / 2));
  fm.members = {{"left", 0, 2}, {"beam", 2, 2}, {"right", 4, 2}};
  fix(fm, 0, true, true, true);
  fix(fm, 6, true, true, true);
  try {
    Frame f(fm);
    f.add_nodal_load(2, Vec3(P, 0, 0));
    f.add_nodal_load(3, Vec3(0, -2 * P, 0));
    f.solve_static(200);
    return f.displacement()(6);
  } catch (const std::runtime_error&) {
    return INFINITY;
  }
}
}  // namespace

double portal_collapse_ratio() {
  const double elastic_sway = 0.0755;  // m near collapse; a sway 100 times larger has no equilibrium worth the name
  double lo = 0.9, hi = 1.1;
  for (int k = 0; k < 7; ++k) {
    const double mid = 0.5 * (lo + hi);
    (portal_sway(mid) < 100 * elastic_sway ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

SdofPeak epp_bar_peak(double ratio, int steps_per_period) {
  const double L = 1, A = 4e-4, fy = 250e6, m = 1000, k = kE * A / L, Ry = fy * A;
  const double T = 2 * std::numbers::pi * std::sqrt(m / k), dt = T / steps_per_period;
  FrameModel fm;
  fm.nodes = {Vec2(0, 0), Vec2(L, 0)};
  FrameElementDef e = element(0, 1, Section::rectangle(0.02, 0.02), fy);
  e.rho = 1e-3;  // a massless bar beside the tip mass
  fm.elements = {e};
  fm.members = {{"bar", 0, 1}};
  fix(fm, 0, true, true, true);
  fix(fm, 1, false, true, true);
  fm.masses = {{1, m, 0.0}};
  fm.integrator = FrameIntegrator::newmark;
  Frame f(fm);
  // Loads held over a step enter the average-acceleration rule as the mean of its end values: n steps under F0
  // impose a pulse of (n + 1/2) dt (the acceleration at t = 0 already feels F0).
  const int n = steps_per_period / 2;
  const double td = (n + 0.5) * dt, F0 = ratio * Ry;
  SdofPeak out;
  for (int s = 0; s < n + 3 * steps_per_period; ++s) {
    f.clear_loads();
    if (s < n) f.add_nodal_load(1, Vec3(F0, 0, 0));
    f.advance(dt);
    out.computed = std::max(out.computed, f.displacement()(3));
  }
  out.exact = epp_exact_peak(m, k, Ry, F0, td);
  return out;
}

ParkesResult parkes_cantilever(double gamma, double energy_ratio, int n, double hardening) {
  const double L = 1, b = 0.1, h = 0.1, fy = 250e6, rho = 7850;
  const double mL = rho * b * h, Mp = fy * b * h * h / 4, G = gamma * mL * L;
  // Elastic capacity: the tip load at first yield P_y = M_y / L, M_y = f_y b h^2 / 6, and its deflection P_y L^3 / 3EI.
  const double Py = fy * b * h * h / 6 / L, EI = kE * b * h * h * h / 12, Ue = 0.5 * Py * Py * L * L * L / (3 * EI);
  const double V0 = std::sqrt(2 * energy_ratio * Ue / G);
  FrameModel fm;
  for (int k = 0; k <= n; ++k) fm.nodes.push_back(Vec2(L * k / n, 0));
  for (int k = 0; k < n; ++k) fm.elements.push_back(element(k, k + 1, Section::rectangle(b, h), fy, 0, hardening));
  fm.members = {{"cantilever", 0, n}};
  fix(fm, 0, true, true, true);
  fm.masses = {{n, G, 0.0}};
  fm.integrator = FrameIntegrator::newmark;
  Frame f(fm);
  Eigen::VectorXd v = Eigen::VectorXd::Zero(3 * (n + 1));
  v(3 * n + 1) = -V0;
  f.set_velocity(v);
  ParkesResult out;
  out.kinetic = 0.5 * G * V0 * V0;
  out.elastic_at_collapse = Mp * Mp * L / (6 * EI);
  const double g = gamma;
  out.rigid_plastic = g * G * V0 * V0 * L / (3 * Mp) * (2 * std::log(1 + 1 / (2 * g)) + 1 / (1 + 2 * g));
  // Time: the rigid-plastic response ends at t = G V0 L / (M_p) (1 + ...) ~ twice its first phase; run to 4 times the
  // time the root hinge would need to absorb the energy at a constant M_p, then average the last elastic period.
  const double T_el = 2 * std::numbers::pi * std::sqrt((G + 0.24 * mL * L) * L * L * L / (3 * EI));
  const double t1 = G * V0 * L / (3 * Mp * (1 + 2 * gamma));  // the travelling hinge reaches the root
  const double t_end = 4 * G * V0 * L / Mp + 4 * T_el, dt = std::min(T_el / 200, t1 / 100);
  double sum = 0;
  int count = 0;
  for (double t = 0; t < t_end; t += dt) {
    f.advance(dt);
    if (t > t_end - T_el) sum += -f.displacement()(3 * n + 1), ++count;
  }
  out.computed = sum / count;
  out.plastic_work = f.plastic_work();
  return out;
}

double SwayHistory::peak() const { return sway.empty() ? NAN : *std::max_element(sway.begin(), sway.end()); }

double SwayHistory::residual(double period) const {
  double hi = -INFINITY, lo = INFINITY;
  for (std::size_t k = 0; k < t.size(); ++k)
    if (t[k] >= t.back() - 1.5 * period) hi = std::max(hi, sway[k]), lo = std::min(lo, sway[k]);
  return 0.5 * (hi + lo);
}

SwayHistory cantilever_pulse_sway(const CantileverPulse& p, int n) {
  FrameModel fm;
  const Section section = Section::rectangle(p.b, p.d);
  for (int k = 0; k <= n; ++k) fm.nodes.push_back(Vec2(p.L * k / n, 0));
  fm.nodes.push_back(Vec2(p.L + p.block_length, 0));
  for (int k = 0; k < n; ++k) {
    FrameElementDef e = element(k, k + 1, section, p.fy, 0, p.hardening);
    e.E = p.E, e.nu = p.nu, e.rho = p.rho, e.steel.E = p.E;
    fm.elements.push_back(e);
  }
  FrameElementDef block = element(n, n + 1, section, 0, 1);  // elastic
  block.E = p.E, block.nu = p.nu, block.rho = p.block_density(), block.steel = SteelLaw{};
  fm.elements.push_back(block);
  fm.members = {{"cantilever", 0, n}, {"block", n, 1}};
  fix(fm, 0, true, true, true);
  fm.integrator = FrameIntegrator::newmark;
  fm.transform = FrameTransform::corotational;
  fm.mass = MassMatrix::consistent;
  Frame f(fm);
  SwayHistory out;
  out.period = 2 * std::numbers::pi / f.natural_frequencies(1).front();
  const int steps = static_cast<int>(std::lround(p.duration / p.dt));
  for (int s = 1; s <= steps; ++s) {
    const double t = s * p.dt;
    f.clear_loads();
    // The push at the step's end (Newmark), across the block (-y'), per metre of it.
    f.add_distributed_load(n, Vec2(0, -p.load_factor(t) * p.peak_force / p.block_length));
    f.advance(p.dt);
    out.t.push_back(t), out.sway.push_back(-f.displacement()(3 * n + 1));
  }
  return out;
}

}  // namespace dmi
