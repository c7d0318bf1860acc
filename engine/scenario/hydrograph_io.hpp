// Reading hydrographs (engine/scenario/hydrograph.hpp) from the scenario: inline or a CSV file.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "core/hydrograph.hpp"

namespace dmi {

// Reads a hydrograph given as `value` at JSON path `path` of scenario `file`: an object of equal-length arrays
// {"time", "depth", "velocity"[, "density"]}, or the name of a CSV file (relative to the scenario's folder) with a
// header row naming those columns (units in the name are accepted: time_s, depth_m, velocity_m_s, density_kg_m3; other
// columns are ignored, lines starting with '#' are comments). Throws InputError naming the scenario file, the path,
// the value and, for a CSV, its line and column.
Hydrograph read_hydrograph(const nlohmann::json& value, const std::string& file, const std::string& path);
// A scenario written elsewhere (a grid-study level, a sweep case) keeps its hydrograph files: relative names at
// /debris_surge/hydrograph and /bodies/*/inflow/hydrograph become absolute, resolved against source_file's folder.
void resolve_file_references(nlohmann::json& scenario, const std::string& source_file);
// The hydrograph as the inline JSON object read_hydrograph accepts.
nlohmann::json hydrograph_json(const Hydrograph& h);

}  // namespace dmi
