// The design basis (core/design_basis.hpp) as JSON: the one writer and the one reader, for the scenario's
// design_basis object and results.h5's /documents/design_basis (docs/design-json.md, "design basis").
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "core/design_basis.hpp"

namespace dmi {

// Every number that is set, under its key (unit in the name).
nlohmann::json design_basis_to_json(const DesignBasis& b);
// Reads and validates: unknown keys, a missing required number or one outside its range throw InputError naming
// `file`, the JSON path under `prefix` (e.g. "/documents/design_basis"), the value and what was expected.
DesignBasis design_basis_from_json(const nlohmann::json& j, const std::string& file, const std::string& prefix);

}  // namespace dmi
