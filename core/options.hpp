// The engine's option types and a material's parameters: what the solver, the materials and the contacts are told,
// below every layer (the scenario reader fills them from JSON; engine/scenario/config.hpp holds the rest of a
// scenario's record).
#pragma once
#include <string>

namespace dmi {

enum class Plane { strain, stress, none };          // 2D kinematics; none in 3D
enum class ShapeKind { linear, gimp, bspline2 };
enum class TransferKind { flip, apic };             // flip with a PIC blend factor
enum class StressUpdate { usl, musl };
enum class ContactMethod { multi_field, single_field };
enum class WallCondition { stick, roller, slip, friction };

// How multi-field contact decides that two bodies touch at a node: surface = their surfaces, located from the
// particles' reach in the node's column, meet (engine/mpm/boundary.hpp); volume = their particle volumes fill the
// node's support (Bardenhagen et al. 2000 with a fill test).
enum class BodyDetection { surface, volume };

// How a unilateral boundary (a slip or friction wall, a member with sharp decay) decides that a grid node is in
// contact: surface = it is engaged by a particle whose material touches the boundary (engine/mpm/touch.hpp);
// node = every node on or behind it.
enum class DetectionKind { surface, node };

// Members as MPM velocity boundaries (Yang 2016; Lin & Yang 2024).
enum class MemberContactMode { stick, separable, friction };
enum class DecayKind { sharp, linear, cosine };
enum class DistanceKind { node, material };

// The members' steel under load reversals: bilinear with linear kinematic hardening (a sharp yield, reversed yielding
// at a stress change of 2 f_y), or Menegotto & Pinto's (1973) smooth curve with Filippou, Popov & Bertero's (1983)
// curvature that falls with the plastic excursion (the Bauschinger effect: a reversal yields gradually, well before 2 f_y).
enum class SteelCurve { bilinear, menegotto_pinto };

struct MaterialConfig {
  std::string name, model;
  double density = 0.0;                              // kg/m^3
  double youngs_modulus = 0.0;                       // Pa
  double poisson_ratio = 0.0;
  double damping_ratio = 0.0, damping_frequency = 0.0;   // -, Hz (linear_elastic, neo_hookean)
  double cohesion = 0.0;                                  // Pa (drucker_prager)
  double friction_angle = 0.0, dilation_angle = 0.0;      // deg (drucker_prager)
  double bulk_modulus = 0.0;                              // Pa (newtonian, bingham)
  double viscosity = 0.0;                                 // Pa s (newtonian, bingham)
  double yield_stress = 0.0;                              // Pa (bingham)
  double regularisation_rate = 0.01;                      // 1/s (bingham, Papanastasiou 1/m)
  double volume_relaxation = 0.0;                         // acoustic cell transits (newtonian, bingham; 0 = off)
  double mu_s = 0.0, mu_2 = 0.0, inertial_I0 = 0.0;       // - (mu_i: Jop, Forterre & Pouliquen 2006)
  double grain_diameter = 0.0, grain_density = 2650.0;    // m, kg/m^3 (mu_i)
  double regularisation_alpha = 1.9;                      // - (mu_i: Barker & Gray 2017; 0 = none)
  double yield_strength = 0.0;                            // Pa (elastic_plastic: members' steel)
  double hardening_ratio = 0.01;                          // - (elastic_plastic: post-yield modulus / E)
  SteelCurve steel_curve = SteelCurve::bilinear;          // elastic_plastic members' steel under reversals
  double transition_r0 = 20, transition_a1 = 18.5, transition_a2 = 0.15;  // - (menegotto_pinto: R0, a1, a2)
};

}  // namespace dmi
