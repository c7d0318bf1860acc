// Elasto-plastic frames with closed-form answers (the validate cases and the unit tests share them): the collapse
// loads of a fixed-end beam and a portal frame (Neal 1977), an elastic-perfectly-plastic SDOF under a rectangular
// pulse (Biggs 1964), and a cantilever struck at its tip by a mass (Parkes 1955; Jones 1989, sec. 3.8).
#pragma once

namespace dmi {

// A fibre section's moment at a uniform curvature kappa over its plastic moment, rectangle b x h or CHS D x t, EPP steel.
double rectangle_moment_ratio(double b, double h, double kappa_over_yield);
double pipe_moment_ratio(double D, double t, double kappa_over_yield);

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
struct ParkesResult {
  double computed = 0, rigid_plastic = 0, plastic_work = 0, kinetic = 0;
};
ParkesResult parkes_cantilever(double gamma, double energy_ratio, int elements, double hardening = 0);

}  // namespace dmi
