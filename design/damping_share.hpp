// How much the members' structural damping shaped the peaks (docs/design-checks.md, "Structural damping"): the frame's
// damping work (results.h5 energy/frame_damping) at the governing instant, at the instant of the peak base shear and
// at the end, as a share of the energy the boulder or surge brought (design basis) and of the energy the members had
// received by then (energy/contact_work, the work of the contact on them). Above a tenth of the energy received by
// either instant the peak demands rest on the damping ratio, which for concrete is known to no better than 2-10 %, and
// design.json and the report say so.
#pragma once
#include <optional>

#include <nlohmann/json.hpp>

#include "design/health_record.hpp"

#include "core/design_basis.hpp"
#include "engine/io/results.hpp"

namespace dmi::design {

inline constexpr double kDampingShareFlag = 0.10;

// The impact energy of the basis (J): 1/2 m v^2 of the boulder, or of the surge (rho h L w v^2 / 2); NaN without one.
double impact_energy(const DesignBasis& b);

// {impact_energy_J, damping_energy_J, damping_energy_at_governing_J, share_at_governing, share, received_at_governing_J,
// share_of_received_at_governing, base_shear_peak {time_s, damping_J, received_J, share_of_received}, flagged}; null
// without the damping history or an impact energy. base_shear_peak_s < 0: no base shear peak.
std::optional<DampingShareRecord> damping_share(const Results& r, const DesignBasis& b, double governing_time_s, double base_shear_peak_s = -1);

}  // namespace dmi::design
