// Geometry of a body's shape (box, ball or ring, 2D polygon): bounding box and point membership,
// shared by the parser (is the body inside the grid?) and the particle seeding.
#pragma once
#include <vector>

#include "engine/scenario/config.hpp"

namespace dmi {

// Axis-aligned bounding box of the shape (dim entries each).
void shape_bounds(const ShapeConfig& s, int dim, DVec& lo, DVec& hi);
// Whether point x (dim coordinates) lies in the shape (boundary included).
bool shape_contains(const ShapeConfig& s, const double* x, int dim);
// Signed area of a 2D polygon (counter-clockwise > 0), m^2.
double polygon_area(const std::vector<DVec>& v);
// Whether two edges of the polygon cross (a self-intersecting outline).
bool polygon_self_intersects(const std::vector<DVec>& v);

}  // namespace dmi
