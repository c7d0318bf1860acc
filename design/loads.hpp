// Support reactions and the contact load on the members, from the stored histories of results.h5.
#pragma once
#include <cmath>
#include <array>
#include <string>
#include <vector>

#include "design/members.hpp"

namespace dmi::design {

// One reaction component over time (force and moment the support exerts on the frame).
struct ReactionComponent {
  std::string key;  // design.json key with its unit: Fx_N, Fy_N, M_Nm (plane); Fx_N .. Mz_Nm, H_N, M_overturning_Nm (space)
  Extreme max, min, abs;
  double final = 0;  // at the last sample
};

// Plane frames: Fx, Fy, M. Space frames (z up): Fx, Fy, Fz, Mx, My, Mz and the horizontal resultants
// H = |(Fx, Fy)| (the base shear) and M_overturning = |(Mx, My)|.
struct ReactionPeaks {
  std::string name;  // support node, or "base total"
  std::vector<ReactionComponent> components;
  const ReactionComponent& at(const std::string& key) const;  // throws std::out_of_range
};

struct Reactions {
  std::vector<ReactionPeaks> supports;
  // Sum over the supports: forces and the moment about the centroid c of the support nodes,
  // M_total = sum M_k + (x_k - c) x F_k (plane: M_k + (x_k - x_c) Fy_k - (y_k - y_c) Fx_k); with one support, its own values.
  ReactionPeaks total;
  std::array<double, 3> about{0, 0, 0};  // the centroid (m)
};

Reactions reactions(const Results& r, const FrameInfo& f, const std::string& where);

// The base totals at every history sample (the same sums as Reactions::total), one series per component key.
struct BaseHistory {
  std::vector<std::string> keys;
  std::vector<std::vector<double>> values;  // values[c][k]: component c at sample k
  std::array<double, 3> about{0, 0, 0};     // m
  const std::vector<double>& at(const std::string& key) const;  // throws std::out_of_range
  // The base shear (plane: Fx; space: H) and the overturning moment (plane: M; space: M_overturning).
  const std::vector<double>& shear() const;
  const std::vector<double>& moment() const;
};
BaseHistory base_history(const Results& r, const FrameInfo& f, const std::string& where);
// The design.json key of the base shear and the overturning moment: Fx_N / M_Nm (plane), H_N / M_overturning_Nm (space).
const char* shear_key(int dim);
const char* moment_key(int dim);

// Contact force the material exerts on the members (frame/contact_force, interval means).
struct Contact {
  bool present = false;
  double peak_N = 0, peak_time_s = -1;
  std::vector<double> impulse_N_s;  // per axis: sum F_i (t_i - t_{i-1}) over the run: exact for interval means
  // The pulse holding the peak: contiguous samples with |F| >= 5 % of the peak; its impulse integrates |F| (so it can
  // exceed the magnitude of the vector impulse when the force turns).
  double pulse_start_s = 0, pulse_end_s = 0, pulse_impulse_N_s = 0;
  double loaded_time_s = 0;  // total time with |F| >= 5 % of the peak
  double impulse_magnitude() const {  // |sum F_i dt| (N s)
    double m2 = 0;
    for (double v : impulse_N_s) m2 += v * v;
    return std::sqrt(m2);
  }
};

Contact contact(const Results& r);
// |F| of frame/contact_force at every history sample (2 or 3 components); empty without it.
std::vector<double> contact_magnitude(const Results& r);

}  // namespace dmi::design
