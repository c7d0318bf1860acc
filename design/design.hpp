// The design layer's entry points (docs/design-checks.md, docs/design-json.md): results.h5 in,
// design.json out. Reads files only, never solver objects.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/design_basis.hpp"
#include "design/comparison.hpp"
#include "design/limits.hpp"
#include "design/design_document.hpp"
#include "design/run_design.hpp"
#include "engine/io/results.hpp"

namespace dmi::design {

// The design of one run (an entry of design.json "runs"): envelopes, reactions, contact, solid-FE peaks,
// closed-form estimates, checks and the verdict. `where` names the results file in errors.
RunDesign design_run(const Results& r, const Limits& limits, const std::string& where);


// With vs without buffer: every compared peak and its reduction in % (docs/design-json.md "comparison").
BufferComparison compare_runs(const RunDesign& with_buffer, const RunDesign& without_buffer);

// The whole design.json. The verdict judges every run except the without_buffer run of a comparison pair (a
// with_buffer and a without_buffer run in the same comparison folder): that one is the reference the design is
// compared with. The first pair gives "comparison".
// design.json's "plane_and_space": for each 3D run of compare_3d, the plane run it stands beside and their governing
// numbers side by side (null without compare_3d).
std::optional<PlaneAndSpace> plane_and_space_section(const std::vector<RunDesign>& runs);
DesignDocument design_document(std::vector<RunDesign> runs, const Limits& limits, const std::string& software_version);

// Writes design.json atomically (a temporary beside it, renamed when complete).
void write_design_json(const std::string& path, const DesignDocument& doc);

// The readable summary `damimpact check` prints.
std::string summary_text(const DesignDocument& design);
// Its verdict lines alone (what `check -q` prints).
std::string verdict_text(const DesignDocument& design);

// `damimpact check PATH... [--limits FILE] [--json] [-o design.json]`: PATH a results.h5 or a run folder (holding
// results.h5, or with_buffer/ and without_buffer/). Writes design.json (atomically) beside the results, or to
// `out`. With with_grid_study, a grid study in the folder (out/grid_study/, from `run --grid-study`) is judged again
// with the same limits (restudy_grid). Returns 0 when every check of the design passes, 1 when one fails; bad input
// throws (exit 2).
// The design document of the runs at `paths` (results files or run folders) under the limits file ("" the defaults),
// without writing or printing it.
DesignDocument check_document(const std::vector<std::string>& paths, const std::string& limits_file, const std::string& software_version);
int check_main(const std::vector<std::string>& paths, const std::string& limits_file, bool print_json, const std::string& out,
               bool quiet, const std::string& software_version, bool with_grid_study = false);

}  // namespace dmi::design
