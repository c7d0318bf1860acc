// Numerical health of the bodies' volumes (docs/design-checks.md, "Numerical health"): a body that flows without
// dilating (a non-dilatant Drucker-Prager or mu(I) debris, a slurry) keeps its volume to within its elastic strain
// (sigma / K ~ 1e-3 for debris), so a body whose particles fill more than 5 % more than they did when created has
// gained volume from the discretisation, not the physics, and its loads are suspect.
#pragma once
#include <vector>

#include <nlohmann/json.hpp>

#include "design/health_record.hpp"

#include "engine/io/results.hpp"

namespace dmi::design {

inline constexpr double kVolumeGrowthFlag = 0.05;

// One entry per body probe that recorded its volume (probes/<name>/volume: the particles' volumes summed now and as
// created, so a body fed by an inflow counts only what has entered): {probe, final_ratio, largest_ratio, largest_time_s,
// flagged (largest ratio above 1 + 5 %)}.
std::vector<VolumeHealthRecord> volume_health(const Results& r);

}  // namespace dmi::design
