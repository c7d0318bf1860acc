// The run's set-up and statistics as a typed record: what results.h5 keeps as the attributes of /run (a number or a
// word each; docs/results.md "/run"). The solver's driver fills it; the report's model table, the run's summary
// line, the grid study and the verification cases read its fields; only the HDF5 edge (results_writer,
// results_reader) sees the attribute names, through to_attributes / from_attributes.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace dmi {

struct RunStats {
  // The set-up: cell size (m), end time (s), the CFL number asked for, the FLIP blend; shape functions, transfer,
  // stress update, plane (strain, stress; none in 3D), body contact method.
  std::optional<double> cell_size, end_time, cfl, flip_blend;
  std::optional<std::string> shape_function, transfer, stress_update, plane, contact;
  // The members' lowest natural periods (s), lowest first.
  std::vector<double> frame_periods;
  // The outcome: "complete", "stopped (...)", "interrupted (...)"; a note on the set-up the run changed (a CFL
  // reduced to its stable limit, then cfl_used).
  std::optional<std::string> status, notes;
  std::optional<double> cfl_used, steps_estimate, wall_estimate_s;
  std::optional<double> steps, wall_seconds, particles, dt_min, dt_max, threads, threads_used, solid_check_seconds;
  // Numerical health: the largest Courant number used, the smallest particle J = V/V0.
  std::optional<double> courant_max, jacobian_min;
  // Solver counters: rigid passes per step, free-rigid switches and steps, viscous sub-steps and stages, member
  // contact candidates and loaded ones, contact projection iterations (mean, max).
  std::optional<double> rigid_passes_per_step, free_rigid_switches, free_rigid_steps, viscous_steps, viscous_stages;
  std::optional<double> member_contact_candidates, member_contact_loaded, projection_iterations_mean, projection_iterations_max;
  // With profiling: seconds per phase of the step ("particles_to_grid", ...), of the whole step ("time_step") and of
  // the recorder ("recorder").
  std::map<std::string, double> profile_seconds;
  // Attributes this build does not know (a file written by a later version), kept as they are.
  std::map<std::string, double> other_numbers;
  std::map<std::string, std::string> other_words;
};

// /run's attributes: the numbers and the words, by name.
struct RunAttributes {
  std::map<std::string, double> numbers;
  std::map<std::string, std::string> words;
};
RunAttributes to_attributes(const RunStats& s);
RunStats from_attributes(const RunAttributes& a);

}  // namespace dmi
