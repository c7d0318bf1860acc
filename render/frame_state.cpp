#include "render/frame_state.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "design/checks.hpp"
#include "engine/structure/fibre.hpp"

namespace dmi::render {

std::size_t nearest_sample(const Results& r, double t) {
  if (r.time.empty()) throw std::runtime_error("results hold no history samples");
  const auto it = std::lower_bound(r.time.begin(), r.time.end(), t);
  if (it == r.time.end()) return r.time.size() - 1;
  const std::size_t k = it - r.time.begin();
  return (k > 0 && t - r.time[k - 1] < *it - t) ? k - 1 : k;
}

namespace {
const Series& need(const Results& r, const char* path, std::size_t columns) {
  const Series* s = r.find(path);
  if (!s || s->components.size() != columns)
    throw std::runtime_error(std::string("history ") + path + " is missing or has the wrong number of columns (expected " + std::to_string(columns) + ")");
  return *s;
}
}  // namespace

FrameState frame_state(const Results& r, const design::FrameInfo& f, std::size_t k) {
  const bool space = f.dim == 3;
  const std::size_t dofs = space ? 6 : 3;
  const Series& d = need(r, "frame/displacement", dofs * f.nodes.size());
  const Series& ef = need(r, "frame/end_forces", 2 * dofs * f.elements.size());
  FrameState s;
  s.x0 = f.nodes;
  for (std::size_t n = 0; n < f.nodes.size(); ++n) {
    const double* u = &d.data[k * d.components.size() + dofs * n];
    s.u.push_back({u[0], u[1], space ? u[2] : 0.0});
  }
  for (std::size_t e = 0; e < f.elements.size(); ++e) {
    const auto& el = f.elements[e];
    ElementState es;
    for (int c = 0; c < 3; ++c) es.xi[c] = s.x0[el.i][c] + s.u[el.i][c], es.xj[c] = s.x0[el.j][c] + s.u[el.j][c];
    es.ci = el.section.half_depth(el.s0), es.cj = el.section.half_depth(el.s1);
    const double* row = &ef.data[k * ef.components.size() + 2 * dofs * e];
    if (space) {
      es.fi = {row[0], row[1], row[2], row[3], row[4], row[5]}, es.fj = {row[6], row[7], row[8], row[9], row[10], row[11]};
      const SpaceFibreStresses a = space_fibre_stresses(el.section, el.s0, es.fi), b = space_fibre_stresses(el.section, el.s1, es.fj);
      es.top_i = a.sigma_max, es.bottom_i = a.sigma_min, es.top_j = b.sigma_max, es.bottom_j = b.sigma_min;
    } else {
      const FibreStresses a = fibre_stresses(el.section, el.s0, {row[0], row[1], row[2]});
      const FibreStresses b = fibre_stresses(el.section, el.s1, {row[3], row[4], row[5]});
      es.top_i = a.sigma_top, es.bottom_i = a.sigma_bottom, es.top_j = b.sigma_top, es.bottom_j = b.sigma_bottom;
    }
    s.elements.push_back(es);
  }
  return s;
}

std::vector<double> demand_history(const Results& r, const design::FrameInfo& f, const std::string& member, double position,
                                   const std::string& id, const design::Limits& L) {
  std::vector<double> out;
  const auto m = std::find_if(f.members.begin(), f.members.end(), [&](const design::FrameInfo::Member& x) { return x.name == member; });
  if (m == f.members.end() || id == "steel_section_class" || id.rfind("solid", 0) == 0 || id == "concrete_punching") return out;
  const bool space = f.dim == 3;
  const Series& ef = need(r, "frame/end_forces", (space ? 12 : 6) * f.elements.size());
  const int k = static_cast<int>(std::lround(position * m->count));
  std::vector<std::pair<int, int>> ends;  // (element, 0 = end i / 1 = end j) meeting at the station
  if (k > 0) ends.push_back({m->first + k - 1, 1});
  if (k < m->count) ends.push_back({m->first + k, 0});
  for (std::size_t t = 0; t < r.time.size(); ++t) {
    double v = 0;
    for (const auto& [e, end] : ends) {
      const auto& el = f.elements[e];
      const double s = end ? el.s1 : el.s0;
      if (space) {  // the design layer's own demands
        const double* q = &ef.data[t * ef.components.size() + 12 * e + 6 * end];
        for (const design::Demand& d : design::space_demands(el.section, s, {q[0], q[1], q[2], q[3], q[4], q[5]}, m->cls == "steel", L))
          if (d.id == id) v = std::max(v, d.demand);
        continue;
      }
      const double* row = &ef.data[t * ef.components.size() + 6 * e + 3 * end];
      const FibreStresses fs = fibre_stresses(el.section, s, {row[0], row[1], row[2]});
      double d = 0;
      if (id == "concrete_flexural_tension") d = std::max({0.0, fs.sigma_top, fs.sigma_bottom});
      else if (id == "concrete_compression") d = std::max({0.0, -fs.sigma_top, -fs.sigma_bottom});
      else if (id == "concrete_shear") d = L.concrete.shear_strength ? fs.tau_max : std::abs(row[1]);
      else if (id == "steel_elastic_stress") d = std::max(std::abs(fs.sigma_top), std::abs(fs.sigma_bottom));
      else if (id == "steel_von_mises") d = fs.von_mises_max;
      else if (id == "steel_shear") d = std::abs(row[1]);
      else if (id == "steel_interaction")
        d = design::chs_interaction(row[0], row[2], el.section.depth(0), el.section.wall_thickness(), L.steel.yield_strength, L.steel.gamma_M0);
      v = std::max(v, d);
    }
    out.push_back(v);
  }
  return out;
}

}  // namespace dmi::render
