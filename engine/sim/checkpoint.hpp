// Checkpoint files (OUT/checkpoint.dmi): the solver, recorder and step-loop state of a run, so that
// `damimpact simulate|run --restart` continues it bit for bit (docs/reliability.md, "Checkpoint and restart").
// Layout: magic "DMICKPT4", u32 dimension, u64 scenario fingerprint, u64 payload size, payload, u64 FNV-1a
// checksum of the payload. Written to <path>.tmp and renamed, so a checkpoint is either whole or absent.
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "engine/common/state_io.hpp"
#include "engine/scenario/config.hpp"

namespace dmi {

// FNV-1a, 64 bit.
std::uint64_t fnv1a(const std::string& bytes, std::uint64_t h = 14695981039346656037ull);
// What a checkpoint must match: the scenario's identity (engine/scenario/identity.hpp), its first 64 bits.
std::uint64_t scenario_fingerprint(const Scenario& s);

// The step loop's own state (engine/sim/run.cpp).
struct LoopState {
  double next_sample = 0, next_snap = 0, dt_min = 0, dt_max = 0, courant_max = 0, j_min = 1, wall_seconds = 0;
  std::uint64_t snapshots = 0;  // snapshots in results.h5.partial when the checkpoint was taken
  std::vector<std::pair<double, std::string>> vtk_files, member_files;
  void save(StateWriter& w) const;
  void load(StateReader& r);
};

// Throws std::runtime_error when the file cannot be written (disk full, permissions).
void write_checkpoint(const std::string& path, int dim, std::uint64_t fingerprint, const std::string& payload);
// The payload; throws InputError naming the file when it is missing, truncated, corrupt, of another dimension or
// written for another scenario.
std::string read_checkpoint(const std::string& path, int dim, std::uint64_t fingerprint);

}  // namespace dmi
