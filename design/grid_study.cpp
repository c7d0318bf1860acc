#include "design/grid_study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace dmi::design {

using nlohmann::json;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Observed order for unequal ratios and a monotone sequence (e32 / e21 > 0): the root of
//   e32 / e21 = r21^p (r32^p - 1) / (r21^p - 1)
// (Celik et al. 2008, eqs. 3-5, with the sign kept: p <= 0 means the change does not shrink with the cell). The
// right side increases with p, so bisection on [-20, 30] finds it.
double observed_order(double r21, double r32, double e21, double e32) {
  const double target = e32 / e21;
  auto g = [&](double p) {
    if (std::abs(p) < 1e-12) return std::log(r32) / std::log(r21);
    return std::pow(r21, p) * (std::pow(r32, p) - 1) / (std::pow(r21, p) - 1);
  };
  double lo = -20, hi = 30;
  if (target <= g(lo)) return lo;
  if (target >= g(hi)) return hi;
  for (int it = 0; it < 200 && hi - lo > 1e-13; ++it) {
    const double mid = 0.5 * (lo + hi);
    (g(mid) < target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

GridConvergence grid_convergence(const std::array<double, 3>& h, const std::array<double, 3>& f) {
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(h[i]) || !std::isfinite(f[i]) || !(h[i] > 0))
      throw std::invalid_argument("grid_convergence: non-finite value or cell size at grid " + std::to_string(i + 1));
  if (!(h[0] < h[1] && h[1] < h[2])) throw std::invalid_argument("grid_convergence: cell sizes must increase from fine to coarse");
  GridConvergence c;
  c.h = h, c.f = f;
  const double r21 = h[1] / h[0], r32 = h[2] / h[1];
  const double e21 = f[1] - f[0], e32 = f[2] - f[1];
  const double scale = std::max({std::abs(f[0]), std::abs(f[1]), std::abs(f[2])});
  const double f1 = std::abs(f[0]) > 0 ? std::abs(f[0]) : scale;
  c.order = c.asymptotic_ratio = kNaN;
  c.extrapolated = f[0];
  if (scale == 0 || (std::abs(e21) <= 1e-9 * scale && std::abs(e32) <= 1e-9 * scale)) {
    c.behaviour = GridBehaviour::converged;
    c.gci = 0;
    return c;
  }
  if (e21 == 0 || e32 / e21 < 0) {  // oscillatory (or the fine pair equal): the spread bounds the error
    c.behaviour = GridBehaviour::oscillatory;
    c.safety_factor = 1.25;
    c.gci = c.safety_factor * std::max(std::abs(e21), std::abs(f[2] - f[0])) / f1;
    return c;
  }
  const double p = observed_order(r21, r32, e21, e32);
  const bool diverging = !(p > 0);  // the change does not shrink as the cell does
  double p_used = p;
  if (diverging) {
    c.behaviour = GridBehaviour::diverging;
  } else if (p < 0.5 || p > 4) {
    c.behaviour = GridBehaviour::out_of_range;
  } else {
    c.behaviour = GridBehaviour::monotone;
  }
  if (c.behaviour != GridBehaviour::monotone) {
    p_used = std::clamp(diverging ? 0.5 : p, 0.5, 2.0);
    c.safety_factor = 3.0;
  }
  c.order = diverging ? kNaN : p;
  const double rp = std::pow(r21, p_used);
  c.extrapolated = diverging ? f[0] : (rp * f[0] - f[1]) / (rp - 1);
  c.gci = c.safety_factor * std::abs(e21) / f1 / (rp - 1);
  if (!diverging) {
    const double gci32 = c.safety_factor * std::abs(e32) / std::max(std::abs(f[1]), 1e-300) / (std::pow(r32, p_used) - 1);
    c.asymptotic_ratio = gci32 / (rp * c.gci);
  }
  return c;
}

const char* behaviour_name(GridBehaviour b) {
  switch (b) {
    case GridBehaviour::converged: return "converged";
    case GridBehaviour::monotone: return "monotone";
    case GridBehaviour::out_of_range: return "outside_asymptotic_range";
    case GridBehaviour::oscillatory: return "oscillatory";
    case GridBehaviour::diverging: return "diverging";
  }
  return "";
}

std::string describe(const GridConvergence& c) {
  char b[256];
  switch (c.behaviour) {
    case GridBehaviour::converged: return "the same on all three grids";
    case GridBehaviour::monotone:
      std::snprintf(b, sizeof b, "converging monotonically, observed order %.2f", c.order);
      return b;
    case GridBehaviour::out_of_range:
      std::snprintf(b, sizeof b, "converging but outside the asymptotic range (observed order %.2f); index with Fs = 3 and order %.1f",
                    c.order, std::clamp(c.order, 0.5, 2.0));
      return b;
    case GridBehaviour::oscillatory:
      return "NOT CONVERGED: oscillates under refinement; the uncertainty is 1.25 times the spread of the three values";
    case GridBehaviour::diverging:
      return "NOT CONVERGED: the change grows as the cell shrinks; index with Fs = 3 and order 0.5, a rough bound only";
  }
  return "";
}

namespace {

const json* find_check(const json& run, const std::string& id, const std::string& member) {
  for (const auto& c : run["checks"])
    if (c["id"] == id && c["member"] == member) return &c;
  return nullptr;
}

double number_at(const json& doc, const json::json_pointer& ptr, const std::string& what, const std::string& folder) {
  if (!doc.contains(ptr) || !doc[ptr].is_number())
    throw std::runtime_error("grid study: " + folder + "/design.json has no number for " + what + " (" + ptr.to_string() + ")");
  const double v = doc[ptr].get<double>();
  if (!std::isfinite(v)) throw std::runtime_error("grid study: " + folder + "/design.json: " + what + " is not finite");
  return v;
}

json quantity(const std::string& variant, const std::string& id, const std::string& title, const std::string& unit,
              const std::array<double, 3>& h, const std::array<double, 3>& f) {
  const GridConvergence c = grid_convergence(h, f);
  auto num = [](double v) { return std::isfinite(v) ? json(v) : json(nullptr); };
  const double bound = std::abs(f[0]) * (1 + c.gci);
  return json{{"variant", variant}, {"id", id}, {"title", title}, {"unit", unit}, {"values", {f[0], f[1], f[2]}},
              {"observed_order", num(c.order)}, {"extrapolated", num(c.extrapolated)}, {"gci", c.gci},
              {"safety_factor", c.safety_factor}, {"asymptotic_ratio", num(c.asymptotic_ratio)},
              {"behaviour", behaviour_name(c.behaviour)}, {"converged", c.behaviour == GridBehaviour::converged || c.behaviour == GridBehaviour::monotone},
              {"conservative_magnitude", bound}, {"statement", describe(c)}};
}

}  // namespace

json grid_study_section(const std::array<json, 3>& designs, const std::array<double, 3>& h, const std::array<std::string, 3>& folders) {
  json qs = json::array();
  const json& fine = designs[0];
  for (std::size_t ri = 0; ri < fine["runs"].size(); ++ri) {
    const json& run = fine["runs"][ri];
    const std::string variant = run.value("variant", "");
    std::array<const json*, 3> runs{};
    for (int g = 0; g < 3; ++g) {
      for (const auto& r : designs[g]["runs"])
        if (r.value("variant", "") == variant) runs[g] = &r;
      if (!runs[g]) throw std::runtime_error("grid study: " + folders[g] + "/design.json has no run '" + variant + "'");
    }
    auto add = [&](const std::string& id, const std::string& title, const std::string& unit, const char* ptr) {
      const json::json_pointer p(ptr);
      if (!run.contains(p) || run[p].is_null()) return;  // not in this kind of run (no frame, no contact)
      std::array<double, 3> f{};
      for (int g = 0; g < 3; ++g) f[g] = std::abs(number_at(*runs[g], p, title + " of run '" + variant + "'", folders[g]));
      qs.push_back(quantity(variant, id, title, unit, h, f));
    };
    add("contact_force", "peak contact force", "N", "/contact/peak_force_N");
    add("base_shear", "peak base shear |sum Fx|", "N", "/base_total/Fx_N/abs_max/value");
    add("base_moment", "peak base moment |sum M|", "N m", "/base_total/M_Nm/abs_max/value");
    if (run.contains("verdict") && run["verdict"]["governing"].is_object()) {
      const json& gov = run["verdict"]["governing"];
      const std::string id = gov["id"], member = gov["member"];
      std::array<double, 3> demand{}, util{};
      for (int g = 0; g < 3; ++g) {
        const json* c = find_check(*runs[g], id, member);
        if (!c) throw std::runtime_error("grid study: " + folders[g] + "/design.json has no check '" + id + "' on '" + member + "' (run '" + variant + "')");
        demand[g] = std::abs(number_at(*c, json::json_pointer("/demand"), "demand of " + id, folders[g]));
        double umax = 0;  // the governing utilisation of each grid: the largest of its checks, whichever governs
        for (const auto& cc : (*runs[g])["checks"]) umax = std::max(umax, number_at(cc, json::json_pointer("/utilisation"), "utilisation", folders[g]));
        util[g] = umax;
      }
      qs.push_back(quantity(variant, "governing_demand", gov.value("title", id) + " (" + member + ")", gov.value("unit", ""), h, demand));
      qs.push_back(quantity(variant, "governing_utilisation", "governing utilisation", "-", h, util));
    }
  }
  json out = {{"method", "Roache 1994 grid convergence index, Celik et al. 2008 procedure (ASME V&V 20-2009); Fs 1.25, 3 outside the asymptotic range"},
              {"cell_sizes_m", {h[0], h[1], h[2]}}, {"refinement_ratios", {h[1] / h[0], h[2] / h[1]}},
              {"folders", {folders[0], folders[1], folders[2]}}, {"quantities", qs}};
  int not_converged = 0;
  for (const auto& q : qs) not_converged += q["converged"].get<bool>() ? 0 : 1;
  out["not_converged"] = not_converged;
  return out;
}

}  // namespace dmi::design
