#include "render/solid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellType.h>
#include <vtkCutter.h>
#include <vtkDataSetMapper.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkDoubleArray.h>
#include <vtkPlane.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkUnstructuredGrid.h>

#include "render/offscreen.hpp"
#include "render/palette.hpp"

namespace dmi::render {

namespace {

template <class T> vtkSmartPointer<T> make() { return vtkSmartPointer<T>::New(); }

// The case the picture shows (the one with the largest principal tension) over the mesh.
struct Field {
  int dim = 3, npe = 8;
  std::size_t nn = 0;
  std::vector<double> x;
  std::vector<long> conn;
  std::string name;
  std::vector<double> vm, s1;
};

Field read_field(const SolidFieldRecord& d) {
  Field f;
  f.dim = d.dim, f.npe = d.nodes_per_element, f.nn = d.nodes(), f.x = d.nodes_m, f.conn = d.elements;
  double best = -1e300;
  for (const SolidFieldCase& k : d.cases) {
    const double m = *std::max_element(k.max_principal_Pa.begin(), k.max_principal_Pa.end());
    if (m > best) best = m, f.s1 = k.max_principal_Pa, f.vm = k.von_mises_Pa, f.name = k.name;
  }
  return f;
}

vtkSmartPointer<vtkUnstructuredGrid> grid_of(const Field& f, const std::vector<double>& values) {
  auto pts = make<vtkPoints>();
  for (std::size_t n = 0; n < f.nn; ++n)
    pts->InsertNextPoint(f.x[f.dim * n], f.dim == 3 ? f.x[f.dim * n + 1] : 0.0, f.x[f.dim * n + f.dim - 1]);
  auto g = make<vtkUnstructuredGrid>();
  g->SetPoints(pts);
  for (std::size_t e = 0; e < f.conn.size() / f.npe; ++e) {
    vtkIdType ids[8];
    for (int c = 0; c < f.npe; ++c) ids[c] = f.conn[e * f.npe + c];
    g->InsertNextCell(f.npe == 8 ? VTK_HEXAHEDRON : VTK_QUAD, f.npe, ids);
  }
  auto a = make<vtkDoubleArray>();
  for (double v : values) a->InsertNextValue(v / 1e6);
  g->GetPointData()->SetScalars(a);
  return g;
}

vtkSmartPointer<vtkActor> coloured(vtkAlgorithmOutput* port, vtkDataSet* data, vtkLookupTable* t) {
  auto m = make<vtkDataSetMapper>();
  if (port) m->SetInputConnection(port);
  else m->SetInputData(data);
  m->SetLookupTable(t), m->UseLookupTableScalarRangeOn(), m->InterpolateScalarsBeforeMappingOn();
  auto a = make<vtkActor>();
  a->SetMapper(m);
  a->GetProperty()->EdgeVisibilityOn();
  a->GetProperty()->SetEdgeColor(0.35, 0.35, 0.35);
  a->GetProperty()->SetAmbient(1.0), a->GetProperty()->SetDiffuse(0.0);  // the colours as on the scale, no shading
  return a;
}

void heading(vtkRenderer* ren, const std::string& text, int font) {
  auto h = make<vtkTextActor>();
  h->SetInput(text.c_str());
  style(h->GetTextProperty(), font, true);
  h->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  h->SetPosition(0.03, 0.93);
  h->GetTextProperty()->SetVerticalJustificationToTop();
  ren->AddActor2D(h);
}

// The view along +y (a section in the x-z plane), the whole extent in view.
void section_camera(vtkRenderer* ren, const double b[6]) {
  const double cx = 0.5 * (b[0] + b[1]), cz = 0.5 * (b[4] + b[5]), cy = 0.5 * (b[2] + b[3]);
  auto cam = ren->GetActiveCamera();
  cam->ParallelProjectionOn();
  const double H = b[5] - b[4], up = cz + 0.08 * H;  // room above the body for the panel's heading
  cam->SetFocalPoint(cx, cy, up), cam->SetPosition(cx, cy - 10 * H, up), cam->SetViewUp(0, 0, 1);
  cam->SetParallelScale(0.62 * H);
  ren->ResetCameraClippingRange();
}

}  // namespace

namespace {

// Left: the body's surface (3D, oblique, from upstream) or the section (2D), von Mises.
vtkSmartPointer<vtkRenderer> surface_renderer(const Field& f, vtkUnstructuredGrid* vm_grid, vtkLookupTable* vm_lut, const double b[6],
                                              double split, double top, int font) {
  auto left = make<vtkRenderer>();
  left->SetViewport(0, 0, split, top), left->SetBackground(1, 1, 1);
  if (f.dim == 3) {
    auto surf = make<vtkDataSetSurfaceFilter>();
    surf->SetInputData(vm_grid);
    left->AddActor(coloured(surf->GetOutputPort(), nullptr, vm_lut));
    const double H = b[5] - b[4], cx = 0.5 * (b[0] + b[1]), cy = 0.5 * (b[2] + b[3]), cz = 0.5 * (b[4] + b[5]);
    auto cam = left->GetActiveCamera();
    cam->SetFocalPoint(cx, cy, cz), cam->SetPosition(cx - 2.2 * H, cy - 1.6 * H, cz + 1.2 * H), cam->SetViewUp(0, 0, 1);
    left->ResetCamera();
    cam->Zoom(0.85);
    cam->Elevation(-4);  // the body a little lower, below the heading
    heading(left, "von Mises, upstream face from above", font);
  } else {
    left->AddActor(coloured(nullptr, vm_grid, vm_lut));
    section_camera(left, b);
    heading(left, "von Mises, section", font);
  }
  return left;
}

// Right: the vertical section under the load (3D: the plane y = y of the largest principal tension), max principal.
vtkSmartPointer<vtkRenderer> section_renderer(const Field& f, vtkUnstructuredGrid* s1_grid, vtkLookupTable* s1_lut, const double b[6],
                                              double section_y, double split, double top, int font) {
  auto right = make<vtkRenderer>();
  right->SetViewport(split, 0, 2 * split, top), right->SetBackground(1, 1, 1);
  if (f.dim == 3) {
    auto plane = make<vtkPlane>();
    plane->SetOrigin(0, section_y, 0), plane->SetNormal(0, 1, 0);
    auto cut = make<vtkCutter>();
    cut->SetCutFunction(plane);
    cut->SetInputData(s1_grid);
    auto m = make<vtkPolyDataMapper>();
    m->SetInputConnection(cut->GetOutputPort());
    m->SetLookupTable(s1_lut), m->UseLookupTableScalarRangeOn(), m->InterpolateScalarsBeforeMappingOn();
    auto a = make<vtkActor>();
    a->SetMapper(m);
    a->GetProperty()->SetAmbient(1.0), a->GetProperty()->SetDiffuse(0.0);
    right->AddActor(a);
    char h[96];
    std::snprintf(h, sizeof h, "max principal, mid-width section y = %.2f m", section_y);
    heading(right, h, font);
  } else {
    right->AddActor(coloured(nullptr, s1_grid, s1_lut));
    heading(right, "max principal, section", font);
  }
  section_camera(right, b);
  return right;
}

// The title strip: the run's title (wrapped at its first ": "), the load case and the peaks.
vtkSmartPointer<vtkRenderer> solid_title(const SolidPicture& pic, const std::string& title, double top, int font) {
  auto strip = make<vtkRenderer>();
  strip->SetViewport(0, top, 1, 1), strip->SetBackground(1, 1, 1);
  char line[256];
  std::snprintf(line, sizeof line, "\nload case '%s'\nvon Mises up to %.3g MPa; principal tension up to %.3g MPa at (%.2f, %.2f, %.2f) m",
                pic.case_name.c_str(), pic.von_mises_max / 1e6, pic.principal_max / 1e6, pic.principal_at[0], pic.principal_at[1], pic.principal_at[2]);
  auto t = make<vtkTextActor>();
  std::string text = title;
  if (const auto k = text.find(": "); k != std::string::npos) text.replace(k, 2, ":\n");
  t->SetInput((text + line).c_str());
  style(t->GetTextProperty(), font, false);
  t->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  t->SetPosition(0.01, 0.08);
  strip->AddActor2D(t);
  return strip;
}

}  // namespace

std::optional<SolidPicture> render_solid(const Results& r, const std::string& title, const std::string& path, int width, int height, bool draw) {
  if (!r.info.solid_field) return std::nullopt;
  const Field f = read_field(*r.info.solid_field);
  SolidPicture pic;
  pic.path = path, pic.case_name = f.name, pic.width = width, pic.height = height;
  const auto k1 = static_cast<std::size_t>(std::max_element(f.s1.begin(), f.s1.end()) - f.s1.begin());
  pic.principal_max = f.s1[k1], pic.von_mises_max = *std::max_element(f.vm.begin(), f.vm.end());
  for (int d = 0; d < f.dim; ++d) pic.principal_at[f.dim == 3 ? d : 2 * d] = f.x[f.dim * k1 + d];
  // The section across the middle of the face: the simulated loads are centred there (uniform across the width, or
  // a round patch about the profile's centroid), as is Lin, Cheng & Tuan's load.
  if (f.dim == 3) {
    double y0 = 1e300, y1 = -1e300;
    for (std::size_t n = 0; n < f.nn; ++n) y0 = std::min(y0, f.x[3 * n + 1]), y1 = std::max(y1, f.x[3 * n + 1]);
    pic.section_y = 0.5 * (y0 + y1);
  }
  const Range vm_range{0.0, std::max(pic.von_mises_max, 1.0)};
  double s1_abs = 0;
  for (double v : f.s1) s1_abs = std::max(s1_abs, std::abs(v));
  const Range s1_range{-std::max(s1_abs, 1.0), std::max(s1_abs, 1.0)};
  if (!draw) return pic;
  auto vm_lut = lut(vm_range, false), s1_lut = lut(s1_range, true);
  const int font = std::max(16, width / 54);
  const double top = 1.0 - (4 * 1.3 * font + 12) / height, split = 0.40;
  auto win = Offscreen::instance().window(width, height);
  auto vm_grid = grid_of(f, f.vm), s1_grid = grid_of(f, f.s1);
  double b[6];
  vm_grid->GetBounds(b);
  win->AddRenderer(surface_renderer(f, vm_grid, vm_lut, b, split, top, font));
  win->AddRenderer(section_renderer(f, s1_grid, s1_lut, b, pic.section_y, split, top, font));
  // Bars and title.
  auto bars = make<vtkRenderer>();
  bars->SetViewport(2 * split, 0, 1, top), bars->SetBackground(1, 1, 1);
  bars->AddActor2D(scalar_bar(vm_lut, "von\nMises\n[MPa]", 0.04, font));
  bars->AddActor2D(scalar_bar(s1_lut, "max\nprincipal\n[MPa]", 0.54, font));
  win->AddRenderer(bars);
  win->AddRenderer(solid_title(pic, title, top, font));
  write_png(win, path);
  return pic;
}

}  // namespace dmi::render
