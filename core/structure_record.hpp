// The members as the run built them: nodes, elements with their sections and materials, members and supports. The
// design checks and the pictures read the frame from it (never from the scenario); results.h5 carries it
// (/documents/structure, docs/results.md). SI units; coordinates have the run's dimension.
#pragma once
#include <array>
#include <string>
#include <vector>

namespace dmi {

struct SectionRecord {
  std::string kind;  // rectangle | tapered_rectangle | pipe | box | i_section
  double diameter_m = 0, wall_thickness_m = 0;                // pipe (box: wall_thickness_m)
  double width_m = 0, depth_start_m = 0, depth_end_m = 0;     // rectangles, box, i_section (width: the flanges')
  double flange_thickness_m = 0, web_thickness_m = 0;         // i_section
};

struct ElementRecord {
  int member = 0, i = 0, j = 0;
  double s0 = 0, s1 = 1;  // the element's span along its member's taper
  SectionRecord section;
  double youngs_modulus_Pa = 0, poisson_ratio = 0, density_kg_m3 = 0;
  double yield_strength_Pa = 0, hardening_ratio = 0;  // elasto-plastic when yield_strength_Pa > 0
  std::string steel_curve;                            // "menegotto_pinto", or "" for the bilinear steel
  std::array<double, 3> e2{0, 0, 0};                  // space frames: the section's depth axis (global)
};

struct MemberRecord {
  std::string name, material;
  int first_element = 0, elements = 0;
};

struct SupportRecord {
  std::string node, type, series;  // series: the history path of its reaction
  int node_index = 0;
  std::vector<bool> fixed;         // restrained DOFs (3 in 2D, 6 in 3D)
};

struct StructureRecord {
  int dimension = 2;
  std::vector<std::vector<double>> nodes_m;
  std::vector<std::string> node_names;
  std::vector<ElementRecord> elements;
  std::vector<MemberRecord> members;
  std::vector<SupportRecord> supports;
  std::vector<double> gravity_m_s2;
  double plane_thickness_m = 1;
};

}  // namespace dmi
