// What the presets say (read by presets.cpp) and the scene builder (preset_scene.cpp).
#pragma once
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/scenario/config.hpp"

namespace dmi {

struct DamPreset {
  std::string type, base = "fixed", sloped_face = "downstream", model = "members", damping_model = "modal";
  std::string beam_theory;  // the members' beam theory (scenario structure.theory); empty before parsing
  std::string member_model = "plastic";  // steel_open: plastic (elastic_plastic steel) or elastic members
  double height = 0, width = 1.0, damping_ratio = 0.05;
  bool width_given = true;  // false: 2D with a boulder takes the effective width of the impact (preset_scene.cpp)
  int elements = 8;
  double crest = 0, base_thickness = 0;                          // concrete_gravity, m
  nlohmann::json concrete, steel;                                // material objects
  double steel_yield = 0;                                        // steel_open: f_y (Pa) the checks take
  int rows = 2, levels = 2;                                      // steel_open
  double row_spacing = 0, column_d = 0, column_t = 0, beam_d = 0, beam_t = 0;
  bool bracing = true;
  int columns = 0;                                               // steel_open in 3D: columns per row across (0: 3)
  // What stands behind a concrete gravity dam when the impact arrives (permanent pressures on the upstream face).
  double deposit_height = 0, deposit_unit_weight = 18000, deposit_coefficient = 0.5;  // m, N/m^3, K
  bool deposit_submerged = false;  // below the water surface: the buoyant unit weight
  double water_height = 0, water_unit_weight = 9810;                                  // m, N/m^3
};

struct BoulderPreset {
  double diameter = 0, mass = 0, density = 2650, youngs_modulus = 50e9, poisson_ratio = 0.25;
  DVec velocity, position;
  double release_height = 0, impact_height = 0, gap = -1;        // gap < 0: default
  double across = 0;                                               // 3D: impact point across the channel (y, m)
  std::string model = "auto";                                      // auto | rigid | elastic
};

struct DebrisPreset {
  double depth = 0, length = 0, velocity = 0, slope = 0, gap = -1, bed_friction = 0.4;
  double front_length = -1;  // < 0: the Coulomb wedge (preset_scene.cpp)
  Hydrograph hydrograph;     // given: an inflow section section_distance upstream of the dam, instead of a block
  double section_distance = -1;  // m; < 0: 2 V / H + 2 h_max (preset_scene.cpp)
  nlohmann::json material;
};

struct BufferPreset {
  std::string type = "homogenised", fill = "none";
  double bottom = 0, top = 0, thickness = 0, viscosity = 0;
  double tyre_diameter = 0.6, ring_thickness = 0.08;
  nlohmann::json material;
};

struct PresetScene {
  DamPreset dam;
  std::optional<BoulderPreset> boulder;
  std::optional<DebrisPreset> debris;
  std::optional<BufferPreset> buffer;
  // The without-buffer variant of a comparison: the buffer it is compared with, which sets the default cell of both
  // (the comparison holds at one resolution).
  std::optional<BufferPreset> compared_buffer;
  double cell_size = 0;          // the user's grid.cell_size, 0 = choose
  bool gravity_given = false;
  int dim = 2;                   // analysis.dimension: 2 (an elevation, plane strain) or 3
};

// The low-level scenario JSON of the presets (without the user's low-level keys).
nlohmann::json build_preset_scene(const PresetScene& p, const std::string& file);
// Recursive merge: objects key by key (from wins), arrays appended, anything else replaced.
void merge_json(nlohmann::json& into, const nlohmann::json& from);

}  // namespace dmi
