// Stress-field pictures: particles coloured by a stress measure, members drawn with their depth and
// coloured by the extreme-fibre stress (top and bottom faces, so bending shows as two colours), the
// members' centre line deformed at a stated scale, supports, two scalar bars with units, a title.
#pragma once
#include <array>
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
  bool member_envelope = false;              // members coloured by their fibre-stress envelope over the whole run
};

struct FieldSpec {
  std::string quantity = "von_mises";
  int width = 2000, height = 1150;  // pixels; panels share the width
  std::string title;
  std::optional<Range> particle_range, member_range;  // fixed scales (a sequence or a comparison); else the data's
  // 3D runs: a vertical section normal to y through y = section_y (m), seen from -y: the particles within a cell of it
  // and the members cut there (the part beyond it). Unset: the oblique view.
  std::optional<double> section_y;
  // false: only the picture's description (scales, peak, deformation scale) is worked out; another process draws it.
  bool draw = true;
};

// The particle with the largest field value over the panels: what a robust colour scale clips.
struct ParticlePeak {
  double value = 0;                   // Pa
  std::array<double, 3> at{0, 0, 0};  // m (z = 0 in a plane run)
  std::size_t panel = 0;
  bool space = false;                 // a 3D run: `at` has z
  std::string where() const;          // "(x, y) m" or "(x, y, z) m"
};

struct FieldImage {
  std::string path;
  int width = 0, height = 0;
  Range particles, members;  // the colour scales used (Pa)
  double deform_scale = 0;   // exaggeration of the deformed centre line (0: none drawn)
  ParticlePeak peak;         // the largest particle value drawn
  bool clipped = false;      // peak.value lies above the particle scale (drawn in its top colour)
};

// Renders one or more panels side by side on shared colour scales and writes a PNG.
FieldImage render_field(const std::vector<Panel>& panels, const FieldSpec& spec, const std::string& path);

// The colour range of the particle field over the given panels: robust, from the 1st (signed quantities; else the
// smallest value) to the 99th percentile, so that a few outlier particles do not wash out the rest (the picture
// states the maximum and where it is); and of the members' fibre stresses (symmetric about zero, as the member colour
// map is diverging; a panel with member_envelope contributes its envelope).
Range particle_range(const std::vector<Panel>& panels, const std::string& quantity);
// Stresses below 1 kPa are round-off for an impact (a dam's self-weight alone gives tens of kPa): a colour scale spans
// at least kStressScaleFloor, so that a field at rest, or before the contact, is not drawn in the top colour.
inline constexpr double kStressScaleFloor = 1e3;  // Pa
Range at_least_round_off(Range r);
Range member_range(const std::vector<Panel>& panels);

}  // namespace dmi::render
