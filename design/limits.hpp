// Strength limits and factors of the design checks (docs/design-checks.md), with their defaults and
// where they come from. Read from a limits file (`damimpact check --limits limits.json`), so limits
// change without re-simulating. SI units: Pa, m.
#pragma once
#include <map>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace dmi::design {

struct ConcreteLimits {
  double compressive_strength = 28e6;  // f'c (Pa); the concrete of Lin, Cheng & Tuan, Table 1
  // f_t (Pa): 3.28 MPa (Lin, Cheng & Tuan, Table 1; = 0.62 sqrt(28), the modulus of rupture), or by tensile_rule:
  // "aci_plain" 0.42 lambda sqrt(f'c) (ACI 318-19 Table 14.5.2.1(a), plain-concrete flexure: 2.22 MPa at 28 MPa),
  // "aci_rupture" 0.62 lambda sqrt(f'c) (ACI 318-19 eq. 19.2.3.1).
  double tensile_strength = 3.28e6;
  std::string tensile_rule = "given";   // given | aci_plain | aci_rupture
  double lambda = 1.0;                  // lightweight-concrete factor (ACI 318-19 19.2.4), 1 for normal weight
  double compression_coefficient = 0.85;  // alpha: usable fraction of f'c (ACI 318 0.85 f'c; EN 1992-1-1 alpha_cc)
  // Strength-reduction factors phi (ACI 318-19 Table 21.2.1: plain concrete, 0.60 for flexure, compression, shear).
  double phi_flexure = 0.60, phi_compression = 0.60, phi_shear = 0.60;
  // A shear stress limit (Pa) instead of ACI 318 one-way shear: tau_max = 1.5 V / A <= phi_shear * shear_strength.
  std::optional<double> shear_strength;
  // Punching shear around the contact patch (ACI 318-19 Table 14.5.5.1, two-way): off unless a patch is given.
  std::optional<double> punching_patch_width, punching_patch_height;  // m, across the face and up the face
  // Strain-rate effects on the tensile and compressive strengths of the member checks (fib Model Code 2010 5.1.11.1).
  bool strain_rate_effects = true;

  double tensile_capacity() const;      // phi_flexure * f_t (Pa)
  double compressive_capacity() const;  // phi_compression * alpha * f'c (Pa)
  double tensile_value() const;         // f_t by the rule (Pa)
};

struct SteelLimits {
  double yield_strength = 235e6;  // f_y (Pa), S235 (EN 10025-2)
  double gamma_M0 = 1.0;          // partial factor of cross-section resistance (EN 1993-1-1 6.1, recommended 1.0)
  double gamma_M1 = 1.0;          // partial factor of member resistance to instability (EN 1993-1-1 6.1, recommended 1.0)
  // Plastic members (docs/design-checks.md, "Plastic steel"), the ultimate level:
  double strain_limit = 0.05;          // principal strain at the section surface (EN 1993-1-5 Annex C.8(1) Note 1)
  double residual_drift_limit = 0.01;  // residual crest displacement / height: the realignment limit (FEMA P-58-1 Table C-1, DS3)
  double dent_depth_limit = 0.06;      // dent depth / D of a struck pipe (ASME B31.8 851.4.1: plain dents deeper call for repair)
  std::string buckling_curve = "a";    // of a circular hollow section: a hot-finished, c cold-formed (EN 1993-1-1 Table 6.2)
  double design_strength() const { return yield_strength / gamma_M0; }
};

// The dam on its foundation joint (docs/design-checks.md, "Stability"). The defaults are stated assumptions: set
// them from the site investigation.
struct FoundationLimits {
  double friction = 0.6;             // tan(phi) of the base joint (concrete on gravel or rock; EM 1110-2-2100 eq. 3-1)
  double cohesion = 0.0;             // c of the base joint (Pa), none by default
  double bearing_capacity = 600e3;   // allowable bearing pressure (Pa): a dense gravel; set it from the site
  // Uplift under water standing behind the dam: the fraction of the full linear uplift (gamma_w h_w at the heel, 0 at
  // the toe) that acts on the base joint; drains reduce it (EM 1110-2-2100 3-3).
  double uplift_factor = 1.0;
  // Sliding factor of the persistent situation (the usual load condition): EM 1110-2-2100 Table 3-3, normal structures,
  // ordinary site information.
  double sliding_factor_usual = 1.5;
  // The impact: how far the dam may slide (Newmark 1965), and the margin on rocking about the toe (Housner 1963).
  double sliding_displacement_limit = 0.05;  // m, a permissible displacement of gravity walls (Richards & Elms 1979)
  double rocking_safety_factor = 1.5;        // critical angle / peak rotation
};

struct Limits {
  ConcreteLimits concrete;
  SteelLimits steel;
  FoundationLimits foundation;
  // With `run --grid-study`: judge the design on the finest grid's utilisation ("finest") or on its conservative
  // bound u (1 + GCI) ("conservative_bound"; Roache 1998: the GCI as an error band).
  std::string grid_judge_on = "finest";
  // The levels whose checks set a run's verdict and the exit code: "both" (serviceability and ultimate), "ultimate" or
  // "serviceability" (docs/design-checks.md, "Two levels").
  std::string verdict_level = "both";
  std::map<std::string, std::string> member_material;  // member name -> concrete | steel (overrides the guess)
  nlohmann::json to_json() const;
};

// Reads a limits file; every key is optional. Throws dmi::InputError naming the file, the JSON path, the
// value and what was expected (unknown key, wrong type, non-positive strength, factor outside (0, 1]).
Limits read_limits(const std::string& path);
Limits parse_limits(const nlohmann::json& j, const std::string& file);

}  // namespace dmi::design
