// Closed-form impact estimates beside the simulation (paper B's SDOF, Hertz, GEO, EN 1991-1-7 Annex C,
// the momentum flux of a surge), computed from the design basis the presets write (/documents/design_basis,
// docs/design-json.md) and compared with the simulated peaks.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace dmi::design {

struct Estimate {
  std::string id, title, formula, source;
  double value = 0;                 // N
  std::string compare_to;           // "peak_base_shear" | "peak_contact_force"
  double simulated = 0, ratio = 0;  // ratio = estimate / simulated (0 when nothing was simulated)
  std::string note;
  nlohmann::json to_json() const;
};

// Throws std::runtime_error naming `where` and the basis key when a needed value is missing or not positive.
std::vector<Estimate> estimates(const nlohmann::json& basis, double simulated_base_shear_N, double simulated_contact_N,
                                const std::string& where);

}  // namespace dmi::design
