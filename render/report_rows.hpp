// Formatting shared by the report's tables (report_data.cpp and the sections beside it).
#pragma once
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "render/render_main.hpp"

namespace dmi::render {

std::string fmt(const char* f, double v);
// Engineering units: Pa -> MPa, N -> kN, N m -> kN m, N s -> kN s, s -> ms, m below 0.1 m -> mm; other units as given.
std::string eng(double v, const std::string& unit);
// A row per quantity, a value per run; a value every run shares is written once across the runs' columns.
nlohmann::json per_run_rows(const std::vector<RunData>& runs,
                            const std::vector<std::pair<std::string, std::function<std::string(const RunData&)>>>& rows);
// The steel members that yield (design.json runs[].plastic), a column per run; empty when no run has them.
nlohmann::json plastic_rows(const std::vector<RunData>& runs);
// A run's label in the report's tables ("with buffer", "without buffer (3D)", "simulation").
std::string label(const RunData& r);
// A far estimate's note (a ratio outside 0.5..2 says so), else the estimate's own note.
std::string estimate_note(double ratio, const std::string& note);
// The largest value of a history (of |value| with absolute), NaN when the file has no such history.
double series_max(const Results& r, const char* path, bool absolute);
// The largest kinetic + strain energy of the run (J).
double reference_energy(const Results& r);
// Whether every history value is finite.
bool all_finite(const Results& r);
// The report's sections (report_sections.cpp): the design-practice loads and a surge's phases; the numerical health;
// the limits used.
void estimates_data(const std::vector<RunData>& runs, const design::DesignDocument& design_doc, bool space, nlohmann::json& d);
void health_data(const std::vector<RunData>& runs, nlohmann::json& d);
nlohmann::json limit_rows(const design::DesignDocument& design_doc);
// A run's member checks by member group (the name before its first '_'): per check and group the members it covers, how
// many fail and the governing one; empty when no group holds more than one member.
nlohmann::json check_group_rows(const design::RunDesign& design_run);
// The pressure on the struck face (its profile's resultant, position and moment) and the sensors' peaks, a column per run;
// empty when no run recorded them.
nlohmann::json pressure_rows(const std::vector<RunData>& runs);
// The debris load beside practice (GEO 270's alpha, Cui et al.'s alpha(Fr) marked second-hand, the deposit's hydrostatic
// load against the static tail), with the grid uncertainty where design_doc holds a grid study; empty without a surge.
nlohmann::json debris_practice_rows(const std::vector<RunData>& runs, const design::DesignDocument& design_doc);

}  // namespace dmi::render
