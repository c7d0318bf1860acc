// How much of the impact's energy the members' structural damping took (docs/design-checks.md, "Structural damping"):
// the frame's damping work (results.h5 energy/frame_damping) at the governing instant and at the end, as a share of
// the energy the boulder or surge brought (design basis). Above a tenth by the governing instant the peak demands rest
// on the damping model (a rate-independent structural damping is not known to better than a factor of 2 at the
// frequencies a hard impact excites), and design.json and the report say so.
#pragma once
#include <nlohmann/json.hpp>

#include "core/design_basis.hpp"
#include "engine/io/results.hpp"

namespace dmi::design {

inline constexpr double kDampingShareFlag = 0.10;

// The impact energy of the basis (J): 1/2 m v^2 of the boulder, or of the surge (rho h L w v^2 / 2); NaN without one.
double impact_energy(const DesignBasis& b);

// {impact_energy_J, damping_energy_J, damping_energy_at_governing_J, share_at_governing, share, flagged}; null without
// the damping history or an impact energy.
nlohmann::json damping_share(const Results& r, const DesignBasis& b, double governing_time_s);

}  // namespace dmi::design
