// Stability of a gravity dam on its foundation joint: sliding, resultant location, overturning and bearing pressure
// (USACE EM 1110-2-2100, 2005, ch. 3 and 5), and the permanent sliding displacement of the dam as a rigid block under
// a force pulse (Newmark 1965). Pure functions, SI (N, m, Pa, s, kg), per dam (not per metre).
#pragma once
#include <vector>

namespace dmi::design {

// The loads on the base joint at one instant, about the toe (the downstream edge of the base, x = 0 there, x positive
// upstream along a base of length B): N the resultant normal force (N, compression positive: weight, deposit and water
// weights, minus uplift), H the resultant shear force (N, towards downstream positive), Mr the moment of the stabilising
// loads about the toe and Mo that of the overturning ones (N m, both positive).
struct BaseJointLoads {
  double N = 0, H = 0, Mr = 0, Mo = 0;
};

// Sliding factor of safety by limit equilibrium on the joint, EM 1110-2-2100 eq. (3-1) with phi and c:
// FS = (N tan(phi) + c A') / |H|, A' the base area in compression (Pa, m^2); infinite when H = 0. N < 0 (the joint
// lifts) gives 0.
double sliding_factor(const BaseJointLoads& l, double friction_coefficient, double cohesion_Pa, double compressed_area_m2);
// Its numerator, the joint's resistance N tan(phi) + c A' (N), 0 when the joint lifts (N <= 0).
double sliding_resistance(const BaseJointLoads& l, double friction_coefficient, double cohesion_Pa, double compressed_area_m2);

// Overturning factor Mr / Mo (infinite when Mo <= 0).
double overturning_factor(const BaseJointLoads& l);

// Where the resultant meets the base and what it does to the foundation (a base of length B, width W out of plane):
// x_r = (Mr - Mo) / N from the toe; e = B/2 - x_r (positive towards the toe); compressed length B for |e| <= B/6, else
// 3 x_r (linear pressure, no tension on the joint); toe and heel pressures q = N / (B W) (1 +- 6 e / B) within the
// middle third, else a triangle of 2 N / (3 x_r W) at the toe (x_r >= 0: the resultant outside the base upstream or at
// the toe gives a compressed length of 0 and an infinite toe pressure).
struct ResultantLocation {
  double x_r = 0;               // m from the toe
  double eccentricity = 0;      // m, B/2 - x_r
  double compressed_fraction = 0;  // of B (1: base fully in compression)
  double toe_pressure = 0, heel_pressure = 0;  // Pa (compression positive)
  bool within_base = false;     // 0 <= x_r <= B
};
ResultantLocation resultant_location(const BaseJointLoads& l, double base_length_m, double width_m);

// Permanent sliding displacement of a rigid block (Newmark 1965) of mass m pushed by H(t) (samples at times t, linear
// between them) against a resistance R(t) = mu N(t) + c A (given per sample, >= 0): the block slides downstream while
// H > R or while it still moves, a = (H - R) / m, and stops when its velocity returns to 0; it never slides upstream.
// Midpoint sub-steps (`substeps` per interval; exact for a constant net force). A block still sliding when the record
// ends goes on under the loads it had before the record (H(t0) - R(t0): the impact is over) until it stops; infinite if
// those do not stop it. The same integrator gives the peak rotation of a block rocking about its toe (Housner 1963,
// small rotations): t, the overturning moment, the restoring moment W x_G and the inertia about the toe.
double newmark_sliding_displacement(const std::vector<double>& t, const std::vector<double>& H, const std::vector<double>& R,
                                    double mass_kg, int substeps = 64);

// The dam's section as a rigid body on its base (a quadrilateral: heel and toe at y = 0, the crest's edges at y = H;
// x along the flow, the toe downstream): mass, weight and centroid, and the moment of inertia about the toe, for a
// width W out of plane and density rho (g = 9.81 m/s^2).
struct RigidSection {
  double area_m2 = 0, mass_kg = 0, weight_N = 0;
  double base_m = 0;                  // toe - heel
  double centroid_from_toe_m = 0;     // horizontal lever of the weight about the toe (upstream positive)
  double centroid_height_m = 0;
  double inertia_about_toe_kg_m2 = 0;  // rho W integral of (x - x_toe)^2 + y^2 over the section
  // The rotation about the toe at which the centroid passes over it and the weight stops restoring (Housner 1963):
  // atan(centroid_from_toe / centroid_height).
  double critical_angle_rad() const;
};
RigidSection rigid_section(double heel_x, double toe_x, double crest_upstream_x, double crest_downstream_x, double height, double width,
                           double density);

}  // namespace dmi::design
