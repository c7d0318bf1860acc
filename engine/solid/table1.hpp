// Lin, Cheng & Tuan, Table 1: stress dispersion of a 980 kN impact on a concrete column, hex8 model.
//   Column H = 4 m, crest 1 m, base 1.6 m thick, face 2 m wide; E = 25 GPa, nu = 0.3; 8 x 10 x 20 hex8
//   (thickness x width x height), base z = 0 fixed. Load 980 kN horizontal (+x) on the upstream face at
//   y = 1 m, z = 3.6 m: at one node, or pyramid patches 0.4 x 0.4, 0.8 x 0.4, 0.4 x 0.8 m (width x height).
//   Paper: peak stress 11 224.99 / 3 666.43 / 3 666.40 / 3 666.4 kPa, peak fixed-end force 122.44 kN.
//   Unknown in the paper: which face slopes and which stress measure is reported; the study tabulates the
//   peaks of several measures at Gauss points, centroids and nodes for each sloped-face choice.
#pragma once
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "engine/solid/mesh.hpp"
#include "engine/solid/stress.hpp"

namespace dmi::solid {

constexpr double kPaperBTable1PeakStress_kPa[4] = {11224.99, 3666.43, 3666.40, 3666.4};
constexpr double kPaperBTable1FixedEndForce_kN = 122.44;

struct Table1Setup {
  TaperedBlock block{};            // defaults are the paper's column and mesh
  double E_Pa = 25e9, nu = 0.3;
  double force_N = 980e3;
  double load_depth_below_crest_m = 0.4;
  std::vector<SlopedFace> sloped = {SlopedFace::upstream, SlopedFace::downstream};
  std::vector<Measure> measures = {Measure::von_mises, Measure::max_principal, Measure::min_principal,
                                   Measure::szz, Measure::max_shear};
  std::vector<Location> locations = {Location::gauss, Location::centroid, Location::node};
};

struct Table1Case {
  std::string name;           // "point", "0.4x0.4", ...
  double width_m = 0, height_m = 0;  // 0 for the point load
};
// The paper's four load cases, in Table 1 order.
std::vector<Table1Case> table1_cases();

struct Table1Row {
  SlopedFace sloped = SlopedFace::upstream;
  Table1Case load;
  double patch_scale = NAN;           // add_patch_load scaling (1 for the point load)
  // peak_kPa[m][l] for setup.measures x setup.locations; peak_z_m the height of that peak.
  std::vector<std::vector<double>> peak_kPa, peak_z_m;
  double max_node_reaction_kN = NAN;  // largest |r| over base nodes
  Eigen::Vector3d max_node_reaction_components_kN = Eigen::Vector3d::Constant(NAN);
  Eigen::Vector3d max_node_reaction_position_m = Eigen::Vector3d::Constant(NAN);
  double max_node_reaction_x_kN = NAN, max_node_reaction_z_kN = NAN;  // largest |r_x|, |r_z| (any node)
  Eigen::Vector3d total_reaction_kN = Eigen::Vector3d::Constant(NAN);
  double tip_displacement_mm = NAN;   // u_x at the load node
};

// Runs every sloped-face choice x load case (one factorisation per choice).
std::vector<Table1Row> table1_study(const Table1Setup& setup = {});

// Markdown tables: per row the peaks (kPa) and reactions, then the ranking of (sloped, measure, location)
// by the RMS relative error against the paper's four peak stresses.
std::string format_table1(const Table1Setup& setup, const std::vector<Table1Row>& rows);

struct Table1Match {
  SlopedFace sloped;
  Measure measure;
  Location location;
  double rms_rel_error;  // over the 4 peak stresses
};
std::vector<Table1Match> rank_table1_matches(const Table1Setup& setup, const std::vector<Table1Row>& rows);

}  // namespace dmi::solid
