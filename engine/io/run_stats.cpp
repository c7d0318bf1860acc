#include "engine/io/run_stats.hpp"

#include <utility>

namespace dmi {

namespace {

using Number = std::optional<double> RunStats::*;
using Word = std::optional<std::string> RunStats::*;

const std::pair<const char*, Number> kNumbers[] = {
    {"cell_size", &RunStats::cell_size},
    {"end_time", &RunStats::end_time},
    {"cfl", &RunStats::cfl},
    {"flip_blend", &RunStats::flip_blend},
    {"cfl_used", &RunStats::cfl_used},
    {"steps_estimate", &RunStats::steps_estimate},
    {"wall_estimate_s", &RunStats::wall_estimate_s},
    {"steps", &RunStats::steps},
    {"wall_seconds", &RunStats::wall_seconds},
    {"particles", &RunStats::particles},
    {"dt_min", &RunStats::dt_min},
    {"dt_max", &RunStats::dt_max},
    {"threads", &RunStats::threads},
    {"threads_used", &RunStats::threads_used},
    {"solid_check_seconds", &RunStats::solid_check_seconds},
    {"courant_max", &RunStats::courant_max},
    {"jacobian_min", &RunStats::jacobian_min},
    {"rigid_passes_per_step", &RunStats::rigid_passes_per_step},
    {"free_rigid_switches", &RunStats::free_rigid_switches},
    {"free_rigid_steps", &RunStats::free_rigid_steps},
    {"viscous_steps", &RunStats::viscous_steps},
    {"viscous_stages", &RunStats::viscous_stages},
    {"member_contact_candidates", &RunStats::member_contact_candidates},
    {"member_contact_loaded", &RunStats::member_contact_loaded},
    {"projection_iterations_mean", &RunStats::projection_iterations_mean},
    {"projection_iterations_max", &RunStats::projection_iterations_max},
};

const std::pair<const char*, Word> kWords[] = {
    {"shape_function", &RunStats::shape_function}, {"transfer", &RunStats::transfer}, {"stress_update", &RunStats::stress_update},
    {"plane", &RunStats::plane},                   {"contact", &RunStats::contact},   {"status", &RunStats::status},
    {"notes", &RunStats::notes},
};

constexpr const char* kPeriod = "frame_period_";
constexpr const char* kProfile = "profile_";
constexpr const char* kSeconds = "_seconds";

bool starts(const std::string& s, const std::string& p) { return s.rfind(p, 0) == 0; }
bool ends(const std::string& s, const std::string& p) { return s.size() >= p.size() && s.compare(s.size() - p.size(), p.size(), p) == 0; }

// frame_period_<k>, k = 1, 2, ...: the index, or 0 when `name` is not one.
std::size_t period_index(const std::string& name) {
  if (!starts(name, kPeriod)) return 0;
  const std::string k = name.substr(std::string(kPeriod).size());
  if (k.empty() || k.size() > 6 || k.find_first_not_of("0123456789") != std::string::npos || k[0] == '0') return 0;
  return std::stoul(k);
}

}  // namespace

RunAttributes to_attributes(const RunStats& s) {
  RunAttributes a{s.other_numbers, s.other_words};
  for (const auto& [name, field] : kNumbers)
    if (s.*field) a.numbers[name] = *(s.*field);
  for (const auto& [name, field] : kWords)
    if (s.*field) a.words[name] = *(s.*field);
  for (std::size_t k = 0; k < s.frame_periods.size(); ++k) a.numbers[kPeriod + std::to_string(k + 1)] = s.frame_periods[k];
  for (const auto& [phase, seconds] : s.profile_seconds) a.numbers[kProfile + phase + kSeconds] = seconds;
  return a;
}

RunStats from_attributes(const RunAttributes& a) {
  RunStats s;
  std::map<std::size_t, double> periods;
  for (const auto& [name, value] : a.numbers) {
    bool known = false;
    for (const auto& [n, field] : kNumbers)
      if (name == n) s.*field = value, known = true;
    if (known) continue;
    if (const std::size_t k = period_index(name)) {
      periods[k] = value;
    } else if (starts(name, kProfile) && ends(name, kSeconds) && name.size() > std::string(kProfile).size() + std::string(kSeconds).size()) {
      s.profile_seconds[name.substr(std::string(kProfile).size(), name.size() - std::string(kProfile).size() - std::string(kSeconds).size())] = value;
    } else {
      s.other_numbers[name] = value;
    }
  }
  // The periods 1..n in turn; one missing from the run (a later one without an earlier) ends the list, the rest kept
  // as they are.
  std::size_t next = 1;
  for (const auto& [k, v] : periods) {
    if (k == next) s.frame_periods.push_back(v), ++next;
    else s.other_numbers[kPeriod + std::to_string(k)] = v;
  }
  for (const auto& [name, value] : a.words) {
    bool known = false;
    for (const auto& [n, field] : kWords)
      if (name == n) s.*field = value, known = true;
    if (!known) s.other_words[name] = value;
  }
  return s;
}

}  // namespace dmi
