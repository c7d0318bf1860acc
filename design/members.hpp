// Member envelopes and member checks from the stored histories of results.h5: the section forces at
// both ends of every element (frame/end_forces) with the sections of /documents/structure.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "design/checks.hpp"
#include "design/limits.hpp"
#include "engine/io/results.hpp"
#include "engine/structure/fibre.hpp"
#include "engine/structure/section.hpp"

namespace dmi::design {

// The frame as /documents/structure describes it (docs/results.md): plane (dim 2: nodes x, y; z = 0) or space
// (dim 3: x, y, z up, each element's depth axis e2).
struct FrameInfo {
  struct Element {
    int member = 0, i = 0, j = 0;
    double s0 = 0, s1 = 1, E = 0;
    double yield_strength = 0;  // Pa: an elasto-plastic element (0: elastic)
    Section section = Section::rectangle(1, 1);
    std::array<double, 3> e2{0, 0, 0};  // space frames: the section's depth axis (global)
  };
  struct Member {
    std::string name, material, cls;  // cls: concrete | steel (limits, material name, section, E; docs/design-checks.md)
    int first = 0, count = 0;
    double length = 0;                // m
    bool plastic = false;             // its elements are elasto-plastic (they yield in the run)
  };
  struct Support {
    std::string node, series;         // series: the history path of its reaction
    int node_index = 0;
  };
  int dim = 2;
  std::vector<std::array<double, 3>> nodes;
  std::vector<Element> elements;
  std::vector<Member> members;
  std::vector<Support> supports;
};

// The frame of the run's structure record, its members classed concrete or steel by the limits; `where` (the results
// file) names errors (std::runtime_error: the limits name a member the structure does not have).
FrameInfo frame_info(const StructureRecord& structure, const std::string& where, const Limits& limits);

// The largest (or smallest) value of a quantity over time and where/when it occurred.
struct Extreme {
  double value = 0, time = -1;
  bool set = false;
  void max(double v, double t) { if (!set || v > value) value = v, time = t, set = true; }
  void min(double v, double t) { if (!set || v < value) value = v, time = t, set = true; }
};

// Envelope at one station (an element end; interior nodes join both adjacent element ends).
// Plane members: V and M are the plane's. Space members: V = |(Vy, Vz)| and M = |(My, Mz)| are the resultants (M_min
// unset), with the components' own extremes and the torque T; the stresses are taken around the perimeter.
struct Station {
  double position = 0, s_m = 0, x = 0, y = 0, z = 0;  // fraction of the length, distance from the start, global location (m)
  double depth = 0;                             // section depth there (m)
  Extreme N_max, N_min, V_abs, M_max, M_min;     // N, N, N, N m, N m
  Extreme sigma_tension, sigma_compression;      // Pa: max over the extreme fibres (tension +), min (compression -)
  Extreme tau, von_mises;                        // Pa
  Extreme Vy_abs, Vz_abs, T_abs, My_max, My_min, Mz_max, Mz_min;  // space members (N, N m)
  Extreme principal;                             // space members: largest principal stress around the perimeter (Pa)
};

struct MemberEnvelope {
  int dim = 2;
  bool plastic = false;  // elasto-plastic: its section resistance is the serviceability level (it yields by design)
  std::string name, cls;
  double length = 0;
  std::vector<Station> stations;
  std::vector<Check> checks;  // the governing instance of each check along the member
};

// One check's demand and capacity at a section (units of the check, docs/design-checks.md).
struct Demand {
  std::string id;
  double demand = 0, capacity = 0;
};
// The member checks of a space member at one section under forces f: biaxial fibre stresses, principal tension with
// torsion (concrete), resultant shear, torsion and the CHS interaction (steel). The one implementation the envelopes
// and the pictures' demand histories use.
std::vector<Demand> space_demands(const Section& section, double s, const SpaceSectionForces& f, bool steel, const Limits& limits);
// The same with the section's stresses fs = space_fibre_stresses(section, s, f) already at hand.
std::vector<Demand> space_demands(const Section& section, double s, const SpaceSectionForces& f, const SpaceFibreStresses& fs, bool steel,
                                  const Limits& limits);

// The member checks of a plane member at one section under forces sf (fibre stresses fs): concrete flexural tension,
// compression and shear; steel extreme-fibre and von Mises stresses, and a CHS's interaction and shear.
std::vector<Demand> plane_demands(const Section& section, double s, const SectionForces& sf, const FibreStresses& fs, bool steel, const Limits& limits);

std::vector<MemberEnvelope> member_envelopes(const Results& r, const FrameInfo& f, const Limits& limits, const std::string& where);

}  // namespace dmi::design
