// Material laws against closed forms: uniaxial strain increments, plane stress / plane strain,
// objectivity under rigid rotation, strain energy, Neo-Hookean plane stress.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/materials/material.hpp"
#include "engine/materials/mu_of_i.hpp"

namespace dmi {
namespace {

MaterialConfig elastic(const std::string& model, double E, double nu) {
  MaterialConfig c;
  c.name = "m";
  c.model = model;
  c.density = 1000;
  c.youngs_modulus = E;
  c.poisson_ratio = nu;
  return c;
}

template <int D> Particles<D> one_particle() {
  Particles<D> p;
  p.push(Vec<D>::Zero(), Vec<D>::Zero(), Vec<D>::Constant(0.1), 1.0, 1e-3, 0);
  return p;
}

template <int D> std::unique_ptr<Material<D>> make(const MaterialConfig& c, Plane plane) {
  MaterialRegistry<D> r;
  register_materials(r);
  return r.make(c, plane);
}

// Uniaxial strain eps_xx (all others zero): sigma_xx = (lambda + 2 mu) eps, sigma_yy = sigma_zz = lambda eps.
TEST(LinearElastic, UniaxialStrainPlaneStrainAnd3D) {
  const double E = 2e9, nu = 0.3, eps = 1e-4;
  const double lam = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  auto m2 = make<2>(elastic("linear_elastic", E, nu), Plane::strain);
  auto p2 = one_particle<2>();
  p2.L[0](0, 0) = eps / 1e-3;  // applied over dt = 1e-3 s
  m2->update(p2, 0, 1, 1e-3);
  EXPECT_NEAR(p2.stress[0](0, 0), (lam + 2 * mu) * eps, 1e-6 * E * eps);
  EXPECT_NEAR(p2.stress[0](1, 1), lam * eps, 1e-6 * E * eps);
  EXPECT_NEAR(p2.stress_zz[0], lam * eps, 1e-6 * E * eps);
  auto m3 = make<3>(elastic("linear_elastic", E, nu), Plane::none);
  auto p3 = one_particle<3>();
  p3.L[0](0, 0) = eps / 1e-3;
  m3->update(p3, 0, 1, 1e-3);
  EXPECT_NEAR(p3.stress[0](2, 2), lam * eps, 1e-6 * E * eps);
  // Strain energy of the uniaxial strain state: (lambda + 2 mu) eps^2 / 2 per volume.
  EXPECT_NEAR(m3->strain_energy(p3, 0, 1) / p3.vol[0], 0.5 * (lam + 2 * mu) * eps * eps, 1e-6 * E * eps * eps);
}

// Plane stress, strain (eps, -nu eps): sigma_xx = E eps, sigma_yy = 0, sigma_zz = 0.
TEST(LinearElastic, PlaneStressUniaxialStress) {
  const double E = 30e9, nu = 0.2, eps = 1e-5;
  auto m = make<2>(elastic("linear_elastic", E, nu), Plane::stress);
  auto p = one_particle<2>();
  p.L[0](0, 0) = eps;
  p.L[0](1, 1) = -nu * eps;
  m->update(p, 0, 1, 1.0);
  EXPECT_NEAR(p.stress[0](0, 0), E * eps, 1e-9 * E * eps);
  EXPECT_NEAR(p.stress[0](1, 1), 0.0, 1e-9 * E * eps);
  EXPECT_EQ(p.stress_zz[0], 0.0);
  EXPECT_NEAR(m->wave_speed(), std::sqrt(E / (1000 * (1 - nu * nu))), 1e-9);
}

// A rigid spin W rotates the stress (Jaumann rate): its invariants stay put over a quarter turn.
TEST(LinearElastic, JaumannRateIsObjective) {
  auto m = make<2>(elastic("linear_elastic", 1e9, 0.25), Plane::strain);
  auto p = one_particle<2>();
  p.stress[0] << 3e6, 1e6, 1e6, -2e6;
  const double tr0 = p.stress[0].trace(), det0 = p.stress[0].determinant();
  const int n = 20000;
  const double omega = 1.0, dt = (M_PI / 2) / omega / n;
  p.L[0] << 0, -omega, omega, 0;
  for (int i = 0; i < n; ++i) m->update(p, 0, 1, dt);
  EXPECT_NEAR(p.stress[0].trace(), tr0, 1e-9 * 3e6);
  EXPECT_NEAR(p.stress[0].determinant() / det0, 1.0, 1e-3);
  // A quarter turn swaps the normal stresses.
  EXPECT_NEAR(p.stress[0](0, 0), -2e6, 2e3);
  EXPECT_NEAR(p.stress[0](1, 1), 3e6, 2e3);
}

// Neo-Hookean reduces to linear elasticity for small strain, and plane stress has sigma_zz = 0.
TEST(NeoHookean, SmallStrainLimitAndPlaneStress) {
  const double E = 5e6, nu = 0.45, eps = 1e-6;
  auto m = make<2>(elastic("neo_hookean", E, nu), Plane::stress);
  auto p = one_particle<2>();
  p.F[0](0, 0) = 1 + eps;
  p.F[0](1, 1) = 1 - nu * eps;
  m->update(p, 0, 1, 0.0);
  EXPECT_NEAR(p.stress[0](0, 0) / (E * eps), 1.0, 1e-4);
  EXPECT_NEAR(p.stress[0](1, 1) / (E * eps), 0.0, 1e-4);
  EXPECT_NEAR(p.stress_zz[0], 0.0, 1e-9 * E);
  // Large stretch in plane strain: sigma = mu/J (B - I) + lambda ln J / J I.
  auto ms = make<2>(elastic("neo_hookean", E, nu), Plane::strain);
  auto q = one_particle<2>();
  q.F[0] << 1.5, 0, 0, 1;
  ms->update(q, 0, 1, 0.0);
  const double lam = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu)), J = 1.5;
  EXPECT_NEAR(q.stress[0](0, 0), mu / J * (J * J - 1) + lam * std::log(J) / J, 1e-9 * E);
  EXPECT_NEAR(q.stress_zz[0], lam * std::log(J) / J, 1e-9 * E);
  EXPECT_NEAR(q.vol[0], 1.5e-3, 1e-15);
  EXPECT_GT(ms->strain_energy(q, 0, 1), 0.0);
}

}  // namespace
}  // namespace dmi

namespace dmi {
namespace {

MaterialConfig dp(double c, double phi_deg, double psi_deg) {
  MaterialConfig m;
  m.name = "debris";
  m.model = "drucker_prager";
  m.density = 2000;
  m.youngs_modulus = 5e7;
  m.poisson_ratio = 0.3;
  m.cohesion = c;
  m.friction_angle = phi_deg;
  m.dilation_angle = psi_deg;
  return m;
}

// Pure shear (W = 0) at confining pressure p0, psi = 0: the shear stress rises elastically (mu gamma) and
// stays at the plane-strain Mohr-Coulomb match tau = k + alpha p0 with
// alpha = 3 tan(phi) / sqrt(9 + 12 tan^2 phi), k = 3 c / sqrt(9 + 12 tan^2 phi); p does not change; the
// plastic work is tau times the plastic shear strain.
TEST(DruckerPrager, PureShearPlateauAndPlasticWork) {
  const double c = 5e3, phi = 30, p0 = 2e4, rate = 1.0, dt = 1e-5;
  const double t = std::tan(phi * 3.14159265358979323846 / 180), m = 3 / std::sqrt(9 + 12 * t * t);
  const double tau_y = m * c + m * t * p0;
  auto mat = make<2>(dp(c, phi, 0), Plane::strain);
  auto p = one_particle<2>();
  p.stress[0] = -p0 * Mat<2>::Identity();
  p.stress_zz[0] = -p0;
  mat->attach(p, 0, 1);
  p.L[0] << 0, 0.5 * rate, 0.5 * rate, 0;  // engineering shear rate gamma_dot = rate
  const double mu = 5e7 / 2.6;
  const int steps = 4000;  // gamma = 0.04, yield at tau_y / mu ~ 1.1e-3
  for (int k = 0; k < steps; ++k) mat->update(p, 0, 1, dt);
  EXPECT_NEAR(p.stress[0](0, 1), tau_y, 1e-9 * tau_y);
  EXPECT_NEAR(p.stress[0].trace() + p.stress_zz[0], -3 * p0, 1e-9 * p0);
  const double gamma = steps * dt * rate, gamma_p = gamma - tau_y / mu;
  EXPECT_NEAR(mat->dissipated(), tau_y * gamma_p * 1e-3, 2e-3 * tau_y * gamma_p * 1e-3);  // volume 1e-3 m^3
}

// mu(I) (Jop, Forterre & Pouliquen 2006) in steady pure shear at pressure P = 2e4 Pa, d = 1 mm, rho_s = 2500:
// gamma_dot 500 1/s gives I = 500 * 1e-3 / sqrt(2e4 / 2500) = 0.176777, mu = 0.38 + 0.26 I / (0.279 + I) = 0.480843,
// above I_N1 = 0.019128 (hand-computed root of Barker & Gray's C, below): the shear stress settles at mu(I) P =
// 9 616.9 Pa with P unchanged. At 1e-3 1/s, I = 3.5355e-7 lies in the regularised range: A = I_N1 exp(1.9 / mu(I_N1)^2)
// = 3 353.97 (mu(I_N1) = 0.396682), mu = sqrt(1.9 / ln(A / I)) = 0.287585: the material creeps below mu_s; without
// the regularisation (alpha 0) it stands at mu_s P.
TEST(MuI, SteadyShearFollowsMuOfI) {
  MaterialConfig m = dp(0, 30, 0);
  m.model = "mu_i", m.mu_s = 0.38, m.mu_2 = 0.64, m.inertial_I0 = 0.279, m.grain_diameter = 1e-3, m.grain_density = 2500;
  const double P = 2e4;
  auto steady = [&](double rate, double alpha) {
    m.regularisation_alpha = alpha;
    auto mat = make<2>(m, Plane::strain);
    auto p = one_particle<2>();
    p.stress[0] = -P * Mat<2>::Identity();
    p.stress_zz[0] = -P;
    mat->attach(p, 0, 1);
    p.L[0] << 0, 0.5 * rate, 0.5 * rate, 0;
    const double dt = 4e-3 / rate;  // 4000 steps to a shear of 16 times the elastic yield strain
    for (int k = 0; k < 4000; ++k) mat->update(p, 0, 1, dt);
    EXPECT_NEAR(p.stress[0].trace() + p.stress_zz[0], -3 * P, 1e-9 * P);
    return p.stress[0](0, 1) / P;
  };
  EXPECT_NEAR(steady(500, 1.9), 0.480843, 1e-6);
  EXPECT_NEAR(steady(500, 0), 0.480843, 1e-6);
  EXPECT_NEAR(steady(1e-3, 1.9), 0.287585, 1e-6);
  EXPECT_NEAR(steady(1e-3, 0), 0.38, 1e-5);
}

// Barker & Gray's criterion for Jop's glass-bead constants: C > 0 (ill posed) below I_N1 = 0.019128 and above
// I_N2 = 0.86338, C < 0 between (hand-computed by bisection); the regularised branch joins Jop's law at I_N1.
TEST(MuI, RegularisationStartsWhereTheLawIsIllPosed) {
  MuOfI law{0.38, 0.64, 0.279};
  law.regularise(1.9);
  EXPECT_NEAR(law.I_N1, 0.019128, 1e-6);
  EXPECT_NEAR(law.C(law.I_N1), 0.0, 1e-12);
  EXPECT_GT(law.C(0.5 * law.I_N1), 0.0);
  EXPECT_LT(law.C(0.1), 0.0);
  EXPECT_GT(law.C(0.9), 0.0);  // the high-I range, left unregularised
  EXPECT_NEAR(law.mu(law.I_N1 * (1 - 1e-12)), law.jop(law.I_N1), 1e-9);
  EXPECT_NEAR(law.A, 3353.97, 0.01);
  EXPECT_DOUBLE_EQ(law.mu(0.1), law.jop(0.1));
  EXPECT_LT(law.mu(1e-9), 0.38);
  const double I = 1e-5, e = 1e-9;  // the slope used by the Newton step
  EXPECT_NEAR(law.slope(I), (law.mu(I * (1 + e)) - law.mu(I * (1 - e))) / (2 * e * I), 1e-5 * law.slope(I));
}

// Without pressure the grains separate: mu_i carries no stress when pulled apart.
TEST(MuI, NoPressureNoStress) {
  MaterialConfig m = dp(0, 30, 0);
  m.model = "mu_i", m.mu_s = 0.38, m.mu_2 = 0.64, m.inertial_I0 = 0.279, m.grain_diameter = 1e-3;
  auto mat = make<3>(m, Plane::none);
  auto p = one_particle<3>();
  mat->attach(p, 0, 1);
  p.L[0] = 1e-2 * Mat<3>::Identity();
  mat->update(p, 0, 1, 1e-3);
  EXPECT_LT(p.stress[0].norm(), 1e-9);
}

// Cohesionless material pulled apart cannot carry tension: it returns to the apex, zero stress, and
// the plastic flow at zero stress does no work.
TEST(DruckerPrager, CohesionlessCarriesNoTension) {
  auto mat = make<3>(dp(0, 35, 0), Plane::none);
  auto p = one_particle<3>();
  mat->attach(p, 0, 1);
  p.L[0] = 1e-2 * Mat<3>::Identity();
  mat->update(p, 0, 1, 1e-3);
  EXPECT_LT(p.stress[0].norm(), 1e-9);
  EXPECT_EQ(mat->dissipated(), 0.0);
}

// Kelvin-Voigt damping (beta = zeta / (pi f)): a uniaxial strain rate eps_dot adds the viscous stress
// beta (lambda + 2 mu) eps_dot and dissipates beta (lambda + 2 mu) eps_dot^2 V per unit time; the strain energy
// is the elastic part only.
TEST(LinearElastic, ViscousDampingStressAndDissipation) {
  MaterialConfig c = elastic("linear_elastic", 1e7, 0.25);
  c.damping_ratio = 0.05;
  c.damping_frequency = 10;
  const double beta = 0.05 / (3.14159265358979323846 * 10), lam = 4e6, mu = 4e6, rate = 0.1, dt = 1e-4;
  auto m = make<2>(c, Plane::strain);
  EXPECT_DOUBLE_EQ(m->damping_time(), beta);
  auto p = one_particle<2>();
  m->attach(p, 0, 1);
  p.L[0](0, 0) = rate;
  for (int k = 0; k < 10; ++k) m->update(p, 0, 1, dt);
  const double eps = 10 * dt * rate;
  EXPECT_NEAR(p.stress[0](0, 0), (lam + 2 * mu) * (eps + beta * rate), 1e-9 * (lam + 2 * mu) * eps);
  EXPECT_NEAR(m->dissipated(), 10 * dt * beta * (lam + 2 * mu) * rate * rate * 1e-3, 1e-9);
  EXPECT_NEAR(m->strain_energy(p, 0, 1), 0.5 * (lam + 2 * mu) * eps * eps * 1e-3, 1e-9 * (lam + 2 * mu) * eps * eps * 1e-3);
}

}  // namespace
}  // namespace dmi
