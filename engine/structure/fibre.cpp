#include "engine/structure/fibre.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace dmi {

FibreStresses fibre_stresses(const Section& section, double s, const SectionForces& f) {
  const double A = section.area(s), I = section.inertia(s), c = section.half_depth(s);
  const bool pipe = section.kind() == SectionKind::pipe;
  FibreStresses r;
  r.sigma_top = f.N / A - f.M * c / I;
  r.sigma_bottom = f.N / A + f.M * c / I;
  r.tau_max = section.shear_stress_factor() * std::abs(f.V) / A;
  r.von_mises_top = std::abs(r.sigma_top);
  r.von_mises_bottom = std::abs(r.sigma_bottom);
  constexpr int kFibres = 21;
  if (section.thin_walled() && !pipe) {  // box and I: Jourawski's shear stress, and the web's side of each flange
    const double yw = c - section.wall_thickness();
    const auto at = [&](double y) {
      const double sigma = f.N / A - f.M * y / I, tau = std::abs(f.V) * section.shear_flow_stress(s, y);
      r.von_mises_max = std::max(r.von_mises_max, std::sqrt(sigma * sigma + 3 * tau * tau));
    };
    for (int k = 0; k < kFibres; ++k) at((-1 + 2.0 * k / (kFibres - 1)) * c);
    at(yw * (1 - 1e-12)), at(-yw * (1 - 1e-12));
    return r;
  }
  for (int k = 0; k < kFibres; ++k) {
    const double eta = -1 + 2.0 * k / (kFibres - 1), sigma = f.N / A - f.M * eta * c / I;
    const double shape = pipe ? std::sqrt(std::max(0.0, 1 - eta * eta)) : 1 - eta * eta;
    const double tau = r.tau_max * shape;
    r.von_mises_max = std::max(r.von_mises_max, std::sqrt(sigma * sigma + 3 * tau * tau));
  }
  return r;
}

namespace {

// Box and I sections in a space frame: the normal stress at the outer corners and along the flanges' faces; the shear
// of V_y' carried by the web(s) (Jourawski, its peak at the axis) and of V_z' by the flanges (a box's flanges as the
// webs of the box turned a quarter; an I's two flanges as rectangles, 3/2 V_z' / (2 b t_f)).
template <class Sample>
void thin_walled_points(const Section& sec, double s, const SpaceSectionForces& f, Sample&& sample) {
  const double c = sec.half_depth(s), w = 0.5 * sec.width(s), tf = sec.wall_thickness(), tw = sec.web_thickness();
  const bool box = sec.kind() == SectionKind::box;
  const double tz = box ? std::abs(f.Vz) * Section::box(2 * c, 2 * w, tf).shear_stress_factor() / sec.area(s) : 0.75 * std::abs(f.Vz) / (2 * w * tf);
  const double zw = box ? w - 0.5 * tw : 0.0;  // the webs' mid-planes
  constexpr int kSide = 11;
  for (int k = 0; k < kSide; ++k) {
    const double eta = -1 + 2.0 * k / (kSide - 1);
    const double y = eta * (c - tf) * (1 - 1e-12), ty = std::abs(f.Vy) * sec.shear_flow_stress(s, y);
    sample(c, eta * w, tz * (1 - eta * eta)), sample(-c, eta * w, tz * (1 - eta * eta));
    sample(y, zw, ty), sample(y, -zw, ty);
  }
}

}  // namespace

SpaceFibreStresses space_fibre_stresses(const Section& section, double s, const SpaceSectionForces& f) {
  const double A = section.area(s), Iz = section.inertia(s), Iy = section.inertia_y(s);
  const double tau_t = std::abs(f.T) / section.torsion_modulus(s);
  SpaceFibreStresses r;
  r.principal_max = -INFINITY;
  r.sigma_max = -INFINITY;
  r.sigma_min = INFINITY;
  const auto sample = [&](double y, double z, double tau_v) {
    const double sigma = space_fibre_sigma(f, A, Iy, Iz, y, z), tau = tau_t + tau_v;
    const double vm = std::sqrt(sigma * sigma + 3 * tau * tau);
    r.sigma_max = std::max(r.sigma_max, sigma);
    r.sigma_min = std::min(r.sigma_min, sigma);
    r.tau_max = std::max(r.tau_max, tau);
    r.principal_max = std::max(r.principal_max, 0.5 * sigma + std::sqrt(0.25 * sigma * sigma + tau * tau));
    if (vm >= r.von_mises_max) r.von_mises_max = vm, r.y = y, r.z = z;
  };
  if (section.kind() == SectionKind::pipe) {
    const double R = 0.5 * section.depth(s), V = std::hypot(f.Vy, f.Vz), phi_v = std::atan2(f.Vz, f.Vy);
    constexpr int kPoints = 72;
    auto at = [&](double phi) { sample(R * std::cos(phi), R * std::sin(phi), 2 * V / A * std::abs(std::sin(phi - phi_v))); };
    for (int k = 0; k < kPoints; ++k) at(2 * std::numbers::pi * k / kPoints);
    const double phi_m = std::atan2(f.My, -f.Mz);  // Iy = Iz: sigma is extreme along the resultant moment's normal
    at(phi_m), at(phi_m + std::numbers::pi);
  } else if (section.thin_walled()) {
    thin_walled_points(section, s, f, sample);
  } else {
    const double c = section.half_depth(s), w = 0.5 * section.width(s);
    constexpr int kSide = 11;
    for (int k = 0; k < kSide; ++k) {
      const double eta = -1 + 2.0 * k / (kSide - 1);  // along each side
      const double ty = 1.5 * std::abs(f.Vy) / A, tz = 1.5 * std::abs(f.Vz) / A;
      sample(c, eta * w, tz * (1 - eta * eta));         // top and bottom faces: Vz's flow varies along them
      sample(-c, eta * w, tz * (1 - eta * eta));
      sample(eta * c, w, ty * (1 - eta * eta));         // side faces: Vy's
      sample(eta * c, -w, ty * (1 - eta * eta));
    }
  }
  return r;
}

}  // namespace dmi
