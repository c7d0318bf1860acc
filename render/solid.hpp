// The solid-FE dam body (Lin, Cheng & Tuan's check, /documents/solid_field of results.h5): an oblique view of the
// body coloured by nodal von Mises stress and the vertical section across the middle of the face, under the load,
// coloured by the maximum principal stress (3D hex8); a 2D plane-strain section shows both measures side by side.
#pragma once
#include <array>
#include <optional>
#include <string>

#include "engine/io/results.hpp"

namespace dmi::render {

struct SolidPicture {
  std::string path, case_name;
  int width = 0, height = 0;
  double von_mises_max = 0, principal_max = 0;  // nodal (Pa)
  std::array<double, 3> principal_at{0, 0, 0};  // m, solid axes (x through the thickness, y across, z up)
  double section_y = 0;                          // m, the section's position across the face (3D: mid-width)
};

// Renders the load case with the largest nodal principal tension; nullopt when the run has no solid field. Throws
// std::runtime_error naming the file and the key when the document is malformed, inconsistent or not finite.
// draw = false: only the description is returned (another process draws the picture).
std::optional<SolidPicture> render_solid(const Results& r, const std::string& title, const std::string& path, int width = 2400, int height = 1100,
                                         bool draw = true);

}  // namespace dmi::render
