// The structure record (core/structure_record.hpp) as results.h5 stores it: /documents/structure.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "core/structure_record.hpp"

namespace dmi {

nlohmann::json structure_to_json(const StructureRecord& s);
// Throws std::runtime_error naming `where` when j is not such a document: a missing key, a dimension other than 2 or 3,
// node indices or element ranges outside the frame, an element span outside 0 <= s0 < s1 <= 1.
StructureRecord structure_from_json(const nlohmann::json& j, const std::string& where);

}  // namespace dmi
