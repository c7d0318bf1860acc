// Elasto-plastic fibre beam-columns: the steel law by hand, a fibre section's moment-curvature against the plastic
// moment and shape factor, a bar with a tip mass against the exact elastic-perfectly-plastic SDOF response to a
// rectangular pulse, the plastic collapse loads of a fixed-end beam and a portal frame (Neal 1977), and a space
// cantilever pipe under a skew load.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "engine/structure/fibre_beam.hpp"
#include "engine/structure/fibre_section.hpp"
#include "engine/structure/space_frame.hpp"
#include "verify/plastic_models.hpp"
#include "tests/engine/structure/beam_models.hpp"

namespace dmi {
namespace {

using test::Beam;
using test::rel;

TEST(SteelLaw, BilinearKinematicHardeningByHand) {
  const SteelLaw law{200e9, 250e6, 0.02};  // eps_y = 1.25e-3, E_t = 4 GPa, H = 4.0816 GPa
  FibreHistory h;
  FibreResponse r = bilinear_response(law, h, 1e-3);
  EXPECT_DOUBLE_EQ(r.sigma, 200e6);
  EXPECT_DOUBLE_EQ(r.tangent, 200e9);
  r = bilinear_response(law, h, 2.5e-3);  // 250 + 4 GPa (2.5e-3 - 1.25e-3) = 255 MPa
  EXPECT_NEAR(r.sigma, 255e6, 1e-3);
  EXPECT_NEAR(r.tangent, 4e9, 1e-3);
  h = r.history;                       // back stress 5 MPa: reversed yield at 255 - 500 = -245 MPa
  r = bilinear_response(law, h, 2.5e-3 - 2.45e-3);
  EXPECT_NEAR(r.sigma, 255e6 - 200e9 * 2.45e-3, 1e-3);  // -235 MPa: still elastic
  EXPECT_DOUBLE_EQ(r.tangent, 200e9);
  r = bilinear_response(law, h, -0.5e-3);  // reversed yield at -245 MPa reached at eps = 0, then E_t: -245 - 4 GPa 0.5e-3
  EXPECT_NEAR(r.sigma, -247e6, 1e-3);
  EXPECT_NEAR(r.tangent, 4e9, 1e-3);
}

// One element under constant curvature (v = [0, -theta, theta]: kappa = 2 theta / L everywhere), its end moment q_j = M.
double moment_at(const Section& s, double kappa, const SteelLaw& law) {
  const double L = 1;
  FibreBeam<1> b(s, 0, 1, L, law, 3);
  FibreBeam<1>::VecV v(0, -0.5 * kappa * L, 0.5 * kappa * L), q;
  b.respond(v, q, nullptr);
  return q(2);
}

TEST(FibreBeam, MomentCurvatureReachesThePlasticMoment) {
  const SteelLaw law{200e9, 355e6, 0.0};
  // Rectangle 0.1 x 0.2: I = b h^3 / 12, M_p = f_y b h^2 / 4, shape factor 1.5; M(kappa) = M_p (1 - (kappa_y/kappa)^2 / 3).
  const Section rect = Section::rectangle(0.1, 0.2);
  const double ky = law.fy / (law.E * 0.1), Mp = law.fy * 0.1 * 0.04 / 4, Mel = law.fy * rect.inertia(0) / 0.1;
  EXPECT_NEAR(moment_at(rect, 0.5 * ky, law) / (0.5 * law.E * rect.inertia(0) * ky), 1.0, 1e-12);  // elastic: EI exact
  EXPECT_NEAR(moment_at(rect, 3 * ky, law) / (Mp * (1 - 1.0 / 27)), 1.0, 2e-3);
  EXPECT_NEAR(moment_at(rect, 50 * ky, law) / Mp, 1.0, 2e-3);
  EXPECT_NEAR(Mp / Mel, 1.5, 1e-12);
  // CHS 0.5 x 0.016: M_p = f_y (D^3 - d^3) / 6 (EN 1993-1-1 W_pl); discretisation 2 rings x 32 fibres.
  const double D = 0.5, t = 0.016, d = D - 2 * t;
  const Section pipe = Section::pipe(D, t);
  const double Mp_pipe = law.fy * (D * D * D - d * d * d) / 6, ky_pipe = law.fy / (law.E * 0.5 * D);
  EXPECT_NEAR(moment_at(pipe, 0.5 * ky_pipe, law) / (0.5 * law.E * pipe.inertia(0) * ky_pipe), 1.0, 1e-12);
  EXPECT_NEAR(moment_at(pipe, 50 * ky_pipe, law) / Mp_pipe, 1.0, 2e-3);
}

// Box and I sections: their flanges and webs in cells at their rms coordinates carry E I exactly in the elastic range
// and W_pl f_y far past yield, in the plane and in space (about both axes).
TEST(FibreBeam, BoxAndISectionsReachTheirPlasticMoments) {
  const SteelLaw law{200e9, 355e6, 0.0};
  for (const Section& s : {Section::box(0.2, 0.3, 0.01), Section::i_section(0.2, 0.4, 0.016, 0.01)}) {
    const double ky = law.fy / (law.E * s.half_depth(0)), Mp = law.fy * s.plastic_modulus(0);
    EXPECT_NEAR(moment_at(s, 0.5 * ky, law) / (0.5 * law.E * s.inertia(0) * ky), 1.0, 1e-12);
    EXPECT_NEAR(moment_at(s, 50 * ky, law) / Mp, 1.0, 2e-3);
    const std::vector<Fibre> fibres = fibre_layout(s, 0, true);
    const double A = std::accumulate(fibres.begin(), fibres.end(), 0.0, [](double a, const Fibre& f) { return a + f.area; });
    EXPECT_NEAR(A / s.area(0), 1.0, 1e-12);
    double Iz = 0, Iy = 0;
    for (const Fibre& f : fibres) Iz += f.area * f.c[0] * f.c[0], Iy += f.area * f.c[1] * f.c[1];
    EXPECT_NEAR(Iz / s.inertia(0), 1.0, 1e-12);
    EXPECT_NEAR(Iy / s.inertia_y(0), 1.0, 1e-12);
    double Wy = 0;  // the fully plastic moment about y': sum |z'| A over the fibres
    for (const Fibre& f : fibres) Wy += std::abs(f.c[1]) * f.area;
    EXPECT_NEAR(Wy / s.plastic_modulus_y(0), 1.0, 2e-3);
  }
}

// Large reversing increments on a nearly perfectly plastic section (hardening 0.01 %): Newton's full steps cycle
// between two fibre branches here; the element state still converges, and its end moments stay at the plastic moment
// but for the hardening, whose back stress is at most b E times the strain range, 2 eps_peak.
TEST(FibreBeam, StateConvergesUnderLargeReversingIncrements) {
  const SteelLaw law{200e9, 250e6, 1e-4};
  const double h = 0.1, L = 0.1, ky = 2 * law.fy / (law.E * h), Mp = law.fy * h * h * h / 4;
  std::uint32_t seed = 1;
  auto unit = [&seed] { return (seed = seed * 1664525u + 1013904223u) / 2147483648.0 - 1.0; };  // in [-1, 1)
  for (int history = 0; history < 50; ++history) {
    FibreBeam<1> b(Section::rectangle(h, h), 0, 1, L, law, 5);
    for (int step = 0; step < 5; ++step) {
      const double axial = unit() * 1e-3 * L, theta_i = unit() * 20 * ky * L, theta_j = unit() * 20 * ky * L;  // in this order
      FibreBeam<1>::VecV v(axial, theta_i, theta_j), q;
      ASSERT_NO_THROW(b.respond(v, q, nullptr)) << "history " << history << ", step " << step;
      b.commit(v);
      const double hardening = 2 * law.hardening * law.E * b.record().peak_strain / law.fy;
      EXPECT_LE(std::max(std::abs(q(1)), std::abs(q(2))), (1 + hardening) * Mp * (1 + 1e-9));
      EXPECT_GT(std::max(std::abs(q(1)), std::abs(q(2))), 0.5 * Mp);  // far past first yield: at least M_y = 2/3 M_p
    }
  }
}

// The frame-level cases run the validate suite's models (verify/plastic_models.hpp) at a coarser setting.
TEST(FibreBeam, BarWithTipMassFollowsTheExactElasticPlasticSdof) {
  for (double ratio : {1.2, 1.5}) {
    const SdofPeak p = epp_bar_peak(ratio, 1000);
    EXPECT_LT(rel(p.computed, p.exact), 2e-3) << "F0/Ry " << ratio;
  }
}

TEST(FibreBeam, FixedEndBeamCollapseLoadAtEveryRefinement) {
  for (int n : {2, 8}) EXPECT_NEAR(fixed_beam_collapse_ratio(n), 1.0, 2e-3) << n << " elements";
}

TEST(FibreBeam, PortalFrameCollapsesByTheCombinedMechanism) { EXPECT_NEAR(portal_collapse_ratio(), 1.0, 6e-3); }

}  // namespace
}  // namespace dmi

namespace dmi {
namespace {

// A space cantilever pipe (D 0.3 m, t 10 mm, L 2 m) under a tip load at 45 degrees between its section axes: the root
// hinge forms under the resultant moment, P_c = M_p / L with M_p = f_y (D^3 - d^3) / 6 in any direction (a circle);
// springs at the tip (k = 3 EI / L^3 along y and z) carry it past collapse as in the fixed beam above.
TEST(FibreBeam, SpaceCantileverPipeYieldsUnderTheResultantMoment) {
  const double L = 2, D = 0.3, t = 0.01, d = D - 2 * t, E = 200e9, fy = 355e6;
  const double Mp = fy * (D * D * D - d * d * d) / 6, Pc = Mp / L;
  for (int n : {1, 4}) {
    SpaceFrameModel m;
    for (int k = 0; k <= n; ++k) m.nodes.push_back(Vec3(L * k / n, 0, 0));
    for (int k = 0; k < n; ++k) {
      SpaceElementDef e;
      e.i = k, e.j = k + 1, e.section = Section::pipe(D, t), e.E = E, e.nu = 0.3, e.rho = 7850, e.orientation = Vec3::UnitY();
      e.steel = SteelLaw{E, fy, 0.0};
      m.elements.push_back(e);
    }
    m.members = {{"cantilever", 0, n}};
    m.supports.push_back(SpaceSupportDef::fixed_support(0));
    const double ks = 3 * E * Section::pipe(D, t).inertia(0) / (L * L * L);
    SpaceSupportDef tip;
    tip.node = n;
    tip.spring[1] = tip.spring[2] = ks;
    m.supports.push_back(tip);
    SpaceFrame f(m);
    const double P = 11 * Pc;
    Vec6 load = Vec6::Zero();
    load(1) = load(2) = P / std::sqrt(2.0);
    f.add_nodal_load(n, load);
    f.solve_static(200);
    const Vec3 u = f.displacement().segment<3>(6 * n);
    const double resistance = P - ks * std::hypot(u(1), u(2));
    EXPECT_NEAR(resistance / Pc, 1.0, 2e-3) << n << " elements";
    EXPECT_NEAR(u(1), u(2), 1e-9 * std::abs(u(1)));
    EXPECT_GT(f.plastic_work(), 0);
  }
}

}  // namespace
}  // namespace dmi
