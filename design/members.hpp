// Member envelopes and member checks from the stored histories of results.h5: the section forces at
// both ends of every element (frame/end_forces) with the sections of /documents/structure.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "design/checks.hpp"
#include "design/limits.hpp"
#include "engine/io/results.hpp"
#include "engine/structure/section.hpp"

namespace dmi::design {

// The frame as /documents/structure describes it (docs/results.md).
struct FrameInfo {
  struct Element {
    int member = 0, i = 0, j = 0;
    double s0 = 0, s1 = 1, E = 0;
    Section section = Section::rectangle(1, 1);
  };
  struct Member {
    std::string name, material, cls;  // cls: concrete | steel (limits, material name, section, E; docs/design-checks.md)
    int first = 0, count = 0;
    double length = 0;                // m
  };
  struct Support {
    std::string node, series;         // series: the history path of its reaction
    int node_index = 0;
  };
  std::vector<std::array<double, 2>> nodes;
  std::vector<Element> elements;
  std::vector<Member> members;
  std::vector<Support> supports;
};

// Parses the structure document; `where` (the results file) names errors (std::runtime_error).
FrameInfo parse_structure(const std::string& doc, const std::string& where, const Limits& limits);

// The largest (or smallest) value of a quantity over time and where/when it occurred.
struct Extreme {
  double value = 0, time = -1;
  bool set = false;
  void max(double v, double t) { if (!set || v > value) value = v, time = t, set = true; }
  void min(double v, double t) { if (!set || v < value) value = v, time = t, set = true; }
};

// Envelope at one station (an element end; interior nodes join both adjacent element ends).
struct Station {
  double position = 0, s_m = 0, x = 0, y = 0;  // fraction of the length, distance from the start, global location (m)
  double depth = 0;                             // section depth there (m)
  Extreme N_max, N_min, V_abs, M_max, M_min;     // N, N, N, N m, N m
  Extreme sigma_tension, sigma_compression;      // Pa: max over both extreme fibres (tension +), min (compression -)
  Extreme tau, von_mises;                        // Pa
};

struct MemberEnvelope {
  std::string name, cls;
  double length = 0;
  std::vector<Station> stations;
  std::vector<Check> checks;  // the governing instance of each check along the member
};

std::vector<MemberEnvelope> member_envelopes(const Results& r, const FrameInfo& f, const Limits& limits, const std::string& where);

}  // namespace dmi::design
