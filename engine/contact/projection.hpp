// Projection of a point on a member's deformed centre-line (replaces the paper's plain Newton
// search, Lin & Yang 2024, appendix, which slows down and can diverge under large deformation).
#pragma once
#include "engine/structure/frame.hpp"

namespace dmi {

struct Projection {
  double xi = 0, dist2 = 0;  // parameter in [0, 1] and squared distance (m^2)
  int iterations = 0;        // Newton/bisection iterations used
};

// Closest point of the cubic Hermite centre-line c to x, xi in [0, 1] minimising |x(xi) - x|:
// the chord's closed form and five samples pick the start and a bracket; Newton on
// g(xi) = (x(xi) - x) . x'(xi), g' = |x'|^2 + (x(xi) - x) . x'', is safeguarded by bisection, so it
// never leaves the bracket and never diverges. Ends are clamped (a node beyond an element end
// projects on the end point).
Projection project_on_curve(const ElementCurve& c, const Vec2& x);

}  // namespace dmi
