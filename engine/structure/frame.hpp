// A 2D beam-column frame: nodes with 3 DOFs (ux, uy, rz), elements made of a basic system
// (element.hpp: axial force N and end moments M_i, M_j against chord deformations, free of rigid
// modes) and a coordinate transformation (linear or corotational), supports, nodal masses, lumped
// or consistent mass, and a time integrator: the explicit scheme of Lin & Yang 2024 eqs. (27)-(29) or
// implicit Newmark (average acceleration).
//
// Sign conventions. Global DOF order per node: ux, uy, rz (rz counter-clockwise +). Element local
// axes: e1 from node i to node j, e2 = e1 rotated +90 deg; "top" is the +e2 surface.
// Section forces at a point: N tension +; V = dM/dx'; M + when it compresses the top fibre
// (sagging for a beam running left to right). Fibre stress sigma(y') = N/A - M y'/I, so
// sigma_top = N/A - M c/I, sigma_bottom = N/A + M c/I.
#pragma once
#include <Eigen/Dense>
#include <memory>
#include <optional>
#include <string>
#include <array>
#include <vector>

#include "engine/common/state_io.hpp"
#include "engine/structure/damping.hpp"
#include "engine/structure/fibre.hpp"
#include "engine/structure/fibre_beam.hpp"
#include "engine/structure/section.hpp"
#include "engine/structure/steel_law.hpp"

namespace dmi {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;

enum class BeamTheory { euler_bernoulli, timoshenko };
enum class FrameTransform { linear, corotational };
enum class MassMatrix { lumped, consistent };
enum class FrameIntegrator { explicit_euler, newmark };

struct FrameElementDef {
  int i = 0, j = 0;               // node indices
  Section section = Section::rectangle(1, 1);
  double s0 = 0.0, s1 = 1.0;      // the element's span as fractions of its member's section taper
  double E = 0, nu = 0, rho = 0;  // Pa, -, kg/m^3
  bool release_i = false, release_j = false;  // moment releases (hinges) at the element ends
  int member = 0;                 // index into FrameModel::members
  // Elasto-plastic fibre element (fibre_beam.hpp) when steel.fy > 0, with integration_points Gauss-Lobatto sections;
  // elastic otherwise. A plastic element carries no moment release.
  SteelLaw steel;                 // its E is the element's
  int integration_points = 5;
};

struct FrameSupportDef {
  int node = 0;
  bool fixed[3] = {false, false, false};    // ux, uy, rz restrained
  double spring[3] = {0.0, 0.0, 0.0};       // N/m, N/m, N m/rad, to ground
};

struct FrameMassDef {
  int node = 0;
  double mass = 0.0;             // kg
  double rotary_inertia = 0.0;   // kg m^2
};

struct FrameMemberDef {
  std::string name;
  int first_element = 0, elements = 0;   // contiguous element range, ordered from start to end
};

struct FrameModel {
  std::vector<Vec2> nodes;                // initial positions (m)
  std::vector<FrameElementDef> elements;
  std::vector<FrameMemberDef> members;
  std::vector<FrameSupportDef> supports;
  std::vector<FrameMassDef> masses;
  BeamTheory theory = BeamTheory::euler_bernoulli;
  FrameTransform transform = FrameTransform::linear;
  MassMatrix mass = MassMatrix::lumped;
  FrameIntegrator integrator = FrameIntegrator::explicit_euler;
  Vec2 gravity = Vec2::Zero();            // m/s^2 acting on the members' own mass (zero: no self-weight)
  // Permanent loads held from t = 0 like the self-weight (earth and water pressure on a dam's face): per element a load
  // varying linearly along it, in global components per metre of its initial length at its start and end (N/m);
  // empty: none.
  std::vector<std::array<Vec2, 2>> permanent;
  double rayleigh_mass = 0.0;             // alpha (1/s): C = alpha M + beta K
  double rayleigh_stiffness = 0.0;        // beta (s)
  double hht_alpha = 0.0;                 // Newmark integrator: HHT alpha in [-1/3, 0]; 0 = average acceleration
  ModalDamping modal_damping;             // modal damping from the computed modes (none by default)
};

// Deformed centre-line of one element, xi in [0, 1]:
//   x(xi) = o + (xi L + u(xi)) e1 + w(xi) e2,   u = u1 + xi (u2 - u1),
//   w(xi) = H1 w1 + L H2 t1 + H3 w2 + L H4 t2   (cubic Hermite: H1 = 1 - 3xi^2 + 2xi^3,
//   H2 = xi - 2xi^2 + xi^3, H3 = 3xi^2 - 2xi^3, H4 = -xi^2 + xi^3).
// Linear transformation: o = X_i (initial), e1/e2 initial axes, L = L0, u/w/t local displacements
// and rotations of the end nodes. Corotational: o = x_i (current), e1 along the current chord,
// L = current chord length, u1 = u2 = w1 = w2 = 0, t = nodal rotation minus chord rotation.
struct ElementCurve {
  Vec2 o = Vec2::Zero(), e1 = Vec2::UnitX(), e2 = Vec2::UnitY();
  double L = 0, u1 = 0, u2 = 0, w1 = 0, t1 = 0, w2 = 0, t2 = 0;
  Vec2 point(double xi) const {
    const double x2 = xi * xi, x3 = x2 * xi;
    const double w = (1 - 3 * x2 + 2 * x3) * w1 + L * (xi - 2 * x2 + x3) * t1 + (3 * x2 - 2 * x3) * w2 + L * (x3 - x2) * t2;
    return o + (xi * L + u1 + xi * (u2 - u1)) * e1 + w * e2;
  }
  Vec2 d1(double xi) const {  // dx/dxi
    const double x2 = xi * xi;
    const double w = (-6 * xi + 6 * x2) * w1 + L * (1 - 4 * xi + 3 * x2) * t1 + (6 * xi - 6 * x2) * w2 + L * (3 * x2 - 2 * xi) * t2;
    return (L + u2 - u1) * e1 + w * e2;
  }
  Vec2 d2(double xi) const {  // d2x/dxi2
    const double w = (-6 + 12 * xi) * w1 + L * (-4 + 6 * xi) * t1 + (6 - 12 * xi) * w2 + L * (6 * xi - 2) * t2;
    return w * e2;
  }
};

class Frame {
 public:
  // Assembles the model; throws std::invalid_argument naming the element/node for zero length,
  // non-positive E/rho/section sizes, bad node indices, or an unrestrained (mechanism) frame.
  explicit Frame(FrameModel model);
  ~Frame();
  Frame(Frame&&) noexcept;
  Frame& operator=(Frame&&) noexcept;

  const FrameModel& model() const;
  int nnodes() const;
  int nelements() const;
  int ndof() const { return 3 * nnodes(); }

  // State, global DOF vectors of size ndof() (constrained entries stay 0).
  const Eigen::VectorXd& displacement() const;
  const Eigen::VectorXd& velocity() const;
  double time() const;
  Vec2 node_position(int n) const;   // current (X + u)
  // Sets the velocity (global DOF vector; restrained entries are ignored): an initial condition, e.g. a struck mass.
  void set_velocity(const Eigen::VectorXd& v);

  // External loads (and attached masses) held over the next advance(); cleared by clear_loads(). Self-weight (model
  // gravity) is added internally and need not be applied.
  void clear_loads();
  void add_nodal_load(int node, const Vec3& f);                  // Fx, Fy (N), Mz (N m)
  // Concentrated force F (global, N) and moment m (N m) at xi of element e, turned into consistent
  // end forces with the element's interpolation (axial linear, transverse cubic Hermite; moment
  // through the Hermite slopes), in the element's current axes (initial axes for linear transf).
  void add_point_load(int e, double xi, const Vec2& F, double m = 0.0);
  // Mass m (kg, a 2x2 translational block in global axes) attached for the next advance() only at the point
  // x(xi) + arm of element e, moving with the section there (centre-line velocity plus rotation times arm, dual to
  // add_point_load with the moment arm x F): material that member contact holds to the member moves with it, so it
  // adds to the inertia of the step (implicit added mass), consistently, the arm's rotary inertia included.
  void add_point_mass(int e, double xi, const Eigen::Matrix2d& m, const Vec2& arm = Vec2::Zero());
  // The end forces (Fx, Fy, Mz at the start node, then at the end node; global) of add_point_load.
  Eigen::Matrix<double, 6, 1> point_load_vector(int e, double xi, const Vec2& F, double m) const;
  // Uniform load per unit length (N/m) in the element's local axes (along e1, along e2).
  void add_distributed_load(int e, const Vec2& w_local);

  // Explicit: the largest step for which eqs. (27)-(29) are stable, 2 / omega_max of M^-1 K
  // (no safety factor; the caller applies its CFL fraction). Newmark: +infinity.
  double stable_time_step() const;
  // The step below which the frame is advanced when free of contact loads (AssembledSystem::ringing_step).
  double ringing_step() const;
  // Advances by dt with the loads held constant over the step.
  void advance(double dt);
  // Static solution for the current loads (state set to it, velocity zero): K d = f, or under the corotational
  // transformation Newton-Raphson on the internal force in `increments` equal load steps.
  void solve_static(int increments = 1);
  // The n lowest natural circular frequencies (rad/s) of the restrained frame, ascending.
  std::vector<double> natural_frequencies(int n) const;

  // Results at the current state.
  ElementCurve curve(int e) const;
  Vec2 velocity_at(int e, double xi) const;       // centre-line velocity (m/s), interpolated as add_point_load
  // Rate of rotation of the centre-line's tangent at xi (rad/s), dual to the moment of add_point_load.
  double angular_velocity_at(int e, double xi) const;
  double half_depth(int e, double xi) const;      // c at xi (m), from the member's section
  SectionForces forces_at(int e, double xi) const;
  FibreStresses stresses_at(int e, double xi) const;
  // Force and moment each support exerts on the frame (Fx, Fy in N, M in N m), in FrameModel::supports order.
  Vec3 reaction(int support) const;
  double kinetic_energy() const;   // J
  double strain_energy() const;    // J
  // Work done on the frame by the external loads since t = 0 (J), including self-weight, accumulated by advance().
  double external_work() const;
  // The part of external_work() done by the loads given through add_nodal_load / add_point_load (J):
  // in a coupled run, the work of the material on the members.
  double applied_work() const;
  // Energy dissipated by Rayleigh damping since t = 0 (J), accumulated by advance().
  double damping_work() const;
  // Plastic work of the plastic elements since t = 0 (J; strain_energy() holds their elastic part), and what element e
  // has done so far (nullopt: an elastic element).
  double plastic_work() const;
  bool plastic() const;  // has elasto-plastic elements
  std::optional<PlasticRecord> plastic_record(int e) const;
  // Dynamic state (displacements, velocities, accelerations, loads, integrator history, work counters) for
  // checkpoints; load_state() requires the same model.
  void save_state(StateWriter& w) const;
  void load_state(StateReader& r);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace dmi
