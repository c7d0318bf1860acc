// Section properties from dimensions (Gere & Goodno, Mechanics of Materials, App. E):
// rectangle A = b h, I = b h^3 / 12; circular hollow A = pi (D^2 - d^2) / 4, I = pi (D^4 - d^4) / 64,
// d = D - 2 t; the tapered rectangle uses the rectangle formulas with h(s) = h0 + s (h1 - h0). Box and I sections: the
// enclosing rectangle less the rectangle between the flanges beside the web(s) (square corners).
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

Section Section::box(double width, double depth, double wall_thickness) {
  require_positive(width, "width", "box");
  require_positive(depth, "depth", "box");
  require_positive(wall_thickness, "wall thickness", "box");
  if (!(2 * wall_thickness < std::min(width, depth)))
    throw std::invalid_argument("Section::box: walls of " + std::to_string(wall_thickness) + " m leave no hollow in " +
                                std::to_string(width) + " x " + std::to_string(depth) + " m");
  Section s;
  s.kind_ = SectionKind::box;
  s.b_ = width;
  s.h0_ = s.h1_ = depth;
  s.t_ = s.tw_ = wall_thickness;
  return s;
}

Section Section::i_section(double flange_width, double depth, double flange_thickness, double web_thickness) {
  require_positive(flange_width, "flange width", "i_section");
  require_positive(depth, "depth", "i_section");
  require_positive(flange_thickness, "flange thickness", "i_section");
  require_positive(web_thickness, "web thickness", "i_section");
  if (!(2 * flange_thickness < depth) || !(web_thickness < flange_width))
    throw std::invalid_argument("Section::i_section: flanges 2 x " + std::to_string(flange_thickness) + " m within a depth of " +
                                std::to_string(depth) + " m and a web of " + std::to_string(web_thickness) + " m narrower than the flanges (" +
                                std::to_string(flange_width) + " m) required");
  Section s;
  s.kind_ = SectionKind::i_section;
  s.b_ = flange_width;
  s.h0_ = s.h1_ = depth;
  s.t_ = flange_thickness;
  s.tw_ = web_thickness;
  return s;
}

namespace {
// The hollow beside the web(s): its width (b less the walls) and depth (h less the flanges); zero for solid sections.
struct Hollow {
  double width = 0, depth = 0;
};

Hollow hollow_of(SectionKind k, double b, double h, double t, double tw) {
  if (k == SectionKind::box) return {b - 2 * t, h - 2 * t};
  if (k == SectionKind::i_section) return {b - tw, h - 2 * t};
  return {};
}
}  // namespace

double Section::depth(double s) const {
  require_fraction(s);
  return h0_ + s * (h1_ - h0_);
}

double Section::width(double s) const {
  require_fraction(s);
  return kind_ == SectionKind::pipe ? h0_ : b_;
}

double Section::wall_thickness() const { return kind_ == SectionKind::pipe ? b_ : t_; }

double Section::web_thickness() const { return tw_; }

double Section::width_at(double s, double y) const {
  const Hollow o = hollow_of(kind_, b_, depth(s), t_, tw_);
  return std::abs(y) < 0.5 * o.depth ? b_ - o.width : b_;
}

double Section::first_moment_beyond(double s, double y) const {
  const double c = half_depth(s), a = std::min(std::abs(y), c);
  const Hollow o = hollow_of(kind_, b_, depth(s), t_, tw_);
  const double ch = 0.5 * o.depth;
  return 0.5 * (b_ * (c * c - a * a) - o.width * std::max(0.0, ch * ch - a * a));
}

double Section::area(double s) const {
  require_fraction(s);
  if (kind_ == SectionKind::pipe) {
    const double d = h0_ - 2 * b_;
    return 0.25 * std::numbers::pi * (h0_ * h0_ - d * d);
  }
  const Hollow o = hollow_of(kind_, b_, depth(s), t_, tw_);
  return b_ * depth(s) - o.width * o.depth;
}

double Section::inertia(double s) const {
  require_fraction(s);
  if (kind_ == SectionKind::pipe) {
    const double D2 = h0_ * h0_, d = h0_ - 2 * b_, d2 = d * d;
    return std::numbers::pi / 64 * (D2 * D2 - d2 * d2);
  }
  const double h = depth(s);
  const Hollow o = hollow_of(kind_, b_, h, t_, tw_);
  return (b_ * h * h * h - o.width * o.depth * o.depth * o.depth) / 12;
}

double Section::inertia_y(double s) const {
  require_fraction(s);
  if (kind_ == SectionKind::pipe) return inertia(s);
  const double h = depth(s);
  if (kind_ == SectionKind::box) return (h * b_ * b_ * b_ - (h - 2 * t_) * std::pow(b_ - 2 * t_, 3)) / 12;
  if (kind_ == SectionKind::i_section) return (2 * t_ * b_ * b_ * b_ + (h - 2 * t_) * tw_ * tw_ * tw_) / 12;
  return h * b_ * b_ * b_ / 12;
}

double Section::torsion_constant(double s) const {
  require_fraction(s);
  if (kind_ == SectionKind::pipe) return 2 * inertia(s);
  // Box: Bredt's thin-walled tube, J = 4 A_m^2 t / p_m on the walls' mid-line (A_m = (b - t)(h - t), p_m its perimeter);
  // I: the open thin-walled sum of b t^3 / 3 over the flanges and the web (Timoshenko & Goodier 1970, sec. 113-115).
  if (kind_ == SectionKind::box) {
    const double bm = b_ - t_, hm = depth(s) - t_;
    return 2 * t_ * bm * bm * hm * hm / (bm + hm);
  }
  if (kind_ == SectionKind::i_section) return (2 * b_ * t_ * t_ * t_ + (depth(s) - 2 * t_) * tw_ * tw_ * tw_) / 3;
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
  if (kind_ == SectionKind::box) return 2 * (b_ - t_) * (depth(s) - t_) * t_;  // Bredt: tau = T / (2 A_m t)
  if (kind_ == SectionKind::i_section) return J / std::max(t_, tw_);          // the thickest plate: tau = T t / J
  const double h = depth(s), b = std::max(b_, h), t = std::min(b_, h);
  double sum = 0;
  for (int n = 1; n < 40; n += 2) sum += 1 / (n * n * std::cosh(n * std::numbers::pi * b / (2 * t)));
  return J / ((1 - 8 / (std::numbers::pi * std::numbers::pi) * sum) * t);
}

double Section::shear_coefficient() const {
  if (kind_ == SectionKind::pipe) return 0.5;
  // EN 1993-1-1 6.2.6(3): a box of uniform walls A h / (b + h) (c), an I section its web h_w t_w (d).
  if (kind_ == SectionKind::box) return h0_ / (b_ + h0_);
  if (kind_ == SectionKind::i_section) return (h0_ - 2 * t_) * tw_ / area(0);
  return 5.0 / 6.0;
}

double Section::shear_stress_factor() const {
  if (kind_ == SectionKind::pipe) return 2.0;
  if (kind_ == SectionKind::rectangle || kind_ == SectionKind::tapered_rectangle) return 1.5;
  return shear_flow_stress(0, 0) * area(0);
}

double Section::shear_flow_stress(double s, double y) const {
  if (kind_ == SectionKind::pipe) {
    const double eta = std::min(1.0, std::abs(y) / half_depth(s));
    return 2 / area(s) * std::sqrt(1 - eta * eta);
  }
  return first_moment_beyond(s, y) / (inertia(s) * width_at(s, y));
}

double Section::plastic_modulus_y(double s) const {
  const double h = depth(s), b = b_;
  if (kind_ == SectionKind::pipe) return plastic_modulus(s);
  if (kind_ == SectionKind::box) return (h * b * b - (h - 2 * t_) * (b - 2 * t_) * (b - 2 * t_)) / 4;
  if (kind_ == SectionKind::i_section) return (2 * t_ * b * b + (h - 2 * t_) * tw_ * tw_) / 4;
  return h * b * b / 4;
}

double Section::plastic_modulus(double s) const {
  if (kind_ == SectionKind::pipe) {
    const double D = h0_, d = D - 2 * b_;
    return (D * D * D - d * d * d) / 6;
  }
  return 2 * first_moment_beyond(s, 0);
}

}  // namespace dmi
