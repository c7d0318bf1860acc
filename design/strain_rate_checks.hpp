// Strain-rate effects on the concrete strengths of the member checks (docs/design-checks.md, "Dynamic strength"): the
// tensile and compressive capacities of a concrete member's fibre-stress checks are raised by the dynamic increase
// factors of fib Model Code 2010 5.1.11.1 at the mean strain rate of the load's rise to the governing demand,
// eps_dot = (sigma - sigma_0) / (E t_r), t_r from the start of the contact pulse to the governing instant and sigma_0 the
// static demand there at the start of the run (self-weight was not applied fast).
#pragma once
#include <vector>

#include "design/limits.hpp"
#include "design/members.hpp"

namespace dmi::design {

// Applies the factors to the concrete members' flexural tension, principal tension and compression checks whose
// governing instant follows load_start_s; a check at or before it (a static demand) keeps the static strength.
void apply_strain_rate(std::vector<MemberEnvelope>& members, const FrameInfo& f, double load_start_s, const ConcreteLimits& C);

}  // namespace dmi::design
