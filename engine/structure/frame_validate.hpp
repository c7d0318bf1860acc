// Validation of a frame model shared by the plane and the space frame (their models have the same fields; the
// space frame adds its orientation check when it builds the local axes): every error names the element, node,
// member, support or mass, through fail (which throws).
#pragma once
#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>
#include <vector>

namespace dmi {

template <class Model, class Fail> void validate_frame_model(const Model& model_, const Fail& fail) {
  const int nn = static_cast<int>(model_.nodes.size()), ne = static_cast<int>(model_.elements.size());
  if (ne == 0) fail("the model has no elements");
  for (int n = 0; n < nn; ++n)
    if (!model_.nodes[n].allFinite()) fail("node " + std::to_string(n) + " has a non-finite coordinate");
  const auto node_ok = [nn](int n) { return n >= 0 && n < nn; };
  using Node = std::decay_t<decltype(model_.nodes[0])>;
  Node lo = Node::Constant(INFINITY), hi = -lo;
  for (const auto& x : model_.nodes) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  const double min_length = 1e-12 * std::max(1.0, (hi - lo).norm());  // m
  for (int e = 0; e < ne; ++e) {
    const auto& el = model_.elements[e];
    const std::string id = "element " + std::to_string(e) + ": ";
    if (!node_ok(el.i) || !node_ok(el.j))
      fail(id + "node index " + std::to_string(node_ok(el.i) ? el.j : el.i) + " outside [0, " +
           std::to_string(nn) + ")");
    if ((model_.nodes[el.j] - model_.nodes[el.i]).norm() <= min_length) fail(id + "zero length");
    if (!(el.E > 0) || !std::isfinite(el.E)) fail(id + "Young's modulus E must be positive");
    if (!(el.rho > 0) || !std::isfinite(el.rho)) fail(id + "density rho must be positive");
    if (!(el.nu > -1 && el.nu <= 0.5)) fail(id + "Poisson's ratio outside (-1, 0.5]");
    if (!(el.s0 >= 0 && el.s0 <= 1 && el.s1 >= 0 && el.s1 <= 1)) fail(id + "section span s0, s1 outside [0, 1]");
    for (double s : {el.s0, el.s1})
      if (!(el.section.depth(s) > 0 && el.section.width(s) > 0 && el.section.area(s) > 0 &&
            el.section.inertia(s) > 0))
        fail(id + "section dimensions must be positive");
    if (el.steel.fy > 0) {
      if (!std::isfinite(el.steel.fy)) fail(id + "yield strength must be finite");
      if (!(el.steel.hardening >= 0 && el.steel.hardening < 1)) fail(id + "hardening ratio outside [0, 1)");
      if (el.integration_points < 3 || el.integration_points > 5) fail(id + "integration points outside [3, 5]");
      if (el.release_i || el.release_j) fail(id + "a plastic element cannot carry a moment release");
    }
    if (!model_.members.empty() && (el.member < 0 || el.member >= static_cast<int>(model_.members.size())))
      fail(id + "member index " + std::to_string(el.member) + " out of range");
  }
  for (size_t m = 0; m < model_.members.size(); ++m) {
    const auto& mb = model_.members[m];
    if (mb.first_element < 0 || mb.elements < 1 || mb.first_element + mb.elements > ne)
      fail("member " + std::to_string(m) + " (" + mb.name + "): element range outside the model");
  }
  std::vector<bool> supported(nn, false);
  for (size_t k = 0; k < model_.supports.size(); ++k) {
    const auto& s = model_.supports[k];
    const std::string id = "support " + std::to_string(k) + ": ";
    if (!node_ok(s.node)) fail(id + "node index " + std::to_string(s.node) + " out of range");
    if (supported[s.node]) fail(id + "node " + std::to_string(s.node) + " already has a support");
    supported[s.node] = true;
    for (double kc : s.spring)
      if (!(kc >= 0) || !std::isfinite(kc)) fail(id + "spring stiffness must be finite and >= 0");
  }
  for (size_t k = 0; k < model_.masses.size(); ++k) {
    const auto& m = model_.masses[k];
    if (!node_ok(m.node))
      fail("mass " + std::to_string(k) + ": node index " + std::to_string(m.node) + " out of range");
    if (!(m.mass >= 0 && m.rotary_inertia >= 0) || !std::isfinite(m.mass + m.rotary_inertia))
      fail("mass " + std::to_string(k) + ": mass and rotary inertia must be finite and >= 0");
  }
  if (!(model_.rayleigh_mass >= 0 && model_.rayleigh_stiffness >= 0) ||
      !std::isfinite(model_.rayleigh_mass + model_.rayleigh_stiffness))
    fail("Rayleigh coefficients must be finite and >= 0");
  if (!(model_.modal_damping.ratio >= 0 && model_.modal_damping.ratio < 1)) fail("modal damping ratio must lie in [0, 1)");
  if (model_.modal_damping.ratio > 0 && model_.transform == FrameTransform::corotational)
    fail("modal damping is built on the initial stiffness and would damp rigid rotation of corotational members");
  if (!model_.gravity.allFinite()) fail("gravity must be finite");
  if (!model_.permanent.empty() && model_.permanent.size() != model_.elements.size())
    fail("permanent loads: " + std::to_string(model_.permanent.size()) + " given for " + std::to_string(ne) + " elements");
  for (std::size_t e = 0; e < model_.permanent.size(); ++e)
    if (!model_.permanent[e][0].allFinite() || !model_.permanent[e][1].allFinite()) fail("element " + std::to_string(e) + ": non-finite permanent load");
}

}  // namespace dmi
