// The three phases of a debris surge's load on a barrier (Cui, Zeng & Lei 2015: the frontal peak of the surge head,
// the dynamic load of its body, the static load of the deposit), read from the contact-force history and set against
// the momentum flux F0 = rho v^2 h w of the approaching surge (alpha = F / F0, the dynamic impact coefficient of
// Kwan 2012, GEO Report 270).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/design_basis.hpp"
#include "engine/io/results.hpp"

namespace dmi::design {

struct DebrisPhases {
  double flux_N = 0;       // F0 = rho v^2 h w
  double passage_s = 0;    // T = L / v, the time the surge takes to pass a section at its front speed
  double arrival_s = 0;    // first sample with |F| > 1 % of F0
  double peak_N = 0, peak_time_s = 0;  // largest |F| from the arrival to arrival + T (the surge's passage)
  double dynamic_N = 0;    // mean |F| over [arrival + T/4, arrival + T]: the body of the surge
  std::optional<double> static_N;  // mean |F| over the last 10 % of the run, if that lies after arrival + T
  nlohmann::json to_json() const;
};

// t: sample times (sample k the mean over (t_{k-1}, t_k]); F: |contact force| at each sample. Nullopt when the
// force never reaches 1 % of F0 (the surge did not arrive).
std::optional<DebrisPhases> debris_phases(const std::vector<double>& t, const std::vector<double>& F, double flux_N, double passage_s);

// The deposit at rest against the face over the last 10 % of the run (face/pressure and /documents/face_profile): its
// height, hydrostatic_N = rho g h_d^2 w / 2 (w the face profile's width) and the face's measured resultant; none
// without a face profile.
struct DepositLoad {
  double height_m = 0, hydrostatic_N = 0, face_resultant_N = 0;
};
std::optional<DepositLoad> deposit_load(const Results& r, double rho);

// design.json's "debris_phases" as a typed record: the phases, the surge's Froude number, the design-practice loads
// alpha rho v^2 h w of GEO (Kwan 2012) and of Cui, Zeng & Lei (2015), and the deposit. Read back validated by
// debris_load_from_json (null: nullopt).
struct DebrisLoad {
  struct Practice {
    double alpha = 0, force_N = 0;
    std::string source;
  };
  DebrisPhases phases;
  double froude = 0;
  Practice geo, cui;
  bool cui_in_range = false;  // Fr within Cui's data (about 2.3-6.2)
  std::optional<DepositLoad> deposit;
  nlohmann::json to_json() const;
};
std::optional<DebrisLoad> debris_load_from_json(const nlohmann::json& j, const std::string& where);

// From a results file: the contact history and the design basis' surge (density, depth, speed, length, width).
// None when the basis has no debris surge or the file no contact history.
std::optional<DebrisLoad> debris_phases(const Results& r, const DesignBasis& basis);

}  // namespace dmi::design
