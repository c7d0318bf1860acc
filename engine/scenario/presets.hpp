// Scenario presets: the engineer's vocabulary (a concrete gravity check dam, a steel open check dam,
// a boulder, a debris surge, a tyre buffer) expanded into the low-level scene (grid, materials,
// bodies, walls, structure, member contact, probes). The expansion is plain JSON, so it can be
// printed (`damimpact simulate --dry-run`), saved, edited and run as a low-level scenario.
//
// Layout of every preset scene (2D elevation along the flow, plane strain):
//   x downstream, y up; the dam's upstream face meets the ground at the origin; the ground (channel
//   bed) is the line through the origin rising upstream at the channel slope; the out-of-plane width
//   (analysis.thickness) is the dam's face width (concrete) or the column spacing (steel).
// Low-level keys given beside the presets are merged into the expansion: objects key by key (the
// user's value wins), arrays appended (the user's entries after the generated ones).
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/variants.hpp"

#include "engine/scenario/schema.hpp"

namespace dmi {

// Whether the scenario uses any preset key (dam, boulder, debris_surge, tyre_buffer, compare).
bool has_presets(const nlohmann::json& j);

// The variants a scenario asks for: {""} normally; {"with_buffer", "without_buffer"} with
// compare = with_and_without_buffer; with compare_3d each followed by its 3D model's variant.
std::vector<std::string> preset_variants(const nlohmann::json& j, const std::string& file);

// The low-level scenario of one variant ("" or a name from preset_variants). Throws InputError
// naming the preset key when a preset value is wrong.
nlohmann::json expand_presets(const nlohmann::json& j, const std::string& file, const std::string& variant = "");

// Declares the preset keys for the generated reference (document mode of o).
void document_presets(schema::Obj& o);

namespace detail {
// Validates a material object (the keys of one materials[] entry) at `path` (defined in parse.cpp).
void read_material_object(const nlohmann::json& j, const std::string& path, const std::string& file, MaterialConfig& out);
}  // namespace detail

}  // namespace dmi
