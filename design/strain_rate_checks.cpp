#include "design/strain_rate_checks.hpp"

#include <algorithm>

#include "design/dynamic_strength.hpp"

namespace dmi::design {

double strain_rate_factor(const std::string& id, double demand, double static_demand, double t, const StrainRate& sr, double* rate) {
  *rate = 0;
  const bool tension = id == "concrete_flexural_tension" || id == "concrete_principal_tension";
  const double rise = demand - std::max(0.0, static_demand);  // the static part was not applied fast
  if (!sr.on || (!tension && id != "concrete_compression") || !(t > sr.load_start_s) || !(rise > 0) || !(sr.E > 0)) return 1.0;
  *rate = strain_rate_from_rise_time(rise, sr.E, t - sr.load_start_s);
  return tension ? dif_tension(*rate) : dif_compression(*rate);
}

}  // namespace dmi::design
