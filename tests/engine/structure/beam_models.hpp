// Straight-beam and support builders shared by the structure tests (steel rectangle 0.1 x 0.2 m by default).
#pragma once
#include <numbers>

#include "engine/structure/frame.hpp"

namespace dmi::test {

struct Beam {
  double L = 2.0, E = 200e9, nu = 0.3, rho = 7850;
  Section section = Section::rectangle(0.1, 0.2);
  double EI() const { return E * section.inertia(0); }
  double EA() const { return E * section.area(0); }
  double rhoA() const { return rho * section.area(0); }
};

// n elements from (0, 0) to (L cos a, L sin a), one member.
inline FrameModel straight(const Beam& b, int n, double angle = 0.0) {
  FrameModel m;
  const Vec2 dir(std::cos(angle), std::sin(angle));
  for (int k = 0; k <= n; ++k) m.nodes.push_back(b.L * k / n * dir);
  for (int k = 0; k < n; ++k) {
    FrameElementDef e;
    e.i = k;
    e.j = k + 1;
    e.section = b.section;
    e.s0 = static_cast<double>(k) / n;
    e.s1 = static_cast<double>(k + 1) / n;
    e.E = b.E;
    e.nu = b.nu;
    e.rho = b.rho;
    m.elements.push_back(e);
  }
  m.members.push_back({"beam", 0, n});
  return m;
}

inline void support(FrameModel& m, int node, bool ux, bool uy, bool rz) {
  FrameSupportDef s;
  s.node = node;
  s.fixed[0] = ux;
  s.fixed[1] = uy;
  s.fixed[2] = rz;
  m.supports.push_back(s);
}

inline double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

}  // namespace dmi::test
