// The members at one history sample, read from results.h5 histories (frame/displacement, frame/end_forces)
// and /documents/structure: what the pictures and charts draw.
#pragma once
#include <array>
#include <cstddef>
#include <vector>

#include "design/members.hpp"
#include "engine/io/results.hpp"
#include "engine/structure/fibre.hpp"

namespace dmi::render {

struct ElementState {
  std::array<double, 3> xi{}, xj{};        // displaced end positions (m; z = 0 in a plane frame)
  double ci = 0, cj = 0;                   // half depths at the ends (m)
  // Extreme-fibre stresses (Pa, tension +): plane frames the +e2 / -e2 faces; space frames the largest and smallest
  // around the section.
  double top_i = 0, bottom_i = 0, top_j = 0, bottom_j = 0;
  SpaceSectionForces fi, fj;               // space frames: section forces at the ends (the pictures' fibre stresses)
};

struct FrameState {
  std::vector<std::array<double, 3>> x0, u;  // initial node positions and displacements (m)
  std::vector<ElementState> elements;
};

// Index of the history sample nearest to t.
std::size_t nearest_sample(const Results& r, double t);
// The frame at sample k; throws std::runtime_error when the histories do not match the structure.
FrameState frame_state(const Results& r, const design::FrameInfo& f, std::size_t k);

// The demand history of a member check at one station (docs/design-checks.md): fibre tension (Pa),
// compression magnitude (Pa), |V| (N), von Mises (Pa) or the steel interaction ratio, by check id.
// Empty when the check has no time history (solid-FE, section class).
std::vector<double> demand_history(const Results& r, const design::FrameInfo& f, const std::string& member, double position,
                                   const std::string& check_id, const design::Limits& limits);

}  // namespace dmi::render
