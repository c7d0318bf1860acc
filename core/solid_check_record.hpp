// The solid check's answer per load case (Lin, Cheng & Tuan, Table 1): the dam body's model, and per case its load,
// stress peaks (von Mises, principal, shear at Gauss points, centroids and nodes, with their places), base reactions
// and largest displacement. The design checks read it; results.h5 carries it (/documents/solid_check).
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace dmi {

struct SolidPeak {
  double value_Pa = 0;
  std::vector<double> location_m;
};

struct SolidProfile {  // a simulation case's face pressure by height
  std::vector<double> height_m, pressure_Pa;
};

struct SolidCase {
  std::string name, type;  // type: point | patch | simulation
  std::optional<double> time_s;  // simulation: the instant of the contact loads
  std::string member;            // simulation: the member whose loads were taken
  std::optional<SolidProfile> profile;
  std::string note;              // why a simulation case carries no load
  double load_resultant_N = 0, max_nodal_base_reaction_N = 0, max_displacement_m = 0;
  std::vector<double> total_base_reaction_N;
  // peaks[measure][location]: measure von_mises | max_principal | min_principal | max_shear, location gauss |
  // centroid | node
  std::map<std::string, std::map<std::string, SolidPeak>> peaks;
};

struct SolidModel {
  std::string element, sloped_face, axes;
  std::vector<int> cells;
  int nodes = 0, elements = 0;
  double height_m = 0, crest_thickness_m = 0, base_thickness_m = 0, width_m = 0, youngs_modulus_Pa = 0, poisson_ratio = 0;
};

struct SolidCheckRecord {
  SolidModel model;
  std::vector<SolidCase> cases;
};

}  // namespace dmi
