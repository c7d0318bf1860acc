#include "render/palette.hpp"

#include <vtkColorTransferFunction.h>
#include <vtkCoordinate.h>

#include "render/offscreen.hpp"

namespace dmi::render {

template <class T> static vtkSmartPointer<T> make() { return vtkSmartPointer<T>::New(); }

vtkSmartPointer<vtkLookupTable> lut(const Range& r, bool diverging) {
  auto ctf = make<vtkColorTransferFunction>();
  if (diverging) {
    ctf->AddRGBPoint(0.0, 0.23, 0.30, 0.75), ctf->AddRGBPoint(0.5, 0.87, 0.87, 0.87), ctf->AddRGBPoint(1.0, 0.71, 0.02, 0.15);
  } else {
    ctf->AddRGBPoint(0.0, 0.99, 0.98, 0.85), ctf->AddRGBPoint(0.3, 0.99, 0.80, 0.36), ctf->AddRGBPoint(0.6, 0.94, 0.36, 0.16),
        ctf->AddRGBPoint(0.85, 0.70, 0.05, 0.15), ctf->AddRGBPoint(1.0, 0.40, 0.0, 0.05);
  }
  auto t = make<vtkLookupTable>();
  t->SetNumberOfTableValues(256);
  for (int i = 0; i < 256; ++i) {
    double c[3];
    ctf->GetColor(i / 255.0, c);
    t->SetTableValue(i, c[0], c[1], c[2], 1.0);
  }
  t->SetTableRange(r.lo / 1e6, r.hi / 1e6);
  t->Build();
  return t;
}

void style(vtkTextProperty* p, int size, bool bold) {
  p->SetFontFamily(VTK_FONT_FILE);
  p->SetFontFile(font_file());
  p->SetFontSize(size);
  p->SetColor(0.1, 0.1, 0.1);
  p->SetBold(bold);
}

vtkSmartPointer<vtkScalarBarActor> scalar_bar(vtkLookupTable* t, const std::string& title, double x, int font) {
  auto bar = make<vtkScalarBarActor>();
  bar->SetLookupTable(t);
  bar->SetTitle(title.c_str());
  bar->SetNumberOfLabels(6);
  bar->SetLabelFormat("%.3g");
  bar->SetUnconstrainedFontSize(true);
  style(bar->GetTitleTextProperty(), font, true);
  style(bar->GetLabelTextProperty(), font);
  bar->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  bar->SetPosition(x, 0.06);
  bar->SetWidth(0.45);
  bar->SetHeight(0.8);
  bar->SetBarRatio(0.35);
  bar->SetTextPositionToSucceedScalarBar();
  bar->SetVerticalTitleSeparation(font / 2);
  return bar;
}

}  // namespace dmi::render
