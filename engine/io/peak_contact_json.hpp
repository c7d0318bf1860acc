// The peak contact record (core/peak_contact.hpp) as results.h5 stores it: /documents/peak_contact.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "core/peak_contact.hpp"

namespace dmi {

nlohmann::json peak_contact_to_json(const PeakContact& p);
// Throws std::runtime_error naming `where` when j is not such a document.
PeakContact peak_contact_from_json(const nlohmann::json& j, const std::string& where);

}  // namespace dmi
