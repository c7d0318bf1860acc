// Stress-field pictures: particles coloured by a stress measure, members drawn with their depth and
// coloured by the extreme-fibre stress (top and bottom faces, so bending shows as two colours), the
// members' centre line deformed at a stated scale, supports, two scalar bars with units, a title.
#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "design/members.hpp"
#include "engine/io/results.hpp"

namespace dmi::render {

// Particle stress measure: von_mises | sigma_xx | sigma_yy | pressure (= -(sxx + syy + szz) / 3).
bool valid_quantity(const std::string& q);
std::string quantity_label(const std::string& q);  // e.g. "von Mises stress"
// The particle field of snapshot `snap` (Pa), one value per particle.
std::vector<double> particle_field(const Snapshot& s, const std::string& quantity);

struct Range {
  double lo = 0, hi = 0;  // Pa
  bool valid() const { return hi > lo; }
};

// One panel: a run at one snapshot.
struct Panel {
  const Results* results = nullptr;
  const design::FrameInfo* frame = nullptr;  // null: no members
  std::size_t snapshot = 0;
  std::string heading;                       // e.g. "with buffer, t = 28.8 ms"
};

struct FieldSpec {
  std::string quantity = "von_mises";
  int width = 2000, height = 1150;  // pixels; panels share the width
  std::string title;
  std::optional<Range> particle_range, member_range;  // fixed scales (a sequence or a comparison); else the data's
};

struct FieldImage {
  std::string path;
  int width = 0, height = 0;
  Range particles, members;  // the colour scales used (Pa)
  double deform_scale = 0;   // exaggeration of the deformed centre line (0: none drawn)
};

// Renders one or more panels side by side on shared colour scales and writes a PNG.
FieldImage render_field(const std::vector<Panel>& panels, const FieldSpec& spec, const std::string& path);

// The data range of the particle field over the given panels, and of the members' fibre stresses
// (symmetric about zero, as the member colour map is diverging).
Range particle_range(const std::vector<Panel>& panels, const std::string& quantity);
Range member_range(const std::vector<Panel>& panels);

}  // namespace dmi::render
