// The checks of a read scenario that need all of it at once (semantics.cpp): cross-references, geometry, ranges that
// depend on other keys. Both throw InputError naming the file, the JSON path, the value and what was expected.
#pragma once
#include <string>

#include "engine/scenario/config.hpp"

namespace dmi {

void check_semantics(const Scenario& s, const std::string& file);
// A solid check's loads against its geometry (also for a scenario that is a solid check alone).
void check_solid_check(const Scenario& s, const std::string& file);

}  // namespace dmi
