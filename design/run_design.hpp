// The design of one run as a typed record (design.json runs[]; docs/design-json.md): what design_run finds in a
// results file (envelopes, reactions, contact, solid-FE peaks, plastic and stability sections, estimates, checks and
// the verdict), written by to_json and read back validated by run_design_from_json, once, by the report, `check`'s
// summary and a sweep.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "design/estimates.hpp"
#include "design/health_record.hpp"
#include "design/members.hpp"
#include "design/phases.hpp"
#include "design/plastic_record.hpp"
#include "design/pressures.hpp"
#include "design/section_records.hpp"
#include "design/stability_record.hpp"
#include "design/verdict.hpp"

namespace dmi::design {

struct RunDesign {
  std::string results_file, scenario_name, variant;
  std::optional<int> dimension;  // the frame's (2 or 3); none without members
  // The bare run of a with / without buffer pair: the reference the design is compared with, not judged (set by
  // design_document).
  bool reference = false;
  std::vector<MemberEnvelope> members;  // their checks are in `checks`
  std::vector<ReactionPeaks> supports;
  std::optional<BaseTotal> base_total;
  Contact contact;
  std::optional<SolidDesign> solid;
  std::optional<PlasticRecord> plastic;
  double steel_yield_strength_Pa = 0;  // the f_y the steel checks took
  std::vector<Estimate> estimates;
  std::optional<DebrisLoad> debris_phases;
  std::optional<StabilityRecord> stability;
  std::optional<LocalDamageRecord> local_damage;
  std::vector<Check> checks;
  Verdict verdict;
  std::optional<DampingShareRecord> damping;
  std::vector<VolumeHealthRecord> volume_health;
  std::optional<FaceProfileAtMoment> face_profile;
  std::vector<SensorPeak> sensors;

  int dim() const { return dimension.value_or(2); }
  // The base total's component `key` (shear_key, moment_key) at its largest magnitude; none without a base total.
  std::optional<double> base_abs_max(const std::string& key) const;
  // Where errors name this run: "design.json run <results_file>".
  std::string where() const { return "design.json run " + results_file; }
};

nlohmann::json to_json(const RunDesign& r);
// `where` names the document and run in errors (a damaged run is refused naming the place).
RunDesign run_design_from_json(const nlohmann::json& j, const std::string& where);

}  // namespace dmi::design
