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

// Cells of a grid ny x nz over the plate y' in [y0, y1], z' in [z0, z1] (plane: nz = 1, z' = 0).
void plate(std::vector<Fibre>& out, double y0, double y1, double z0, double z1, int ny, int nz, bool space) {
  const double dy = (y1 - y0) / ny, dz = (z1 - z0) / nz;
  for (int i = 0; i < ny; ++i)
    for (int k = 0; k < nz; ++k) {
      Fibre f;
      f.c[0] = rms_coordinate(y0 + (i + 0.5) * dy, dy);
      f.c[1] = space ? rms_coordinate(z0 + (k + 0.5) * dz, dz) : 0.0;
      f.area = dy * dz;
      out.push_back(f);
    }
}

void rectangle(std::vector<Fibre>& out, double b, double h, bool space) {
  const int ny = space ? kGrid : kLayers, nz = space ? kGrid : 1;
  plate(out, -0.5 * h, 0.5 * h, -0.5 * b, 0.5 * b, ny, nz, space);
}

// Box and I: two flanges b x t_f and the web(s) between them; box webs of the wall t at the sides, the I's web t_w on
// the axis. Each plate in kPlate cells along it and kThrough across its thickness, a web kWebThrough (its cells near
// the axis carry the plastic moment about it); plane: the flanges in kThrough layers, the webs in kLayers.
constexpr int kPlate = 32, kThrough = 4, kWebThrough = 8;
void flanged(std::vector<Fibre>& out, const Section& sec, double s, bool space) {
  const double b = sec.width(s), h = sec.depth(s), tf = sec.wall_thickness(), tw = sec.web_thickness();
  const double c = 0.5 * h, w = 0.5 * b, yw = c - tf;
  for (double side : {-1.0, 1.0}) {
    const double y0 = side > 0 ? yw : -c;
    plate(out, y0, y0 + tf, -w, w, kThrough, space ? kPlate : 1, space);
  }
  const int along = space ? kPlate : kLayers, through = space ? kWebThrough : 1;
  if (sec.kind() == SectionKind::i_section) {
    plate(out, -yw, yw, -0.5 * tw, 0.5 * tw, along, through, space);
    return;
  }
  plate(out, -yw, yw, -w, -w + tw, along, through, space);
  plate(out, -yw, yw, w - tw, w, along, through, space);
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
  else if (section.thin_walled()) flanged(out, section, s, space);
  else rectangle(out, section.width(s), section.depth(s), space);
  return out;
}

}  // namespace dmi
