// Space frame (6 DOFs per node) against closed forms: a cantilever bent about both section axes and twisted
// (Roark's Formulas for Stress and Strain, 8th ed., tables 8.1 and 10.1), its Timoshenko shear deflection, the
// same cantilever turned to a skew direction, a simply supported beam under a uniform load across its width, a
// fixed-base portal swaying out of the x-y plane (slope-deflection), the first bending and torsional frequencies
// of a cantilever (Blevins, Formulas for Natural Frequency and Mode Shape, tables 8-1 and 9-2), Newmark energy
// conservation, the plane frame reproduced, and the input errors.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "engine/structure/space_frame.hpp"

namespace dmi {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double E = 30e9, nu = 0.2, rho = 2400;
constexpr double G = E / (2 * (1 + nu));

double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

// n elements from a to b, members of one section.
// Members along x take e2 = y unless told (the sections' depth along y, as the plane frame's).
SpaceFrameModel line(const Vec3& a, const Vec3& b, int n, const Section& s, const Vec3& orientation = Vec3::UnitY()) {
  SpaceFrameModel m;
  for (int k = 0; k <= n; ++k) m.nodes.push_back(a + (b - a) * (double(k) / n));
  for (int k = 0; k < n; ++k) {
    SpaceElementDef e;
    e.i = k, e.j = k + 1, e.section = s, e.E = E, e.nu = nu, e.rho = rho, e.orientation = orientation;
    m.elements.push_back(e);
  }
  return m;
}

// The rotation that takes global x to unit d and global y to the orientation's normal part.
Eigen::Matrix3d frame_of(const Vec3& d, const Vec3& o) {
  Eigen::Matrix3d R;
  const Vec3 e1 = d.normalized(), e2 = (o - o.dot(e1) * e1).normalized();
  R.col(0) = e1, R.col(1) = e2, R.col(2) = e1.cross(e2);
  return R;
}

TEST(SpaceFrameStatic, CantileverBentAboutBothAxesAndTwisted) {
  const double L = 2, b = 0.2, h = 0.4, Py = 1e4, Pz = 5e3, T = 2e3;
  const Section s = Section::rectangle(b, h);
  SpaceFrameModel m = line(Vec3::Zero(), Vec3(L, 0, 0), 4, s);
  m.supports.push_back(SpaceSupportDef::fixed_support(0));
  SpaceFrame f(m);
  Vec6 load;
  load << 0, Py, Pz, T, 0, 0;
  f.add_nodal_load(4, load);
  f.solve_static();
  const Eigen::VectorXd& d = f.displacement();
  const double Iz = s.inertia(0), Iy = s.inertia_y(0), J = s.torsion_constant(0);
  EXPECT_LT(rel(d(24 + 1), Py * L * L * L / (3 * E * Iz)), 1e-10);
  EXPECT_LT(rel(d(24 + 2), Pz * L * L * L / (3 * E * Iy)), 1e-10);
  EXPECT_LT(rel(d(24 + 3), T * L / (G * J)), 1e-10);
  EXPECT_LT(rel(d(24 + 5), Py * L * L / (2 * E * Iz)), 1e-10);   // rz: slope of u_y
  EXPECT_LT(rel(d(24 + 4), -Pz * L * L / (2 * E * Iy)), 1e-10);  // ry = -slope of u_z
  Vec6 r_expected;
  r_expected << 0, -Py, -Pz, -T, Pz * L, -Py * L;  // minus the loads and their moments about the root
  EXPECT_LT((f.reaction(0) - r_expected).norm(), 1e-6 * Py);
  // Root section: on the positive face Vy = Py, Vz = Pz, T, Mz = Py L, My = -Pz L; mid-length half the moments.
  const SpaceSectionForces r = f.forces_at(0, 0);
  EXPECT_NEAR(r.N, 0, 1e-6);
  EXPECT_LT(rel(r.Vy, Py), 1e-9);
  EXPECT_LT(rel(r.Vz, Pz), 1e-9);
  EXPECT_LT(rel(r.T, T), 1e-9);
  EXPECT_LT(rel(r.Mz, Py * L), 1e-9);
  EXPECT_LT(rel(r.My, -Pz * L), 1e-9);
  EXPECT_LT(rel(f.forces_at(1, 1).Mz, Py * L / 2), 1e-9);
  // Extreme fibre at the root: |Mz| c / Iz + |My| (b/2) / Iy at the corner (y' = +c, z' = -b/2 in tension).
  const SpaceFibreStresses st = f.stresses_at(0, 0);
  const double sigma = Py * L * (h / 2) / Iz + Pz * L * (b / 2) / Iy;
  EXPECT_LT(rel(st.sigma_max, sigma), 1e-9);
  EXPECT_LT(rel(st.sigma_min, -sigma), 1e-9);
  EXPECT_NEAR(std::abs(st.y), h / 2, 1e-12);  // the von Mises maximum sits at a corner
  EXPECT_NEAR(std::abs(st.z), b / 2, 1e-12);
  // Strain energy = half the work of the loads.
  EXPECT_LT(rel(f.strain_energy(), 0.5 * load.dot(d.segment<6>(24))), 1e-9);
  // The centre-line between nodes: the Hermite cubic is exact for end loads.
  const double x = 0.3 * L / 4;
  EXPECT_LT(rel(f.displacement_at(0, 0.3)(1), Py * x * x * (3 * L - x) / (6 * E * Iz)), 1e-9);
}

TEST(SpaceFrameStatic, TimoshenkoAddsTheShearDeflectionInBothPlanes) {
  const double L = 1, P = 1e5;
  const Section s = Section::rectangle(0.3, 0.5);
  SpaceFrameModel m = line(Vec3::Zero(), Vec3(L, 0, 0), 3, s);
  m.theory = BeamTheory::timoshenko;
  m.supports.push_back(SpaceSupportDef::fixed_support(0));
  SpaceFrame f(m);
  Vec6 load;
  load << 0, P, P, 0, 0, 0;
  f.add_nodal_load(3, load);
  f.solve_static();
  const double kGA = s.shear_coefficient() * G * s.area(0);
  EXPECT_LT(rel(f.displacement()(18 + 1), P * L * L * L / (3 * E * s.inertia(0)) + P * L / kGA), 1e-10);
  EXPECT_LT(rel(f.displacement()(18 + 2), P * L * L * L / (3 * E * s.inertia_y(0)) + P * L / kGA), 1e-10);
}

TEST(SpaceFrameStatic, ASkewCantileverGivesTheSameLocalResponse) {
  const double L = 3, P = 2e4, T = 5e3;
  const Section s = Section::tapered(0.25, 0.6, 0.3);
  const Vec3 dir = Vec3(1, 2, -1.5).normalized(), o = Vec3(0.3, -0.2, 1);
  const Eigen::Matrix3d R = frame_of(dir, o);
  SpaceFrameModel ref = line(Vec3::Zero(), Vec3(L, 0, 0), 6, s), skew = line(Vec3(1, 2, 3), Vec3(1, 2, 3) + L * dir, 6, s, o);
  for (std::size_t e = 0; e < ref.elements.size(); ++e) {  // the taper runs along the member
    ref.elements[e].s0 = skew.elements[e].s0 = e / 6.0;
    ref.elements[e].s1 = skew.elements[e].s1 = (e + 1) / 6.0;
  }
  for (SpaceFrameModel* m : {&ref, &skew}) m->supports.push_back(SpaceSupportDef::fixed_support(0));
  SpaceFrame a(ref), b(skew);
  const Vec3 F(0.3 * P, P, -0.7 * P), M(T, -0.2 * T, 0.4 * T);  // in the member's axes
  Vec6 la, lb;
  la << F, M;
  lb << R * F, R * M;
  a.add_nodal_load(6, la);
  b.add_nodal_load(6, lb);
  a.add_distributed_load(2, Vec3(100, -2e3, 3e3));
  b.add_distributed_load(2, Vec3(100, -2e3, 3e3));
  a.solve_static();
  b.solve_static();
  const Vec3 ua = a.displacement().segment<3>(36), ub = R.transpose() * b.displacement().segment<3>(36);
  const Vec3 ta = a.displacement().segment<3>(39), tb = R.transpose() * b.displacement().segment<3>(39);
  EXPECT_LT((ua - ub).norm(), 1e-9 * ua.norm());
  EXPECT_LT((ta - tb).norm(), 1e-9 * ta.norm());
  EXPECT_LT((b.axes(3) - R.transpose()).norm(), 1e-12);
  for (double xi : {0.0, 0.4, 1.0}) {
    const SpaceSectionForces fa = a.forces_at(2, xi), fb = b.forces_at(2, xi);
    for (auto [x, y] : {std::pair{fa.N, fb.N}, {fa.Vy, fb.Vy}, {fa.Vz, fb.Vz}, {fa.T, fb.T}, {fa.My, fb.My}, {fa.Mz, fb.Mz}})
      EXPECT_NEAR(x, y, 1e-8 * P * L);
  }
}

TEST(SpaceFrameStatic, SimplySupportedBeamUnderLoadAcrossItsWidthAndSelfWeight) {
  const double L = 6, w = 4e3;
  const Section s = Section::rectangle(0.3, 0.6);
  SpaceFrameModel m = line(Vec3::Zero(), Vec3(L, 0, 0), 8, s);
  m.gravity = Vec3(0, -9.81, 0);
  SpaceSupportDef a = SpaceSupportDef::pinned(0), b;
  a.fixed[3] = true;  // torsion held at one end
  b.node = 8, b.fixed[1] = b.fixed[2] = true;
  m.supports = {a, b};
  SpaceFrame f(m);
  for (int e = 0; e < 8; ++e) f.add_distributed_load(e, Vec3(0, 0, w));  // along e3 = global z
  f.solve_static();
  const double q = rho * s.area(0) * 9.81;
  EXPECT_LT(rel(f.displacement()(24 + 2), 5 * w * L * L * L * L / (384 * E * s.inertia_y(0))), 1e-10);
  EXPECT_LT(rel(f.displacement()(24 + 1), -5 * q * L * L * L * L / (384 * E * s.inertia(0))), 1e-10);
  EXPECT_LT(rel(f.forces_at(3, 1).My, w * L * L / 8), 1e-9);  // sagging towards +z: tension at z' > 0, My > 0
  EXPECT_LT(rel(f.forces_at(3, 1).Mz, q * L * L / 8), 1e-9);
  EXPECT_LT(rel(f.forces_at(1, 0.5).Vz, w * (L / 2 - 1.5 * L / 8)), 1e-9);  // inside an element: the particular solution
  EXPECT_LT(rel(f.reaction(1)(2), -w * L / 2), 1e-9);
  EXPECT_LT(rel(f.reaction(0)(1), q * L / 2), 1e-9);
}

// Fixed-base portal in the y-z plane (columns along y at z = 0 and z = Lb, beam along z), swayed along z by H:
// slope-deflection with i_c = E I_c / h, i_b = E I_b / Lb gives Delta = H h^2 (2 i_c + 3 i_b) / (12 i_c (i_c + 6 i_b)),
// axial deformation neglected: the columns' shortening under the overturning pair tilts the beam and adds a share
// of order (column width / Lb)^2, ~ 1e-4 here.
TEST(SpaceFrameStatic, PortalSwaysOutOfThePlaneAsSlopeDeflection) {
  const double h = 3, Lb = 16, H = 5e4;
  const Section col = Section::rectangle(0.2, 0.5), beam = Section::rectangle(0.3, 0.6);
  SpaceFrameModel m;
  const int n = 4;
  for (int k = 0; k <= n; ++k) m.nodes.push_back(Vec3(0, h * k / n, 0));             // 0..4 left column
  for (int k = 1; k <= n; ++k) m.nodes.push_back(Vec3(0, h, Lb * k / n));            // 5..8 beam
  for (int k = n - 1; k >= 0; --k) m.nodes.push_back(Vec3(0, h * k / n, Lb));        // 9..12 right column, down
  for (int k = 0; k < 3 * n; ++k) {
    SpaceElementDef e;
    e.i = k, e.j = k + 1, e.section = (k >= n && k < 2 * n) ? beam : col, e.E = E, e.nu = nu, e.rho = rho;
    e.orientation = (k >= n && k < 2 * n) ? Vec3(0, 1, 0) : Vec3(-1, 0, 0);
    m.elements.push_back(e);
  }
  m.supports = {SpaceSupportDef::fixed_support(0), SpaceSupportDef::fixed_support(3 * n)};
  SpaceFrame f(m);
  Vec6 load;
  load << 0, 0, H, 0, 0, 0;
  f.add_nodal_load(n, load);
  f.solve_static();
  // Columns along y with e2 = -x: bending towards z is about e2 (inertia_y); the beam along z with e2 = y: its joints
  // turn it about e3 = -x (inertia).
  const double ic = E * col.inertia_y(0) / h, ib = E * beam.inertia(0) / Lb;
  const double delta = H * h * h * (2 * ic + 3 * ib) / (12 * ic * (ic + 6 * ib));
  // The beam carries H / 2 in compression: the two tops differ by its shortening H Lb / (2 E A_b); their mean sways.
  const double left = f.displacement()(6 * n + 2), right = f.displacement()(6 * 2 * n + 2);
  EXPECT_LT(rel(0.5 * (left + right), delta), 1e-3);
  EXPECT_LT(rel(left - right, H * Lb / (2 * E * beam.area(0))), 0.02);
  // Global equilibrium: the reactions' forces and their moments about the left base balance H and its moment.
  const Vec6 r0 = f.reaction(0), r1 = f.reaction(1);
  EXPECT_NEAR(r0(2) + r1(2), -H, 1e-6 * H);
  const Vec3 moment = r0.tail<3>() + r1.tail<3>() + Vec3(0, 0, Lb).cross(Vec3(r1.head<3>())) + Vec3(0, h, 0).cross(Vec3(0, 0, H));
  EXPECT_LT(moment.norm(), 1e-6 * H * h);
}

// Errors at 4, 8 and 16 elements and their observed order: Hermite bending with consistent mass converges as h^4,
// with lumped mass as h^2; the linear torsion elements as h^2 (the rod's (k h)^2 / 24).
TEST(SpaceFrameDynamics, BendingAndTorsionalFrequenciesConvergeAtTheirOrders) {
  const double L = 5;
  const Section pipe = Section::pipe(0.5, 0.02), rect = Section::rectangle(0.3, 0.5);
  for (MassMatrix mass : {MassMatrix::consistent, MassMatrix::lumped}) {
    for (const Section& s : {pipe, rect}) {
      const double rA = rho * s.area(0), b1 = 1.875104068711961 * 1.875104068711961;
      const double exact[3] = {b1 * std::sqrt(E * s.inertia(0) / (rA * L * L * L * L)), b1 * std::sqrt(E * s.inertia_y(0) / (rA * L * L * L * L)),
                               kPi / (2 * L) * std::sqrt(G * s.torsion_constant(0) / (rho * (s.inertia(0) + s.inertia_y(0))))};
      double err[3][3];
      for (int r = 0; r < 3; ++r) {
        SpaceFrameModel m = line(Vec3::Zero(), Vec3(L, 0, 0), 4 << r, s);
        m.mass = mass;
        m.supports.push_back(SpaceSupportDef::fixed_support(0));
        const std::vector<double> w = SpaceFrame(m).natural_frequencies(8);
        for (int k = 0; k < 3; ++k) {  // the mode nearest each closed form
          double best = INFINITY;
          for (double x : w) best = std::min(best, std::abs(x - exact[k]) / exact[k]);
          err[k][r] = best;
        }
      }
      const double p_bend = mass == MassMatrix::consistent ? 4 : 2;
      for (int k = 0; k < 3; ++k) {
        const double order = std::log2(err[k][1] / err[k][2]), expected = k < 2 ? p_bend : 2;
        EXPECT_NEAR(order, expected, 0.3) << "mode " << k << " errors " << err[k][0] << " " << err[k][1] << " " << err[k][2];
      }
    }
  }
}

TEST(SpaceFrameDynamics, NewmarkConservesEnergyInFreeVibration) {
  const Section s = Section::pipe(0.4, 0.015);
  SpaceFrameModel m = line(Vec3::Zero(), Vec3(0, 4, 0), 8, s, Vec3::UnitX());
  m.integrator = FrameIntegrator::newmark;
  m.supports.push_back(SpaceSupportDef::fixed_support(0));
  SpaceFrame f(m);
  Vec6 load;
  load << 1e4, 0, 2e4, 3e3, 0, 0;
  f.add_nodal_load(8, load);
  f.solve_static();
  const double e0 = f.strain_energy();
  f.clear_loads();
  const double w1 = f.natural_frequencies(1)[0];
  for (int k = 0; k < 400; ++k) f.advance(2 * kPi / w1 / 100);
  EXPECT_LT(rel(f.kinetic_energy() + f.strain_energy(), e0), 1e-9);
}

TEST(SpaceFrameDynamics, ExplicitStepFollowsOmegaMaxAndStaysBounded) {
  const Section s = Section::rectangle(0.2, 0.3);
  SpaceFrameModel m = line(Vec3::Zero(), Vec3(3, 0, 0), 6, s);
  m.supports.push_back(SpaceSupportDef::fixed_support(0));
  SpaceFrame f(m);
  const std::vector<double> w = f.natural_frequencies(6 * 6);
  EXPECT_LT(rel(f.stable_time_step(), 2 / w.back()), 1e-9);
  Vec6 load;
  load << 0, 1e4, 1e4, 1e3, 0, 0;
  f.add_nodal_load(6, load);
  for (int k = 0; k < 2000; ++k) f.advance(0.9 * f.stable_time_step());
  // Under a suddenly applied constant load the energy is bounded by the work at twice the static deflection.
  EXPECT_LT(f.kinetic_energy() + f.strain_energy(), 1.05 * f.external_work() + 1e-12);
  EXPECT_TRUE(f.displacement().allFinite());
}

// An in-plane frame in the x-y plane: the space frame gives the plane frame's displacements and forces.
TEST(SpaceFrameStatic, ReproducesThePlaneFrameInItsPlane) {
  const Section s = Section::tapered(0.3, 0.8, 0.4);
  FrameModel p;
  SpaceFrameModel q;
  const Vec2 pts[4] = {{0, 0}, {0.5, 2}, {1.5, 3.5}, {4, 3.5}};
  for (const Vec2& x : pts) p.nodes.push_back(x), q.nodes.push_back(Vec3(x.x(), x.y(), 0));
  for (int k = 0; k < 3; ++k) {
    FrameElementDef e;
    e.i = k, e.j = k + 1, e.section = s, e.s0 = k / 3.0, e.s1 = (k + 1) / 3.0, e.E = E, e.nu = nu, e.rho = rho;
    p.elements.push_back(e);
    SpaceElementDef g;
    g.i = k, g.j = k + 1, g.section = s, g.s0 = e.s0, g.s1 = e.s1, g.E = E, g.nu = nu, g.rho = rho;
    g.orientation = Vec3::UnitZ().cross(q.nodes[k + 1] - q.nodes[k]);  // the plane frame's e2
    q.elements.push_back(g);
  }
  p.theory = q.theory = BeamTheory::timoshenko;
  p.gravity = Vec2(0, -9.81), q.gravity = Vec3(0, -9.81, 0);
  FrameSupportDef a;
  a.node = 0, a.fixed[0] = a.fixed[1] = a.fixed[2] = true;
  p.supports.push_back(a);
  q.supports.push_back(SpaceSupportDef::fixed_support(0));
  Frame pf(p);
  SpaceFrame sf(q);
  pf.add_nodal_load(3, Vec3(1e4, -2e4, 5e3));
  Vec6 l;
  l << 1e4, -2e4, 0, 0, 0, 5e3;
  sf.add_nodal_load(3, l);
  pf.add_distributed_load(1, Vec2(1e3, -4e3));
  sf.add_distributed_load(1, Vec3(1e3, -4e3, 0));
  pf.solve_static();
  sf.solve_static();
  for (int n = 1; n < 4; ++n) {
    EXPECT_NEAR(pf.displacement()(3 * n), sf.displacement()(6 * n), 1e-12);
    EXPECT_NEAR(pf.displacement()(3 * n + 1), sf.displacement()(6 * n + 1), 1e-12);
    EXPECT_NEAR(pf.displacement()(3 * n + 2), sf.displacement()(6 * n + 5), 1e-12);
    EXPECT_NEAR(sf.displacement()(6 * n + 2), 0, 1e-15);
  }
  for (double xi : {0.0, 0.5, 1.0}) {
    const SectionForces a2 = pf.forces_at(1, xi);
    const SpaceSectionForces a3 = sf.forces_at(1, xi);
    EXPECT_NEAR(a2.N, a3.N, 1e-6);
    EXPECT_NEAR(a2.M, a3.Mz, 1e-6);
    EXPECT_NEAR(a2.V, -a3.Vy, 1e-6);
  }
  // The in-plane modes are among the space frame's (lumped masses: rz takes the plane element's rotary inertia).
  const std::vector<double> w3 = sf.natural_frequencies(12);
  for (double w2 : pf.natural_frequencies(3)) {
    double best = INFINITY;
    for (double x : w3) best = std::min(best, std::abs(x - w2) / w2);
    EXPECT_LT(best, 1e-9) << w2;
  }
}

TEST(SpaceFrameStatic, RejectsInvalidModelsNamingTheCulprit) {
  const Section s = Section::rectangle(0.2, 0.3);
  SpaceFrameModel m = line(Vec3::Zero(), Vec3(0, 2, 0), 2, s, Vec3(0, 1, 0));
  m.supports.push_back(SpaceSupportDef::fixed_support(0));
  try {
    SpaceFrame f(m);
    FAIL() << "orientation along the member accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("element 0: the orientation vector is parallel"), std::string::npos) << e.what();
  }
  m = line(Vec3::Zero(), Vec3(2, 0, 0), 2, s);
  SpaceSupportDef a = SpaceSupportDef::pinned(0), b = SpaceSupportDef::pinned(2);
  m.supports = {a, b};  // free to spin about its own axis
  try {
    SpaceFrame f(m);
    FAIL() << "mechanism accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("mechanism: no stiffness against rx"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace dmi
