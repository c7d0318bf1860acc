// Strain-rate effects on the concrete strengths of the member checks (docs/design-checks.md, "Dynamic strength"): the
// tensile and compressive capacities of a concrete member's fibre-stress checks are raised by the dynamic increase
// factors of fib Model Code 2010 5.1.11.1 at the mean strain rate of the load's rise to the demand,
// eps_dot = (sigma - sigma_0) / (E t_r), t_r from the start of the contact pulse and sigma_0 the static demand there at
// the start of the run (self-weight was not applied fast). Applied at every instant a demand is weighed, so the
// governing instant is the one of the largest dynamic utilisation.
#pragma once
#include <limits>
#include <string>

#include "design/limits.hpp"

namespace dmi::design {

struct StrainRate {
  bool on = false;
  double load_start_s = std::numeric_limits<double>::infinity();  // the contact pulse's start
  double E = 0;                                                    // the member's Young's modulus (Pa)
};

// The factor on a check's capacity for demand at time t (static_demand at the first sample there): 1 for checks other
// than concrete_flexural_tension / concrete_principal_tension / concrete_compression, before the load, or when the
// demand is no larger than the static one; the strain rate it was taken at in *rate (0 then).
double strain_rate_factor(const std::string& id, double demand, double static_demand, double t, const StrainRate& sr, double* rate);

}  // namespace dmi::design
