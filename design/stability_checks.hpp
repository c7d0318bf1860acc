// The concrete gravity dam as a rigid body on its foundation joint, under the simulated base reactions: sliding,
// resultant location, bearing and overturning in the persistent situation (self-weight at rest: the frame starts in
// static equilibrium, the first history sample), and under the impact (every sample): the Newmark (1965) sliding
// displacement and the peak rocking rotation about the toe (Housner 1963) against the limits (docs/design-checks.md,
// "Stability"). Plane models of a concrete gravity dam with its base supports; the totals are those of the width the
// model stands for.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/design_basis.hpp"
#include "design/checks.hpp"
#include "design/limits.hpp"
#include "design/members.hpp"
#include "design/stability_record.hpp"
#include "engine/io/results.hpp"

namespace dmi::design {

// True when the run can be assessed: a plane frame with supports and a concrete gravity dam whose section corners the
// basis records.
bool stability_applies(const FrameInfo& f, const DesignBasis& b);

// The design.json "stability" record of a run (none when it does not apply), and its checks appended to `checks`.
std::optional<StabilityRecord> stability(const Results& r, const FrameInfo& f, const DesignBasis& b, const FoundationLimits& L,
                                         std::vector<Check>& checks, const std::string& where);

}  // namespace dmi::design
