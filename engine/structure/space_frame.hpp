// A 3D beam-column (space) frame: nodes with 6 DOFs (ux, uy, uz, rx, ry, rz), elements made of a basic system
// (space_element.hpp: axial force, end moments about both section axes and torque, against chord deformations, free
// of rigid modes) and a coordinate transformation (linear; corotational in space_transform.hpp), supports with any
// of the 6 DOFs fixed or on springs, end releases, nodal masses, lumped or consistent mass, and the plane frame's
// time integrators (explicit, Lin & Yang 2024 eqs. 27-29, or Newmark/HHT), shared through AssembledSystem.
//
// Axes. The scenario's (docs/scenario.md: in 3D z is up; by the presets' convention x along the flow, y across the
// channel). Element local axes: e1 from node i to node j; e2 the section's depth direction (Section::depth, bending
// about e3 uses Section::inertia); e3 = e1 x e2 the width direction (bending about e2 uses Section::inertia_y). e2 is
// the part of the element's orientation vector normal to e1; by default the vertical (global z: a beam's depth is
// vertical) and global x for a vertical member (a column's depth along the flow), so a member in the x-z plane bends
// in that plane as the plane frame's members do in theirs (the plane analysis's y is 3D's z).
// Section forces at a point, on the positive face (the part towards node i acted on by the part towards j), as
// vectors along the local axes: N (tension +), Vy, Vz, T, My, Mz. Fibre stress at (y', z') of the section
// sigma = N/A - Mz y'/Iz + My z'/Iy (Gere & Goodno, Mechanics of Materials, sec. 6.5). Mz equals the plane
// frame's M; its V is -Vy.
#pragma once
#include <Eigen/Dense>
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/common/state_io.hpp"
#include "engine/structure/damping.hpp"
#include "engine/structure/fibre.hpp"
#include "engine/structure/frame.hpp"
#include "engine/structure/section.hpp"

namespace dmi {

using Vec6 = Eigen::Matrix<double, 6, 1>;

struct SpaceElementDef {
  int i = 0, j = 0;               // node indices
  Section section = Section::rectangle(1, 1);
  double s0 = 0.0, s1 = 1.0;      // the element's span as fractions of its member's section taper
  double E = 0, nu = 0, rho = 0;  // Pa, -, kg/m^3
  bool release_i = false, release_j = false;  // both bending moments released (a ball joint) at the element ends
  Vec3 orientation = Vec3::Zero();  // hint for e2 (zero: the default of the header: global z, or x for a vertical member)
  int member = 0;                 // index into SpaceFrameModel::members
  // Elasto-plastic fibre element (fibre_beam.hpp) when steel.fy > 0, with integration_points Gauss-Lobatto sections;
  // elastic otherwise. A plastic element carries no moment release.
  SteelLaw steel;                 // its E is the element's
  int integration_points = 5;
};

struct SpaceSupportDef {
  int node = 0;
  bool fixed[6] = {false, false, false, false, false, false};  // ux, uy, uz, rx, ry, rz restrained
  double spring[6] = {0, 0, 0, 0, 0, 0};                       // N/m and N m/rad, to ground
  static SpaceSupportDef fixed_support(int node);   // all six restrained
  static SpaceSupportDef pinned(int node);          // translations restrained, rotations free
};

struct SpaceMassDef {
  int node = 0;
  double mass = 0.0;             // kg
  double rotary_inertia = 0.0;   // kg m^2, about every axis
};

struct SpaceFrameModel {
  std::vector<Vec3> nodes;                // initial positions (m)
  std::vector<SpaceElementDef> elements;
  std::vector<FrameMemberDef> members;
  std::vector<SpaceSupportDef> supports;
  std::vector<SpaceMassDef> masses;
  BeamTheory theory = BeamTheory::euler_bernoulli;
  FrameTransform transform = FrameTransform::linear;
  MassMatrix mass = MassMatrix::lumped;
  FrameIntegrator integrator = FrameIntegrator::explicit_euler;
  Vec3 gravity = Vec3::Zero();            // m/s^2 on the members' own mass
  // Permanent loads held from t = 0 like the self-weight: per element a load varying linearly along it, in global
  // components per metre of its initial length at its start and end (N/m); empty: none.
  std::vector<std::array<Vec3, 2>> permanent;
  double rayleigh_mass = 0.0;             // alpha (1/s): C = alpha M + beta K
  double rayleigh_stiffness = 0.0;        // beta (s)
  double hht_alpha = 0.0;                 // Newmark: HHT alpha in [-1/3, 0]
  ModalDamping modal_damping;             // modal damping from the computed modes (none by default)
};

// Deformed centre-line of one space element, xi in [0, 1] (the plane ElementCurve with two transverse directions):
//   x(xi) = o + (xi L + u(xi)) e1 + w(xi) e2 + v(xi) e3, u linear in [u1, u2], w and v cubic Hermite on
//   [w1, t1, w2, t2] and [v1, s1, v2, s2] (s = -rotation about e2, the slope of v).
// Linear transformation: o, axes and L initial, end values the local displacements and rotations. Corotational:
// o = x_i, axes the element frame, L the chord, u = w1 = w2 = v1 = v2 = 0, slopes the basic end rotations.
struct SpaceElementCurve {
  Vec3 o = Vec3::Zero(), e1 = Vec3::UnitX(), e2 = Vec3::UnitY(), e3 = Vec3::UnitZ();
  double L = 0, u1 = 0, u2 = 0, w1 = 0, t1 = 0, w2 = 0, t2 = 0, v1 = 0, s1 = 0, v2 = 0, s2 = 0;
  Vec3 point(double xi) const {
    const double x2 = xi * xi, x3 = x2 * xi, h1 = 1 - 3 * x2 + 2 * x3, h2 = L * (xi - 2 * x2 + x3), h3 = 3 * x2 - 2 * x3, h4 = L * (x3 - x2);
    return o + (xi * L + u1 + xi * (u2 - u1)) * e1 + (h1 * w1 + h2 * t1 + h3 * w2 + h4 * t2) * e2 + (h1 * v1 + h2 * s1 + h3 * v2 + h4 * s2) * e3;
  }
  Vec3 d1(double xi) const {  // dx/dxi
    const double x2 = xi * xi, h1 = -6 * xi + 6 * x2, h2 = L * (1 - 4 * xi + 3 * x2), h3 = 6 * xi - 6 * x2, h4 = L * (3 * x2 - 2 * xi);
    return (L + u2 - u1) * e1 + (h1 * w1 + h2 * t1 + h3 * w2 + h4 * t2) * e2 + (h1 * v1 + h2 * s1 + h3 * v2 + h4 * s2) * e3;
  }
  Vec3 d2(double xi) const {  // d2x/dxi2
    const double h1 = -6 + 12 * xi, h2 = L * (-4 + 6 * xi), h3 = 6 - 12 * xi, h4 = L * (6 * xi - 2);
    return (h1 * w1 + h2 * t1 + h3 * w2 + h4 * t2) * e2 + (h1 * v1 + h2 * s1 + h3 * v2 + h4 * s2) * e3;
  }
};

class SpaceFrame {
 public:
  // Assembles the model; throws std::invalid_argument naming the element/node for zero length, non-positive
  // E/rho/section sizes, an orientation vector along the element, bad node indices, or a mechanism.
  explicit SpaceFrame(SpaceFrameModel model);
  ~SpaceFrame();
  SpaceFrame(SpaceFrame&&) noexcept;
  SpaceFrame& operator=(SpaceFrame&&) noexcept;

  const SpaceFrameModel& model() const;
  int nnodes() const;
  int nelements() const;
  int ndof() const { return 6 * nnodes(); }
  const Eigen::VectorXd& displacement() const;
  const Eigen::VectorXd& velocity() const;
  double time() const;
  Vec3 node_position(int n) const;
  // The element's local axes (rows e1, e2, e3) at the current state.
  Eigen::Matrix3d axes(int e) const;

  void clear_loads();
  void add_nodal_load(int node, const Vec6& f);  // Fx, Fy, Fz (N), Mx, My, Mz (N m), global
  // Force F and moment m (global) at xi of element e as consistent end loads (axial linear, transverse Hermite,
  // torque linear, bending moments through the Hermite slopes).
  void add_point_load(int e, double xi, const Vec3& F, const Vec3& m = Vec3::Zero());
  // Mass (a 3 x 3 translational block in global axes) attached for the next advance() only at x(xi) + arm of
  // element e, moving with the section there, consistently (frame.hpp, add_point_mass).
  void add_point_mass(int e, double xi, const Eigen::Matrix3d& m, const Vec3& arm = Vec3::Zero());
  // The end forces (global, start node then end node) of add_point_load.
  Eigen::Matrix<double, 12, 1> point_load_vector(int e, double xi, const Vec3& F, const Vec3& m) const;
  void add_distributed_load(int e, const Vec3& w_local);  // uniform, per metre, along (e1, e2, e3)

  double stable_time_step() const;
  // The step below which the frame is advanced when free of contact loads (AssembledSystem::ringing_step).
  double ringing_step() const;
  void advance(double dt);
  // Static solution for the current loads (frame.hpp, solve_static).
  void solve_static(int increments = 1);
  std::vector<double> natural_frequencies(int n) const;

  SpaceElementCurve curve(int e) const;
  Vec3 displacement_at(int e, double xi) const;  // centre-line displacement (m), interpolated as add_point_load
  Vec3 velocity_at(int e, double xi) const;      // centre-line velocity (m/s)
  // Angular velocity of the section at xi (rad/s, global), dual to the moment of add_point_load: twist rate linear,
  // the bending rotations' rates as the slopes of the Hermite deflection rates.
  Vec3 angular_velocity_at(int e, double xi) const;
  SpaceSectionForces forces_at(int e, double xi) const;
  SpaceFibreStresses stresses_at(int e, double xi) const;
  Vec6 reaction(int support) const;  // force and moment the support exerts on the frame, global
  double kinetic_energy() const;
  double strain_energy() const;
  double external_work() const;
  double applied_work() const;
  double damping_work() const;
  // Plastic work of the plastic elements since t = 0 (J), and what element e has done so far (nullopt: elastic).
  double plastic_work() const;
  bool plastic() const;  // has elasto-plastic elements
  std::optional<PlasticRecord> plastic_record(int e) const;
  void save_state(StateWriter& w) const;
  void load_state(StateReader& r);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace dmi
