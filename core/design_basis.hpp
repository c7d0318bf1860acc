// The design basis: the dam, the boulder or debris surge and the buffer as the engineer described them (the real,
// spherical boulder; the dam's real section), which the design checks and the closed-form estimates need beside the
// simulated histories. The presets fill it; results.h5 carries it (/documents/design_basis, docs/design-json.md).
// SI units, named in the fields. A number the record does not hold is NaN (kUnset).
#pragma once
#include <cmath>
#include <limits>
#include <optional>
#include <string>

namespace dmi {

inline constexpr double kUnset = std::numeric_limits<double>::quiet_NaN();
inline bool is_set(double v) { return !std::isnan(v); }

enum class DamKind { concrete_gravity, steel_open };

struct DamBasis {
  DamKind type = DamKind::concrete_gravity;
  double height_m = kUnset;
  double width_m = kUnset;  // across the channel: the width a 2D model stands for, or the 3D crest length
  std::string width_rule;    // how a 2D model's width was chosen ("given", or the rule; "" unknown)
  double youngs_modulus_Pa = kUnset, poisson_ratio = kUnset, density_kg_m3 = kUnset;
  // Concrete gravity: the section, and its corners along the flow (model x, the flow runs towards +x; the base at
  // y = 0): heel and toe where the base meets the foundation, the crest's upstream and downstream edges.
  double crest_thickness_m = kUnset, base_thickness_m = kUnset;
  double heel_x_m = kUnset, toe_x_m = kUnset, crest_upstream_x_m = kUnset, crest_downstream_x_m = kUnset;
  // What stands behind it when the impact arrives (unset: nothing): a deposit and water, permanent pressures on the
  // upstream face in the run, and the water's uplift on the base joint in the stability checks.
  double deposit_height_m = kUnset, deposit_unit_weight_N_m3 = kUnset, deposit_coefficient = kUnset;
  bool deposit_submerged = false;  // below the water surface at its buoyant unit weight (deposit_unit_weight the saturated one)
  double water_height_m = kUnset, water_unit_weight_N_m3 = kUnset;
  // Steel open: the column pipes, the steel's yield strength and how the members were modelled (plastic: they yield,
  // elastic: they do not).
  double column_diameter_m = kUnset, column_wall_thickness_m = kUnset;
  double yield_strength_Pa = kUnset;
  std::string member_model;  // plastic | elastic ("" unknown)
};

enum class BoulderModel { elastic, rigid, elastic_when_touching };

struct BoulderBasis {
  double mass_kg = kUnset, diameter_m = kUnset, density_kg_m3 = kUnset;
  double youngs_modulus_Pa = kUnset, poisson_ratio = kUnset;
  double speed_m_s = kUnset, impact_height_m = kUnset;  // speed at impact; height of its centre above the base then
  BoulderModel model = BoulderModel::elastic;
};

struct HydrographBasis {
  std::string source;
  double duration_s = kUnset, volume_m3_per_m = kUnset, mass_kg_per_m = kUnset, peak_flux_time_s = kUnset, section_distance_m = kUnset;
};

struct DebrisBasis {
  double density_kg_m3 = kUnset, depth_m = kUnset, length_m = kUnset, speed_m_s = kUnset, channel_slope_deg = kUnset;
  double front_length_m = kUnset;                                     // the snout; 0 a blunt front
  double youngs_modulus_Pa = kUnset, poisson_ratio = kUnset;          // a granular flow
  double bulk_modulus_Pa = kUnset;                                    // a slurry (weakly compressible fluid)
  std::optional<HydrographBasis> hydrograph;
};

struct BufferBasis {
  std::string type;  // homogenised | tyres
  double youngs_modulus_Pa = kUnset, poisson_ratio = kUnset, thickness_m = kUnset, bottom_m = kUnset, top_m = kUnset;
  double friction_angle_deg = kUnset;
};

struct DesignBasis {
  DamBasis dam;
  std::optional<BoulderBasis> boulder;
  std::optional<DebrisBasis> debris;
  std::optional<BufferBasis> buffer;
};

}  // namespace dmi
