// ParaView-ready VTK XML output of particle snapshots: one .vtu (UnstructuredGrid of vertex cells,
// appended raw binary) per snapshot and a .pvd collection listing them with their times.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "engine/io/results.hpp"

namespace dmi {

// Writes a snapshot as .vtu: points (z = 0 in 2D), point data displacement, velocity, stress
// (6 components), von_mises, volume, body, material. Throws std::runtime_error on failure.
void write_vtu(const std::string& path, const Snapshot& s);
// Writes a .pvd collection; entries are (time, file name relative to the .pvd).
void write_pvd(const std::string& path, const std::vector<std::pair<double, std::string>>& entries);

}  // namespace dmi
