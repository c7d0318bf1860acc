#include "engine/sim/build_frame.hpp"

#include <algorithm>
#include <map>
#include <type_traits>


namespace dmi {
namespace {

SectionRecord section_record(const Section& c) {
  SectionRecord r;
  switch (c.kind()) {
    case SectionKind::pipe: r.kind = "pipe"; break;
    case SectionKind::tapered_rectangle: r.kind = "tapered_rectangle"; break;
    case SectionKind::box: r.kind = "box"; break;
    case SectionKind::i_section: r.kind = "i_section"; break;
    case SectionKind::rectangle: r.kind = "rectangle"; break;
  }
  if (c.kind() == SectionKind::pipe) {
    r.diameter_m = c.depth(0), r.wall_thickness_m = c.wall_thickness();
    return r;
  }
  r.width_m = c.width(0), r.depth_start_m = c.depth(0), r.depth_end_m = c.depth(1);
  if (c.kind() == SectionKind::box) r.wall_thickness_m = c.wall_thickness();
  if (c.kind() == SectionKind::i_section) r.flange_thickness_m = c.wall_thickness(), r.web_thickness_m = c.web_thickness();
  return r;
}

Section make_section(const SectionConfig& c) {
  if (c.type == "pipe") return Section::pipe(c.diameter, c.wall_thickness);
  if (c.type == "tapered_rectangle") return Section::tapered(c.width, c.depth_start, c.depth_end);
  if (c.type == "box") return Section::box(c.width, c.depth, c.wall_thickness);
  if (c.type == "i_section") return Section::i_section(c.width, c.depth, c.flange_thickness, c.web_thickness);
  return Section::rectangle(c.width, c.depth);
}

}  // namespace

namespace {

template <int D> struct FrameTypes;
template <> struct FrameTypes<2> {
  using Model = FrameModel;
  using Element = FrameElementDef;
  using Support = FrameSupportDef;
  using Mass = FrameMassDef;
};
template <> struct FrameTypes<3> {
  using Model = SpaceFrameModel;
  using Element = SpaceElementDef;
  using Support = SpaceSupportDef;
  using Mass = SpaceMassDef;
};

// Pressure loads as each element's permanent load: q(s) = gradient max(0, surface - y(s)) |dy/ds| per metre of the
// element along the direction, replaced by the linear load a + (b - a) s / L with the same force F = integral q ds and
// moment M = integral q s ds about the element's start (a = (4F - 6M/L)/L, b = (6M/L - 2F)/L): the reactions of a
// statically determinate frame are exact, the surface anywhere. The integrals split at the surface; each piece is
// integrated exactly by two-point Gauss (q linear).
template <class Model> void add_pressure_loads(const StructureConfig& st, Model& fm) {
  if (st.pressure_loads.empty()) return;
  using V = std::decay_t<decltype(fm.nodes[0])>;
  constexpr int up = V::RowsAtCompileTime - 1;  // the vertical axis: y in 2D, z in 3D
  fm.permanent.assign(fm.elements.size(), {V::Zero(), V::Zero()});
  for (const PressureLoadConfig& l : st.pressure_loads) {
    V dir;
    for (int c = 0; c < dir.size(); ++c) dir[c] = l.direction[c];
    dir.normalize();
    for (const FrameMemberDef& m : fm.members) {
      if (m.name != l.member) continue;
      for (int e = m.first_element; e < m.first_element + m.elements; ++e) {
        const V A = fm.nodes[fm.elements[e].i], B = fm.nodes[fm.elements[e].j];
        const double L = (B - A).norm(), dy = B[up] - A[up];
        const auto q = [&](double s) { return l.gradient * std::max(0.0, l.surface - (A[up] + dy * s / L)) * std::abs(dy) / L; };
        std::vector<double> cuts = {0.0, L};
        if (dy != 0) {
          const double s0 = (l.surface - A[up]) * L / dy;
          if (s0 > 0 && s0 < L) cuts.insert(cuts.begin() + 1, s0);
        }
        double F = 0, M = 0;
        for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
          const double c = 0.5 * (cuts[k] + cuts[k + 1]), h = 0.5 * (cuts[k + 1] - cuts[k]);
          for (double g : {-1 / std::sqrt(3.0), 1 / std::sqrt(3.0)}) F += h * q(c + g * h), M += h * q(c + g * h) * (c + g * h);
        }
        fm.permanent[e][0] += dir * ((4 * F - 6 * M / L) / L);
        fm.permanent[e][1] += dir * ((6 * M / L - 2 * F) / L);
      }
    }
  }
}

// Members subdivided into elements with interior nodes evenly spaced along them; supports as restrained DOFs (2D:
// ux, uy, rz; 3D: ux, uy, uz, rx, ry, rz) or springs; nodal masses; the integration options.
template <int D> typename FrameTypes<D>::Model build_model(const Scenario& s) {
  using T = FrameTypes<D>;
  const StructureConfig& st = s.structure;
  typename T::Model fm;
  std::map<std::string, int> node;
  for (const auto& n : st.nodes) {
    node[n.name] = static_cast<int>(fm.nodes.size());
    Vec<D> x;
    for (int d = 0; d < D; ++d) x[d] = n.position[d];
    fm.nodes.push_back(x);
  }
  for (const auto& mc : st.members) {
    const MaterialConfig& mat = *std::find_if(s.materials.begin(), s.materials.end(),
                                              [&](const MaterialConfig& m) { return m.name == mc.material; });
    const Section sec = make_section(mc.section);
    FrameMemberDef md{mc.name, static_cast<int>(fm.elements.size()), mc.elements};
    const int a = node.at(mc.start), b = node.at(mc.end);
    const Vec<D> xa = fm.nodes[a], xb = fm.nodes[b];
    int prev = a;
    for (int k = 0; k < mc.elements; ++k) {
      int next = b;
      if (k + 1 < mc.elements) {
        next = static_cast<int>(fm.nodes.size());
        fm.nodes.push_back(xa + (xb - xa) * (double(k + 1) / mc.elements));
      }
      typename T::Element e;
      e.i = prev;
      e.j = next;
      e.section = sec;
      e.s0 = double(k) / mc.elements;
      e.s1 = double(k + 1) / mc.elements;
      e.E = mat.youngs_modulus;
      e.nu = mat.poisson_ratio;
      e.rho = mat.density;
      e.release_i = k == 0 && mc.release_start;
      e.release_j = k + 1 == mc.elements && mc.release_end;
      e.member = static_cast<int>(fm.members.size());
      if (mat.model == "elastic_plastic") {
        e.steel = SteelLaw{mat.youngs_modulus, mat.yield_strength, mat.hardening_ratio, mat.steel_curve, mat.transition_r0, mat.transition_a1,
                           mat.transition_a2};
        e.integration_points = st.integration_points;
      }
      if constexpr (D == 3)
        if (mc.orientation.size() == 3) e.orientation = Vec3(mc.orientation[0], mc.orientation[1], mc.orientation[2]);
      fm.elements.push_back(e);
      prev = next;
    }
    fm.members.push_back(md);
  }
  add_pressure_loads(st, fm);
  constexpr int n_dof = D == 2 ? 3 : 6, n_tr = D;
  for (const auto& sc : st.supports) {
    typename T::Support d;
    d.node = node.at(sc.node);
    if (sc.type == "fixed") {
      for (int c = 0; c < n_dof; ++c) d.fixed[c] = true;
    } else if (sc.type == "pinned") {
      for (int c = 0; c < n_tr; ++c) d.fixed[c] = true;
    } else if (sc.type == "roller") {
      d.fixed[sc.restrained == "x" ? 0 : sc.restrained == "y" ? 1 : 2] = true;
    } else {
      for (int k = 0; k < n_dof; ++k) d.spring[k] = sc.stiffness[k];
    }
    fm.supports.push_back(d);
  }
  for (const auto& m : st.masses) fm.masses.push_back(typename T::Mass{node.at(m.node), m.mass, m.rotary_inertia});
  fm.theory = st.theory == BeamTheoryKind::timoshenko ? BeamTheory::timoshenko : BeamTheory::euler_bernoulli;
  fm.transform = st.transformation == FrameTransformKind::corotational ? FrameTransform::corotational : FrameTransform::linear;
  fm.mass = st.mass == FrameMassKind::consistent ? MassMatrix::consistent : MassMatrix::lumped;
  fm.integrator = st.integrator == FrameIntegratorKind::newmark ? FrameIntegrator::newmark : FrameIntegrator::explicit_euler;
  if (st.self_weight)
    for (int d = 0; d < D; ++d) fm.gravity[d] = s.analysis.gravity[d];
  fm.rayleigh_mass = st.rayleigh_mass;
  fm.rayleigh_stiffness = st.rayleigh_stiffness;
  fm.modal_damping = ModalDamping{st.modal_damping_ratio, st.modal_damping_max_frequency};
  fm.hht_alpha = st.hht_alpha;
  return fm;
}

}  // namespace

FrameModel build_frame_model(const Scenario& s) { return build_model<2>(s); }
SpaceFrameModel build_space_frame_model(const Scenario& s) { return build_model<3>(s); }

template <int D> MemberCoupling build_coupling(const Scenario& s, const Scene<D>& scene) {
  const MemberContactConfig& mc = s.member_contact;
  MemberCoupling c{mc.mode, mc.friction, mc.decay, mc.decay_scale, mc.distance, mc.detection, {}, {}};
  for (const Body& b : scene.bodies) {
    const bool listed = mc.bodies.empty() || std::find(mc.bodies.begin(), mc.bodies.end(), b.name) != mc.bodies.end();
    if (listed && std::find(c.fields.begin(), c.fields.end(), b.field) == c.fields.end()) c.fields.push_back(b.field);
  }
  std::sort(c.fields.begin(), c.fields.end());
  for (const Body& b : scene.bodies)
    if (std::find(mc.bonded.begin(), mc.bonded.end(), b.name) != mc.bonded.end()) c.bonded_fields.push_back(b.field);
  return c;
}

template MemberCoupling build_coupling<2>(const Scenario&, const Scene<2>&);
template MemberCoupling build_coupling<3>(const Scenario&, const Scene<3>&);

}  // namespace dmi

namespace dmi {

// The frame as design/ needs it (docs/results.md, /documents/structure): geometry, sections and
// materials of every element, members and supports, so results.h5 alone answers "which section
// carried these forces" without the scenario parser. A space frame adds each element's depth axis e2.
template <class F> StructureRecord structure_record(const Scenario& s, const F& frame) {
  const auto& fm = frame.model();
  constexpr bool space = std::is_same_v<F, SpaceFrame>;
  constexpr int D = space ? 3 : 2;
  StructureRecord r;
  r.dimension = D;
  for (std::size_t k = 0; k < fm.nodes.size(); ++k) {
    r.nodes_m.emplace_back(fm.nodes[k].data(), fm.nodes[k].data() + D);
    r.node_names.push_back(k < s.structure.nodes.size() ? s.structure.nodes[k].name : "");
  }
  for (std::size_t k = 0; k < fm.elements.size(); ++k) {
    const auto& e = fm.elements[k];
    const Section& c = e.section;
    ElementRecord el;
    el.member = e.member, el.i = e.i, el.j = e.j, el.s0 = e.s0, el.s1 = e.s1;
    el.section = section_record(c);
    el.youngs_modulus_Pa = e.E, el.poisson_ratio = e.nu, el.density_kg_m3 = e.rho;
    if (e.steel.fy > 0) el.yield_strength_Pa = e.steel.fy, el.hardening_ratio = e.steel.hardening;
    if (e.steel.fy > 0 && e.steel.curve == SteelCurve::menegotto_pinto) el.steel_curve = "menegotto_pinto";
    if constexpr (space) {
      const Eigen::Matrix3d a = frame.axes(static_cast<int>(k));
      el.e2 = {a(1, 0), a(1, 1), a(1, 2)};
    }
    r.elements.push_back(el);
  }
  for (std::size_t k = 0; k < fm.members.size(); ++k) {
    const auto& m = fm.members[k];
    r.members.push_back({m.name, s.structure.members[k].material, m.first_element, m.elements});
  }
  for (std::size_t k = 0; k < fm.supports.size(); ++k) {
    const auto& d = fm.supports[k];
    const std::string& node = s.structure.supports[k].node;
    r.supports.push_back({node, s.structure.supports[k].type, "supports/" + node + "/reaction", d.node, std::vector<bool>(d.fixed, d.fixed + 3 * (D - 1))});
  }
  r.gravity_m_s2.assign(fm.gravity.data(), fm.gravity.data() + D);
  r.plane_thickness_m = s.analysis.thickness;
  return r;
}

template StructureRecord structure_record(const Scenario&, const Frame&);
template StructureRecord structure_record(const Scenario&, const SpaceFrame&);

}  // namespace dmi
