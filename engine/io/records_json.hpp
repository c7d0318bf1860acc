// The run's typed records as results.h5 stores them, under /documents: the peak contact (core/peak_contact.hpp), the
// structure as built (core/structure_record.hpp), the struck face's profile (core/face_profile.hpp) and the solid
// check's answer and field (core/solid_check_record.hpp, core/solid_field.hpp).
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "core/face_profile.hpp"
#include "core/peak_contact.hpp"
#include "core/solid_check_record.hpp"
#include "core/solid_field.hpp"
#include "core/structure_record.hpp"

namespace dmi {

// The readers throw std::runtime_error naming `where` when j is not such a document.
nlohmann::json peak_contact_to_json(const PeakContact& p);
PeakContact peak_contact_from_json(const nlohmann::json& j, const std::string& where);

// Validated on reading: dimension 2 or 3, node indices and element ranges inside the frame, element spans within
// 0 <= s0 < s1 <= 1.
nlohmann::json structure_to_json(const StructureRecord& s);
StructureRecord structure_from_json(const nlohmann::json& j, const std::string& where);

nlohmann::json face_profile_to_json(const FaceProfileRecord& f);
FaceProfileRecord face_profile_from_json(const nlohmann::json& j, const std::string& where);

// Validated on reading: hex8 in 3D or quad4 in 2D, whole nodes and elements, corners that exist, at least one case,
// every case's stresses one finite value per node.
// Validated on reading: every case's peaks present with their places.
nlohmann::json solid_model_to_json(const SolidModel& m);
SolidModel solid_model_from_json(const nlohmann::json& j, const std::string& where);
nlohmann::json solid_check_to_json(const SolidCheckRecord& c);
SolidCheckRecord solid_check_from_json(const nlohmann::json& j, const std::string& where);

nlohmann::json solid_field_to_json(const SolidFieldRecord& f);
SolidFieldRecord solid_field_from_json(const nlohmann::json& j, const std::string& where);

}  // namespace dmi
