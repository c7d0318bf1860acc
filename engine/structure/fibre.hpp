// Section forces and the stresses they cause in a 2D member section: pure functions of the section
// geometry, shared by the frame (engine/structure/frame.hpp) and the design checks (design/), which
// read section forces from results.h5 and must compute the same stresses.
// Conventions (frame.hpp): N tension +; M + compresses the top (+e2) fibre; sigma(y') = N/A - M y'/I.
#pragma once
#include "engine/structure/section.hpp"

namespace dmi {

struct SectionForces { double N = 0, V = 0, M = 0; };  // N, N, N m

struct FibreStresses {
  double sigma_top = 0, sigma_bottom = 0;          // Pa, normal stress at the +e2 / -e2 surfaces
  double tau_max = 0;                              // Pa, peak shear stress over the section
  double von_mises_top = 0, von_mises_bottom = 0;  // Pa, sqrt(sigma^2 + 3 tau^2) with tau at that fibre (0 for
                                                   // the extreme fibres of a rectangle or pipe)
  double von_mises_max = 0;                        // Pa, max over the depth of sqrt(sigma^2 + 3 tau^2)
};

// Stresses at the fraction s of the member's section taper under forces f (Gere & Goodno, Mechanics of
// Materials, ch. 5): sigma_top/bottom = N/A -/+ M c/I; tau_max = factor V/A (rectangle 3/2, thin pipe 2);
// tau over the depth eta = y'/c in [-1, 1]: rectangle tau_max (1 - eta^2), pipe tau_max sqrt(1 - eta^2);
// von_mises_max sampled at 21 fibres.
FibreStresses fibre_stresses(const Section& section, double s, const SectionForces& f);

// Section forces of a space-frame member (space_frame.hpp): on the positive face, along the local axes (N, m).
struct SpaceSectionForces { double N = 0, Vy = 0, Vz = 0, T = 0, My = 0, Mz = 0; };

struct SpaceFibreStresses {
  double sigma_max = 0, sigma_min = 0;  // Pa, extreme normal stresses around the perimeter
  double tau_max = 0;                   // Pa, largest shear stress (torsion and shear force) around the perimeter
  double von_mises_max = 0;             // Pa, max of sqrt(sigma^2 + 3 tau^2) around the perimeter
  double principal_max = 0;             // Pa, max of the principal stress sigma/2 + sqrt(sigma^2/4 + tau^2) around the perimeter
  double y = 0, z = 0;                  // m, the section point of the von Mises maximum (local y', z')
};

// Stresses around the perimeter of a space member's section at the fraction s of its taper: sigma(y', z') =
// N/A - Mz y'/Iz + My z'/Iy (Gere & Goodno, sec. 6.5). Shear: torsion tau_T = T / W_t (pipe T R / J; rectangle
// k t T / J at the middle of the long sides, Timoshenko & Goodier 1970 sec. 109, taken everywhere on the perimeter:
// conservative at the corners) plus the shear forces' parabolic (rectangle, 3/2 V/A at the axis) or thin-wall
// (pipe, 2 V/A |sin|) distribution, added in magnitude: on one side of a pipe the two flows add, so for a pipe
// the maximum is exact. Sampled at 72 points around a pipe (and the two where sigma is extreme, so sigma_max/min are
// exact: N/A +- |M|/W_el) and 11 per side of a rectangle (corners included: sigma_max/min exact there too).
SpaceFibreStresses space_fibre_stresses(const Section& section, double s, const SpaceSectionForces& f);
// The normal stress at (y', z') of a section with area A and inertias Iy, Iz: N/A - Mz y'/Iz + My z'/Iy.
inline double space_fibre_sigma(const SpaceSectionForces& f, double A, double Iy, double Iz, double y, double z) {
  return f.N / A - f.Mz * y / Iz + f.My * z / Iy;
}

}  // namespace dmi
