// In-memory form of what results.h5 holds (layout: docs/results.md). Writer and reader share it.
// Solver-independent: plain arrays, so design/ and render/ never see solver objects.
#pragma once
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/design_basis.hpp"
#include "core/face_profile.hpp"
#include "core/peak_contact.hpp"
#include "core/solid_check_record.hpp"
#include "core/solid_field.hpp"
#include "core/structure_record.hpp"
#include "engine/io/run_stats.hpp"

namespace dmi {

constexpr int kResultsFormatVersion = 1;

// A time series sampled at the history times: rows = samples, cols = components.
struct Series {
  std::string path;                     // e.g. "energy/kinetic", "probes/tip/velocity", "walls/floor/force"
  std::string unit;                     // e.g. "J", "m/s", "N"
  std::vector<std::string> components;  // e.g. {"x","y"}; one entry for scalars
  std::vector<double> data;             // row-major, size = samples * components.size()
  std::size_t samples() const { return components.empty() ? 0 : data.size() / components.size(); }
};

// Particle field snapshot at one instant.
struct Snapshot {
  double time = 0.0;   // s
  long step = 0;
  int dim = 2;
  std::size_t count = 0;
  std::vector<double> position;      // count * dim (m)
  std::vector<double> displacement;  // count * dim (m)
  std::vector<double> velocity;      // count * dim (m/s)
  std::vector<double> stress;        // count * 6, Voigt xx yy zz xy yz xz (Pa)
  std::vector<double> von_mises;     // count (Pa)
  std::vector<double> volume;        // count (m^3)
  std::vector<std::int32_t> body;    // count, body index
  std::vector<std::int32_t> material;  // count, material index
};

// Throws std::runtime_error("<where>: snapshot <array> has N values, expected M") unless every
// array of s matches s.count and s.dim.
void check_snapshot(const Snapshot& s, const std::string& where);

struct RunInfo {
  std::string scenario_name;
  std::string scenario_file;
  std::string scenario_json;   // the scenario text as given
  std::string scenario_expanded_json;  // the low-level scenario its presets expanded to ("" without presets)
  std::string variant;         // with_buffer / without_buffer of a comparison, else ""
  std::string software_version;
  int dimension = 2;
  std::vector<std::string> body_names, material_names;
  RunStats stats;  // /run's attributes: the set-up, the outcome, the solver's counters
  std::optional<DesignBasis> design_basis;  // /documents/design_basis: what the presets described (checks, estimates)
  std::optional<PeakContact> peak_contact;  // /documents/peak_contact: members touched in the run
  std::optional<StructureRecord> structure;  // /documents/structure: the members as built
  std::optional<FaceProfileRecord> face_profile;  // /documents/face_profile: the struck face's bins
  std::optional<SolidCheckRecord> solid_check;    // /documents/solid_check: the solid check's peaks per case
  std::optional<SolidFieldRecord> solid_field;    // /documents/solid_field: the solid check's mesh and fields
  // Any other document under /documents, as its text (a file written by a later version); docs/results.md.
  std::map<std::string, std::string> documents;
};

struct Results {
  RunInfo info;
  bool complete = false;
  std::vector<double> time;        // history sample times (s)
  std::vector<Series> series;      // all histories
  std::vector<Snapshot> snapshots; // may be left empty by a reader asked for histories only
  const Series* find(const std::string& path) const {
    for (const auto& s : series) if (s.path == path) return &s;
    return nullptr;
  }
};

}  // namespace dmi
