#include "engine/structure/fibre.hpp"

#include <algorithm>
#include <cmath>

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
  for (int k = 0; k < kFibres; ++k) {
    const double eta = -1 + 2.0 * k / (kFibres - 1), sigma = f.N / A - f.M * eta * c / I;
    const double shape = pipe ? std::sqrt(std::max(0.0, 1 - eta * eta)) : 1 - eta * eta;
    const double tau = r.tau_max * shape;
    r.von_mises_max = std::max(r.von_mises_max, std::sqrt(sigma * sigma + 3 * tau * tau));
  }
  return r;
}

}  // namespace dmi
