#include "render/field.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <vtkActor.h>
#include <vtkActor2D.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkColorTransferFunction.h>
#include <vtkDoubleArray.h>
#include <vtkLookupTable.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include "render/frame_state.hpp"
#include "render/palette.hpp"
#include "render/offscreen.hpp"

namespace dmi::render {

bool valid_quantity(const std::string& q) { return q == "von_mises" || q == "sigma_xx" || q == "sigma_yy" || q == "pressure"; }

std::string quantity_label(const std::string& q) {
  if (q == "sigma_xx") return "stress σxx";
  if (q == "sigma_yy") return "stress σyy";
  if (q == "pressure") return "pressure";
  return "von Mises stress";
}

std::vector<double> particle_field(const Snapshot& s, const std::string& q) {
  std::vector<double> v(s.count);
  for (std::size_t p = 0; p < s.count; ++p) {
    const double* st = &s.stress[6 * p];
    v[p] = q == "sigma_xx" ? st[0] : q == "sigma_yy" ? st[1] : q == "pressure" ? -(st[0] + st[1] + st[2]) / 3 : s.von_mises[p];
  }
  return v;
}

namespace {

using Vtk = vtkSmartPointer<vtkObject>;
template <class T> vtkSmartPointer<T> make() { return vtkSmartPointer<T>::New(); }

const Snapshot& snap_of(const Panel& p) {
  if (p.snapshot >= p.results->snapshots.size()) throw std::runtime_error("snapshot " + std::to_string(p.snapshot) + " does not exist");
  return p.results->snapshots[p.snapshot];
}

// The actor drawing `pd`; with a lookup table its point scalars are coloured through it (the table's range).
vtkSmartPointer<vtkActor> actor_of(vtkPolyData* pd, vtkLookupTable* t = nullptr) {
  auto m = make<vtkPolyDataMapper>();
  m->SetInputData(pd);
  if (t) m->SetLookupTable(t), m->UseLookupTableScalarRangeOn();
  auto a = make<vtkActor>();
  a->SetMapper(m);
  return a;
}

vtkSmartPointer<vtkActor> particles_actor(const Snapshot& s, const std::vector<double>& field, vtkLookupTable* t, double point_px) {
  auto pts = make<vtkPoints>();
  auto verts = make<vtkCellArray>();
  auto val = make<vtkDoubleArray>();
  for (std::size_t p = 0; p < s.count; ++p) {
    pts->InsertNextPoint(s.position[s.dim * p], s.position[s.dim * p + 1], 0.0);
    verts->InsertNextCell(1);
    verts->InsertCellPoint(static_cast<vtkIdType>(p));
    val->InsertNextValue(field[p] / 1e6);
  }
  auto pd = make<vtkPolyData>();
  pd->SetPoints(pts), pd->SetVerts(verts), pd->GetPointData()->SetScalars(val);
  auto a = actor_of(pd, t);
  a->GetProperty()->SetPointSize(static_cast<float>(point_px));
  return a;
}

// Members as quads through their depth; the +e2 (top) corners carry sigma_top, the -e2 corners sigma_bottom.
vtkSmartPointer<vtkActor> members_actor(const FrameState& fs, vtkLookupTable* t) {
  auto pts = make<vtkPoints>();
  auto polys = make<vtkCellArray>();
  auto val = make<vtkDoubleArray>();
  for (const auto& e : fs.elements) {
    const double dx = e.xj[0] - e.xi[0], dy = e.xj[1] - e.xi[1], L = std::hypot(dx, dy);
    const double nx = -dy / L, ny = dx / L;  // e2
    const vtkIdType b = pts->GetNumberOfPoints();
    pts->InsertNextPoint(e.xi[0] - e.ci * nx, e.xi[1] - e.ci * ny, 0.01), val->InsertNextValue(e.bottom_i / 1e6);
    pts->InsertNextPoint(e.xj[0] - e.cj * nx, e.xj[1] - e.cj * ny, 0.01), val->InsertNextValue(e.bottom_j / 1e6);
    pts->InsertNextPoint(e.xj[0] + e.cj * nx, e.xj[1] + e.cj * ny, 0.01), val->InsertNextValue(e.top_j / 1e6);
    pts->InsertNextPoint(e.xi[0] + e.ci * nx, e.xi[1] + e.ci * ny, 0.01), val->InsertNextValue(e.top_i / 1e6);
    const vtkIdType q[4] = {b, b + 1, b + 2, b + 3};
    polys->InsertNextCell(4, q);
  }
  auto pd = make<vtkPolyData>();
  pd->SetPoints(pts), pd->SetPolys(polys), pd->GetPointData()->SetScalars(val);
  auto a = actor_of(pd, t);
  a->GetMapper()->InterpolateScalarsBeforeMappingOn();
  a->GetProperty()->EdgeVisibilityOn();
  a->GetProperty()->SetEdgeColor(0.15, 0.15, 0.15);
  a->GetProperty()->SetLineWidth(1.5f);
  return a;
}

vtkSmartPointer<vtkActor> lines_actor(const std::vector<std::vector<std::array<double, 2>>>& lines, double r, double g, double b, float width) {
  auto pts = make<vtkPoints>();
  auto cells = make<vtkCellArray>();
  for (const auto& l : lines) {
    cells->InsertNextCell(static_cast<vtkIdType>(l.size()));
    for (const auto& x : l) cells->InsertCellPoint(pts->InsertNextPoint(x[0], x[1], 0.02));
  }
  auto pd = make<vtkPolyData>();
  pd->SetPoints(pts), pd->SetLines(cells);
  auto a = actor_of(pd);
  a->GetProperty()->SetColor(r, g, b);
  a->GetProperty()->SetLineWidth(width);
  return a;
}

// Filled triangles under the supports (apex at the node), `size` m high.
vtkSmartPointer<vtkActor> supports_actor(const design::FrameInfo& f, double size) {
  auto pts = make<vtkPoints>();
  auto polys = make<vtkCellArray>();
  for (const auto& s : f.supports) {
    const auto& x = f.nodes[s.node_index];
    const vtkIdType a = pts->InsertNextPoint(x[0], x[1], 0.03);
    const vtkIdType b = pts->InsertNextPoint(x[0] - 0.6 * size, x[1] - size, 0.03);
    const vtkIdType c = pts->InsertNextPoint(x[0] + 0.6 * size, x[1] - size, 0.03);
    const vtkIdType t[3] = {a, b, c};
    polys->InsertNextCell(3, t);
  }
  auto pd = make<vtkPolyData>();
  pd->SetPoints(pts), pd->SetPolys(polys);
  auto act = actor_of(pd);
  act->GetProperty()->SetColor(0.2, 0.2, 0.2);
  return act;
}

double nice_scale(double target) {  // 1, 2, 5 x 10^k not above target
  if (!(target > 0)) return 0;
  const double p = std::pow(10.0, std::floor(std::log10(target)));
  for (double m : {5.0, 2.0, 1.0})
    if (m * p <= target) return m * p;
  return p;
}

}  // namespace

Range particle_range(const std::vector<Panel>& panels, const std::string& q) {
  std::vector<double> v;
  for (const auto& p : panels) {
    const std::vector<double> f = particle_field(snap_of(p), q);
    v.insert(v.end(), f.begin(), f.end());
  }
  if (v.empty()) return {0, 1.0};
  auto rank = [&](double frac) {  // the value at this fraction of the sorted field (nearest rank)
    const std::size_t k = std::min(v.size() - 1, static_cast<std::size_t>(std::ceil(frac * static_cast<double>(v.size()))) - (frac > 0 ? 1 : 0));
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
    return v[k];
  };
  Range r{q == "von_mises" ? *std::min_element(v.begin(), v.end()) : rank(0.01), rank(0.99)};
  if (r.hi <= r.lo) r.hi = r.lo + 1.0;  // a uniform field still gets a scale
  return r;
}

namespace {

// Per element, the fibre stresses of largest magnitude over every history sample (signed): the envelope drawn on a
// member_envelope panel, at the panel's own displaced shape.
FrameState with_envelope(const Results& r, const design::FrameInfo& f, FrameState at) {
  auto bigger = [](double& keep, double v) {
    if (std::abs(v) > std::abs(keep)) keep = v;
  };
  for (std::size_t k = 0; k < r.time.size(); ++k) {
    const FrameState s = frame_state(r, f, k);
    for (std::size_t e = 0; e < at.elements.size(); ++e) {
      ElementState& a = at.elements[e];
      const ElementState& b = s.elements[e];
      if (k == 0) a.top_i = b.top_i, a.bottom_i = b.bottom_i, a.top_j = b.top_j, a.bottom_j = b.bottom_j;
      bigger(a.top_i, b.top_i), bigger(a.bottom_i, b.bottom_i), bigger(a.top_j, b.top_j), bigger(a.bottom_j, b.bottom_j);
    }
  }
  return at;
}

FrameState panel_frame(const Panel& p) {
  FrameState fs = frame_state(*p.results, *p.frame, nearest_sample(*p.results, snap_of(p).time));
  return p.member_envelope ? with_envelope(*p.results, *p.frame, std::move(fs)) : fs;
}

}  // namespace

Range member_range(const std::vector<Panel>& panels) {
  double m = 0;
  for (const auto& p : panels) {
    if (!p.frame || p.frame->members.empty()) continue;
    const FrameState fs = panel_frame(p);
    for (const auto& e : fs.elements) m = std::max({m, std::abs(e.top_i), std::abs(e.bottom_i), std::abs(e.top_j), std::abs(e.bottom_j)});
  }
  return m > 0 ? Range{-m, m} : Range{-1.0, 1.0};
}

FieldImage render_field(const std::vector<Panel>& panels, const FieldSpec& spec, const std::string& path) {
  if (panels.empty()) throw std::runtime_error("render_field: no panel");
  if (!valid_quantity(spec.quantity)) throw std::runtime_error("unknown field quantity '" + spec.quantity + "'");
  FieldImage img;
  img.path = path, img.width = spec.width, img.height = spec.height;
  img.particles = spec.particle_range ? *spec.particle_range : particle_range(panels, spec.quantity);
  img.members = spec.member_range ? *spec.member_range : member_range(panels);
  const bool any_members = std::any_of(panels.begin(), panels.end(), [](const Panel& p) { return p.frame && !p.frame->members.empty(); });
  img.peak.value = -1e300;
  for (std::size_t i = 0; i < panels.size(); ++i) {
    const Snapshot& s = snap_of(panels[i]);
    const std::vector<double> f = particle_field(s, spec.quantity);
    for (std::size_t k = 0; k < f.size(); ++k)
      if (f[k] > img.peak.value) img.peak = {f[k], {s.position[s.dim * k], s.position[s.dim * k + 1]}, i};
  }
  img.clipped = img.peak.value > img.particles.hi * (1 + 1e-9) + 1e-9;
  auto win = Offscreen::instance().window(spec.width, spec.height);
  auto plut = lut(img.particles, spec.quantity != "von_mises");
  auto mlut = lut(img.members, true);
  const int font = std::max(16, spec.width / 54);  // ~9 pt when the picture is printed 180 mm wide
  const double right = 0.76;  // panels left of the bars
  // The title strip holds the title (wrapped once), the members' legend line and the particle-scale line.
  const bool wrap = spec.title.size() * 0.55 * font > 0.97 * spec.width && spec.title.find(": ") != std::string::npos;
  const int lines = 1 + (wrap ? 1 : 0) + (any_members ? 1 : 0) + (img.clipped ? 1 : 0);
  const double top = std::min(0.85, 1.0 - (lines * 1.3 * font + 12) / spec.height);
  // Shared view box: all panels' particles and nodes, so the panels align.
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  for (const auto& p : panels) {
    const Snapshot& s = snap_of(p);
    for (std::size_t k = 0; k < s.count; ++k)
      for (int d = 0; d < 2; ++d) lo[d] = std::min(lo[d], s.position[s.dim * k + d]), hi[d] = std::max(hi[d], s.position[s.dim * k + d]);
    if (p.frame)
      for (const auto& x : p.frame->nodes)
        for (int d = 0; d < 2; ++d) lo[d] = std::min(lo[d], x[d]), hi[d] = std::max(hi[d], x[d]);
  }
  const double size = std::max(hi[0] - lo[0], hi[1] - lo[1]);
  lo[1] -= 0.06 * size;  // room for the support symbols
  hi[1] += 0.08 * size;  // and for the panel heading
  // Deformation scale: the largest member displacement drawn as ~4 % of the picture's extent.
  double umax = 0;
  std::vector<FrameState> states(panels.size());
  for (std::size_t i = 0; i < panels.size(); ++i)
    if (panels[i].frame && !panels[i].frame->members.empty()) {
      states[i] = panel_frame(panels[i]);
      for (const auto& u : states[i].u) umax = std::max(umax, std::hypot(u[0], u[1]));
    }
  img.deform_scale = umax > 0 ? nice_scale(0.04 * size / umax) : 0;
  for (std::size_t i = 0; i < panels.size(); ++i) {
    const Panel& p = panels[i];
    const Snapshot& s = snap_of(p);
    auto ren = make<vtkRenderer>();
    ren->SetViewport(right * i / panels.size(), 0, right * (i + 1) / panels.size(), top);
    ren->SetBackground(1, 1, 1);
    const double vw = spec.width * right / panels.size(), vh = spec.height * top;
    const double cx = 0.5 * (lo[0] + hi[0]), cy = 0.5 * (lo[1] + hi[1]);
    const double half = 0.54 * std::max(hi[1] - lo[1], (hi[0] - lo[0]) * vh / vw);
    const double px_per_m = vh / (2 * half);
    const auto cs = p.results->info.numbers.find("cell_size");
    const double spacing = cs != p.results->info.numbers.end() ? 0.5 * cs->second : 0.01 * size;
    ren->AddActor(particles_actor(s, particle_field(s, spec.quantity), plut, std::max(1.0, 1.2 * spacing * px_per_m)));
    if (!states[i].elements.empty()) {
      const FrameState& fs = states[i];
      ren->AddActor(members_actor(fs, mlut));
      std::vector<std::vector<std::array<double, 2>>> deformed, initial;
      for (const auto& m : p.frame->members) {
        std::vector<std::array<double, 2>> d, o;
        for (int e = 0; e <= m.count; ++e) {
          const auto& el = p.frame->elements[m.first + std::min(e, m.count - 1)];
          const int n = e < m.count ? el.i : el.j;
          o.push_back(fs.x0[n]);
          d.push_back({fs.x0[n][0] + img.deform_scale * fs.u[n][0], fs.x0[n][1] + img.deform_scale * fs.u[n][1]});
        }
        deformed.push_back(d), initial.push_back(o);
      }
      ren->AddActor(lines_actor(initial, 0.45, 0.45, 0.45, 2.0f));
      if (img.deform_scale > 0) ren->AddActor(lines_actor(deformed, 0.75, 0.0, 0.75, 3.0f));
      ren->AddActor(supports_actor(*p.frame, 0.04 * size));
    }
    auto cam = ren->GetActiveCamera();
    cam->ParallelProjectionOn();
    cam->SetFocalPoint(cx, cy, 0), cam->SetPosition(cx, cy, 10 * size), cam->SetViewUp(0, 1, 0);
    cam->SetParallelScale(half);
    ren->ResetCameraClippingRange();
    auto head = make<vtkTextActor>();
    head->SetInput(p.heading.c_str());
    style(head->GetTextProperty(), font, true);
    head->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    head->SetPosition(0.03, 0.94);
    head->GetTextProperty()->SetVerticalJustificationToTop();
    ren->AddActor2D(head);
    win->AddRenderer(ren);
  }
  // Title strip and bar strip.
  auto top_ren = make<vtkRenderer>();
  top_ren->SetViewport(0, top, 1, 1);
  top_ren->SetBackground(1, 1, 1);
  auto title = make<vtkTextActor>();
  std::string text = spec.title;
  // Wrap a long title at its first ": " (scenario name, then what is shown).
  if (wrap) text.replace(text.find(": "), 2, ":\n");
  if (img.deform_scale > 0 && any_members) {
    char b[160];
    std::snprintf(b, sizeof b, "\nmembers: faces coloured by fibre stress (tension +); magenta: centre line deformed × %g", img.deform_scale);
    text += b;
  }
  if (img.clipped) {
    char b[200];
    std::snprintf(b, sizeof b, "\nparticles: scale to the 99th percentile, %.3g MPa; maximum %.3g MPa at (%.2f, %.2f) m", img.particles.hi / 1e6,
                  img.peak.value / 1e6, img.peak.at[0], img.peak.at[1]);
    text += b;
  }
  title->SetInput(text.c_str());
  style(title->GetTextProperty(), font, false);
  title->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  title->SetPosition(0.01, 0.08);
  top_ren->AddActor2D(title);
  win->AddRenderer(top_ren);
  auto bar_ren = make<vtkRenderer>();
  bar_ren->SetViewport(right, 0, 1, top);
  bar_ren->SetBackground(1, 1, 1);
  std::string q = quantity_label(spec.quantity);
  if (q.size() > 10) q.replace(q.rfind(' '), 1, "\n");  // "von Mises\nstress" fits the bar's width
  bar_ren->AddActor2D(scalar_bar(plut, "particles\n" + q + "\n[MPa]", 0.04, font));
  if (any_members) bar_ren->AddActor2D(scalar_bar(mlut, "members\nfibre\nstress\n[MPa]", 0.54, font));
  win->AddRenderer(bar_ren);
  write_png(win, path);
  return img;
}

}  // namespace dmi::render
