// Section properties from dimensions (Gere & Goodno, Mechanics of Materials, App. E):
// rectangle A = b h, I = b h^3 / 12; circular hollow A = pi (D^2 - d^2) / 4, I = pi (D^4 - d^4) / 64,
// d = D - 2 t; the tapered rectangle uses the rectangle formulas with h(s) = h0 + s (h1 - h0).
#include "engine/structure/section.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace dmi {
namespace {

void require_positive(double x, const char* what, const char* factory) {
  if (!(x > 0) || !std::isfinite(x))
    throw std::invalid_argument(std::string("Section::") + factory + ": " + what +
                                " must be positive and finite, got " + std::to_string(x));
}

void require_fraction(double s) {
  if (!(s >= 0 && s <= 1))
    throw std::invalid_argument("Section: position s = " + std::to_string(s) + " outside [0, 1]");
}

}  // namespace

Section Section::rectangle(double width, double depth) {
  require_positive(width, "width", "rectangle");
  require_positive(depth, "depth", "rectangle");
  Section s;
  s.kind_ = SectionKind::rectangle;
  s.b_ = width;
  s.h0_ = s.h1_ = depth;
  return s;
}

Section Section::pipe(double diameter, double wall_thickness) {
  require_positive(diameter, "diameter", "pipe");
  require_positive(wall_thickness, "wall thickness", "pipe");
  if (wall_thickness > 0.5 * diameter)
    throw std::invalid_argument("Section::pipe: wall thickness " + std::to_string(wall_thickness) +
                                " exceeds the radius " + std::to_string(0.5 * diameter));
  Section s;
  s.kind_ = SectionKind::pipe;
  s.b_ = wall_thickness;
  s.h0_ = s.h1_ = diameter;
  return s;
}

Section Section::tapered(double width, double depth_start, double depth_end) {
  require_positive(width, "width", "tapered");
  require_positive(depth_start, "depth_start", "tapered");
  require_positive(depth_end, "depth_end", "tapered");
  Section s;
  s.kind_ = SectionKind::tapered_rectangle;
  s.b_ = width;
  s.h0_ = depth_start;
  s.h1_ = depth_end;
  return s;
}

double Section::depth(double s) const {
  require_fraction(s);
  return h0_ + s * (h1_ - h0_);
}

double Section::width(double s) const {
  require_fraction(s);
  return kind_ == SectionKind::pipe ? h0_ : b_;
}

double Section::wall_thickness() const { return kind_ == SectionKind::pipe ? b_ : 0.0; }

double Section::area(double s) const {
  require_fraction(s);
  if (kind_ == SectionKind::pipe) {
    const double d = h0_ - 2 * b_;
    return 0.25 * std::numbers::pi * (h0_ * h0_ - d * d);
  }
  return b_ * depth(s);
}

double Section::inertia(double s) const {
  require_fraction(s);
  if (kind_ == SectionKind::pipe) {
    const double D2 = h0_ * h0_, d = h0_ - 2 * b_, d2 = d * d;
    return std::numbers::pi / 64 * (D2 * D2 - d2 * d2);
  }
  const double h = depth(s);
  return b_ * h * h * h / 12;
}

double Section::inertia_y(double s) const {
  require_fraction(s);
  if (kind_ == SectionKind::pipe) return inertia(s);
  return depth(s) * b_ * b_ * b_ / 12;
}

double Section::torsion_constant(double s) const {
  require_fraction(s);
  if (kind_ == SectionKind::pipe) return 2 * inertia(s);
  // J = t^3 b / 3 [1 - (192 / pi^5) (t / b) sum_{n odd} tanh(n pi b / (2 t)) / n^5], b >= t (Timoshenko & Goodier
  // 1970, eq. 159); the terms fall as n^-5, so 20 of them leave < 1e-9 of J.
  const double h = depth(s), b = std::max(b_, h), t = std::min(b_, h);
  double sum = 0;
  for (int n = 1; n < 40; n += 2) sum += std::tanh(n * std::numbers::pi * b / (2 * t)) / std::pow(n, 5);
  return t * t * t * b / 3 * (1 - 192 / std::pow(std::numbers::pi, 5) * (t / b) * sum);
}

double Section::torsion_modulus(double s) const {
  const double J = torsion_constant(s);
  if (kind_ == SectionKind::pipe) return J / (0.5 * h0_);
  const double h = depth(s), b = std::max(b_, h), t = std::min(b_, h);
  double sum = 0;
  for (int n = 1; n < 40; n += 2) sum += 1 / (n * n * std::cosh(n * std::numbers::pi * b / (2 * t)));
  return J / ((1 - 8 / (std::numbers::pi * std::numbers::pi) * sum) * t);
}

double Section::shear_coefficient() const { return kind_ == SectionKind::pipe ? 0.5 : 5.0 / 6.0; }

double Section::shear_stress_factor() const { return kind_ == SectionKind::pipe ? 2.0 : 1.5; }

}  // namespace dmi
