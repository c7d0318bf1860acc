// SpaceFrame: the public face of SpaceFrameSystem and the shared FrameDynamics, plus results; loads and energies as
// the plane frame's (frame.cpp): nodal and point loads are global nodal forces, uniform element loads are kept per
// element in local axes and turned, with the self-weight, into equivalent nodal loads at each step.
#include "engine/structure/space_frame.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "engine/structure/frame_core.hpp"
#include "engine/structure/space_frame_system.hpp"

namespace dmi {

SpaceSupportDef SpaceSupportDef::fixed_support(int node) {
  SpaceSupportDef s;
  s.node = node;
  for (bool& f : s.fixed) f = true;
  return s;
}

SpaceSupportDef SpaceSupportDef::pinned(int node) {
  SpaceSupportDef s;
  s.node = node;
  for (int c = 0; c < 3; ++c) s.fixed[c] = true;
  return s;
}

struct SpaceFrame::Impl : FrameCore<SpaceFrameSystem, Vec3, 6> {
  explicit Impl(SpaceFrameModel m) : FrameCore(std::move(m), "SpaceFrame") {}
  // The element's current local axes and its end DOFs in them.
  Vec12 local_dofs(int e, const Eigen::VectorXd& x, Eigen::Matrix3d& R, double& L) const {
    const SpaceChordState s = sys.element_state(e, dyn.state.d);
    R = s.R;
    L = s.L;
    return rotation12(R) * sys.element_dofs(e, x);
  }
  // Centre-line field at xi interpolated from local end values ul (axial and torsion linear, transverse Hermite).
  static Vec3 interpolate(const Vec12& ul, double xi, double L) {
    const BeamShape sh = beam_shape(xi, L);
    const double u1 = sh.axial[0] * ul(0) + sh.axial[1] * ul(6);
    const double u2 = sh.hermite[0] * ul(1) + sh.hermite[1] * ul(5) + sh.hermite[2] * ul(7) + sh.hermite[3] * ul(11);
    const double u3 = sh.hermite[0] * ul(2) - sh.hermite[1] * ul(4) + sh.hermite[2] * ul(8) - sh.hermite[3] * ul(10);
    return {u1, u2, u3};
  }
};

SpaceFrame::SpaceFrame(SpaceFrameModel model) : impl_(std::make_unique<Impl>(std::move(model))) {}
SpaceFrame::~SpaceFrame() = default;
SpaceFrame::SpaceFrame(SpaceFrame&&) noexcept = default;
SpaceFrame& SpaceFrame::operator=(SpaceFrame&&) noexcept = default;

const SpaceFrameModel& SpaceFrame::model() const { return impl_->sys.model(); }
int SpaceFrame::nnodes() const { return impl_->nnodes(); }
int SpaceFrame::nelements() const { return impl_->sys.nelements(); }
const Eigen::VectorXd& SpaceFrame::displacement() const { return impl_->dyn.state.d; }
const Eigen::VectorXd& SpaceFrame::velocity() const { return impl_->dyn.state.v; }
double SpaceFrame::time() const { return impl_->dyn.state.t; }

Vec3 SpaceFrame::node_position(int n) const {
  impl_->check_node(n);
  return model().nodes[n] + impl_->dyn.state.d.segment<3>(6 * n);
}

Eigen::Matrix3d SpaceFrame::axes(int e) const {
  impl_->check_element(e, 0);
  return impl_->sys.element_state(e, impl_->dyn.state.d).R;
}

void SpaceFrame::clear_loads() { impl_->clear_loads(); }

void SpaceFrame::add_nodal_load(int node, const Vec6& f) { impl_->add_nodal_load(node, f); }

void SpaceFrame::add_point_load(int e, double xi, const Vec3& F, const Vec3& m) {
  impl_->check_element(e, xi);
  if (!F.allFinite() || !m.allFinite()) throw std::invalid_argument("SpaceFrame: non-finite point load on element " + std::to_string(e));
  impl_->add_element_end_loads(e, point_load_vector(e, xi, F, m));
}

Vec12 SpaceFrame::point_load_vector(int e, double xi, const Vec3& F, const Vec3& m) const {
  const SpaceChordState s = impl_->sys.element_state(e, impl_->dyn.state.d);
  const Vec3 f = s.R * F, t = s.R * m;
  const BeamShape sh = beam_shape(xi, s.L);
  Vec12 l = Vec12::Zero();
  for (int k = 0; k < 2; ++k) {
    const int o = 6 * k;
    l(o) = sh.axial[k] * f(0);
    l(o + 3) = sh.axial[k] * t(0);                                           // torque
    l(o + 1) = sh.hermite[2 * k] * f(1) + sh.slope[2 * k] * t(2);            // plane 1: u2, th3
    l(o + 5) = sh.hermite[2 * k + 1] * f(1) + sh.slope[2 * k + 1] * t(2);
    l(o + 2) = sh.hermite[2 * k] * f(2) - sh.slope[2 * k] * t(1);            // plane 2: u3, t' = -th2, m' = -m2
    l(o + 4) = -(sh.hermite[2 * k + 1] * f(2) - sh.slope[2 * k + 1] * t(1));
  }
  return rotation12(s.R).transpose() * l;
}

void SpaceFrame::add_point_mass(int e, double xi, const Eigen::Matrix3d& m, const Vec3& arm) {
  impl_->check_element(e, xi);
  if (!m.allFinite() || !arm.allFinite()) throw std::invalid_argument("SpaceFrame: non-finite attached mass on element " + std::to_string(e));
  Eigen::Matrix<double, 12, 3> G;  // the point's velocity is G^T times the end DOFs (dual to the point load)
  for (int a = 0; a < 3; ++a) {
    const Vec3 F = Vec3::Unit(a);
    G.col(a) = point_load_vector(e, xi, F, arm.cross(F));
  }
  const auto& el = model().elements[e];
  impl_->dyn.add_point_mass(6, el.i, el.j, G, m);
}

void SpaceFrame::add_distributed_load(int e, const Vec3& w_local) { impl_->add_distributed_load(e, w_local); }

double SpaceFrame::stable_time_step() const { return impl_->dyn.integrator->stable_time_step(); }
double SpaceFrame::ringing_step() const { return impl_->sys.ringing_step(); }

void SpaceFrame::advance(double dt) { impl_->advance(dt); }
void SpaceFrame::solve_static(int increments) { impl_->solve_static(increments); }

std::vector<double> SpaceFrame::natural_frequencies(int n) const { return impl_->sys.natural_frequencies(n); }

// The deformed centre-line (curve: linear, the small-displacement interpolation of the end values in the initial
// axes; corotational, the chord plus the Hermite deflections of the basic end rotations, so a rigid rotation is exact)
// less the initial position.
Vec3 SpaceFrame::displacement_at(int e, double xi) const {
  impl_->check_element(e, xi);
  const SpaceElementDef& el = model().elements[e];
  return curve(e).point(xi) - (model().nodes[el.i] + xi * (model().nodes[el.j] - model().nodes[el.i]));
}

Vec3 SpaceFrame::velocity_at(int e, double xi) const {
  impl_->check_element(e, xi);
  Eigen::Matrix3d R;
  double L = 0;
  const Vec12 ul = impl_->local_dofs(e, impl_->dyn.state.v, R, L);
  return R.transpose() * Impl::interpolate(ul, xi, L);
}

SpaceElementCurve SpaceFrame::curve(int e) const {
  impl_->check_element(e, 0);
  const Eigen::VectorXd& d = impl_->dyn.state.d;
  const SpaceChordState s = impl_->sys.element_state(e, d);
  SpaceElementCurve c;
  c.e1 = s.R.row(0).transpose(), c.e2 = s.R.row(1).transpose(), c.e3 = s.R.row(2).transpose();
  c.L = s.L;
  const SpaceElementDef& el = model().elements[e];
  if (model().transform == FrameTransform::linear) {
    const Vec12 ul = rotation12(s.R) * impl_->sys.element_dofs(e, d);
    c.o = model().nodes[el.i];
    c.u1 = ul(0), c.u2 = ul(6);
    c.w1 = ul(1), c.t1 = ul(5), c.w2 = ul(7), c.t2 = ul(11);
    c.v1 = ul(2), c.s1 = -ul(4), c.v2 = ul(8), c.s2 = -ul(10);
  } else {
    c.o = model().nodes[el.i] + d.segment<3>(6 * el.i);
    c.t1 = s.v(1), c.t2 = s.v(2), c.s1 = s.v(3), c.s2 = s.v(4);
  }
  return c;
}

Vec3 SpaceFrame::angular_velocity_at(int e, double xi) const {
  impl_->check_element(e, xi);
  Eigen::Matrix3d R;
  double L = 0;
  const Vec12 vl = impl_->local_dofs(e, impl_->dyn.state.v, R, L);
  const BeamShape sh = beam_shape(xi, L);
  const double w1 = sh.axial[0] * vl(3) + sh.axial[1] * vl(9);
  const double w3 = sh.slope[0] * vl(1) + sh.slope[1] * vl(5) + sh.slope[2] * vl(7) + sh.slope[3] * vl(11);       // d(u2)/dx rate
  const double w2 = -(sh.slope[0] * vl(2) - sh.slope[1] * vl(4) + sh.slope[2] * vl(8) - sh.slope[3] * vl(10));  // -d(u3)/dx rate
  return R.transpose() * Vec3(w1, w2, w3);
}

SpaceSectionForces SpaceFrame::forces_at(int e, double xi) const {
  impl_->check_element(e, xi);
  const SpaceFrameSystem& sys = impl_->sys;
  const SpaceChordState s = sys.element_state(e, impl_->dyn.state.d);
  return sys.element(e).section_forces(sys.basic_forces(e, s.v), s.L, sys.element_load(e, impl_->w[e], impl_->dyn.state.d), xi);
}

SpaceFibreStresses SpaceFrame::stresses_at(int e, double xi) const {
  const SpaceElementDef& el = model().elements[e];
  return space_fibre_stresses(el.section, el.s0 + xi * (el.s1 - el.s0), forces_at(e, xi));
}

Vec6 SpaceFrame::reaction(int support) const { return impl_->reaction(support, model().supports); }

double SpaceFrame::kinetic_energy() const { return impl_->dyn.kinetic_energy(impl_->sys); }

double SpaceFrame::strain_energy() const { return impl_->strain_energy(); }

double SpaceFrame::external_work() const { return impl_->dyn.work_ext; }
double SpaceFrame::applied_work() const { return impl_->dyn.work_applied; }
double SpaceFrame::damping_work() const { return impl_->dyn.work_damp; }

bool SpaceFrame::plastic() const { return impl_->sys.plastic(); }

double SpaceFrame::plastic_work() const { return impl_->sys.fibres().plastic_work(); }

std::optional<PlasticRecord> SpaceFrame::plastic_record(int e) const {
  impl_->check_element(e, 0);
  return impl_->sys.fibres().record(e);
}

void SpaceFrame::save_state(StateWriter& w) const { impl_->save_state(w, "space_frame"); }
void SpaceFrame::load_state(StateReader& r) { impl_->load_state(r, "space_frame"); }

}  // namespace dmi
