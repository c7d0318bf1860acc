#include "design/design_document.hpp"

#include <fstream>
#include <stdexcept>

#include "design/record_reader.hpp"

namespace dmi::design {

using nlohmann::json;

json to_json(const DesignDocument& d) {
  json runs = json::array();
  for (const RunDesign& r : d.runs) runs.push_back(to_json(r));
  json j{{"format", "damimpact-design"}, {"format_version", kDesignFormatVersion}, {"software_version", d.software_version},
         {"limits", d.limits.to_json()}, {"runs", runs}, {"comparison", d.comparison ? to_json(*d.comparison) : json(nullptr)},
         {"plane_and_space", d.plane_and_space ? to_json(*d.plane_and_space) : json(nullptr)}, {"verdict", to_json(d.verdict)}};
  if (d.grid_study) j["grid_study"] = to_json(*d.grid_study);
  return j;
}

DesignDocument design_document_from_json(const json& j, const std::string& where) {
  if (!j.is_object() || j.value("format", std::string()) != "damimpact-design")
    throw std::runtime_error(where + " is not a damimpact design document (its 'format' is not \"damimpact-design\")");
  if (record::count(j, "format_version", where) != kDesignFormatVersion)
    throw std::runtime_error(where + ": format_version " + j["format_version"].dump() + " is not the version this build reads, " +
                             std::to_string(kDesignFormatVersion));
  DesignDocument d;
  d.software_version = record::text(j, "software_version", where);
  d.limits = parse_limits(record::field(j, "limits", where), where + " limits");
  const json& runs = record::list(j, "runs", where);
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const json& r = runs[k];
    const std::string file = r.is_object() && r.contains("results_file") && r["results_file"].is_string() ? r["results_file"].get<std::string>()
                                                                                                        : "runs[" + std::to_string(k) + "]";
    d.runs.push_back(run_design_from_json(r, where + " run " + file));
  }
  d.comparison = comparison_from_json(record::field(j, "comparison", where), where + " comparison");
  d.plane_and_space = plane_and_space_from_json(j.contains("plane_and_space") ? j["plane_and_space"] : json(), where + " plane_and_space");
  d.verdict = verdict_from_json(record::field(j, "verdict", where), true, where + " verdict");
  d.grid_study = grid_study_from_json(j.contains("grid_study") ? j["grid_study"] : json(), where + " grid_study");
  return d;
}

DesignDocument read_design_json(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot be opened");
  const json j = json::parse(in, nullptr, false);
  if (j.is_discarded()) throw std::runtime_error(path + " is not valid JSON");
  return design_document_from_json(j, path);
}

}  // namespace dmi::design
