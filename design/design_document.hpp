// design.json as a typed record (docs/design-json.md): the limits the design was checked under, every run's design,
// the with / without buffer comparison, the plane model beside its 3D model, the document's verdict and, after a grid
// study, its section. Built by design_document (design/document.cpp) and the grid study, written by to_json, read
// back validated by design_document_from_json, once, by the report, `check`'s summary and a sweep.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "design/comparison.hpp"
#include "design/grid_study_record.hpp"
#include "design/limits.hpp"
#include "design/run_design.hpp"
#include "design/verdict.hpp"

namespace dmi::design {

constexpr int kDesignFormatVersion = 1;

struct DesignDocument {
  std::string software_version;
  Limits limits;
  std::vector<RunDesign> runs;
  std::optional<BufferComparison> comparison;
  std::optional<PlaneAndSpace> plane_and_space;
  Verdict verdict;  // the document's: over the judged runs
  std::optional<GridStudyRecord> grid_study;
};

nlohmann::json to_json(const DesignDocument& d);
// `where` names the file in errors: a document of another format or version, or damaged, is refused naming the place.
DesignDocument design_document_from_json(const nlohmann::json& j, const std::string& where);
// Reads and validates the design.json at `path`.
DesignDocument read_design_json(const std::string& path);

}  // namespace dmi::design
