// A scenario's identity: two runs with the same identity are the same run (the step loop is deterministic for any
// thread count). It is the SHA-256 of the low-level scenario -- the presets' expansion, or the file as given without
// presets -- in canonical JSON (keys sorted, no spacing; a text that is not JSON as it is), and the variant's label:
// a checkpoint is resumed, a complete result kept and a sweep's run shared only under the identity it was computed
// for.
#pragma once
#include <string>

#include "engine/scenario/config.hpp"

namespace dmi {

std::string scenario_identity(const std::string& source_text, const std::string& expanded_text, const std::string& variant);
inline std::string scenario_identity(const Scenario& s) { return scenario_identity(s.source_text, s.expanded_text, s.variant); }

}  // namespace dmi
