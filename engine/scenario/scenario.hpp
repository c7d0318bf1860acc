// Scenario files (schema version 1): read once at the edge into config structs.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "engine/scenario/config.hpp"

namespace dmi {

constexpr int kScenarioSchemaVersion = 1;

// Parses and validates scenario JSON text; `file` names the source in messages. Throws InputError.
Scenario parse_scenario(const std::string& text, const std::string& file);
// Same from an already parsed JSON value (e.g. a validation case with overrides).
Scenario parse_scenario(const nlohmann::json& j, const std::string& file);
// Reads and parses a scenario file. Throws InputError (unreadable file, syntax error with line/column, ...).
Scenario load_scenario(const std::string& path);
// The variants a scenario asks for (compare = with_and_without_buffer gives two, labelled
// with_buffer and without_buffer; otherwise one, labelled ""), each parsed and validated.
struct ScenarioVariant {
  std::string label;
  Scenario scenario;
};
std::vector<ScenarioVariant> parse_scenario_variants(const std::string& text, const std::string& file);
std::vector<ScenarioVariant> load_scenario_variants(const std::string& path);
// The cell size every variant shares (a grid study refines one); throws InputError naming `file` if they differ.
double common_cell_size(const std::vector<ScenarioVariant>& variants, const std::string& file);

// Markdown reference of every key (generated from the parser's declarations).
std::string scenario_reference_markdown();

// Probe quantities per probe type.
const std::vector<std::string>& particle_probe_quantities();
const std::vector<std::string>& body_probe_quantities();
const std::vector<std::string>& member_probe_quantities();

}  // namespace dmi
