#include "design/estimates.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "engine/sdof/sdof.hpp"

namespace dmi::design {

using nlohmann::json;

json Estimate::to_json() const {
  return json{{"id", id}, {"title", title}, {"formula", formula}, {"source", source}, {"value_N", value}, {"compare_to", compare_to},
              {"simulated_N", simulated}, {"ratio", ratio}, {"note", note}};
}

namespace {

struct Basis {
  const json& j;
  const std::string& where;
  double get(const char* obj, const char* key) const {
    const std::string p = std::string("/documents/design_basis/") + obj + "/" + key;
    if (!j.contains(obj) || !j[obj].is_object() || !j[obj].contains(key) || !j[obj][key].is_number())
      throw std::runtime_error(where + ": " + p + " missing (expected a number)");
    const double v = j[obj][key];
    if (!(v > 0) || !std::isfinite(v)) throw std::runtime_error(where + ": " + p + " = " + j[obj][key].dump() + ": expected a number > 0");
    return v;
  }
};

Estimate make(const char* id, const char* title, const char* formula, const char* source, double value, const char* compare, double sim) {
  Estimate e{id, title, formula, source, value, compare, sim, sim > 0 ? value / sim : 0.0, ""};
  return e;
}

}  // namespace

std::vector<Estimate> estimates(const json& basis, double shear, double contact, const std::string& where) {
  std::vector<Estimate> out;
  if (!basis.is_object() || !basis.contains("dam")) return out;
  const Basis b{basis, where};
  const std::string type = basis["dam"].value("type", "");
  const double E = b.get("dam", "youngs_modulus_Pa"), nu = basis["dam"].value("poisson_ratio", 0.2), H = b.get("dam", "height_m");
  const double W = b.get("dam", "width_m");
  const bool buffer = basis.contains("tyre_buffer");
  if (basis.contains("boulder")) {
    const double m = b.get("boulder", "mass_kg"), v = b.get("boulder", "speed_m_s"), D = b.get("boulder", "diameter_m");
    const double Er = b.get("boulder", "youngs_modulus_Pa"), nur = basis["boulder"].value("poisson_ratio", 0.25);
    const double a = std::min(b.get("boulder", "impact_height_m"), H);
    double I = 0;
    double kb = 0;  // buffer layer under the boulder's projected area pi D^2 / 4 (an assumption, docs/design-checks.md)
    if (buffer) kb = sdof::buffer_layer_stiffness(b.get("tyre_buffer", "youngs_modulus_Pa"), std::numbers::pi * D * D / 4, b.get("tyre_buffer", "thickness_m"));
    if (type == "concrete_gravity") {
      const auto sec = sdof::tapered_rectangular_section(W, b.get("dam", "crest_thickness_m"), b.get("dam", "base_thickness_m"));
      I = sec.second_moment_m4;
      const auto c = sdof::cantilever_sdof(E, b.get("dam", "density_kg_m3"), sec, H);
      const auto r = buffer ? sdof::buffered_boulder_on_dam(m, v, c.effective_mass_kg, c.stiffness_N_per_m, kb)
                            : sdof::boulder_on_dam(m, v, c.effective_mass_kg, c.stiffness_N_per_m);
      out.push_back(make("sdof_base_force", buffer ? "SDOF peak base force, buffer in series" : "SDOF peak base force",
                         buffer ? "F_T = m v0 omega, omega = sqrt(k_eff / M), k_eff = 1/(1/k + 1/k_b), k = 3EI/H^3, M = rho A H / 2, k_b = E_b (pi D^2/4) / t_b"
                                : "F_T = m v0 omega_n, omega_n = sqrt(k / M), k = 3EI/H^3, M = rho A H / 2 (mean section)",
                         "Lin, Cheng & Tuan eqs. (21)-(23)", r.peak_base_force_N, "peak_base_shear", shear));
    } else {
      const double Dc = b.get("dam", "column_diameter_m"), tc = b.get("dam", "column_wall_thickness_m"), d = Dc - 2 * tc;
      I = std::numbers::pi / 64 * (std::pow(Dc, 4) - std::pow(d, 4));
    }
    // EN 1991-1-7 C.2.1: the struck column or wall as a cantilever loaded at the impact height a.
    double k = 3 * E * I / (a * a * a);
    if (buffer) k = sdof::series_stiffness(k, kb);
    const auto en = sdof::en1991_hard_impact(v, m, k);
    // EN 1991-1-7 C.2.1 takes k as the impacting object's stiffness on a rigid structure; here the form of eq. (C.1) is
    // used as a spring-mass estimate with the struck member's stiffness at the impact height (a rock is far stiffer).
    Estimate e = make("en1991_hard_impact", "spring-mass, EN 1991-1-7 eq. (C.1) form", buffer ? "F = v sqrt(k m), k = 1/(1/(3EI/a^3) + 1/k_b)" : "F = v sqrt(k m), k = 3EI/a^3",
                      "EN 1991-1-7 Annex C.2.1 eq. (C.1), k of the struck member", en.peak_force_N, "peak_contact_force", contact);
    e.note = "pulse " + std::to_string(en.duration_s * 1e3) + " ms";
    out.push_back(e);
    if (!buffer) {  // rigid-barrier formulas: not for a soft buffer
      const auto hz = sdof::hertz_sphere_impact(m, v, 0.5 * D, Er, nur, E, nu);
      e = make("hertz", "Hertz sphere on an elastic half-space", "F = (4/3) E* R^1/2 delta^3/2, delta = (15 m v^2 / (16 E* R^1/2))^2/5",
               "Johnson (1985) Contact Mechanics ch. 11", hz.peak_force_N, "peak_contact_force", contact);
      e.note = "contact " + std::to_string(hz.contact_duration_s * 1e3) + " ms; the 2D model strikes with an equal-mass cylinder";
      out.push_back(e);
      out.push_back(make("geo_hertz", "GEO empirical Hertz (K_c = 0.1)", "F = K_c 4000 v^1.2 r^2 kN", "Kwan (2012) GEO Report 270",
                         sdof::geo_hertz_impact_force_N(v, 0.5 * D), "peak_contact_force", contact));
    }
  }
  if (basis.contains("debris_surge")) {
    const double rho = b.get("debris_surge", "density_kg_m3"), h = b.get("debris_surge", "depth_m"), v = b.get("debris_surge", "speed_m_s");
    out.push_back(make("surge_momentum_flux", "momentum flux of the surge", "F = rho v^2 h W (a surge stopped by a rigid wall)",
                       "momentum balance", rho * v * v * h * W, "peak_contact_force", contact));
  }
  return out;
}

}  // namespace dmi::design
