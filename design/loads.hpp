// Support reactions and the contact load on the members, from the stored histories of results.h5.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "design/members.hpp"

namespace dmi::design {

struct ReactionPeaks {
  std::string name;                   // support node, or "base total"
  Extreme Fx_max, Fx_min, Fy_max, Fy_min, M_max, M_min;  // N, N, N m: force and moment the support exerts on the frame
  Extreme Fx_abs, Fy_abs, M_abs;
  std::array<double, 3> final{0, 0, 0};  // at the last sample
};

struct Reactions {
  std::vector<ReactionPeaks> supports;
  // Sum over the supports: Fx, Fy and the moment about the centroid of the support nodes
  // (M_total = sum M_k + (x_k - x_c) Fy_k - (y_k - y_c) Fx_k); with one support, its own values.
  ReactionPeaks total;
  std::array<double, 2> about{0, 0};  // the centroid (m)
};

Reactions reactions(const Results& r, const FrameInfo& f, const std::string& where);

// The base totals at every history sample (the same sums as Reactions::total).
struct BaseHistory {
  std::vector<double> fx, fy, m;      // N, N, N m
  std::array<double, 2> about{0, 0};  // m
};
BaseHistory base_history(const Results& r, const FrameInfo& f, const std::string& where);

// Contact force the material exerts on the members (frame/contact_force, interval means).
struct Contact {
  bool present = false;
  double peak_N = 0, peak_time_s = -1;
  std::array<double, 2> impulse_N_s{0, 0};  // sum F_i (t_i - t_{i-1}) over the run: exact for interval means
  // The pulse holding the peak: contiguous samples with |F| >= 5 % of the peak; its impulse integrates |F| (so it can
  // exceed the magnitude of the vector impulse when the force turns).
  double pulse_start_s = 0, pulse_end_s = 0, pulse_impulse_N_s = 0;
  double loaded_time_s = 0;  // total time with |F| >= 5 % of the peak
};

Contact contact(const Results& r);

}  // namespace dmi::design
