// Elasto-plastic frames with closed-form answers (the validate cases and the unit tests share them): the collapse
// loads of a fixed-end beam and a portal frame (Neal 1977), an elastic-perfectly-plastic SDOF under a rectangular
// pulse (Biggs 1964), and a cantilever struck at its tip by a mass (Parkes 1955; Jones 1989, sec. 3.8).
#pragma once
#include <vector>

#include "engine/structure/section.hpp"

namespace dmi {

// A fibre section's moment at a uniform curvature kappa over its plastic moment, rectangle b x h or CHS D x t, EPP steel.
double rectangle_moment_ratio(double b, double h, double kappa_over_yield);
double pipe_moment_ratio(double D, double t, double kappa_over_yield);
// The same for any section (box, I: M_p = f_y W_pl), in-plane bending.
double section_moment_ratio(const Section& s, double kappa_over_yield);

// Fixed-end beam (rectangle 0.1 x 0.2, L 2 m, f_y 355 MPa, perfectly plastic) with a central point load, n elements:
// the beam's resistance far past collapse over P_c = 8 M_p / L (a spring under the load point carries the excess).
double fixed_beam_collapse_ratio(int elements);

// Fixed-base portal (columns and beam 4 m, rectangles 0.1 x 0.2, perfectly plastic), loads lambda (P, 2P): the collapse
// load factor found by bisection on the static solution, over the combined mechanism's 6 M_p / (h + L) (within 0.3 %).
double portal_collapse_ratio();

// A bar (E A / L = k, R_y = f_y A) with a tip mass m under F0 = ratio R_y for half the elastic period: the peak
// displacement with `steps` Newmark steps per elastic period, and the exact EPP SDOF peak for the same pulse.
struct SdofPeak {
  double computed = 0, exact = 0;
};
SdofPeak epp_bar_peak(double ratio, int steps_per_period);

// A cantilever (L 1 m, rectangle 0.1 x 0.1, f_y 250 MPa, perfectly plastic) whose tip mass G = gamma m L moves at V0
// at t = 0, with kinetic energy `energy_ratio` times the cantilever's elastic capacity: the permanent tip deflection
// with `elements` elements, and the rigid-plastic one W_f = (gamma G V0^2 L / 3 M_p) [2 ln(1 + 1/(2 gamma)) + 1/(1 + 2 gamma)].
// elastic_at_collapse: the cantilever's elastic energy under the tip load M_p / L, M_p^2 L / (6 E I), the energy the
// rigid-plastic theory leaves out.
struct ParkesResult {
  double computed = 0, rigid_plastic = 0, plastic_work = 0, kinetic = 0, elastic_at_collapse = 0;
};
ParkesResult parkes_cantilever(double gamma, double energy_ratio, int elements, double hardening = 0);

// A steel cantilever (L 4 m, rectangle b 0.1 x d 0.2, f_y 355 MPa, 1 % hardening, nu 0) carrying at its free end an
// elastic block of its own section, 0.2 m long and of mass 10 t, pushed across the member by a triangular pulse on the
// block's face (0 to 350 kN, about 4 M_p / L, in 50 ms and back to 0 at 100 ms), run 3 s in steps of `dt` with the
// corotational frame (CalculiX's automatic increments at most `max_increment`): the sway of the cantilever's end (m, in the direction of the push) at every step, `elements`
// elements along the cantilever. nu = 0: beam theory has no lateral contraction, and a clamped continuum would hold
// it there. The same cantilever in CalculiX bricks: verify/calculix.hpp.
struct CantileverPulse {
  double L = 4, b = 0.1, d = 0.2, E = 200e9, nu = 0.0, rho = 7850, fy = 355e6, hardening = 0.01;
  double block_length = 0.2, block_mass = 1e4, peak_force = 3.5e5, td = 0.1, duration = 3.0, dt = 1e-3, max_increment = 4e-3;
  double block_density() const { return block_mass / (block_length * b * d); }
  double load_factor(double t) const { return t < 0.5 * td ? 2 * t / td : t < td ? 2 * (1 - t / td) : 0.0; }
};
struct SwayHistory {
  std::vector<double> t, sway;  // s, m
  double period = 0;            // the first elastic period (s)
  double peak() const;
  // The residual sway: the centre of the elastic ringing that follows, midway between the largest and the smallest sway
  // over the last 1.5 `period`s (a window of more than one cycle even when yielding has lengthened the period).
  double residual(double period) const;
};
SwayHistory cantilever_pulse_sway(const CantileverPulse& p, int elements);

}  // namespace dmi
