// Colour maps, text style and scalar bars shared by the field and solid-body pictures.
#pragma once
#include <string>

#include <vtkLookupTable.h>
#include <vtkScalarBarActor.h>
#include <vtkSmartPointer.h>
#include <vtkTextProperty.h>

#include "render/field.hpp"

namespace dmi::render {

// Sequential map for magnitudes (white - yellow - orange - red - dark red) or a diverging one for signed stresses
// (blue - white - red); 256 entries over r in MPa.
vtkSmartPointer<vtkLookupTable> lut(const Range& r, bool diverging);
// DejaVu Sans at `size` px, dark grey.
void style(vtkTextProperty* p, int size, bool bold = false);
// A vertical bar at normalized-viewport x of its renderer, titled, 6 labels.
vtkSmartPointer<vtkScalarBarActor> scalar_bar(vtkLookupTable* t, const std::string& title, double x, int font);

}  // namespace dmi::render
