// Projection of a point on a member's deformed centre-line (replaces the paper's plain Newton
// search, Lin & Yang 2024, appendix, which slows down and can diverge under large deformation).
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

namespace dmi {

struct Projection {
  double xi = 0, dist2 = 0;  // parameter in [0, 1] and squared distance (m^2)
  int iterations = 0;        // Newton/bisection iterations used
};

// Closest point of the cubic Hermite centre-line c (plane ElementCurve or SpaceElementCurve: point, d1, d2) to x,
// xi in [0, 1] minimising |x(xi) - x|: the chord's closed form and five samples pick the start and a bracket; Newton
// on g(xi) = (x(xi) - x) . x'(xi), g' = |x'|^2 + (x(xi) - x) . x'', is safeguarded by bisection, so it never leaves
// the bracket and never diverges. Ends are clamped (a node beyond an element end projects on the end point).
template <class Curve> using CurvePoint = std::decay_t<decltype(std::declval<const Curve&>().point(0.0))>;
template <class Curve> Projection project_on_curve(const Curve& c, const CurvePoint<Curve>& x) {
  using Point = CurvePoint<Curve>;
  auto dist2 = [&](double s) { return (c.point(s) - x).squaredNorm(); };
  auto g = [&](double s) { return (c.point(s) - x).dot(c.d1(s)); };
  // Start: closed form on the chord, then the best of it and five samples.
  const Point p0 = c.point(0), chord = c.point(1) - p0;
  const double l2 = chord.squaredNorm();
  double best = l2 > 0 ? std::clamp((x - p0).dot(chord) / l2, 0.0, 1.0) : 0.0;
  double dbest = dist2(best);
  for (double s : {0.0, 0.25, 0.5, 0.75, 1.0}) {
    const double d = dist2(s);
    if (d < dbest) { dbest = d; best = s; }
  }
  // Bracket [a, b] around the start with g(a) < 0 < g(b), or an end minimum.
  double a = std::max(0.0, best - 0.25), b = std::min(1.0, best + 0.25);
  double ga = g(a), gb = g(b);
  Projection pr;
  if (ga >= 0 || gb <= 0) {  // monotone distance on [a, b]: the minimum is an end of it
    const double s = ga >= 0 ? a : b;
    pr.xi = dist2(s) < dbest ? s : best;
    pr.dist2 = dist2(pr.xi);
    return pr;
  }
  double s = std::clamp(best, a, b);
  const double tol = 1e-12;
  for (pr.iterations = 1; pr.iterations <= 60; ++pr.iterations) {
    const Point r = c.point(s) - x, t = c.d1(s);
    const double gs = r.dot(t), dg = t.squaredNorm() + r.dot(c.d2(s));
    if (gs < 0) a = s; else b = s;
    const double delta = dg > 0 ? gs / dg : std::numeric_limits<double>::infinity();
    if (std::abs(delta) < tol) break;  // converged (checked first: a zero step sits on the bracket's edge)
    double next = s - delta;
    if (!(next > a && next < b)) next = 0.5 * (a + b);  // Newton left the bracket: bisect
    s = next;
    if (b - a < tol) break;
  }
  pr.xi = s;
  pr.dist2 = dist2(s);
  if (pr.dist2 > dbest) {  // cannot happen for a true local minimum; keep the best sample
    pr.xi = best;
    pr.dist2 = dbest;
  }
  return pr;
}

}  // namespace dmi
