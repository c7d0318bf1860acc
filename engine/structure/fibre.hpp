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

}  // namespace dmi
