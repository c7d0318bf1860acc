#include "render/field.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include <vtkActor.h>
#include <vtkActor2D.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkClipPolyData.h>
#include <vtkPlane.h>
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

std::string ParticlePeak::where() const {
  char b[96];
  if (space) std::snprintf(b, sizeof b, "(%.2f, %.2f, %.2f) m", at[0], at[1], at[2]);
  else std::snprintf(b, sizeof b, "(%.2f, %.2f) m", at[0], at[1]);
  return b;
}

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

// Particles as points; with a slab (3D section) only those with |y - slab_y| <= slab_half.
vtkSmartPointer<vtkActor> particles_actor(const Snapshot& s, const std::vector<double>& field, vtkLookupTable* t, double point_px,
                                          std::optional<double> slab_y = {}, double slab_half = 0) {
  auto pts = make<vtkPoints>();
  auto verts = make<vtkCellArray>();
  auto val = make<vtkDoubleArray>();
  for (std::size_t p = 0; p < s.count; ++p) {
    if (slab_y && std::abs(s.position[s.dim * p + 1] - *slab_y) > slab_half) continue;
    const vtkIdType id = pts->InsertNextPoint(s.position[s.dim * p], s.position[s.dim * p + 1], s.dim == 3 ? s.position[s.dim * p + 2] : 0.0);
    verts->InsertNextCell(1);
    verts->InsertCellPoint(id);
    val->InsertNextValue(field[p] / 1e6);
  }
  auto pd = make<vtkPolyData>();
  pd->SetPoints(pts), pd->SetVerts(verts), pd->GetPointData()->SetScalars(val);
  auto a = actor_of(pd, t);
  a->GetProperty()->SetPointSize(static_cast<float>(point_px));
  if (s.dim == 3) a->GetProperty()->RenderPointsAsSpheresOn();  // shaded splats: depth reads in an oblique view
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

// A space element's section axes: e1 along the chord a -> b, e2 the structure's depth axis made normal to it, e3 = e1 x e2.
void section_axes(const std::array<double, 3>& a, const std::array<double, 3>& b, const std::array<double, 3>& e2_hint, double e1[3], double e2[3],
                  double e3[3]) {
  double n = 0;
  for (int c = 0; c < 3; ++c) e1[c] = b[c] - a[c], n += e1[c] * e1[c];
  for (int c = 0; c < 3; ++c) e1[c] /= std::sqrt(n);
  const double d = e2_hint[0] * e1[0] + e2_hint[1] * e1[1] + e2_hint[2] * e1[2];
  n = 0;
  for (int c = 0; c < 3; ++c) e2[c] = e2_hint[c] - d * e1[c], n += e2[c] * e2[c];
  for (int c = 0; c < 3; ++c) e2[c] /= std::sqrt(n);
  e3[0] = e1[1] * e2[2] - e1[2] * e2[1], e3[1] = e1[2] * e2[0] - e1[0] * e2[2], e3[2] = e1[0] * e2[1] - e1[1] * e2[0];
}

// The corners of every space element's end sections in the initial geometry (a pipe's bounding square).
std::vector<std::array<double, 3>> section_corners(const design::FrameInfo& f) {
  std::vector<std::array<double, 3>> out;
  for (const auto& el : f.elements) {
    double e1[3], e2[3], e3[3];
    section_axes(f.nodes[el.i], f.nodes[el.j], el.e2, e1, e2, e3);
    for (int end = 0; end < 2; ++end) {
      const double s = end ? el.s1 : el.s0, c = el.section.half_depth(s), w = 0.5 * el.section.width(s);
      const auto& x = f.nodes[end ? el.j : el.i];
      for (double y : {-c, c})
        for (double z : {-w, w}) out.push_back({x[0] + y * e2[0] + z * e3[0], x[1] + y * e2[1] + z * e3[1], x[2] + y * e2[2] + z * e3[2]});
    }
  }
  return out;
}

// Space members as prisms along their displaced chords: a rectangle's four corners or a pipe's 16-gon at +-c along the
// section's depth axis e2 and +-w across (e3 = e1 x e2), each vertex coloured by its own fibre stress
// sigma = N/A - Mz y'/Iz + My z'/Iy (space_frame.hpp), so biaxial bending shows around the section.
vtkSmartPointer<vtkActor> space_members_actor(const FrameState& fs, const design::FrameInfo& f, vtkLookupTable* t, std::optional<double> cut_y = {}) {
  auto pts = make<vtkPoints>();
  auto polys = make<vtkCellArray>();
  auto val = make<vtkDoubleArray>();
  for (std::size_t k = 0; k < fs.elements.size(); ++k) {
    const auto& e = fs.elements[k];
    const auto& el = f.elements[k];
    const bool pipe = el.section.kind() == SectionKind::pipe;
    double e1[3], e2[3], e3[3];
    section_axes(e.xi, e.xj, el.e2, e1, e2, e3);
    const int sides = pipe ? 16 : 4;
    const vtkIdType base = pts->GetNumberOfPoints();
    for (int end = 0; end < 2; ++end) {
      const double s = end ? el.s1 : el.s0, c = el.section.half_depth(s), w = 0.5 * el.section.width(s);
      const SpaceSectionForces& q = end ? e.fj : e.fi;
      const auto& x = end ? e.xj : e.xi;
      const double A = el.section.area(s), Iz = el.section.inertia(s), Iy = el.section.inertia_y(s);
      for (int v = 0; v < sides; ++v) {
        const double a = 2 * std::numbers::pi * (v + (pipe ? 0.0 : 0.5)) / sides;
        const double y = pipe ? c * std::cos(a) : (std::cos(a) > 0 ? c : -c), z = pipe ? c * std::sin(a) : (std::sin(a) > 0 ? w : -w);
        pts->InsertNextPoint(x[0] + y * e2[0] + z * e3[0], x[1] + y * e2[1] + z * e3[1], x[2] + y * e2[2] + z * e3[2]);
        val->InsertNextValue(space_fibre_sigma(q, A, Iy, Iz, y, z) / 1e6);
      }
    }
    for (int v = 0; v < sides; ++v) {
      const vtkIdType quad[4] = {base + v, base + (v + 1) % sides, base + sides + (v + 1) % sides, base + sides + v};
      polys->InsertNextCell(4, quad);
    }
  }
  auto pd = make<vtkPolyData>();
  pd->SetPoints(pts), pd->SetPolys(polys), pd->GetPointData()->SetScalars(val);
  if (cut_y) {  // keep y >= cut_y: the section's far side
    auto plane = make<vtkPlane>();
    plane->SetOrigin(0, *cut_y, 0), plane->SetNormal(0, 1, 0);
    auto clip = make<vtkClipPolyData>();
    clip->SetInputData(pd), clip->SetClipFunction(plane), clip->Update();
    pd->DeepCopy(clip->GetOutput());
  }
  auto a = actor_of(pd, t);
  a->GetMapper()->InterpolateScalarsBeforeMappingOn();
  return a;
}

// Polylines; a plane picture's (z = 0) drawn just in front of the members' faces.
vtkSmartPointer<vtkActor> lines_actor(const std::vector<std::vector<std::array<double, 3>>>& lines, double r, double g, double b, float width, bool space) {
  auto pts = make<vtkPoints>();
  auto cells = make<vtkCellArray>();
  for (const auto& l : lines) {
    cells->InsertNextCell(static_cast<vtkIdType>(l.size()));
    for (const auto& x : l) cells->InsertCellPoint(pts->InsertNextPoint(x[0], x[1], space ? x[2] : 0.02));
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
    if (f.dim == 3) {  // a square plate in the horizontal plane at the node (z up)
      const vtkIdType q[4] = {pts->InsertNextPoint(x[0] - size, x[1] - size, x[2]), pts->InsertNextPoint(x[0] + size, x[1] - size, x[2]),
                              pts->InsertNextPoint(x[0] + size, x[1] + size, x[2]), pts->InsertNextPoint(x[0] - size, x[1] + size, x[2])};
      polys->InsertNextCell(4, q);
      continue;
    }
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
  return at_least_round_off({q == "von_mises" ? *std::min_element(v.begin(), v.end()) : rank(0.01), rank(0.99)});
}

Range at_least_round_off(Range r) {
  if (!(r.hi - r.lo >= kStressScaleFloor)) r.hi = r.lo + kStressScaleFloor;
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
  m = std::max(m, 0.5 * kStressScaleFloor);
  return Range{-m, m};
}

namespace {

// The largest particle value over the panels and where it is.
ParticlePeak particle_peak(const std::vector<Panel>& panels, const std::string& quantity) {
  ParticlePeak peak;
  peak.value = -1e300;
  for (std::size_t i = 0; i < panels.size(); ++i) {
    const Snapshot& s = snap_of(panels[i]);
    const std::vector<double> f = particle_field(s, quantity);
    for (std::size_t k = 0; k < f.size(); ++k)
      if (f[k] > peak.value)
        peak = {f[k], {s.position[s.dim * k], s.position[s.dim * k + 1], s.dim == 3 ? s.position[s.dim * k + 2] : 0.0}, i, s.dim == 3};
  }
  return peak;
}

// Shared view box: all panels' particles and nodes, so the panels align (a space member's section corners too: a wide
// wall reaches far from its centre line). A plane picture keeps room for the support symbols and the panel heading.
struct ViewBox {
  bool space = false;
  double lo[3] = {1e300, 1e300, 0}, hi[3] = {-1e300, -1e300, 0};
  double size = 0;
};

ViewBox view_box(const std::vector<Panel>& panels) {
  ViewBox b;
  b.space = std::any_of(panels.begin(), panels.end(), [](const Panel& p) { return snap_of(p).dim == 3; });
  const int nd = b.space ? 3 : 2;
  if (b.space) b.lo[2] = 1e300, b.hi[2] = -1e300;
  auto take = [&](const auto& x, int dims) {
    for (int d = 0; d < dims; ++d) b.lo[d] = std::min(b.lo[d], x[d]), b.hi[d] = std::max(b.hi[d], x[d]);
  };
  for (const auto& p : panels) {
    const Snapshot& s = snap_of(p);
    for (std::size_t k = 0; k < s.count; ++k) take(&s.position[s.dim * k], nd);
    if (p.frame)
      for (const auto& x : p.frame->nodes) take(x, nd);
    if (p.frame && b.space)
      for (const auto& x : section_corners(*p.frame)) take(x, 3);
  }
  b.size = std::max({b.hi[0] - b.lo[0], b.hi[1] - b.lo[1], b.hi[2] - b.lo[2]});
  if (!b.space) {
    b.lo[1] -= 0.06 * b.size;
    b.hi[1] += 0.08 * b.size;
  }
  return b;
}

// The oblique view's axes: towards the camera (view), up and right on the screen. A section is seen from upstream.
struct ViewAxes {
  double view[3], up[3], right[3];
};

ViewAxes view_axes(bool section) {
  ViewAxes a{{section ? 0.0 : -0.62, section ? -1.0 : -0.62, section ? 0.0 : 0.48}, {}, {}};
  const double up0[3] = {0, 0, 1};
  const double* view = a.view;
  const double d = up0[0] * view[0] + up0[1] * view[1] + up0[2] * view[2];
  double n = 0;
  for (int c = 0; c < 3; ++c) a.up[c] = up0[c] - d * view[c] / (view[0] * view[0] + view[1] * view[1] + view[2] * view[2]), n += a.up[c] * a.up[c];
  for (double& c : a.up) c /= std::sqrt(n);
  double* u = a.up;
  a.right[0] = u[1] * view[2] - u[2] * view[1], a.right[1] = u[2] * view[0] - u[0] * view[2], a.right[2] = u[0] * view[1] - u[1] * view[0];
  n = std::sqrt(a.right[0] * a.right[0] + a.right[1] * a.right[1] + a.right[2] * a.right[2]);
  for (double& c : a.right) c /= n;
  return a;
}

// Where a panel's camera looks and how much it shows (half the height, m): the box's centre; in 3D the centre of its
// corners on the screen, with a little room above for the heading.
void panel_camera(const ViewBox& b, const ViewAxes& ax, double vw, double vh, double centre[3], double& half) {
  centre[0] = 0.5 * (b.lo[0] + b.hi[0]), centre[1] = 0.5 * (b.lo[1] + b.hi[1]), centre[2] = 0.5 * (b.lo[2] + b.hi[2]);
  half = 0.54 * std::max(b.hi[1] - b.lo[1], (b.hi[0] - b.lo[0]) * vh / vw);
  if (!b.space) return;
  double r0 = 1e300, r1 = -1e300, u0 = 1e300, u1 = -1e300;
  for (int k = 0; k < 8; ++k) {
    const double x[3] = {k & 1 ? b.hi[0] : b.lo[0], k & 2 ? b.hi[1] : b.lo[1], k & 4 ? b.hi[2] : b.lo[2]};
    const double r = x[0] * ax.right[0] + x[1] * ax.right[1] + x[2] * ax.right[2], u = x[0] * ax.up[0] + x[1] * ax.up[1] + x[2] * ax.up[2];
    r0 = std::min(r0, r), r1 = std::max(r1, r), u0 = std::min(u0, u), u1 = std::max(u1, u);
  }
  const double rc = 0.5 * (r0 + r1), uc = 0.5 * (u0 + u1) + 0.04 * (u1 - u0);
  const double c0[3] = {centre[0], centre[1], centre[2]};
  const double rr = c0[0] * ax.right[0] + c0[1] * ax.right[1] + c0[2] * ax.right[2], uu = c0[0] * ax.up[0] + c0[1] * ax.up[1] + c0[2] * ax.up[2];
  for (int c = 0; c < 3; ++c) centre[c] += (rc - rr) * ax.right[c] + (uc - uu) * ax.up[c];
  half = 0.58 * std::max(u1 - u0, (r1 - r0) * vh / vw);
}

// The members' centre lines, as built and deformed (displacements times the picture's scale).
void add_member_lines(vtkRenderer* ren, const Panel& p, const FrameState& fs, double scale, bool space, double size) {
  std::vector<std::vector<std::array<double, 3>>> deformed, initial;
  for (const auto& m : p.frame->members) {
    std::vector<std::array<double, 3>> d, o;
    for (int e = 0; e <= m.count; ++e) {
      const auto& el = p.frame->elements[m.first + std::min(e, m.count - 1)];
      const int n = e < m.count ? el.i : el.j;
      o.push_back(fs.x0[n]);
      d.push_back({fs.x0[n][0] + scale * fs.u[n][0], fs.x0[n][1] + scale * fs.u[n][1], fs.x0[n][2] + scale * fs.u[n][2]});
    }
    deformed.push_back(d), initial.push_back(o);
  }
  ren->AddActor(lines_actor(initial, 0.45, 0.45, 0.45, 2.0f, space));
  if (scale > 0) ren->AddActor(lines_actor(deformed, 0.75, 0.0, 0.75, 3.0f, space));
  ren->AddActor(supports_actor(*p.frame, 0.04 * size));
}

struct PanelStyle {
  const FieldSpec& spec;
  const ViewBox& box;
  const ViewAxes& axes;
  vtkSmartPointer<vtkLookupTable> particles, members;
  double right, top, scale;
  int font;
};

// One panel: its particles coloured, its members, the camera and the heading.
vtkSmartPointer<vtkRenderer> panel_renderer(const Panel& p, std::size_t i, std::size_t n, const FrameState& fs, const PanelStyle& st) {
  const Snapshot& s = snap_of(p);
  const bool space = st.box.space, section = space && st.spec.section_y.has_value();
  auto ren = make<vtkRenderer>();
  ren->SetViewport(st.right * i / n, 0, st.right * (i + 1) / n, st.top);
  ren->SetBackground(1, 1, 1);
  const double vw = st.spec.width * st.right / n, vh = st.spec.height * st.top;
  double centre[3], half = 0;
  panel_camera(st.box, st.axes, vw, vh, centre, half);
  const double px_per_m = vh / (2 * half);
  const std::optional<double>& cs = p.results->info.stats.cell_size;
  const double spacing = cs ? 0.5 * *cs : 0.01 * st.box.size;
  const auto cut = section ? st.spec.section_y : std::nullopt;
  ren->AddActor(particles_actor(s, particle_field(s, st.spec.quantity), st.particles, std::max(1.0, 1.2 * spacing * px_per_m), cut, 2 * spacing));
  if (!fs.elements.empty()) {
    ren->AddActor(space ? space_members_actor(fs, *p.frame, st.members, cut) : members_actor(fs, st.members));
    add_member_lines(ren, p, fs, st.scale, space, st.box.size);
  }
  auto cam = ren->GetActiveCamera();
  cam->ParallelProjectionOn();
  const double size = st.box.size;
  if (space) {
    const double* view = st.axes.view;
    cam->SetFocalPoint(centre[0], centre[1], centre[2]);
    cam->SetPosition(centre[0] + 10 * size * view[0], centre[1] + 10 * size * view[1], centre[2] + 10 * size * view[2]);
    cam->SetViewUp(0, 0, 1);
  } else {
    cam->SetFocalPoint(centre[0], centre[1], 0), cam->SetPosition(centre[0], centre[1], 10 * size), cam->SetViewUp(0, 1, 0);
  }
  cam->SetParallelScale(half);
  ren->ResetCameraClippingRange();
  auto head = make<vtkTextActor>();
  head->SetInput(p.heading.c_str());
  style(head->GetTextProperty(), st.font, true);
  head->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  head->SetPosition(0.03, 0.94);
  head->GetTextProperty()->SetVerticalJustificationToTop();
  ren->AddActor2D(head);
  return ren;
}

// The title strip: the title (wrapped at its first ": " when long), the members' legend and the particles' scale.
vtkSmartPointer<vtkRenderer> title_renderer(const FieldSpec& spec, const FieldImage& img, bool wrap, bool any_members, double top, int font) {
  auto ren = make<vtkRenderer>();
  ren->SetViewport(0, top, 1, 1);
  ren->SetBackground(1, 1, 1);
  auto title = make<vtkTextActor>();
  std::string text = spec.title;
  if (wrap) text.replace(text.find(": "), 2, ":\n");
  if (img.deform_scale > 0 && any_members) {
    char b[160];
    std::snprintf(b, sizeof b, "\nmembers: faces coloured by fibre stress (tension +); magenta: centre line deformed × %g", img.deform_scale);
    text += b;
  }
  if (img.clipped) {
    char b[200];
    std::snprintf(b, sizeof b, "\nparticles: scale to the 99th percentile, %.3g MPa; maximum %.3g MPa at %s", img.particles.hi / 1e6,
                  img.peak.value / 1e6, img.peak.where().c_str());
    text += b;
  }
  title->SetInput(text.c_str());
  style(title->GetTextProperty(), font, false);
  title->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  title->SetPosition(0.01, 0.08);
  ren->AddActor2D(title);
  return ren;
}

// The colour bars: particles, and members when there are any.
vtkSmartPointer<vtkRenderer> bar_renderer(const FieldSpec& spec, const PanelStyle& st, bool any_members) {
  auto ren = make<vtkRenderer>();
  ren->SetViewport(st.right, 0, 1, st.top);
  ren->SetBackground(1, 1, 1);
  std::string q = quantity_label(spec.quantity);
  if (q.size() > 10) q.replace(q.rfind(' '), 1, "\n");  // "von Mises\nstress" fits the bar's width
  ren->AddActor2D(scalar_bar(st.particles, "particles\n" + q + "\n[MPa]", 0.04, st.font));
  if (any_members) ren->AddActor2D(scalar_bar(st.members, "members\nfibre\nstress\n[MPa]", 0.54, st.font));
  return ren;
}

}  // namespace

FieldImage render_field(const std::vector<Panel>& panels, const FieldSpec& spec, const std::string& path) {
  if (panels.empty()) throw std::runtime_error("render_field: no panel");
  if (!valid_quantity(spec.quantity)) throw std::runtime_error("unknown field quantity '" + spec.quantity + "'");
  FieldImage img;
  img.path = path, img.width = spec.width, img.height = spec.height;
  img.particles = spec.particle_range ? *spec.particle_range : particle_range(panels, spec.quantity);
  img.members = spec.member_range ? *spec.member_range : member_range(panels);
  const bool any_members = std::any_of(panels.begin(), panels.end(), [](const Panel& p) { return p.frame && !p.frame->members.empty(); });
  img.peak = particle_peak(panels, spec.quantity);
  img.clipped = img.peak.value > img.particles.hi * (1 + 1e-9) + 1e-9;
  const int font = std::max(16, spec.width / 54);  // ~9 pt when the picture is printed 180 mm wide
  const double right = 0.76;  // panels left of the bars
  // The title strip holds the title (wrapped once), the members' legend line and the particle-scale line.
  const bool wrap = spec.title.size() * 0.55 * font > 0.97 * spec.width && spec.title.find(": ") != std::string::npos;
  const int lines = 1 + (wrap ? 1 : 0) + (any_members ? 1 : 0) + (img.clipped ? 1 : 0);
  const double top = std::min(0.85, 1.0 - (lines * 1.3 * font + 12) / spec.height);
  const ViewBox box = view_box(panels);
  // Deformation scale: the largest member displacement drawn as ~4 % of the picture's extent.
  double umax = 0;
  std::vector<FrameState> states(panels.size());
  for (std::size_t i = 0; i < panels.size(); ++i)
    if (panels[i].frame && !panels[i].frame->members.empty()) {
      states[i] = panel_frame(panels[i]);
      for (const auto& u : states[i].u) umax = std::max(umax, std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]));
    }
  img.deform_scale = umax > 0 ? nice_scale(0.04 * box.size / umax) : 0;
  if (!spec.draw) return img;
  auto win = Offscreen::instance().window(spec.width, spec.height);
  const ViewAxes axes = view_axes(box.space && spec.section_y.has_value());
  const PanelStyle st{spec, box, axes, lut(img.particles, spec.quantity != "von_mises"), lut(img.members, true), right, top, img.deform_scale, font};
  for (std::size_t i = 0; i < panels.size(); ++i) win->AddRenderer(panel_renderer(panels[i], i, panels.size(), states[i], st));
  win->AddRenderer(title_renderer(spec, img, wrap, any_members, top, font));
  win->AddRenderer(bar_renderer(spec, st, any_members));
  write_png(win, path);
  return img;
}

}  // namespace dmi::render
