#include "design/estimates.hpp"

#include "design/grid_study_record.hpp"
#include "design/record_reader.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include "engine/sdof/practice_loads.hpp"
#include "engine/sdof/sdof.hpp"

namespace dmi::design {

using nlohmann::json;

json Estimate::to_json() const {
  auto num = [&](double v) { return applicable ? json(v) : json(nullptr); };
  json j{{"id", id}, {"title", title}, {"formula", formula}, {"source", source}, {"parameters", parameters}, {"applicable", applicable},
         {"value_N", num(value)}, {"compare_to", compare_to}, {"simulated_N", num(simulated)}, {"ratio", num(ratio)}, {"note", note}};
  if (grid) {
    j["simulated_gci"] = simulated_gci, j["ratio_low"] = ratio_low;
    j["simulated_extrapolated_N"] = simulated_extrapolated ? json(*simulated_extrapolated) : json(nullptr);
    j["ratio_high"] = ratio_high ? json(*ratio_high) : json(nullptr);
  }
  return j;
}


Estimate estimate_from_json(const json& j, const std::string& w) {
  Estimate e;
  e.id = record::text(j, "id", w), e.title = record::text(j, "title", w), e.formula = record::text(j, "formula", w), e.source = record::text(j, "source", w);
  e.parameters = record::text(j, "parameters", w), e.compare_to = record::text(j, "compare_to", w), e.note = record::text(j, "note", w);
  e.applicable = record::flag(j, "applicable", w);
  // Where the estimate does not apply, value, simulated and ratio are null.
  const auto value = [&](const char* key) { return e.applicable ? record::number(j, key, w) : record::number_or(j, key, NAN, w); };
  e.value = value("value_N"), e.simulated = value("simulated_N"), e.ratio = value("ratio");
  if (j.contains("simulated_gci")) {
    e.grid = true;
    e.simulated_gci = record::number(j, "simulated_gci", w), e.ratio_low = record::number(j, "ratio_low", w);
    e.simulated_extrapolated = record::number_or_none(j, "simulated_extrapolated_N", w);
    e.ratio_high = record::number_or_none(j, "ratio_high", w);
  }
  return e;
}

std::vector<Estimate> estimates_from_json(const json& run, const std::string& where) {
  std::vector<Estimate> out;
  const json& list = run.is_object() && run.contains("estimates") ? run["estimates"] : json::array();
  if (!list.is_array()) throw std::runtime_error(where + ".estimates is not an array");
  for (std::size_t k = 0; k < list.size(); ++k) out.push_back(estimate_from_json(list[k], where + ".estimates[" + std::to_string(k) + "]"));
  return out;
}

namespace {

std::string fmt(const char* f, double a, double b = 0, double c = 0, double d = 0, double e = 0, double g = 0) {
  char s[256];
  std::snprintf(s, sizeof s, f, a, b, c, d, e, g);
  return s;
}

struct Table {
  std::vector<Estimate>& out;
  double shear, contact;
  Estimate& add(const char* id, const char* title, const char* formula, const char* source, const char* compare, std::string params, double value) {
    const double sim = std::string(compare) == "peak_base_shear" ? shear : contact;
    out.push_back(Estimate{id, title, formula, source, std::move(params), true, value, compare, sim, sim > 0 ? value / sim : 0.0, ""});
    return out.back();
  }
  void not_applicable(const char* id, const char* title, const char* formula, const char* source, const char* compare, std::string why) {
    Estimate e{id, title, formula, source, "", false, 0, compare, 0, 0, std::move(why)};
    out.push_back(e);
  }
};

constexpr double kG = 9.81;
constexpr double kAssumedFrictionDeg = 30;  // ASTRA's cushion friction angle when the basis gives none

// What every boulder estimate reads: the dam, the rock, the buffer layer under the boulder's projected area
// pi D^2 / 4 (docs/design-checks.md).
struct BoulderCase {
  const DesignBasis& basis;
  const DamBasis& dam;
  const BoulderBasis& rock;
  bool buffer;
  double E, nu, H, W, m, v, D, r, Er, nur, a;
  std::string mv;
  double kb = 0, tb = 0, Eb = 0;
  double nu_c;  // Poisson's ratio of what the rock strikes: the buffer, or the bare face

  explicit BoulderCase(const DesignBasis& b)
      : basis(b), dam(b.dam), rock(*b.boulder), buffer(b.buffer.has_value()), E(dam.youngs_modulus_Pa),
        nu(is_set(dam.poisson_ratio) ? dam.poisson_ratio : 0.2), H(dam.height_m), W(dam.width_m), m(rock.mass_kg), v(rock.speed_m_s),
        D(rock.diameter_m), r(0.5 * D), Er(rock.youngs_modulus_Pa), nur(is_set(rock.poisson_ratio) ? rock.poisson_ratio : 0.25),
        a(std::min(rock.impact_height_m, H)), mv(fmt("m = %.4g kg, v = %.3g m/s", m, v)) {
    if (buffer) {
      Eb = b.buffer->youngs_modulus_Pa, tb = b.buffer->thickness_m;
      kb = sdof::buffer_layer_stiffness(Eb, std::numbers::pi * D * D / 4, tb);
    }
    nu_c = buffer ? b.buffer->poisson_ratio : nu;
  }
};

// Lin, Cheng & Tuan eqs. (21)-(23): the dam as a cantilever SDOF struck by the boulder's impulse. Returns the struck
// section's second moment of area.
double sdof_row(const BoulderCase& c, Table& t) {
  const DamBasis& dam = c.dam;
  const bool buffer = c.buffer;
  const double E = c.E, H = c.H, W = c.W, m = c.m, v = c.v, kb = c.kb;
  const std::string& mv = c.mv;
  double I = 0;
  const char* sdof_formula = buffer ? "F_T = m v ω, ω = √(k_eff / M), k_eff = 1/(1/k + 1/k_b), k = 3EI/H³, M = ρAH/2, k_b = E_b (πD²/4) / t_b"
                                    : "F_T = m v ω_n, ω_n = √(k / M), k = 3EI/H³, M = ρAH/2 (mean section)";
  if (dam.type == DamKind::concrete_gravity) {
    const auto sec = sdof::tapered_rectangular_section(W, dam.crest_thickness_m, dam.base_thickness_m);
    I = sec.second_moment_m4;
    const auto cant = sdof::cantilever_sdof(E, dam.density_kg_m3, sec, H);
    const auto res = buffer ? sdof::buffered_boulder_on_dam(m, v, cant.effective_mass_kg, cant.stiffness_N_per_m, kb)
                            : sdof::boulder_on_dam(m, v, cant.effective_mass_kg, cant.stiffness_N_per_m);
    std::string p = mv + fmt(", k = %.3g N/m, M = %.4g kg", cant.stiffness_N_per_m, cant.effective_mass_kg);
    if (buffer) p += fmt(", k_b = %.3g N/m", kb);
    t.add("sdof_base_force", "SDOF peak base force (Lin, Cheng & Tuan)", sdof_formula, "Lin, Cheng & Tuan eqs. (21)-(23)", "peak_base_shear", p,
          res.peak_base_force_N);
  } else {
    const double Dc = dam.column_diameter_m, tc = dam.column_wall_thickness_m, d = Dc - 2 * tc;
    I = std::numbers::pi / 64 * (std::pow(Dc, 4) - std::pow(d, 4));
    t.not_applicable("sdof_base_force", "SDOF peak base force (Lin, Cheng & Tuan)", sdof_formula, "Lin, Cheng & Tuan eqs. (21)-(23)",
                     "peak_base_shear", "written for a solid gravity dam as one cantilever; a steel open dam is a frame of columns");
  }
  return I;
}

// EN 1991-1-7 C.2.1 eq. (C.1) takes k as the impacting object's stiffness on a rigid structure; here its form is used
// as a spring-mass estimate with the struck member's stiffness at the impact height a (a rock is far stiffer).
void en1991_row(const BoulderCase& c, double I, Table& t) {
  const bool buffer = c.buffer;
  const double E = c.E, a = c.a, m = c.m, v = c.v, kb = c.kb;
  const std::string& mv = c.mv;
  double k = 3 * E * I / (a * a * a);
  if (buffer) k = sdof::series_stiffness(k, kb);
  const auto en = sdof::en1991_hard_impact(v, m, k);
  t.add("en1991_hard_impact", "spring-mass, EN 1991-1-7 eq. (C.1) form",
        buffer ? "F = v √(k m), k = 1/(1/(3EI/a³) + 1/k_b)" : "F = v √(k m), k = 3EI/a³", "EN 1991-1-7 Annex C.2.1 eq. (C.1), k of the struck member",
        "peak_contact_force", mv + fmt(", a = %.3g m, k = %.3g N/m", a, k), en.peak_force_N)
      .note = fmt("pulse %.3g ms", en.duration_s * 1e3);
}

// Hertz and GEO's reduced Hertz: a boulder on the bare, rigid face.
void hertz_rows(const BoulderCase& c, int dimension, Table& t) {
  const bool buffer = c.buffer;
  const double m = c.m, v = c.v, r = c.r, Er = c.Er, nur = c.nur, E = c.E, nu = c.nu;
  const std::string& mv = c.mv;
  const char* hz_formula = "F = (4/3) E* R^½ δ^{3/2}, δ = (15 m v² / (16 E* R^½))^{2/5}";
  const char* geo_formula = "F = K_c 4000 v^1.2 r² kN";
  if (!buffer) {
    const auto hz = sdof::hertz_sphere_impact(m, v, r, Er, nur, E, nu);
    t.add("hertz", "Hertz sphere on an elastic half-space", hz_formula, "Johnson (1985) Contact Mechanics ch. 11", "peak_contact_force",
          mv + fmt(", R = %.3g m, E* = %.3g Pa", r, hz.effective_modulus_Pa), hz.peak_force_N)
        .note = fmt("contact %.3g ms", hz.contact_duration_s * 1e3) +
                (dimension == 2 ? "; the 2D model strikes with an equal-mass cylinder as long as the width represented" : "; the 3D model strikes with the sphere");
    t.add("geo_hertz", "GEO Report 270 reduced Hertz", geo_formula, "Kwan (2012) GEO Report 270", "peak_contact_force",
          fmt("v = %.3g m/s, r = %.3g m, K_c = 0.1", v, r), sdof::geo_hertz_impact_force_N(v, r));
  } else {
    const char* why = "a boulder on a bare face; here the boulder strikes the buffer (the cushion formulas below)";
    t.not_applicable("hertz", "Hertz sphere on an elastic half-space", hz_formula, "Johnson (1985) Contact Mechanics ch. 11", "peak_contact_force", why);
    t.not_applicable("geo_hertz", "GEO Report 270 reduced Hertz", geo_formula, "Kwan (2012) GEO Report 270", "peak_contact_force", why);
  }
}

// Japan Road Association (2000): Hertz-type, with the Lame constant of what is struck (the buffer, or the bare face).
void japanese_row(const BoulderCase& c, Table& t) {
  const bool buffer = c.buffer;
  const double m = c.m, v = c.v, E = c.E, Eb = c.Eb, nu_c = c.nu_c;
  const DamBasis& dam = c.dam;
  const double Hf = v * v / (2 * kG);
  const char* jp_formula = "P = 2.108 W^{2/3} λ^{2/5} H^{3/5} (kN, kN/m², m), W = m g, H = v²/(2g)";
  const char* jp_source = "Japan Road Association (2000) Rockfall Countermeasure Handbook";
  if (std::isnan(nu_c)) {
    t.not_applicable("japanese_rockfall", "Japanese rock-fall formula", jp_formula, jp_source, "peak_contact_force",
                     "the design basis has no tyre_buffer/poisson_ratio (results written before it was recorded)");
  } else if (!(nu_c > 0)) {
    t.not_applicable("japanese_rockfall", "Japanese rock-fall formula", jp_formula, jp_source, "peak_contact_force",
                     "Lamé's λ = E ν / ((1 + ν)(1 − 2ν)) is not positive for ν ≤ 0");
  } else if (!buffer && dam.type == DamKind::steel_open) {
    t.not_applicable("japanese_rockfall", "Japanese rock-fall formula", jp_formula, jp_source, "peak_contact_force",
                     "written for a rock on a cushion or a soil or concrete half-space; a steel pipe is neither (λ of steel would give "
                     "ten times the simulated force)");
  } else {
    const double lam = sdof::lame_first_parameter(buffer ? Eb : E, nu_c);
    t.add("japanese_rockfall", "Japanese rock-fall formula", jp_formula, jp_source, "peak_contact_force",
          fmt("W = %.4g kN, λ = %.3g kN/m², H = %.3g m", m * kG / 1e3, lam / 1e3, Hf), sdof::japanese_rockfall_force_N(m, lam, Hf, kG))
        .note = buffer ? "λ of the buffer; half-space form (no thin-cushion factor)" : "λ of the bare concrete face (rigid rock on the dam)";
  }
}

// ASTRA 12006: a granular cushion on a gallery roof.
void astra_row(const BoulderCase& c, Table& t) {
  const bool buffer = c.buffer;
  const double m = c.m, v = c.v, r = c.r, Eb = c.Eb, tb = c.tb, nu_c = c.nu_c;
  const DesignBasis& basis = c.basis;
  const char* as_formula = "F = 2.8 e^-0.5 r^0.7 M_E^0.4 tan φ (m v²/2)^0.6 (kN, m, kN/m², kJ)";
  const char* as_source = "ASTRA 12006 (2008)";
  if (!buffer) {
    t.not_applicable("astra_gallery", "ASTRA rock-fall gallery formula", as_formula, as_source, "peak_contact_force", "needs a cushion layer");
  } else if (std::isnan(nu_c)) {
    t.not_applicable("astra_gallery", "ASTRA rock-fall gallery formula", as_formula, as_source, "peak_contact_force",
                     "the design basis has no tyre_buffer/poisson_ratio (results written before it was recorded)");
  } else {
    const bool given = is_set(basis.buffer->friction_angle_deg);
    const double phi = given ? basis.buffer->friction_angle_deg : kAssumedFrictionDeg;
    const double ME = sdof::constrained_modulus(Eb, nu_c);
    t.add("astra_gallery", "ASTRA rock-fall gallery formula", as_formula, as_source, "peak_contact_force",
          fmt("e = %.3g m, r = %.3g m, M_E = %.3g kN/m², φ = %.3g°, E_k = %.4g kJ", tb, r, ME / 1e3, phi, 0.5 * m * v * v / 1e3),
          sdof::astra_gallery_force_N(tb, r, ME, phi, m, v))
        .note = std::string("calibrated on gravel cushions, a tyre buffer is outside that range; M_E taken as the buffer's constrained modulus") +
                (given ? "" : fmt("; φ = %.0f° assumed (no tyre_buffer/friction_angle_deg)", kAssumedFrictionDeg));
  }
}

void boulder_rows(const DesignBasis& basis, int dimension, Table& t) {
  const BoulderCase c(basis);
  const double I = sdof_row(c, t);
  en1991_row(c, I, t);
  hertz_rows(c, dimension, t);
  japanese_row(c, t);
  astra_row(c, t);
}

// The debris modulus up to which the snout's peak was measured not to depend on E (the bundled surge: +-5 % for
// E 1.25-20 MPa at h 0.05 m; +17 % at 40 MPa, +35 % at 80 MPa; docs/verification.md, "Debris surge: the front").
constexpr double kDebrisModulusShownInertPa = 20e6;

void debris_rows(const DesignBasis& basis, Table& t) {
  const DebrisBasis& f = *basis.debris;
  const double W = basis.dam.width_m;
  const double rho = f.density_kg_m3, h = f.depth_m, v = f.speed_m_s;
  const std::string p = fmt("ρ = %.4g kg/m³, v = %.3g m/s, h = %.3g m, w = %.3g m", rho, v, h, W);
  t.add("geo_debris", "GEO Report 270 dynamic debris load", "F = α ρ v² h w, α = 2.5", "Kwan (2012) GEO Report 270", "peak_contact_force", p,
        sdof::debris_dynamic_force_N(2.5, rho, v, h, W));
  t.add("hydrostatic_dynamic", "hydrostatic plus dynamic debris load", "F = (k ρ g h/2 + α ρ v²) h w, k = 1, α = 1",
        "hydrostatic and hydrodynamic forms, Hübl et al. (2009)", "peak_contact_force", p, sdof::debris_hydrostatic_dynamic_force_N(1, 1, rho, v, h, W, kG));
  t.add("surge_momentum_flux", "momentum flux of the surge", "F = ρ v² h w (a surge stopped by a rigid wall)", "momentum balance",
        "peak_contact_force", p, sdof::debris_dynamic_force_N(1, rho, v, h, W));
  const char* wave = "blunt-front elastic wave (a bound, not a design load)";
  const char* wave_f = "F = ρ c v h w, c = √(M/ρ), M = E(1−ν)/((1+ν)(1−2ν))";
  const bool slurry = is_set(f.bulk_modulus_Pa);
  if ((!slurry && (!is_set(f.youngs_modulus_Pa) || !is_set(f.poisson_ratio))) || !is_set(f.front_length_m)) {
    t.not_applicable("blunt_front_wave", wave, wave_f, "Joukowsky (1900)", "peak_contact_force",
                     "needs the debris modulus and front length in the design basis (results written before they were recorded)");
    return;
  }
  const double front = f.front_length_m;
  if (slurry) {  // a fluid: M = K (nu = 0 in the same formula), c0 its numerical sound speed
    const double K = f.bulk_modulus_Pa;
    t.add("blunt_front_wave", wave, "F = ρ c₀ v h w, c₀ = √(K/ρ)", "Joukowsky (1900)", "peak_contact_force", p + fmt(", K = %.3g MPa", K / 1e6),
          sdof::debris_elastic_wave_force_N(rho, K, 0.0, v, h, W))
        .note = front > 0 ? fmt("a slurry's peak still grows with its sound speed c₀ = %.0f m/s behind a %.2f m snout (a weakly "
                                "compressible fluid has no friction to spread the arrival): keep c₀ near ten times the flow speed and read "
                                "the peak against this bound (docs/verification.md)",
                                std::sqrt(K / rho), front)
                          : "this slurry has a blunt front (front_length 0): its arrival peak is this wave, set by the numerical sound speed c₀";
    return;
  }
  const double E = f.youngs_modulus_Pa, nu = f.poisson_ratio;
  t.add("blunt_front_wave", wave, wave_f, "Joukowsky (1900)", "peak_contact_force", p + fmt(", E = %.3g MPa, ν = %.2f", E / 1e6, nu),
        sdof::debris_elastic_wave_force_N(rho, E, nu, v, h, W))
      .note = front > 0 ? fmt("reached only by a vertical, full-depth front; this surge's snout is %.2f m long, so its peak is set by the "
                              "momentum of the arriving flow, not by E",
                              front) +
                              (E > kDebrisModulusShownInertPa
                                   ? fmt("; but E = %.3g MPa is above the %.0f MPa up to which that was shown: the snout's thin toe "
                                         "strikes as a small blunt front and adds to the peak (docs/verification.md)",
                                         E / 1e6, kDebrisModulusShownInertPa / 1e6)
                                   : std::string())
                        : "this surge has a blunt front (front_length 0): its arrival peak is this elastic wave, which scales with √E, a "
                          "stiffness real loose fronts do not have";
}

}  // namespace

std::vector<Estimate> estimates(const DesignBasis& basis, double shear, double contact, int dimension) {
  std::vector<Estimate> out;
  Table t{out, shear, contact};
  if (basis.boulder) boulder_rows(basis, dimension, t);
  if (basis.debris) debris_rows(basis, t);
  return out;
}

}  // namespace dmi::design
