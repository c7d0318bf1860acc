// A member's envelope as design.json holds it (runs[].members[]: stations, peaks; docs/design-json.md), written and
// read back validated: the report's charts and pictures read the typed envelope, not the document's keys.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "design/members.hpp"

namespace dmi::design {

nlohmann::json extreme_json(const Extreme& e);  // {"value", "time_s"}, or null when unset
// j[key] as an extreme: unset where the key is absent or null; anything but {value, time_s} is refused naming `where`.
Extreme extreme_from_json(const nlohmann::json& j, const char* key, const std::string& where);
nlohmann::json member_json(const MemberEnvelope& m);
// The envelope of runs[].members[k] (its stations and their extremes; the member's checks are the run's, not read
// here); `dim` the run's dimension, `where` names the place in errors.
MemberEnvelope member_from_json(const nlohmann::json& j, int dim, const std::string& where);
std::vector<MemberEnvelope> members_from_json(const nlohmann::json& run, const std::string& where);

}  // namespace dmi::design
