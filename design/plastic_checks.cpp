#include "design/plastic_checks.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace dmi::design {

using nlohmann::json;

std::string member_group(const std::string& name) { return name.substr(0, name.find('_')); }

Residual residual_of(const std::vector<double>& time, const std::vector<double>& u, double window) {
  Residual out;
  if (time.empty() || u.size() != time.size()) return out;
  const double t_end = time.back();
  double sum = 0, lo = INFINITY, hi = -INFINITY;
  int n = 0;
  for (std::size_t k = 0; k < time.size(); ++k)
    if (time[k] >= t_end - window) sum += u[k], ++n, lo = std::min(lo, u[k]), hi = std::max(hi, u[k]);
  out.value = sum / n - u.front();
  out.amplitude = 0.5 * (hi - lo);
  return out;
}

namespace {

// What a member's elements did, from the last row of frame/plastic (three columns per element).
struct MemberPlastic {
  double work = 0, peak_strain = 0, peak_time = -1, position = 0.5;
  bool yielded = false;
};

MemberPlastic member_plastic(const Results& r, const Series& s, const FrameInfo::Member& m) {
  MemberPlastic out;
  const std::size_t nc = s.components.size(), rows = s.samples();
  const double* last = s.data.data() + (rows - 1) * nc;
  int peak_element = -1;
  for (int e = m.first; e < m.first + m.count; ++e) {
    out.work += last[3 * e];
    out.yielded = out.yielded || last[3 * e + 2] > 0;
    if (last[3 * e + 1] > out.peak_strain) out.peak_strain = last[3 * e + 1], peak_element = e;
  }
  if (peak_element < 0) return out;
  out.position = (peak_element - m.first + 0.5) / m.count;
  for (std::size_t k = 0; k < rows; ++k)  // the running maximum first reaches its final value
    if (s.data[k * nc + 3 * peak_element + 1] >= out.peak_strain * (1 - 1e-12)) {
      out.peak_time = r.time[k];
      break;
    }
  return out;
}

Check base_check(const std::string& id, const std::string& title, const std::string& member, const std::string& unit,
                 const std::string& formula, const std::string& source) {
  Check c;
  c.id = id, c.title = title, c.member = member, c.material = "steel", c.unit = unit, c.formula = formula, c.source = source;
  c.level = "ultimate";
  c.situation = "accidental";
  return c;
}

void place(Check& c, const FrameInfo& f, const FrameInfo::Member& m, double position) {
  const auto& a = f.nodes[f.elements[m.first].i];
  const auto& b = f.nodes[f.elements[m.first + m.count - 1].j];
  c.position = position, c.s_m = position * m.length, c.space = f.dim == 3;
  c.x_m = a[0] + position * (b[0] - a[0]), c.y_m = a[1] + position * (b[1] - a[1]), c.z_m = a[2] + position * (b[2] - a[2]);
}

// The largest compression over the member's stations (N > 0) and when and where it acted.
Check buckling_check(const FrameInfo& f, const FrameInfo::Member& m, const MemberEnvelope& env, const SteelLimits& S) {
  const FrameInfo::Element& e = f.elements[m.first];
  const Section& sec = e.section;
  const double A = sec.area(0), I = sec.kind() == SectionKind::pipe ? sec.inertia(0) : std::min(sec.inertia(0), sec.inertia_y(0));
  // Pipes: the limits' curve; solid, box and I sections curve c (Table 6.2: solid, cold-formed or welded box, welded I
  // about z-z), about the weaker axis.
  const std::string curve = sec.kind() == SectionKind::pipe ? S.buckling_curve : "c";
  Check c = base_check("steel_flexural_buckling", "flexural buckling, L_cr = L (curve " + curve + ")", m.name, "N",
                       "N_Ed <= chi A f_y / gamma_M1, chi from lambda = sqrt(A f_y / N_cr), N_cr = pi^2 E I / L^2",
                       "EN 1993-1-1 6.3.1, eqs. 6.46-6.50, Tables 6.1-6.2");
  c.capacity = flexural_buckling_resistance(A, I, m.length, e.E, S.yield_strength, buckling_imperfection(curve), S.gamma_M1);
  for (const Station& st : env.stations)
    if (st.N_min.set && -st.N_min.value > c.demand) {
      c.demand = -st.N_min.value, c.time_s = st.N_min.time;
      place(c, f, m, st.position);
    }
  c.finish();
  return c;
}

// The crest's residual displacement along the flow (and across it in 3D): the nodes at the top of the frame.
std::optional<PlasticRecord::Drift> residual_drift(const Results& r, const FrameInfo& f, const std::optional<DesignBasis>& basis, const SteelLimits& S,
                                                   std::vector<Check>& checks) {
  const Series* d = r.find("frame/displacement");
  if (!d || d->samples() != r.time.size() || r.time.size() < 2) return std::nullopt;
  const int up = f.dim == 3 ? 2 : 1, per = f.dim == 3 ? 6 : 3;
  double top = -INFINITY, bottom = INFINITY;
  for (const auto& n : f.nodes) top = std::max(top, n[up]), bottom = std::min(bottom, n[up]);
  const double height = basis && is_set(basis->dam.height_m) ? basis->dam.height_m : top - bottom;
  if (!(height > 0)) return std::nullopt;  // a frame without height (a horizontal member) has no drift
  const std::vector<double>& periods = r.info.stats.frame_periods;
  const double window = !periods.empty() ? periods.front() : 0.1 * (r.time.back() - r.time.front());
  Residual worst;
  double worst_h = -1;
  int node = -1;
  for (std::size_t k = 0; k < f.nodes.size(); ++k) {
    if (f.nodes[k][up] < top - 1e-6 * std::max(1.0, std::abs(top))) continue;
    Residual along[2];
    for (int c = 0; c < f.dim - 1; ++c) {
      std::vector<double> u(r.time.size());
      for (std::size_t s = 0; s < u.size(); ++s) u[s] = d->data[s * d->components.size() + per * k + c];
      along[c] = residual_of(r.time, u, window);
    }
    const double h = std::hypot(along[0].value, f.dim == 3 ? along[1].value : 0.0);
    if (h > worst_h) worst_h = h, node = int(k), worst = {h, std::hypot(along[0].amplitude, f.dim == 3 ? along[1].amplitude : 0.0)};
  }
  if (node < 0) return std::nullopt;
  Check c = base_check("steel_residual_drift", "residual drift of the crest", "", "-",
                       "|u_res| / H <= limit, u_res the mean crest displacement over the last period minus the state at rest",
                       "FEMA P-58-1 Table C-1 (1 %: realignment no longer economic)");
  c.demand = worst.value / height, c.capacity = S.residual_drift_limit, c.time_s = r.time.back();
  c.x_m = f.nodes[node][0], c.y_m = f.nodes[node][1], c.z_m = f.nodes[node][2], c.space = f.dim == 3;
  c.finish();
  checks.push_back(c);
  return PlasticRecord::Drift{node, worst.value, worst.amplitude, height, window, worst.value / height, worst.amplitude <= 0.2 * worst.value};
}

// The struck pipe's dent: the depth at which its wall carries the contact pulse's mean force, and the depth that
// absorbs the impact's energy (the boulder's kinetic energy, at most the work the material did on the members); the
// smaller governs. A knife-edge contact (b = 0), the lower resistance curve.
std::optional<PlasticRecord::Dent> dent(const Results& r, const FrameInfo& f, const std::optional<DesignBasis>& basis, const Contact& contact,
                                        const SteelLimits& S, std::vector<Check>& checks) {
  if (!r.info.peak_contact || r.info.peak_contact->loads.empty() || !contact.present) return std::nullopt;
  std::map<std::string, double> per_member;
  for (const ContactLoadAt& l : r.info.peak_contact->loads) {
    double m2 = 0;
    for (double x : l.force) m2 += x * x;
    per_member[l.member] += std::sqrt(m2);
  }
  const auto struck = std::max_element(per_member.begin(), per_member.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
  const auto m = std::find_if(f.members.begin(), f.members.end(), [&](const FrameInfo::Member& x) { return x.name == struck->first; });
  if (m == f.members.end() || f.elements[m->first].section.kind() != SectionKind::pipe) return std::nullopt;
  const Section& sec = f.elements[m->first].section;
  const double D = sec.depth(0), t = sec.wall_thickness();
  const double duration = contact.pulse_end_s - contact.pulse_start_s;
  const double F = duration > 0 ? contact.pulse_impulse_N_s / duration : contact.peak_N;
  const Series* cw = r.find("energy/contact_work");
  double work = 0;
  if (cw) for (double w : cw->data) work = std::max(work, w);
  double E = work;
  if (basis && basis->boulder && is_set(basis->boulder->mass_kg) && is_set(basis->boulder->speed_m_s))
    E = std::min(E, 0.5 * basis->boulder->mass_kg * basis->boulder->speed_m_s * basis->boulder->speed_m_s);
  const double w_force = dent_depth_at_force(F, D, t, S.yield_strength, 0), w_energy = dent_depth_for_energy(E, D, t, S.yield_strength, 0);
  const double w = std::min({w_force, w_energy, D});
  Check c = base_check("steel_dent", "dent of the struck pipe", m->name, "-",
                       "w/D <= limit; w the smaller of R(w) = F (contact pulse mean force) and int R dw = E (impact energy), "
                       "R = 22 f_y t^2/4 sqrt(D/t) (w/D)^0.55",
                       "DNV-RP-C204 (2010) sec. 3.10 (knife-edge contact); limit ASME B31.8 851.4.1");
  c.demand = w / D, c.capacity = S.dent_depth_limit, c.time_s = contact.peak_time_s;
  place(c, f, *m, r.info.peak_contact->loads[0].position);
  c.finish();
  checks.push_back(c);
  return PlasticRecord::Dent{m->name, D, t, F, E, std::min(w_force, D), std::min(w_energy, D), w};
}

}  // namespace

std::optional<PlasticRecord> plastic_part(const Results& r, const FrameInfo& f, const std::vector<MemberEnvelope>& members,
                                          const std::optional<DesignBasis>& basis, const Contact& contact, const SteelLimits& S,
                                          std::vector<Check>& checks, const std::string& where) {
  if (std::none_of(f.members.begin(), f.members.end(), [](const FrameInfo::Member& m) { return m.plastic; })) return std::nullopt;
  const Series* s = r.find("frame/plastic");
  if (!s || s->components.size() != 3 * f.elements.size() || s->samples() != r.time.size() || r.time.empty())
    throw std::runtime_error(where + ": frame/plastic is missing or malformed although the structure has elasto-plastic members");
  PlasticRecord out;
  if (r.info.structure && std::any_of(r.info.structure->elements.begin(), r.info.structure->elements.end(),
                                      [](const ElementRecord& e) { return e.steel_curve == "menegotto_pinto"; }))
    out.member_model += " (Menegotto-Pinto steel)";
  for (std::size_t k = 0; k < f.members.size(); ++k) {
    const FrameInfo::Member& m = f.members[k];
    if (!m.plastic) continue;
    const MemberPlastic p = member_plastic(r, *s, m);
    out.energy.by_group_J[member_group(m.name)] += p.work;
    out.members.push_back({m.name, member_group(m.name), p.work, p.peak_strain, p.yielded});
    Check strain = base_check("steel_strain", "peak strain", m.name, "-", "eps_max at the section surface <= eps_lim",
                              "EN 1993-1-5 Annex C.8(1), Note 1 (limiting principal strain 5 %)");
    strain.demand = p.peak_strain, strain.capacity = S.strain_limit, strain.time_s = p.peak_time;
    place(strain, f, m, p.position);
    strain.finish();
    checks.push_back(strain);
    const Section& sec = f.elements[m.first].section;
    if (p.yielded && sec.kind() == SectionKind::pipe) {
      Check cls = base_check("steel_hinge_class", "class 1 where it yields", m.name, "-", "D/t <= 50 eps^2, eps^2 = 235/f_y[MPa]",
                             "EN 1993-1-1 5.6(2) and Table 5.2 (sheet 3)");
      cls.demand = sec.depth(0) / sec.wall_thickness(), cls.capacity = 50 * 235e6 / S.yield_strength;
      cls.finish();
      checks.push_back(cls);
    } else if (p.yielded && sec.thin_walled()) {
      Check cls = base_check("steel_hinge_class", "class 1 where it yields", m.name, "-",
                             "largest c/t of flanges and webs over its class-1 limit <= 1: box 33 eps and 72 eps, I outstand 9 eps and web 72 eps",
                             "EN 1993-1-1 5.6(2) and Table 5.2 (sheets 1-2)");
      cls.demand = flanged_class_ratio(sec, S.yield_strength, 1), cls.capacity = 1;
      cls.finish();
      checks.push_back(cls);
    }
    const Check b = buckling_check(f, m, members[k], S);
    if (b.demand > 0) checks.push_back(b);
  }
  const auto last_of = [&](const char* path) {
    const Series* e = r.find(path);
    return e && !e->data.empty() ? e->data.back() : 0.0;
  };
  PlasticRecord::Energy& energy = out.energy;
  energy.plastic_work_J = last_of("energy/frame_plastic");
  energy.damping_J = last_of("energy/frame_damping");
  energy.elastic_at_end_J = last_of("energy/frame_strain");
  energy.kinetic_at_end_J = last_of("energy/frame_kinetic");
  if (const Series* cw = r.find("energy/contact_work")) energy.contact_work_max_J = *std::max_element(cw->data.begin(), cw->data.end());
  if (basis && basis->boulder && is_set(basis->boulder->mass_kg) && is_set(basis->boulder->speed_m_s))
    energy.boulder_kinetic_J = 0.5 * basis->boulder->mass_kg * basis->boulder->speed_m_s * basis->boulder->speed_m_s;
  out.residual_drift = residual_drift(r, f, basis, S, checks);
  out.dent = dent(r, f, basis, contact, S, checks);
  return out;
}

}  // namespace dmi::design
