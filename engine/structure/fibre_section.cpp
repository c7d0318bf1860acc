#include "engine/structure/fibre_section.hpp"

#include <cmath>
#include <numbers>

namespace dmi {
namespace {

constexpr int kLayers = 48;        // rectangle layers across the depth (plane)
constexpr int kGrid = 24;          // rectangle fibres along each side (space)
constexpr int kRings = 2;          // pipe wall layers
constexpr int kAround = 32;        // fibres around a pipe ring

double rms_coordinate(double centre, double size) {
  return std::copysign(std::sqrt(centre * centre + size * size / 12), centre);
}

void rectangle(std::vector<Fibre>& out, double b, double h, bool space) {
  const int ny = space ? kGrid : kLayers, nz = space ? kGrid : 1;
  const double dy = h / ny, dz = b / nz;
  for (int i = 0; i < ny; ++i)
    for (int k = 0; k < nz; ++k) {
      Fibre f;
      f.c[0] = rms_coordinate(-0.5 * h + (i + 0.5) * dy, dy);
      f.c[1] = space ? rms_coordinate(-0.5 * b + (k + 0.5) * dz, dz) : 0.0;
      f.area = dy * dz;
      out.push_back(f);
    }
}

void pipe(std::vector<Fibre>& out, double D, double t) {
  const double ro = 0.5 * D, ri = std::max(0.0, ro - t);
  for (int ring = 0; ring < kRings; ++ring) {
    const double ra = ri + (ro - ri) * ring / kRings, rb = ri + (ro - ri) * (ring + 1) / kRings;
    const double r = std::sqrt(0.5 * (ra * ra + rb * rb)), area = std::numbers::pi * (rb * rb - ra * ra) / kAround;
    for (int k = 0; k < kAround; ++k) {
      const double phi = 2 * std::numbers::pi * (k + 0.5) / kAround;
      Fibre f;
      f.c[0] = r * std::cos(phi);
      f.c[1] = r * std::sin(phi);
      f.area = area;
      out.push_back(f);
    }
  }
}

}  // namespace

std::vector<Fibre> fibre_layout(const Section& section, double s, bool space) {
  std::vector<Fibre> out;
  if (section.kind() == SectionKind::pipe) pipe(out, section.depth(s), section.wall_thickness());
  else rectangle(out, section.width(s), section.depth(s), space);
  return out;
}

}  // namespace dmi
