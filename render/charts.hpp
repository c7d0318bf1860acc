// Time-history and envelope charts (VTK charts, off-screen): curves, limit lines, legend, unit-labelled axes.
#pragma once
#include <array>
#include <string>
#include <vector>

namespace dmi::render {

struct Curve {
  std::string label;
  std::vector<double> x, y;
  std::array<unsigned char, 3> color{31, 119, 180};
  bool dashed = false;
  bool points = false;  // markers only (a scatter plot), no line
  float width = 3.0f;
};

struct ChartSpec {
  std::string title, x_label, y_label;
  std::vector<Curve> curves;
  int width = 1600, height = 900;
  double x_max = 0;  // > 0: the x axis ends here (e.g. shortly after the contact)
  bool x_tight = true;  // the x axis spans the data exactly (a time axis ends with the record); false: whole ticks
  bool log_x = false, log_y = false;  // logarithmic axes (VTK's own ticks)
  std::string svg_path;               // non-empty (ending .svg): the chart also as vector graphics there
  bool draw = true;                   // false: nothing is drawn or written (another process draws it)
};

// Writes the chart as PNG (and as SVG with spec.svg_path); throws std::runtime_error when no curve has two points.
void render_chart(const ChartSpec& spec, const std::string& path);

// The curves whose peak |y| is below a tenth of the largest curve's: on a common linear axis they lie flat, so a chart
// draws them again on their own scale. by_x: the magnitude is along x (a profile: value across, position up).
std::vector<Curve> small_magnitude_curves(const std::vector<Curve>& curves, bool by_x = false);

// A horizontal (or, with vertical = true, vertical) limit line across [a, b] as a dashed curve.
Curve limit_line(const std::string& label, double value, double a, double b, bool vertical = false);

}  // namespace dmi::render
