// Plain configuration structs: what a scenario says, after parsing and validation.
// No JSON here; engine/ builds the scene from these. Every field is documented where it is
// declared to the parser (engine/scenario/parse.cpp), which also generates docs/scenario.md.
#pragma once
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/design_basis.hpp"
#include "core/options.hpp"
#include "core/hydrograph.hpp"

namespace dmi {

using DVec = std::vector<double>;  // length = analysis dimension


struct AnalysisConfig {
  int dimension = 2;
  Plane plane = Plane::strain;
  double thickness = 1.0;                            // m, out-of-plane (2D)
  double end_time = std::numeric_limits<double>::quiet_NaN();  // s, required
  double dt_max = 0.0;                               // s, 0 = no user bound
  double cfl = 0.5;                                  // fraction of the CFL limit
  DVec gravity;                                      // m/s^2
  double max_steps = 1e7;                            // refuse runs estimated longer (end_time / first step)
  double max_wall_hours = 48;                        // refuse runs estimated longer on one core (a lower bound)
};

struct MpmConfig {
  ShapeKind shape = ShapeKind::bspline2;
  TransferKind transfer = TransferKind::flip;
  double flip_blend = 1.0;                           // 1 = pure FLIP, 0 = pure PIC
  StressUpdate update = StressUpdate::usl;
  bool implicit_damping = true;                      // mpm.damping: implicit (true) or explicit
  // Code-level only (not a scenario key): use analysis.cfl as given even above the scheme's measured stability
  // limit (stable_cfl_limit); for the studies that measure that limit (validate --stress cfl_sweep).
  bool allow_unstable_cfl = false;
};

struct GridConfig {
  DVec origin, size;                                 // m
  double cell_size = 0.0;                            // m
};


struct ShapeConfig {
  std::string type;                                  // box | ball | polygon (2D)
  DVec min, max, center;                             // m
  double radius = 0.0;                               // m
  double inner_radius = 0.0;                         // m, ball: > 0 makes a ring / hollow sphere
  std::vector<DVec> vertices;                        // m, polygon (2D), in order
};

// Debris entering through a channel section from a hydrograph (engine/mpm/inflow.hpp). 2D.
struct InflowConfig {
  bool present = false;
  DVec point;                                        // m, the section's foot on the bed
  DVec direction;                                    // flow direction along the bed (normalised by the parser)
  double zone = 0.0;                                 // m, length of the driven zone upstream of the section; 0 = 3 cells
  Hydrograph hydrograph;
};

struct BodyConfig {
  std::string name, material;
  ShapeConfig shape;                                 // type "" for a body that only an inflow fills
  InflowConfig inflow;
  int particles_per_cell = 2;                        // per direction
  bool rigid = false;                                // rigid body: no stress, translation and rotation only
  bool rigid_when_free = false;                      // elastic in contact, rigid while nothing is near it
  DVec velocity;                                     // m/s
  // Optional sine mode added to velocity: v += amplitude sin(wavevector . (x - origin)).
  DVec sine_amplitude, sine_wavevector, sine_origin;  // m/s, rad/m, m
  bool geostatic = false;                            // start from the stress of its own weight (engine/sim/geostatic.hpp)
  double earth_pressure_coefficient = -1;            // K0 = sigma_h / sigma_v; < 0: the material's default
};


struct ContactConfig {
  ContactMethod method = ContactMethod::multi_field;
  double friction = 0.0;                             // Coulomb coefficient between bodies
  BodyDetection detection = BodyDetection::surface;
};


struct WallConfig {
  std::string name, type;                            // plane | box
  DVec point, normal, min, max;
  WallCondition condition = WallCondition::slip;
  double friction = 0.0;
  DetectionKind detection = DetectionKind::surface;  // slip and friction walls
};

struct PrescribedVelocityConfig {
  std::string name;
  DVec min, max, velocity;                           // region (m), velocity (m/s)
  double start = 0.0, end = std::numeric_limits<double>::infinity();  // s
};

struct ProbeConfig {
  std::string name, type, target;                    // type: particle | body | member
  DVec point;                                        // particle probes: nearest particle
  double position = 0.5;                             // member probes: fraction of the member length from its start
  std::vector<std::string> quantities;
};

// --- Beam-column frame (2D; Lin & Yang 2024) -------------------------------------------------------
enum class BeamTheoryKind { euler_bernoulli, timoshenko };
enum class FrameTransformKind { linear, corotational };
enum class FrameMassKind { lumped, consistent };
enum class FrameIntegratorKind { explicit_euler, newmark };
enum class FrameInitialState { static_equilibrium, unloaded };

struct SectionConfig {
  std::string type;                                  // rectangle | pipe | tapered_rectangle | box | i_section
  double width = 0, depth = 0;                       // m (rectangle, box, i_section: flange width; tapered: width)
  double depth_start = 0, depth_end = 0;             // m (tapered_rectangle)
  double diameter = 0, wall_thickness = 0;           // m (pipe; box: wall)
  double flange_thickness = 0, web_thickness = 0;    // m (i_section)
};

struct FrameNodeConfig {
  std::string name;
  DVec position;                                     // m
};

struct MemberConfig {
  std::string name, start, end, material;            // start/end: node names
  SectionConfig section;
  int elements = 1;                                  // beam-column elements along the member
  bool release_start = false, release_end = false;   // moment hinges at the member ends
  DVec orientation;                                  // 3D: the section's depth direction (empty: the default)
};

struct SupportConfig {
  std::string node, type;                            // fixed | pinned | roller | spring
  std::string restrained = "y";                      // roller: the restrained translation, x, y (or z in 3D)
  DVec stiffness;                                    // spring: kx, ky, kr (2D) or kx, ky, kz, krx, kry, krz (3D)
};

struct NodalMassConfig {
  std::string node;
  double mass = 0, rotary_inertia = 0;               // kg, kg m^2
};

// A permanent pressure on a plane member (earth or water standing behind a dam), held from t = 0 like the self-weight:
// at height y below the surface, gradient (surface - y) per unit height along direction (N/m per m of height).
struct PressureLoadConfig {
  std::string member;
  DVec direction;
  double surface = 0, gradient = 0;  // m (height of the free surface), N/m^2 per m (unit weight x coefficient x width)
};

struct StructureConfig {
  bool present = false;
  BeamTheoryKind theory = BeamTheoryKind::euler_bernoulli;
  FrameTransformKind transformation = FrameTransformKind::linear;
  FrameMassKind mass = FrameMassKind::lumped;
  FrameIntegratorKind integrator = FrameIntegratorKind::explicit_euler;
  bool self_weight = true;                           // gravity on the members' own mass
  FrameInitialState initial_state = FrameInitialState::static_equilibrium;  // with self_weight
  double rayleigh_mass = 0, rayleigh_stiffness = 0;  // C = alpha M + beta K: alpha (1/s), beta (s)
  double modal_damping_ratio = 0;                    // modal damping: zeta of every mode up to the frequency below
  double modal_damping_max_frequency = std::numeric_limits<double>::infinity();  // Hz
  double hht_alpha = -0.1;                           // newmark: HHT alpha in [-1/3, 0]
  int integration_points = 5;                        // Gauss-Lobatto sections of an elastic_plastic member's elements
  std::vector<FrameNodeConfig> nodes;
  std::vector<MemberConfig> members;
  std::vector<SupportConfig> supports;
  std::vector<NodalMassConfig> masses;
  std::vector<PressureLoadConfig> pressure_loads;
};

// --- Members as MPM velocity boundaries (Yang 2016; Lin & Yang 2024) ---------------------------

struct MemberContactConfig {
  MemberContactMode mode = MemberContactMode::separable;
  double friction = 0.0;                             // Coulomb coefficient (mode friction)
  DecayKind decay = DecayKind::sharp;                // q of eq. (16): held or free, with hysteresis
  double decay_scale = 1.0;                          // multiplies l_n of eq. (18)
  DistanceKind distance = DistanceKind::node;        // where r of eq. (23) is measured from
  DetectionKind detection = DetectionKind::surface;  // sharp decay: a node is held only where the material touches
  std::vector<std::string> bodies;                   // bodies the members act on; empty = all
  std::vector<std::string> bonded;                   // bodies stuck to the members whatever the mode
};

// A pressure sensor: the normal traction on a wall or a member face averaged over a square (a segment in 2D) of
// side size centred at point, as a transducer of that face reads it.
struct SensorConfig {
  std::string name, wall, member;                    // exactly one of wall and member
  DVec point;                                        // m, on the face
  double size = 0;                                   // m
};

// The pressure profile along a struck face made of members: the normal contact force on each element, per unit
// face area, with its resultant and the resultant's position along the face.
struct FaceProfileConfig {
  bool present = false;
  std::vector<std::string> members;                  // in order along the face, each starting where the last ended
  DVec direction;                                    // into the face (the load's direction); normalised when read
  double width = 0;                                  // m, loaded width of the face (3D); 2D: the analysis thickness
};

struct OutputConfig {
  double snapshot_interval = 0.0;                    // s; 0 = first and last state only
  double history_interval = 0.0;                     // s; 0 = every step
  bool vtk = true;
  std::vector<ProbeConfig> probes;
  std::vector<SensorConfig> sensors;
  FaceProfileConfig face_profile;
};

// --- Solid-FE check of a concrete dam body (Lin, Cheng & Tuan, Table 1) ------------------------------
struct SolidLoadConfig {
  std::string name, type;                            // point | patch | simulation
  double force = 0;                                  // N (point, patch)
  double height = 0;                                 // m above the base (point, patch centre)
  double across = -1;                                // m from the side edge of the face (3D); < 0: mid-width
  double patch_width = 0, patch_height = 0;          // m (patch)
  std::string shape = "pyramid";                     // uniform | pyramid (patch)
  std::string member;                                // simulation: the dam member ("" = the first)
  std::string spread = "uniform";                    // simulation, 3D: uniform across the width | axisymmetric
};

struct SolidCheckConfig {
  bool present = false;
  double height = 0, crest_thickness = 0, base_thickness = 0, width = 0;  // m
  std::string sloped_face = "downstream";            // upstream | downstream | both
  std::string element = "hex8";                      // hex8 (3D) | quad4 (2D plane strain)
  std::vector<int> cells = {8, 10, 20};              // through the thickness, across the width, up the height
  double max_dofs = 1.5e5;                           // refuse larger meshes (a sparse LDL^T grows ~ DOFs^2 in 3D)
  double youngs_modulus = 25e9, poisson_ratio = 0.2; // Pa, -
  std::vector<SolidLoadConfig> loads;
};

struct Scenario {
  int schema_version = 1;
  std::string name, description;
  AnalysisConfig analysis;
  MpmConfig mpm;
  GridConfig grid;
  std::vector<MaterialConfig> materials;
  std::vector<BodyConfig> bodies;
  ContactConfig contact;
  std::vector<WallConfig> walls;
  std::vector<PrescribedVelocityConfig> prescribed_velocity;
  StructureConfig structure;
  MemberContactConfig member_contact;
  OutputConfig output;
  SolidCheckConfig solid_check;
  std::string source_file;   // where it came from, for messages
  std::string source_text;   // the JSON as given, stored in results.h5
  std::string expanded_text; // the low-level scenario the presets expanded into ("" without presets)
  std::string variant;       // "" or with_buffer / without_buffer (compare)
  std::optional<DesignBasis> design_basis;  // what the design checks and estimates need (the presets write it)
  // The file for messages about the scene as built: a preset scenario's paths are those of its expansion, said so.
  std::string message_source() const { return expanded_text.empty() ? source_file : source_file + " (expanded presets; see --dry-run --expand)"; }
};

}  // namespace dmi
