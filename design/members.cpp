#include "design/members.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "design/loads.hpp"
#include "design/strain_rate_checks.hpp"
#include "engine/structure/fibre.hpp"

namespace dmi::design {

using nlohmann::json;

namespace {

std::string lower(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Concrete or steel: the limits file decides; else the material's name; else a pipe or E >= 100 GPa is steel.
std::string classify(const std::string& member, const std::string& material, const Section& sec, double E, const Limits& L) {
  if (auto it = L.member_material.find(member); it != L.member_material.end()) return it->second;
  const std::string m = lower(material);
  if (m.find("steel") != std::string::npos) return "steel";
  if (m.find("concrete") != std::string::npos) return "concrete";
  return sec.kind() == SectionKind::pipe || E >= 100e9 ? "steel" : "concrete";
}

Section section_of(const SectionRecord& s) {
  if (s.kind == "pipe") return Section::pipe(s.diameter_m, s.wall_thickness_m);
  if (s.kind == "box") return Section::box(s.width_m, s.depth_start_m, s.wall_thickness_m);
  if (s.kind == "i_section") return Section::i_section(s.width_m, s.depth_start_m, s.flange_thickness_m, s.web_thickness_m);
  return s.kind == "tapered_rectangle" ? Section::tapered(s.width_m, s.depth_start_m, s.depth_end_m) : Section::rectangle(s.width_m, s.depth_start_m);
}

}  // namespace

FrameInfo frame_info(const StructureRecord& st, const std::string& where, const Limits& L) {
  FrameInfo f;
  f.dim = st.dimension;
  for (const auto& n : st.nodes_m) f.nodes.push_back({n[0], n[1], f.dim == 3 ? n[2] : 0.0});
  for (const ElementRecord& e : st.elements) {
    FrameInfo::Element el;
    el.member = e.member, el.i = e.i, el.j = e.j, el.s0 = e.s0, el.s1 = e.s1, el.E = e.youngs_modulus_Pa;
    el.section = section_of(e.section);
    el.yield_strength = e.yield_strength_Pa;
    if (f.dim == 3) el.e2 = e.e2;
    f.elements.push_back(el);
  }
  for (const MemberRecord& m : st.members) {
    FrameInfo::Member mb;
    mb.name = m.name, mb.material = m.material, mb.first = m.first_element, mb.count = m.elements;
    const auto& a = f.nodes[f.elements[mb.first].i];
    const auto& b = f.nodes[f.elements[mb.first + mb.count - 1].j];
    mb.length = std::sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) + (b[2] - a[2]) * (b[2] - a[2]));
    const auto& e0 = f.elements[mb.first];
    mb.cls = classify(mb.name, mb.material, e0.section, e0.E, L);
    mb.plastic = e0.yield_strength > 0;
    f.members.push_back(mb);
  }
  for (const SupportRecord& s : st.supports) f.supports.push_back({s.node, s.series, s.node_index});
  for (const auto& entry : L.member_material) {  // not a structured binding: clang < 16 cannot capture one (fuzz build)
    const std::string& name = entry.first;
    if (std::none_of(f.members.begin(), f.members.end(), [&](const FrameInfo::Member& m) { return m.name == name; }))
      throw std::runtime_error(where + ": the limits name member '" + name + "', which the structure does not have");
  }
  return f;
}

std::vector<Demand> space_demands(const Section& sec, double s, const SpaceSectionForces& sf, bool steel, const Limits& L) {
  return space_demands(sec, s, sf, space_fibre_stresses(sec, s, sf), steel, L);
}

std::vector<Demand> space_demands(const Section& sec, double s, const SpaceSectionForces& sf, const SpaceFibreStresses& fs, bool steel,
                                  const Limits& L) {
  const ConcreteLimits& C = L.concrete;
  const SteelLimits& S = L.steel;
  const double V = std::hypot(sf.Vy, sf.Vz), M = std::hypot(sf.My, sf.Mz);
  std::vector<Demand> out;
  if (!steel) {
    out.push_back({"concrete_flexural_tension", std::max(0.0, fs.sigma_max), C.tensile_capacity()});
    out.push_back({"concrete_compression", std::max(0.0, -fs.sigma_min), C.compressive_capacity()});
    out.push_back({"concrete_principal_tension", std::max(0.0, fs.principal_max), C.tensile_capacity()});
    if (C.shear_strength) out.push_back({"concrete_shear", fs.tau_max, C.phi_shear * *C.shear_strength});
    else out.push_back({"concrete_shear", V, concrete_one_way_shear_capacity(C.compressive_strength, C.lambda, sec.width(s), sec.depth(s), C.phi_shear)});
    return out;
  }
  out.push_back({"steel_elastic_stress", std::max(std::abs(fs.sigma_max), std::abs(fs.sigma_min)), S.design_strength()});
  out.push_back({"steel_von_mises", fs.von_mises_max, S.design_strength()});
  if (sec.kind() == SectionKind::pipe) {
    const double D = sec.depth(s), t = sec.wall_thickness();
    out.push_back({"steel_interaction", chs_interaction(sf.N, M, D, t, S.yield_strength, S.gamma_M0), 1.0});
    out.push_back({"steel_shear", V, chs_shear_resistance_with_torsion(sf.T, D, t, S.yield_strength, S.gamma_M0)});
    out.push_back({"steel_torsion", std::abs(sf.T), chs_torsion_resistance(D, t, S.yield_strength, S.gamma_M0)});
  } else if (sec.thin_walled()) {  // box and I: the web(s) along y', the moment Mz in their plane
    const double fy = S.yield_strength, g = S.gamma_M0;
    out.push_back({"steel_interaction", flanged_interaction(sf.N, sf.Mz, sf.My, sec, fy, g), 1.0});
    out.push_back({"steel_shear", std::max(std::abs(sf.Vy) / flanged_shear_resistance(sec, true, fy, g), std::abs(sf.Vz) / flanged_shear_resistance(sec, false, fy, g)), 1.0});
    out.push_back({"steel_torsion", std::abs(sf.T), flanged_torsion_resistance(sec, fy, g)});
  }
  return out;
}

std::vector<Demand> plane_demands(const Section& sec, double s, const SectionForces& sf, const FibreStresses& fs, bool steel, const Limits& L) {
  const ConcreteLimits& C = L.concrete;
  const SteelLimits& S = L.steel;
  std::vector<Demand> out;
  if (!steel) {
    out.push_back({"concrete_flexural_tension", std::max(0.0, std::max(fs.sigma_top, fs.sigma_bottom)), C.tensile_capacity()});
    out.push_back({"concrete_compression", std::max(0.0, -std::min(fs.sigma_top, fs.sigma_bottom)), C.compressive_capacity()});
    if (C.shear_strength) out.push_back({"concrete_shear", fs.tau_max, C.phi_shear * *C.shear_strength});
    else out.push_back({"concrete_shear", std::abs(sf.V), concrete_one_way_shear_capacity(C.compressive_strength, C.lambda, sec.width(s), sec.depth(s), C.phi_shear)});
    return out;
  }
  out.push_back({"steel_elastic_stress", std::max(std::abs(fs.sigma_top), std::abs(fs.sigma_bottom)), S.design_strength()});
  out.push_back({"steel_von_mises", fs.von_mises_max, S.design_strength()});
  if (sec.kind() == SectionKind::pipe) {
    const double D = sec.depth(s), t = sec.wall_thickness();
    out.push_back({"steel_interaction", chs_interaction(sf.N, sf.M, D, t, S.yield_strength, S.gamma_M0), 1.0});
    out.push_back({"steel_shear", std::abs(sf.V), chs_shear_resistance(D, t, S.yield_strength, S.gamma_M0)});
  } else if (sec.thin_walled()) {
    out.push_back({"steel_interaction", flanged_interaction(sf.N, sf.M, 0, sec, S.yield_strength, S.gamma_M0), 1.0});
    out.push_back({"steel_shear", std::abs(sf.V), flanged_shear_resistance(sec, true, S.yield_strength, S.gamma_M0)});
  }
  return out;
}

namespace {

// The persistent design situation of a concrete member (EN 1990 6.4.3.2 eq. 6.10 with Table A1.2(B)): the section
// forces at rest (self-weight, deposit and water, not split by source) with gamma_G,sup = 1.35 where unfavourable and
// gamma_G,inf = 1.0 where favourable: the axial compression of the weight relieves tension, so for the tension checks
// a compressive N keeps 1.0 while shears, moments and torques take 1.35; every other check takes 1.35 throughout.
constexpr double kGammaSup = 1.35, kGammaInf = 1.0;
bool relieved_by_compression(const std::string& id) { return id == "concrete_flexural_tension" || id == "concrete_principal_tension"; }
SectionForces persistent_forces(const SectionForces& f, bool relieving) {
  return {f.N * (relieving && f.N < 0 ? kGammaInf : kGammaSup), kGammaSup * f.V, kGammaSup * f.M};
}
SpaceSectionForces persistent_forces(const SpaceSectionForces& f, bool relieving) {
  const double g = kGammaSup;
  return {f.N * (relieving && f.N < 0 ? kGammaInf : g), g * f.Vy, g * f.Vz, g * f.T, g * f.My, g * f.Mz};
}
Check persistent_proto(const Check& accidental) {
  Check c = accidental;
  c.id += "_persistent", c.title += ", persistent situation (the loads at rest)", c.situation = "persistent";
  c.formula = "gamma_G 1.35 x the forces at rest (a compressive N relieving tension at 1.0); " + c.formula;
  c.source = "EN 1990 6.4.3.2 eq. 6.10, Table A1.2(B); " + c.source;
  return c;
}

// Tracks the governing instance (largest utilisation) of each check of a member, and each check's demand at the first
// history sample at every station (the static state the run starts from), kept as static_demand where it governs.
struct CheckTracker {
  StrainRate rate;  // strain-rate effects on the concrete strengths (design/strain_rate_checks)
  std::map<std::string, Check> by_id;
  std::vector<std::string> order;
  std::map<std::pair<std::string, const Station*>, double> first;
  std::map<std::string, const Station*> at;
  void consider(const Check& proto, double demand, double capacity, const Station& st, double t) {
    const double static_demand = first.emplace(std::make_pair(proto.id, &st), demand).first->second;
    double eps_dot = 0;
    const double dif = strain_rate_factor(proto.id, demand, static_demand, t, rate, &eps_dot);
    capacity *= dif;
    auto it = by_id.find(proto.id);
    const double u = capacity > 0 ? demand / capacity : (demand > 0 ? 1e300 : 0.0);  // as Check::finish
    if (it == by_id.end()) {
      order.push_back(proto.id);
      it = by_id.emplace(proto.id, proto).first;
      it->second.utilisation = -1;
    }
    Check& c = it->second;
    if (u <= c.utilisation) return;
    c.demand = demand, c.capacity = capacity, c.utilisation = u;
    c.position = st.position, c.s_m = st.s_m, c.x_m = st.x, c.y_m = st.y, c.z_m = st.z, c.time_s = t;
    c.dynamic_factor = dif, c.strain_rate = eps_dot;
    at[proto.id] = &st;
  }
  std::vector<Check> result() {
    std::vector<Check> v;
    for (const auto& id : order) {
      Check c = by_id.at(id);
      c.static_demand = first.at({id, at.at(id)});
      if (c.dynamic_factor != 1) {
        char b[160];
        std::snprintf(b, sizeof b, "; x DIF %.3f at %.3g 1/s (fib MC2010 5.1.11.1, eps_dot = (sigma - sigma_0) / (E t_r))", c.dynamic_factor,
                      c.strain_rate);
        c.formula += b;
      }
      c.finish();
      v.push_back(c);
    }
    return v;
  }
};

Check proto(const std::string& id, const std::string& title, const MemberEnvelope& m, const std::string& unit, const std::string& formula,
            const std::string& source) {
  Check c;
  c.id = id, c.title = title, c.member = m.name, c.material = m.cls, c.unit = unit, c.formula = formula, c.source = source;
  c.space = m.dim == 3;
  // Elastic stresses within strengths are the serviceability level; the members' resistances are the ultimate one. A
  // member that yields by design (plastic) reaches its axial + bending resistance by construction: that is its
  // serviceability limit (no permanent deformation), its ultimate level the strain, drift, buckling and dent checks
  // (plastic_checks.hpp); shear and torsion stay ultimate (the fibres do not limit them).
  if (id == "concrete_shear" || id == "steel_shear" || id == "steel_torsion" || (id == "steel_interaction" && !m.plastic)) c.level = "ultimate";
  return c;
}

// Local buckling: the section class of a CHS from D/t (time-independent).
// A box or I section's plates against the class-3 limits.
Check flanged_section_class(const MemberEnvelope& env, const Section& sec, const SteelLimits& S) {
  Check c = proto("steel_section_class", "local buckling (class <= 3)", env, "-",
                  "largest c/t of flanges (compression) and webs (bending) over its class-3 limit <= 1: box 42 eps and 124 eps, "
                  "I outstand 14 eps and web 124 eps, eps = sqrt(235/f_y[MPa])",
                  "EN 1993-1-1 Table 5.2 (sheets 1-2)");
  c.demand = flanged_class_ratio(sec, S.yield_strength, 3), c.capacity = 1;
  c.title += ": class " + std::to_string(flanged_class(sec, S.yield_strength));
  c.finish();
  return c;
}

Check section_class(const MemberEnvelope& env, double D, double t_w, const SteelLimits& S) {
  Check c = proto("steel_section_class", "local buckling (class <= 3)", env, "-", "D/t <= 90 eps^2, eps^2 = 235/f_y[MPa]",
                  "EN 1993-1-1 Table 5.2 (sheet 3)");
  c.demand = D / t_w, c.capacity = chs_class3_limit(S.yield_strength);
  c.title += ": class " + std::to_string(chs_class(D, t_w, S.yield_strength));
  c.finish();
  return c;
}

// A space member (docs/design-checks.md, "Space frames"): resultant shear and moment, torque, stresses around the
// perimeter (space_fibre_stresses, the frame's own function) under biaxial bending, torsion and shear.
void space_member(const Results& r, const Series& ef, const FrameInfo& f, const FrameInfo::Member& m, const Limits& L, const StrainRate& rate,
                  MemberEnvelope& env) {
  const bool steel = m.cls == "steel";
  const bool pipe = f.elements[m.first].section.kind() == SectionKind::pipe;
  const bool flanged = f.elements[m.first].section.thin_walled() && !pipe;  // box or I
  const double D = f.elements[m.first].section.depth(0), t_w = f.elements[m.first].section.wall_thickness();
  const SteelLimits& S = L.steel;
  const Check tension = proto("concrete_flexural_tension", "flexural tension (biaxial)", env, "Pa",
                              "sigma_t = N/A + |My| c_z/I_y + |Mz| c_y/I_z <= phi_f f_t (the most stressed corner)",
                              "f_t: Lin, Cheng & Tuan, Table 1 or ACI 318-19 14.5.2.1 / 19.2.3.1 by tensile_rule; phi: ACI 318-19 21.2.1");
  const Check compr = proto("concrete_compression", "compression (biaxial)", env, "Pa", "|sigma_c| = |N/A - |My| c_z/I_y - |Mz| c_y/I_z| <= phi_c alpha f'c",
                            "elastic fibre stress limit alpha f'c (alpha 0.85, ACI 318-19 22.2.2.4.1); phi: ACI 318-19 21.2.1");
  const Check principal = proto("concrete_principal_tension", "principal tension (bending, torsion, shear)", env, "Pa",
                                "sigma_1 = sigma/2 + sqrt(sigma^2/4 + tau^2) around the perimeter <= phi_f f_t, tau = T/W_t + shear flow",
                                "elastic principal stress (plain concrete has no torsion provision in ACI 318-19 ch. 14; the cracking torque of "
                                "22.7.5 is this criterion); W_t: Timoshenko & Goodier 1970 sec. 109");
  const Check shear_c = L.concrete.shear_strength ? proto("concrete_shear", "shear stress (with torsion)", env, "Pa", "tau = T/W_t + k V/A <= phi_v tau_lim", "user shear limit")
                                         : proto("concrete_shear", "one-way shear (resultant)", env, "N", "|(Vy, Vz)| <= phi_v 0.11 lambda sqrt(f'c) b h",
                                                 "ACI 318-19 Table 14.5.5.1(a), with the resultant of both shear forces");
  const Check elastic = proto("steel_elastic_stress", "extreme-fibre stress (biaxial)", env, "Pa", "max |sigma| around the section <= f_y / gamma_M0",
                              "EN 1993-1-1 6.2.1(5)");
  const Check mises = proto("steel_von_mises", "von Mises stress (with torsion)", env, "Pa", "sqrt(sigma^2 + 3 tau^2) <= f_y / gamma_M0, tau = T/W_t + shear flow",
                            "EN 1993-1-1 6.2.1(5) eq. 6.1");
  const Check inter = flanged ? proto("steel_interaction", "axial + biaxial bending resistance", env, "-",
                                      "|N|/N_Rd + |Mz|/M_z,Rd + |My|/M_y,Rd <= 1, M_Rd = W_pl (class 1-2) or W_el (3) f_y/gamma_M0 about each axis",
                                      "EN 1993-1-1 6.2.1(7) eq. 6.2, 6.2.5 eqs. 6.13-6.14")
                              : proto("steel_interaction", "axial + bending resistance", env, "-",
                                      "|N|/N_Rd + |(My, Mz)|/M_Rd <= 1, M_Rd = W_pl (class 1-2) or W_el (3) f_y/gamma_M0 (a CHS bends about the resultant's axis)",
                                      "EN 1993-1-1 6.2.1(7) eq. 6.2, 6.2.5 eqs. 6.13-6.14");
  const Check shear_s = flanged ? proto("steel_shear", "shear resistance, each axis", env, "-",
                                        "max(|Vy|/V_y,Rd, |Vz|/V_z,Rd) <= 1, V_Rd = A_v f_y / (sqrt 3 gamma_M0), A_v along the web(s) A h/(b + h) (box) "
                                        "or h_w t_w (I), across A b/(b + h) (box) or 2 b t_f (I)",
                                        "EN 1993-1-1 6.2.6 eq. 6.18, 6.2.6(3)(c)-(d)")
                                : proto("steel_shear", "shear resistance with torsion", env, "N",
                                        "|(Vy, Vz)| <= V_pl,T,Rd = [1 - tau_t,Ed / (f_y / (sqrt 3 gamma_M0))] A_v f_y / (sqrt 3 gamma_M0), A_v = 2A/pi",
                                        "EN 1993-1-1 6.2.6 eq. 6.18, 6.2.6(3)(g), 6.2.7(9) eq. 6.28");
  const Check torsion = proto("steel_torsion", "torsional resistance", env, "N m",
                              flanged ? "|T| <= T_Rd = W_t f_y / (sqrt 3 gamma_M0), W_t = 2 A_m t (box, Bredt) or J / t_max (I)"
                                      : "|T| <= T_Rd = W_t f_y / (sqrt 3 gamma_M0), W_t = J / (D/2)",
                              "EN 1993-1-1 6.2.7(1) eq. 6.23 (elastic St Venant resistance)");
  const std::map<std::string, const Check*> protos{{tension.id, &tension}, {compr.id, &compr}, {principal.id, &principal}, {shear_c.id, &shear_c},
                                                   {elastic.id, &elastic}, {mises.id, &mises}, {inter.id, &inter}, {shear_s.id, &shear_s},
                                                   {torsion.id, &torsion}};
  CheckTracker tracker, at_rest;  // at_rest: the persistent situation (no strain-rate effects)
  tracker.rate = rate;
  const std::size_t nc = ef.components.size();
  for (std::size_t k = 0; k < r.time.size(); ++k) {
    const double t = r.time[k];
    for (int e = 0; e < m.count; ++e) {
      const auto& el = f.elements[m.first + e];
      const double* row = &ef.data[k * nc + 12 * (m.first + e)];
      for (int end = 0; end < 2; ++end) {
        Station& st = env.stations[e + end];
        const double* v = row + 6 * end;
        const SpaceSectionForces sf{v[0], v[1], v[2], v[3], v[4], v[5]};
        const double s = end == 0 ? el.s0 : el.s1, V = std::hypot(sf.Vy, sf.Vz), M = std::hypot(sf.My, sf.Mz);  // resultants
        const SpaceFibreStresses fs = space_fibre_stresses(el.section, s, sf);
        st.N_max.max(sf.N, t), st.N_min.min(sf.N, t), st.V_abs.max(V, t), st.M_max.max(M, t);
        st.Vy_abs.max(std::abs(sf.Vy), t), st.Vz_abs.max(std::abs(sf.Vz), t), st.T_abs.max(std::abs(sf.T), t);
        st.My_max.max(sf.My, t), st.My_min.min(sf.My, t), st.Mz_max.max(sf.Mz, t), st.Mz_min.min(sf.Mz, t);
        st.sigma_tension.max(fs.sigma_max, t), st.sigma_compression.min(fs.sigma_min, t);
        st.tau.max(fs.tau_max, t), st.von_mises.max(fs.von_mises_max, t), st.principal.max(fs.principal_max, t);
        for (const Demand& d : space_demands(el.section, s, sf, fs, steel, L)) tracker.consider(*protos.at(d.id), d.demand, d.capacity, st, t);
        if (k > 0 || steel) continue;
        for (bool relieving : {true, false})
          for (const Demand& d : space_demands(el.section, s, persistent_forces(sf, relieving), steel, L))
            if (relieved_by_compression(d.id) == relieving) at_rest.consider(persistent_proto(*protos.at(d.id)), d.demand, d.capacity, st, t);
      }
    }
  }
  env.checks = tracker.result();
  for (const Check& c : at_rest.result()) env.checks.push_back(c);
  if (steel && pipe) env.checks.push_back(section_class(env, D, t_w, S));
  if (steel && flanged) env.checks.push_back(flanged_section_class(env, f.elements[m.first].section, S));
}

}  // namespace

namespace {

// A member's stations: its element ends, with their place and the section depth there.
std::vector<Station> stations_of(const FrameInfo& f, const FrameInfo::Member& m) {
  std::vector<Station> out;
  for (int k = 0; k <= m.count; ++k) {
    const auto& el = f.elements[m.first + std::min(k, m.count - 1)];
    const auto& x = f.nodes[k < m.count ? el.i : el.j];
    Station st;
    st.position = k < m.count ? el.s0 : el.s1, st.s_m = st.position * m.length, st.x = x[0], st.y = x[1], st.z = x[2];
    st.depth = el.section.depth(k < m.count ? el.s0 : el.s1);
    out.push_back(st);
  }
  return out;
}

// A plane member's envelopes and checks over the histories: every element end at every sample, the persistent
// situation at t = 0 (concrete), the section class of a steel pipe.
void plane_member(const Results& r, const Series& ef_series, const FrameInfo& f, const FrameInfo::Member& m, const Limits& L,
                  const StrainRate& rate, MemberEnvelope& env) {
  const Series* ef = &ef_series;
  const ConcreteLimits& C = L.concrete;
  const SteelLimits& S = L.steel;
  const bool steel = m.cls == "steel";
  const bool pipe = f.elements[m.first].section.kind() == SectionKind::pipe;
  const bool flanged = f.elements[m.first].section.thin_walled() && !pipe;  // box or I
  const double D = f.elements[m.first].section.depth(0), t_w = f.elements[m.first].section.wall_thickness();
  // Capacities that do not vary in time (docs/design-checks.md).
  const Check tension = proto("concrete_flexural_tension", "flexural tension", env, "Pa", "sigma_t = N/A + |M| c/I <= phi_f f_t",
                              "f_t: Lin, Cheng & Tuan, Table 1 or ACI 318-19 14.5.2.1 / 19.2.3.1 by tensile_rule; phi: ACI 318-19 21.2.1");
  const Check compr = proto("concrete_compression", "compression", env, "Pa", "|sigma_c| = |N/A - |M| c/I| <= phi_c alpha f'c",
                            "elastic fibre stress limit alpha f'c (alpha 0.85, ACI 318-19 22.2.2.4.1); phi: ACI 318-19 21.2.1");
  const Check shear_c = C.shear_strength ? proto("concrete_shear", "shear stress", env, "Pa", "tau = k V/A <= phi_v tau_lim", "user shear limit")
                                         : proto("concrete_shear", "one-way shear", env, "N", "V <= phi_v 0.11 lambda sqrt(f'c) b h",
                                                 "ACI 318-19 Table 14.5.5.1(a)");
  const Check elastic = proto("steel_elastic_stress", "extreme-fibre stress", env, "Pa", "|N|/A + |M|/W_el <= f_y / gamma_M0",
                              "EN 1993-1-1 6.2.1(5)");
  const Check mises = proto("steel_von_mises", "von Mises stress", env, "Pa", "sqrt(sigma^2 + 3 tau^2) <= f_y / gamma_M0", "EN 1993-1-1 6.2.1(5) eq. 6.1");
  const Check inter = proto("steel_interaction", "axial + bending resistance", env, "-", "|N|/N_Rd + |M|/M_Rd <= 1, M_Rd = W_pl (class 1-2) or W_el (3) f_y/gamma_M0",
                            "EN 1993-1-1 6.2.1(7) eq. 6.2, 6.2.5 eqs. 6.13-6.14");
  const Check shear_s = proto("steel_shear", "shear resistance", env, "N",
                              flanged ? "V <= A_v f_y / (sqrt 3 gamma_M0), A_v = A h/(b + h) (box) or h_w t_w (I)"
                                      : "V <= A_v f_y / (sqrt 3 gamma_M0), A_v = 2A/pi (CHS)",
                              flanged ? "EN 1993-1-1 6.2.6 eq. 6.18, 6.2.6(3)(c)-(d)" : "EN 1993-1-1 6.2.6 eq. 6.18, 6.2.6(3)(g)");
  const std::map<std::string, const Check*> protos{{tension.id, &tension}, {compr.id, &compr}, {shear_c.id, &shear_c}, {elastic.id, &elastic},
                                                   {mises.id, &mises}, {inter.id, &inter}, {shear_s.id, &shear_s}};
  CheckTracker tracker, at_rest;
  tracker.rate = rate;
  for (std::size_t k = 0; k < r.time.size(); ++k) {
    const double t = r.time[k];
    for (int e = 0; e < m.count; ++e) {
      const auto& el = f.elements[m.first + e];
      const double* row = &ef->data[k * ef->components.size() + 6 * (m.first + e)];
      for (int end = 0; end < 2; ++end) {
        Station& st = env.stations[e + end];
        const SectionForces sf{row[3 * end], row[3 * end + 1], row[3 * end + 2]};
        const double s = end == 0 ? el.s0 : el.s1;
        const FibreStresses fs = fibre_stresses(el.section, s, sf);
        st.N_max.max(sf.N, t), st.N_min.min(sf.N, t), st.V_abs.max(std::abs(sf.V), t);
        st.M_max.max(sf.M, t), st.M_min.min(sf.M, t);
        st.sigma_tension.max(std::max(fs.sigma_top, fs.sigma_bottom), t);
        st.sigma_compression.min(std::min(fs.sigma_top, fs.sigma_bottom), t);
        st.tau.max(fs.tau_max, t), st.von_mises.max(fs.von_mises_max, t);
        for (const Demand& d : plane_demands(el.section, s, sf, fs, steel, L)) tracker.consider(*protos.at(d.id), d.demand, d.capacity, st, t);
        if (k > 0 || steel) continue;
        for (bool relieving : {true, false}) {
          const SectionForces pf = persistent_forces(sf, relieving);
          for (const Demand& d : plane_demands(el.section, s, pf, fibre_stresses(el.section, s, pf), steel, L))
            if (relieved_by_compression(d.id) == relieving) at_rest.consider(persistent_proto(*protos.at(d.id)), d.demand, d.capacity, st, t);
        }
      }
    }
  }
  env.checks = tracker.result();
  for (const Check& c : at_rest.result()) env.checks.push_back(c);
  if (steel && pipe) env.checks.push_back(section_class(env, D, t_w, S));
  if (steel && flanged) env.checks.push_back(flanged_section_class(env, f.elements[m.first].section, S));
}

}  // namespace

std::vector<MemberEnvelope> member_envelopes(const Results& r, const FrameInfo& f, const Limits& L, const std::string& where) {
  // The strain-rate factors count the rise from the start of the contact pulse (none without contact).
  const Contact contact_pulse = contact(r);
  const double load_start = contact_pulse.present ? contact_pulse.pulse_start_s : std::numeric_limits<double>::infinity();
  std::vector<MemberEnvelope> out;
  if (f.members.empty()) return out;
  const Series* ef = r.find("frame/end_forces");
  if (!ef) throw std::runtime_error(where + ": missing history frame/end_forces (needed for the member envelopes)");
  const std::size_t per = f.dim == 3 ? 12 : 6;  // N, V, M (plane) or N, Vy, Vz, T, My, Mz (space) at both ends
  if (ef->components.size() != per * f.elements.size())
    throw std::runtime_error(where + ": frame/end_forces has " + std::to_string(ef->components.size()) + " columns, expected " + std::to_string(per) +
                             " x " + std::to_string(f.elements.size()) + " elements");
  for (const auto& m : f.members) {
    MemberEnvelope env;
    env.dim = f.dim, env.name = m.name, env.cls = m.cls, env.length = m.length, env.plastic = m.plastic;
    env.stations = stations_of(f, m);
    const StrainRate rate{L.concrete.strain_rate_effects && m.cls == "concrete", load_start, f.elements[m.first].E};
    if (f.dim == 3)
      space_member(r, *ef, f, m, L, rate, env);
    else
      plane_member(r, *ef, f, m, L, rate, env);
    out.push_back(std::move(env));
  }
  return out;
}

}  // namespace dmi::design
