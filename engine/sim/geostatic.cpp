#include "engine/sim/geostatic.hpp"

#include <array>
#include <cmath>
#include <map>

#include "engine/common/error.hpp"

namespace dmi {

double earth_pressure_at_rest(const MaterialConfig& m, double given) {
  if (given >= 0) return given;
  if (m.model == "newtonian" || m.model == "bingham") return 1.0;
  if (m.model == "drucker_prager") return 1 - std::sin(m.friction_angle * M_PI / 180);
  if (m.model == "mu_i") return 1 - std::sin(std::atan(m.mu_s));
  return m.poisson_ratio / (1 - m.poisson_ratio);
}

template <int D> void geostatic_state(Scene<D>& sc, const Body& b, double K0, const std::string& file, const std::string& body_path) {
  const double g = sc.gravity.norm(), h = sc.grid->h();
  if (!(g > 0)) throw InputError(file, body_path + "/initial_stress", "\"geostatic\"", "a geostatic state under gravity (analysis.gravity is zero)");
  const Vec<D> down = sc.gravity / g;
  Particles<D>& P = sc.particles;
  // Column key: the particle's position across the gravity direction, in cells.
  auto key = [&](const Vec<D>& x) {
    const Vec<D> across = x - x.dot(down) * down;
    std::array<long, D> k{};
    for (int d = 0; d < D; ++d) k[d] = std::lround(std::floor(across[d] / h));
    return k;
  };
  std::map<std::array<long, D>, double> top;  // the column's highest upper edge, as a height -x . down
  for (Index i = b.begin; i < b.end; ++i) {
    const double z = -P.x[i].dot(down) + P.half_size[i].cwiseProduct(down).norm();
    auto [it, fresh] = top.emplace(key(P.x[i]), z);
    if (!fresh) it->second = std::max(it->second, z);
  }
  Material<D>& mat = *sc.materials[static_cast<std::size_t>(b.material)];
  const double rho = mat.density();
  Mat<3> nn = Mat<3>::Zero();
  for (int a = 0; a < D; ++a)
    for (int c = 0; c < D; ++c) nn(a, c) = down[a] * down[c];
  for (Index i = b.begin; i < b.end; ++i) {
    const double depth = std::max(0.0, top.at(key(P.x[i])) + P.x[i].dot(down));
    const double sv = -rho * g * depth, sh = K0 * sv;
    const Mat<3> sigma = sh * Mat<3>::Identity() + (sv - sh) * nn;
    if (!mat.prestress(P, i, sigma))
      throw InputError(file, body_path + "/initial_stress", "\"geostatic\"",
                       "stress_free for this body's material (its law takes its stress from the deformation, not from a given state)");
  }
}

template void geostatic_state<2>(Scene<2>&, const Body&, double, const std::string&, const std::string&);
template void geostatic_state<3>(Scene<3>&, const Body&, double, const std::string&, const std::string&);

}  // namespace dmi
