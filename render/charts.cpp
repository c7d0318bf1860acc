#include "render/charts.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkGL2PSExporter.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkPlotPoints.h>
#include <vtkRenderer.h>
#include <vtkStringArray.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>

#include "render/offscreen.hpp"

namespace dmi::render {

namespace {

// About `target` ticks at 1-2-5 x 10^k steps covering [lo, hi]; the axis range is rounded out to whole steps, or with
// `tight` ends at the data (ticks inside it).
void nice_axis(vtkAxis* a, double lo, double hi, int target = 6, bool tight = false) {
  if (!(hi > lo)) hi = lo + 1;
  const double raw = (hi - lo) / target, p = std::pow(10.0, std::floor(std::log10(raw)));
  double step = 10 * p;
  for (double m : {1.0, 2.0, 5.0})
    if (m * p >= raw) {
      step = m * p;
      break;
    }
  const double a0 = tight ? std::ceil(lo / step - 1e-9) * step : std::floor(lo / step + 1e-9) * step;
  const double a1 = tight ? std::floor(hi / step + 1e-9) * step : std::ceil(hi / step - 1e-9) * step;
  auto ticks = vtkSmartPointer<vtkDoubleArray>::New();
  for (double t = a0; t <= a1 + 0.5 * step; t += step) ticks->InsertNextValue(std::abs(t) < 1e-12 * step ? 0.0 : t);
  a->SetBehavior(vtkAxis::FIXED);
  a->SetRange(tight ? lo : a0, tight ? hi : a1);
  a->SetCustomTickPositions(ticks);
}

// A logarithmic axis drawn on log10 data: ticks at the powers of ten (and 2, 5 between them when the range is short),
// labelled with the original values. (VTK 9.1's SetLogScale left the plots unscaled.)
void log_axis(vtkAxis* a, double lo, double hi) {
  const double a0 = std::floor(lo), a1 = std::ceil(hi);
  auto pos = vtkSmartPointer<vtkDoubleArray>::New();
  auto lab = vtkSmartPointer<vtkStringArray>::New();
  const bool fine = a1 - a0 <= 3;
  for (double e = a0; e <= a1 + 1e-9; e += 1)
    for (double m : fine ? std::vector<double>{1, 2, 5} : std::vector<double>{1}) {
      const double v = std::log10(m) + e;
      if (v > a1 + 1e-9) continue;
      char b[32];
      std::snprintf(b, sizeof b, "%g", m * std::pow(10.0, e));
      pos->InsertNextValue(v), lab->InsertNextValue(b);
    }
  a->SetBehavior(vtkAxis::FIXED);
  a->SetRange(a0, a1);
  a->SetCustomTickPositions(pos, lab);
}

void font(vtkTextProperty* p, int size, bool bold = false) {
  p->SetFontFamily(VTK_FONT_FILE);
  p->SetFontFile(font_file());
  p->SetFontSize(size);
  p->SetBold(bold);
  p->SetColor(0.1, 0.1, 0.1);
}
}  // namespace

std::vector<Curve> small_magnitude_curves(const std::vector<Curve>& curves, bool by_x) {
  auto peak = [by_x](const Curve& c) {
    double p = 0;
    for (double v : by_x ? c.x : c.y) p = std::max(p, std::abs(v));
    return p;
  };
  double top = 0;
  for (const Curve& c : curves) top = std::max(top, peak(c));
  std::vector<Curve> small;
  for (const Curve& c : curves)
    if (const double p = peak(c); p > 0 && p < 0.1 * top) small.push_back(c);
  return small;
}

Curve limit_line(const std::string& label, double value, double a, double b, bool vertical) {
  Curve c;
  c.label = label;
  c.color = {200, 30, 30};
  c.dashed = true;
  c.width = 2.5f;
  if (vertical) c.x = {value, value}, c.y = {a, b};
  else c.x = {a, b}, c.y = {value, value};
  return c;
}

namespace {

// The curves with two or more points, each a table of (x, y) on the chart (log10 on a log axis, where it is positive);
// the tables are returned to outlive the rendering.
std::vector<vtkSmartPointer<vtkTable>> add_curves(vtkChartXY* chart, const ChartSpec& spec) {
  std::vector<vtkSmartPointer<vtkTable>> tables;
  for (const auto& c : spec.curves) {
    if (c.x.size() < 2) continue;
    auto t = vtkSmartPointer<vtkTable>::New();
    auto x = vtkSmartPointer<vtkDoubleArray>::New();
    auto y = vtkSmartPointer<vtkDoubleArray>::New();
    x->SetName("x"), y->SetName(c.label.c_str());
    for (std::size_t k = 0; k < c.x.size(); ++k) {
      if ((spec.log_x && !(c.x[k] > 0)) || (spec.log_y && !(c.y[k] > 0))) continue;  // not on a log axis
      x->InsertNextValue(spec.log_x ? std::log10(c.x[k]) : c.x[k]), y->InsertNextValue(spec.log_y ? std::log10(c.y[k]) : c.y[k]);
    }
    t->AddColumn(x), t->AddColumn(y);
    vtkPlot* p = chart->AddPlot(c.points ? vtkChart::POINTS : vtkChart::LINE);
    p->SetInputData(t, 0, 1);
    p->SetColor(c.color[0], c.color[1], c.color[2], 255);
    p->SetWidth(c.width);
    p->SetLabel(c.label);
    if (c.dashed) p->GetPen()->SetLineType(vtkPen::DASH_LINE);
    if (!c.points)
      if (auto* pp = vtkPlotPoints::SafeDownCast(p)) pp->SetMarkerStyle(vtkPlotPoints::NONE);  // no raster sprites in the SVG
    tables.push_back(t);
  }
  return tables;
}

// The axes' ranges: every curve's points (up to x_max), on nice ticks or decades.
void set_ranges(vtkAxis* bottom, vtkAxis* left, const ChartSpec& spec) {
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const auto& c : spec.curves)
    for (std::size_t k = 0; k < c.x.size(); ++k) {
      if (spec.x_max > 0 && c.x[k] > spec.x_max) continue;
      if ((spec.log_x && !(c.x[k] > 0)) || (spec.log_y && !(c.y[k] > 0))) continue;
      const double x = spec.log_x ? std::log10(c.x[k]) : c.x[k], y = spec.log_y ? std::log10(c.y[k]) : c.y[k];
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
  if (spec.log_x) log_axis(bottom, x0, x1);
  else nice_axis(bottom, x0, x1, 8, spec.x_tight);
  if (spec.log_y) log_axis(left, y0, y1);
  else nice_axis(left, y0, y1, 6);
}

// The same chart as vector graphics (GL2PS): lines and text stay sharp in the PDF.
void write_svg(vtkRenderWindow* win, const std::string& svg_path) {
  const std::string base = svg_path.substr(0, svg_path.size() - 4);
  auto ex = vtkSmartPointer<vtkGL2PSExporter>::New();
  ex->SetRenderWindow(win);
  ex->SetFileFormatToSVG();
  ex->SetFilePrefix((base + ".tmp").c_str());
  ex->CompressOff();
  ex->SetSortToOff();
  ex->DrawBackgroundOn();  // the OpenGL2 backend draws it in any case
  ex->TextAsPathOff();
  {
    // GL2PS prints a warning on stderr for the background, a raster layer it cannot embed without libpng support
    // (Debian's build); the page behind the chart is white, so nothing is lost. fd 2 is pointed away meanwhile.
    std::fflush(stderr);
    const int saved = dup(2), null = open("/dev/null", O_WRONLY);
    if (null >= 0) dup2(null, 2), close(null);
    ex->Write();
    std::fflush(stderr);
    if (saved >= 0) dup2(saved, 2), close(saved);
  }
  std::error_code ec;
  std::filesystem::rename(base + ".tmp.svg", svg_path, ec);
  if (ec) throw std::runtime_error(svg_path + ": cannot write the SVG (" + ec.message() + ")");
}

}  // namespace

void render_chart(const ChartSpec& spec, const std::string& path) {
  bool any = false;
  for (const auto& c : spec.curves) any = any || c.x.size() >= 2;
  if (!any) throw std::runtime_error(path + ": a chart needs a curve with two points");
  if (!spec.draw) return;
  auto win = Offscreen::instance().window(spec.width, spec.height);
  auto view = vtkSmartPointer<vtkContextView>::New();
  view->SetRenderWindow(win);
  view->GetRenderer()->SetBackground(1, 1, 1);
  auto chart = vtkSmartPointer<vtkChartXY>::New();
  view->GetScene()->AddItem(chart);
  chart->SetAutoSize(false);
  // Margins: large fonts clip the bottom title, the top tick label and the last x label otherwise.
  chart->SetSize(vtkRectf(0, 8, spec.width - 40, spec.height - 30));
  const int fs = std::max(18, spec.height / 30);
  chart->SetTitle(spec.title);
  font(chart->GetTitleProperties(), fs + 4, true);
  vtkAxis* bottom = chart->GetAxis(vtkAxis::BOTTOM);
  vtkAxis* left = chart->GetAxis(vtkAxis::LEFT);
  bottom->SetTitle(spec.x_label), left->SetTitle(spec.y_label);
  for (vtkAxis* a : {bottom, left}) {
    font(a->GetTitleProperties(), fs, true);
    font(a->GetLabelProperties(), fs);
    a->GetGridPen()->SetColor(220, 220, 220);
  }
  const auto tables = add_curves(chart, spec);
  set_ranges(bottom, left, spec);
  chart->SetShowLegend(true);
  font(chart->GetLegend()->GetLabelProperties(), fs);
  chart->GetLegend()->SetInline(true);
  chart->GetLegend()->SetHorizontalAlignment(vtkChartLegend::RIGHT);
  chart->GetLegend()->SetVerticalAlignment(vtkChartLegend::TOP);
  write_png(win, path);
  if (!spec.svg_path.empty()) write_svg(win, spec.svg_path);
}

}  // namespace dmi::render
