#include "design/strain_rate_checks.hpp"

#include <algorithm>
#include <cstdio>

#include "design/dynamic_strength.hpp"

namespace dmi::design {

void apply_strain_rate(std::vector<MemberEnvelope>& members, const FrameInfo& f, double load_start_s, const ConcreteLimits& C) {
  if (!C.strain_rate_effects) return;
  for (MemberEnvelope& env : members) {
    if (env.cls != "concrete") continue;
    double E = 0;
    for (const auto& m : f.members)
      if (m.name == env.name) E = f.elements[m.first].E;
    if (!(E > 0)) continue;
    for (Check& c : env.checks) {
      const bool tension = c.id == "concrete_flexural_tension" || c.id == "concrete_principal_tension";
      const double rise = c.demand - std::max(0.0, c.static_demand);  // the static part was not applied fast
      if ((!tension && c.id != "concrete_compression") || !(c.time_s > load_start_s) || !(rise > 0)) continue;
      c.strain_rate = strain_rate_from_rise_time(rise, E, c.time_s - load_start_s);
      c.dynamic_factor = tension ? dif_tension(c.strain_rate) : dif_compression(c.strain_rate);
      c.capacity *= c.dynamic_factor;
      char b[160];
      std::snprintf(b, sizeof b, "; x DIF %.3f at %.3g 1/s (fib MC2010 5.1.11.1, eps_dot = (sigma - sigma_0) / (E t_r))", c.dynamic_factor, c.strain_rate);
      c.formula += b;
      c.finish();
    }
  }
}

}  // namespace dmi::design
