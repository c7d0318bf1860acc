// Frame: the public face of FrameSystem (assembled operators) and a FrameTimeIntegrator, plus results.
// Loads: nodal and point loads are stored as global nodal forces (point loads converted when added, in
// the element axes of that moment); uniform element loads are kept per element in local axes and, with
// the self-weight, turned into equivalent nodal loads in the current axes at the start of each step.
// Section forces (forces_at): q = kb v + q0, with q0 the fixed-end forces of the element's uniform load and
// self-weight (intensity rho A(x) g, per metre of initial length), plus that load's particular solution
// (element.hpp), so N, V, M inside an element are exact for those loads; point loads act through the end
// nodes only (the jump under a point load inside an element is not represented).
// Energies are those of the discrete model: strain 0.5 q^T f q with q = kb v (= 0.5 d^T K d, linear), so
// kinetic + strain + damping work - external work is conserved by Newmark for a linear frame.
#include "engine/structure/frame.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "engine/structure/frame_system.hpp"
#include "engine/structure/frame_core.hpp"

namespace dmi {

struct Frame::Impl : FrameCore<FrameSystem, Vec2, 3> {
  explicit Impl(FrameModel m) : FrameCore(std::move(m), "Frame") {}
};

Frame::Frame(FrameModel model) : impl_(std::make_unique<Impl>(std::move(model))) {}
Frame::~Frame() = default;
Frame::Frame(Frame&&) noexcept = default;
Frame& Frame::operator=(Frame&&) noexcept = default;

const FrameModel& Frame::model() const { return impl_->sys.model(); }
int Frame::nnodes() const { return impl_->nnodes(); }
int Frame::nelements() const { return impl_->sys.nelements(); }
const Eigen::VectorXd& Frame::displacement() const { return impl_->dyn.state.d; }
const Eigen::VectorXd& Frame::velocity() const { return impl_->dyn.state.v; }
double Frame::time() const { return impl_->dyn.state.t; }

Vec2 Frame::node_position(int n) const {
  impl_->check_node(n);
  return model().nodes[n] + impl_->dyn.state.d.segment<2>(3 * n);
}

void Frame::set_velocity(const Eigen::VectorXd& v) {
  if (v.size() != impl_->sys.ndof() || !v.allFinite()) throw std::invalid_argument("Frame::set_velocity: a finite vector of ndof() entries");
  impl_->dyn.state.v = v.cwiseProduct(impl_->sys.free());
  impl_->dyn.state.a_current = false;
}

void Frame::clear_loads() { impl_->clear_loads(); }

void Frame::add_nodal_load(int node, const Vec3& f) { impl_->add_nodal_load(node, f); }

void Frame::add_point_load(int e, double xi, const Vec2& F, double m) {
  impl_->check_element(e, xi);
  if (!F.allFinite() || !std::isfinite(m))
    throw std::invalid_argument("Frame: non-finite point load on element " + std::to_string(e));
  impl_->add_element_end_loads(e, point_load_vector(e, xi, F, m));
}

Eigen::Matrix<double, 6, 1> Frame::point_load_vector(int e, double xi, const Vec2& F, double m) const {
  const ElementCurve c = curve(e);
  const BeamShape sh = beam_shape(xi, c.L);
  const double fa = F.dot(c.e1), ft = F.dot(c.e2);
  Eigen::Matrix<double, 6, 1> g;
  for (int k = 0; k < 2; ++k) {
    const double fw = sh.hermite[2 * k] * ft + sh.slope[2 * k] * m;
    g.segment<2>(3 * k) = sh.axial[k] * fa * c.e1 + fw * c.e2;
    g(3 * k + 2) = sh.hermite[2 * k + 1] * ft + sh.slope[2 * k + 1] * m;
  }
  return g;
}

void Frame::add_point_mass(int e, double xi, const Eigen::Matrix2d& m, const Vec2& arm) {
  impl_->check_element(e, xi);
  if (!m.allFinite() || !arm.allFinite()) throw std::invalid_argument("Frame: non-finite attached mass on element " + std::to_string(e));
  Eigen::Matrix<double, 6, 2> G;  // the point's velocity is G^T times the end DOFs (dual to the point load)
  for (int a = 0; a < 2; ++a) {
    const Vec2 F = Vec2::Unit(a);
    G.col(a) = point_load_vector(e, xi, F, arm.x() * F.y() - arm.y() * F.x());
  }
  const auto& el = model().elements[e];
  impl_->dyn.add_point_mass(3, el.i, el.j, G, m);
}

void Frame::add_distributed_load(int e, const Vec2& w_local) { impl_->add_distributed_load(e, w_local); }

double Frame::stable_time_step() const { return impl_->dyn.integrator->stable_time_step(); }
double Frame::ringing_step() const { return impl_->sys.ringing_step(); }

void Frame::advance(double dt) { impl_->advance(dt); }
void Frame::solve_static(int increments) { impl_->solve_static(increments); }

std::vector<double> Frame::natural_frequencies(int n) const { return impl_->sys.natural_frequencies(n); }

ElementCurve Frame::curve(int e) const {
  impl_->check_element(e, 0);
  return impl_->sys.transform().curve(impl_->sys.chord(e), impl_->sys.element_dofs(e, impl_->dyn.state.d));
}

Vec2 Frame::velocity_at(int e, double xi) const {
  impl_->check_element(e, xi);
  const ElementCurve c = curve(e);
  const BeamShape sh = beam_shape(xi, c.L);
  const Vec6 ve = impl_->sys.element_dofs(e, impl_->dyn.state.v);
  const double ua = sh.axial[0] * ve.head<2>().dot(c.e1) + sh.axial[1] * ve.segment<2>(3).dot(c.e1);
  const double wt = sh.hermite[0] * ve.head<2>().dot(c.e2) + sh.hermite[1] * ve(2) +
                    sh.hermite[2] * ve.segment<2>(3).dot(c.e2) + sh.hermite[3] * ve(5);
  return ua * c.e1 + wt * c.e2;
}

double Frame::angular_velocity_at(int e, double xi) const {
  impl_->check_element(e, xi);
  const ElementCurve c = curve(e);
  const BeamShape sh = beam_shape(xi, c.L);
  const Vec6 ve = impl_->sys.element_dofs(e, impl_->dyn.state.v);
  return sh.slope[0] * ve.head<2>().dot(c.e2) + sh.slope[1] * ve(2) + sh.slope[2] * ve.segment<2>(3).dot(c.e2) +
         sh.slope[3] * ve(5);
}

double Frame::half_depth(int e, double xi) const {
  impl_->check_element(e, xi);
  const FrameElementDef& el = model().elements[e];
  return el.section.half_depth(el.s0 + xi * (el.s1 - el.s0));
}

SectionForces Frame::forces_at(int e, double xi) const {
  impl_->check_element(e, xi);
  const FrameSystem& sys = impl_->sys;
  const ChordState s = sys.element_state(e, impl_->dyn.state.d);
  return sys.element(e).section_forces(sys.basic_forces(e, s.v), s.L, sys.element_load(e, impl_->w[e], impl_->dyn.state.d), xi);
}

// sigma(y) = N/A - M y/I (frame.hpp); tau(y) = tau_max (1 - (y/c)^2) for a rectangle, tau_max sqrt(1 - (y/c)^2)
// for a thin pipe (shear flow ~ cos of the polar angle); von Mises sqrt(sigma^2 + 3 tau^2) on 21 fibres.
FibreStresses Frame::stresses_at(int e, double xi) const {
  const FrameElementDef& el = model().elements[e];
  return fibre_stresses(el.section, el.s0 + xi * (el.s1 - el.s0), forces_at(e, xi));
}

Vec3 Frame::reaction(int support) const { return impl_->reaction(support, model().supports); }

double Frame::kinetic_energy() const { return impl_->dyn.kinetic_energy(impl_->sys); }

double Frame::strain_energy() const { return impl_->strain_energy(); }

double Frame::external_work() const { return impl_->dyn.work_ext; }
double Frame::applied_work() const { return impl_->dyn.work_applied; }
double Frame::damping_work() const { return impl_->dyn.work_damp; }

bool Frame::plastic() const { return impl_->sys.plastic(); }

double Frame::plastic_work() const { return impl_->sys.fibres().plastic_work(); }

std::optional<PlasticRecord> Frame::plastic_record(int e) const {
  impl_->check_element(e, 0);
  return impl_->sys.fibres().record(e);
}

void Frame::save_state(StateWriter& w) const { impl_->save_state(w, "frame"); }
void Frame::load_state(StateReader& r) { impl_->load_state(r, "frame"); }

}  // namespace dmi
