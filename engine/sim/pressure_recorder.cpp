#include "engine/sim/pressure_recorder.hpp"


#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/common/error.hpp"
#include "engine/sim/build_scene.hpp"

namespace dmi {
namespace {

// The sensor's patch on a member's face: the point's projection on the nearest element's initial chord gives the
// face normal (from the centre-line through the point); the square's first axis runs along the member.
template <int D> PressurePatch<D> member_patch(const FrameOf<D>& f, const FrameMemberDef& m, const SensorConfig& c, double thickness) {
  const Vec<D> x = vec<D>(c.point);
  double best = std::numeric_limits<double>::infinity();
  Vec<D> n = Vec<D>::Zero(), axis = Vec<D>::Zero();
  for (int e = m.first_element; e < m.first_element + m.elements; ++e) {
    const auto& el = f.model().elements[static_cast<std::size_t>(e)];
    const Vec<D> a = f.model().nodes[static_cast<std::size_t>(el.i)], b = f.model().nodes[static_cast<std::size_t>(el.j)];
    const double t = std::clamp((x - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
    const Vec<D> r = x - (a + t * (b - a));
    if (r.norm() < best) best = r.norm(), n = r, axis = (b - a).normalized();
  }
  if (!(n.norm() > 0))
    throw InputError("sensor '" + c.name + "' lies on the centre-line of member '" + m.name + "': give a point on its face");
  return make_patch<D>(c.name, x, n, c.size, thickness, axis);
}

}  // namespace

template <int D> PressureRecorder<D>::PressureRecorder(const Solver<D>& solver, const Scenario& s) {
  const Scene<D>& sc = solver.scene();
  h_ = sc.grid->h();
  for (std::size_t w = 0; w < sc.walls.size(); ++w)
    for (std::size_t j = 0; j < sc.walls[w].sensors.size(); ++j) {
      walls_.push_back({w, j});
      wall_names_.push_back(sc.walls[w].sensors[j].name);
      wall_area_.push_back(sc.walls[w].sensors[j].area);
    }
  const FrameOf<D>* f = sc.frame.get();
  auto member = [&](const std::string& name) -> const FrameMemberDef& {
    const auto& ms = f->model().members;
    return *std::find_if(ms.begin(), ms.end(), [&](const FrameMemberDef& m) { return m.name == name; });
  };
  for (const SensorConfig& c : s.output.sensors) {
    if (c.member.empty() || !f) continue;
    const FrameMemberDef& m = member(c.member);
    members_.push_back({member_patch<D>(*f, m, c, s.analysis.thickness), m.first_element, m.first_element + m.elements});
  }
  const FaceProfileConfig& fp = s.output.face_profile;
  if (fp.present && f) {
    face_members_ = fp.members;
    direction_ = vec<D>(fp.direction);
    width_ = D == 2 ? s.analysis.thickness : fp.width;
    bin_of_.assign(static_cast<std::size_t>(f->nelements()), -1);
    double along = 0;
    {
      const FrameMemberDef& first = member(fp.members.front());
      foot_ = f->model().nodes[static_cast<std::size_t>(f->model().elements[static_cast<std::size_t>(first.first_element)].i)];
    }
    for (const std::string& name : fp.members) {
      const FrameMemberDef& m = member(name);
      for (int e = m.first_element; e < m.first_element + m.elements; ++e) {
        const auto& el = f->model().elements[static_cast<std::size_t>(e)];
        const Vec<D> a = f->model().nodes[static_cast<std::size_t>(el.i)], b = f->model().nodes[static_cast<std::size_t>(el.j)];
        const double L = (b - a).norm();
        bin_of_[static_cast<std::size_t>(e)] = static_cast<int>(bins_.size());
        bins_.push_back({name, e, along, along + L, arm(a), arm(b)});
        along += L;
      }
    }
  }
  impulse_.assign(walls_.size() + members_.size() + bins_.size(), 0.0);
}

template <int D> void PressureRecorder<D>::add_series(std::vector<Series>& out) const {
  for (const std::string& n : wall_names_) out.push_back(Series{"sensors/" + n + "/pressure", "Pa", {"value"}, {}});
  for (const MemberSensor& m : members_) out.push_back(Series{"sensors/" + m.patch.name + "/pressure", "Pa", {"value"}, {}});
  if (bins_.empty()) return;
  std::vector<std::string> comps;
  for (std::size_t b = 0; b < bins_.size(); ++b) comps.push_back("bin" + std::to_string(b));
  out.push_back(Series{"face/pressure", "Pa", comps, {}});
  out.push_back(Series{"face/resultant", "N", {"value"}, {}});
  out.push_back(Series{"face/height", "m", {"value"}, {}});
}

template <int D> void PressureRecorder<D>::accumulate(const Solver<D>& solver, double dt) {
  const Scene<D>& sc = solver.scene();
  std::size_t k = 0;
  for (const WallSensor& w : walls_) impulse_[k++] += sc.walls[w.wall].sensors[w.index].force * dt;
  const auto* mc = solver.member_contact();
  if (!mc) return;
  for (MemberSensor& m : members_) {
    m.patch.force = 0;
    for (const ContactLoadOf<D>& l : mc->loads())
      if (l.element >= m.first && l.element < m.last) patch_add(m.patch, l.point, l.force, h_);
    impulse_[k++] += m.patch.force * dt;
  }
  for (const ContactLoadOf<D>& l : mc->loads()) {
    const int b = bin_of_.empty() ? -1 : bin_of_[static_cast<std::size_t>(l.element)];
    if (b < 0) continue;
    const double fn = l.force.dot(direction_) * dt;
    impulse_[k + static_cast<std::size_t>(b)] += fn;
    moment_ += fn * arm(l.point);
  }
}

template <int D> void PressureRecorder<D>::sample(std::vector<Series>& out, std::size_t& k, double elapsed) {
  const double inv = elapsed > 0 ? 1 / elapsed : 0.0;
  std::size_t j = 0;
  for (double a : wall_area_) out[k++].data.push_back(patch_pressure(impulse_[j++] * inv, a));
  for (const MemberSensor& m : members_) out[k++].data.push_back(patch_pressure(impulse_[j++] * inv, m.patch.area));
  if (!bins_.empty()) {
    Series& p = out[k++];
    double total = 0;
    for (const Bin& b : bins_) {
      total += impulse_[j];
      p.data.push_back(patch_pressure(impulse_[j++] * inv, (b.to - b.from) * width_));
    }
    out[k++].data.push_back(total * inv);
    out[k++].data.push_back(total != 0 ? moment_ / total : 0.0);
  }
  std::fill(impulse_.begin(), impulse_.end(), 0.0);
  moment_ = 0;
}

template <int D> std::optional<FaceProfileRecord> PressureRecorder<D>::face_profile() const {
  if (bins_.empty()) return std::nullopt;
  FaceProfileRecord f;
  f.members = face_members_;
  f.direction.assign(direction_.data(), direction_.data() + D);
  f.width = width_;
  for (const Bin& b : bins_) f.bins.push_back({b.member, b.element, b.from, b.to, b.height_from, b.height_to});
  return f;
}

template <int D> void PressureRecorder<D>::save_state(StateWriter& w) const {
  w.tag("pressures");
  w.put(impulse_), w.put(moment_);
}

template <int D> void PressureRecorder<D>::load_state(StateReader& r) {
  r.tag("pressures");
  const std::size_t n = impulse_.size();
  r.get(impulse_);
  r.expect_size("pressure impulses", impulse_.size(), n);
  r.get(moment_);
}

template class PressureRecorder<2>;
template class PressureRecorder<3>;

}  // namespace dmi
