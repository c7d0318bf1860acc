// The sections of a run's design as typed records (docs/design-json.md): the supports' reactions and the base total,
// the contact's peak and pulse, the solid-FE peaks and the local damage of the struck face. Built by design
// (design.cpp, local_damage_checks.cpp), written by to_json, read back validated by the *_from_json readers.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/solid_check_record.hpp"
#include "design/loads.hpp"

namespace dmi::design {

// The supports' reactions summed (Reactions::total) about the supports' centroid `about_m` (2 or 3 coordinates).
struct BaseTotal {
  ReactionPeaks peaks;
  std::vector<double> about_m;
};

// runs[].solid: the solid model and, per load case, the Gauss-point peaks the concrete checks judge (Lin, Cheng &
// Tuan, Table 1).
struct SolidDesignCase {
  std::string name, type;
  double load_resultant_N = 0, max_nodal_base_reaction_N = 0, max_displacement_m = 0;
  SolidPeak von_mises, max_principal, min_principal;
};
struct SolidDesign {
  SolidModel model;
  std::vector<SolidDesignCase> cases;
};

// runs[].local_damage: the boulder as a hard projectile on the bare concrete face, the empirical penetration,
// scabbing and perforation depths by formula and the design thicknesses with their margins.
struct LocalDamageRecord {
  std::string model;
  double mass_kg = 0, diameter_m = 0, speed_m_s = 0, compressive_strength_Pa = 0, impact_height_m = 0, thickness_m = 0, penetration_m = 0;
  double scabbing_ndrc_m = 0, scabbing_chang_m = 0, perforation_ndrc_m = 0, perforation_degen_m = 0, perforation_chang_m = 0;
  bool ndrc_in_range = false, degen_in_range = false, chang_in_range = false;
  double scabbing_design_m = 0, perforation_design_m = 0;
};

nlohmann::json to_json(const ReactionPeaks& p);
nlohmann::json to_json(const BaseTotal& b);
nlohmann::json to_json(const Contact& c);  // null when no contact was recorded
nlohmann::json to_json(const SolidDesign& s);
nlohmann::json to_json(const LocalDamageRecord& l);

// `where` names the place in errors; a null section reads as nullopt (the contact: present = false).
ReactionPeaks reaction_from_json(const nlohmann::json& j, const std::string& where);
std::optional<BaseTotal> base_total_from_json(const nlohmann::json& j, const std::string& where);
Contact contact_from_json(const nlohmann::json& j, const std::string& where);
std::optional<SolidDesign> solid_design_from_json(const nlohmann::json& j, const std::string& where);
std::optional<LocalDamageRecord> local_damage_from_json(const nlohmann::json& j, const std::string& where);

}  // namespace dmi::design
