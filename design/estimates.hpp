// Design-practice impact loads beside the simulation: Lin, Cheng & Tuan's SDOF, EN 1991-1-7 Annex C, Hertz, GEO
// Report 270, the Japanese rock-fall formula, ASTRA 12006, and for a debris surge GEO's alpha rho v^2 h w and a
// hydrostatic-plus-dynamic model; computed from the design basis the presets write (/documents/design_basis,
// docs/design-json.md) and compared with the simulated peaks. Every model of the scenario's kind is listed; one that
// does not apply says why (value null) instead of being left out.
#pragma once
#include <string>
#include <vector>

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/design_basis.hpp"

namespace dmi::design {

struct Estimate {
  std::string id, title, formula, source;
  std::string parameters;           // the values put into the formula, as text
  bool applicable = true;           // false: value, simulated and ratio are null, note says why
  double value = 0;                 // N
  std::string compare_to;           // "peak_base_shear" | "peak_contact_force"
  double simulated = 0, ratio = 0;  // ratio = estimate / simulated (0 when nothing was simulated)
  std::string note;
  // With a grid study: the grid uncertainty of the simulated peak compared with (add_grid_uncertainty), the
  // extrapolated peak (none: not converged) and the ratio band for the simulated value within +-GCI (no upper end
  // when GCI >= 1).
  bool grid = false;
  double simulated_gci = 0, ratio_low = 0;
  std::optional<double> simulated_extrapolated, ratio_high;
  nlohmann::json to_json() const;
};
// An estimate read back from design.json (runs[].estimates[]), validated; `where` names the place in errors.
Estimate estimate_from_json(const nlohmann::json& j, const std::string& where);
std::vector<Estimate> estimates_from_json(const nlohmann::json& run, const std::string& where);

// Every estimate of the scenario's kind (boulder, debris surge) for the basis, which design_basis_from_json validated.
// `dimension`: the model's (2 or 3), for the notes on how it represents the boulder.
std::vector<Estimate> estimates(const DesignBasis& basis, double simulated_base_shear_N, double simulated_contact_N, int dimension = 2);


}  // namespace dmi::design
