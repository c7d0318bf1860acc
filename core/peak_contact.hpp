// The contact loads on the members at the instant of the largest total contact force: what the solid check applies to
// the dam body, the punching and dent checks take as their demand and the pictures centre on. The run records it;
// results.h5 carries it (/documents/peak_contact, docs/results.md). SI units; vectors have the run's dimension.
#pragma once
#include <string>
#include <vector>

namespace dmi {

struct ContactLoadAt {
  std::string member;
  double position = 0;         // along the member, a fraction of its length
  std::vector<double> point;   // m
  std::vector<double> force;   // N, on the member
};

struct PeakContact {
  double time = 0;                   // s
  std::vector<double> total_force;   // N
  std::vector<ContactLoadAt> loads;
};

}  // namespace dmi
