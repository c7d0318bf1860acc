#include "design/local_damage_checks.hpp"

#include <algorithm>

#include "design/local_damage.hpp"

namespace dmi::design {

double section_thickness_at(const DamBasis& d, double y) {
  const double s = std::clamp(y / d.height_m, 0.0, 1.0);
  const double up = d.heel_x_m + s * (d.crest_upstream_x_m - d.heel_x_m), down = d.toe_x_m + s * (d.crest_downstream_x_m - d.toe_x_m);
  return down - up;
}

std::optional<LocalDamageRecord> local_damage_checks(const DesignBasis& b, const ConcreteLimits& L, std::vector<Check>& checks) {
  const DamBasis& d = b.dam;
  if (!b.boulder || b.buffer || d.type != DamKind::concrete_gravity || !is_set(d.heel_x_m) || !is_set(d.crest_upstream_x_m)) return std::nullopt;
  const BoulderBasis& k = *b.boulder;
  const double y = std::min(k.impact_height_m, d.height_m), t = section_thickness_at(d, y);
  const LocalDamage ld = local_damage(k.mass_kg, k.diameter_m, k.speed_m_s, L.compressive_strength, kNoseSpherical);
  const DesignThickness dt = design_thickness(ld, kDoeScabbingMargin, kDoePerforationMargin);
  auto check = [&](const char* level, const char* id, const char* title, double demand, const std::string& by, bool in_range, const char* src) {
    Check c;
    c.level = level, c.id = id, c.title = title, c.member = "struck face", c.material = "concrete", c.unit = "m";
    c.demand = demand, c.capacity = t, c.y_m = y;
    c.formula = std::string(title) + " x margin <= the section's thickness at the impact height (governing formula: " + by +
                (in_range ? "" : ", outside its calibrated range") + ")";
    c.source = src;
    c.finish();
    checks.push_back(c);
  };
  check("ultimate", "local_perforation", "perforation thickness", dt.perforation_design_m, dt.perforation_by, dt.perforation_in_range,
        "Kennedy (1976), Degen (1980), Chang (1981); margin 1.2: DOE-STD-3014 App. C");
  check("serviceability", "local_scabbing", "scabbing thickness", dt.scabbing_design_m, dt.scabbing_by, dt.scabbing_in_range,
        "Kennedy (1976), Chang (1981); margin 1.1: DOE-STD-3014 App. C");
  LocalDamageRecord r;
  r.model = "the boulder as a hard spherical-nosed projectile (N* = 1) on a thick plain-concrete target";
  r.mass_kg = k.mass_kg, r.diameter_m = k.diameter_m, r.speed_m_s = k.speed_m_s, r.compressive_strength_Pa = L.compressive_strength;
  r.impact_height_m = y, r.thickness_m = t, r.penetration_m = ld.penetration_m;
  r.scabbing_ndrc_m = ld.scabbing_ndrc_m, r.scabbing_chang_m = ld.scabbing_chang_m;
  r.perforation_ndrc_m = ld.perforation_ndrc_m, r.perforation_degen_m = ld.perforation_degen_m, r.perforation_chang_m = ld.perforation_chang_m;
  r.ndrc_in_range = ld.scabbing_ndrc_in_range && ld.perforation_ndrc_in_range, r.degen_in_range = ld.perforation_degen_in_range;
  r.chang_in_range = ld.perforation_chang_in_range;
  r.scabbing_design_m = dt.scabbing_design_m, r.perforation_design_m = dt.perforation_design_m;
  return r;
}

}  // namespace dmi::design
