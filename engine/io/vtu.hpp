// ParaView-ready VTK XML output of particle snapshots: one .vtu (UnstructuredGrid of vertex cells,
// appended raw binary) per snapshot and a .pvd collection listing them with their times.
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "engine/io/results.hpp"

namespace dmi {

// Writes a snapshot as .vtu: points (z = 0 in 2D), point data displacement, velocity, stress
// (6 components), von_mises, volume, body, material. Throws std::runtime_error on failure.
void write_vtu(const std::string& path, const Snapshot& s);
// Beam-column members at one instant, sampled along their deformed centre-lines: consecutive
// points, one polyline cell per element (cell k uses points [ends[k-1], ends[k]) with ends[-1] = 0).
struct LineSnapshot {
  int dim = 2;                       // components per point: 2 (x, y; written with z = 0) or 3
  std::vector<double> points;        // dim per point (m)
  std::vector<double> displacement;  // dim per point (m)
  std::vector<std::size_t> ends;     // per cell, one past its last point
  std::vector<std::pair<std::string, std::vector<double>>> point_scalars;  // name (with unit) -> one value per point
  std::vector<std::int32_t> member;  // per cell, member index
};
// Writes members as a .vtu of VTK_POLY_LINE cells, arrays appended raw as write_vtu's (z = 0 in 2D). Throws
// std::runtime_error on failure.
void write_lines_vtu(const std::string& path, const LineSnapshot& s);
// Writes a .pvd collection; entries are (time, file name relative to the .pvd).
void write_pvd(const std::string& path, const std::vector<std::pair<double, std::string>>& entries);

}  // namespace dmi
