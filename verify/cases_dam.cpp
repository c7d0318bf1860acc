// The members model of a concrete gravity dam against an independent solid model: the in-plane natural periods of the
// bundled trial and demo dams (preset members: tapered Timoshenko beam-column, 16 elements, fixed base) against
// CalculiX 3D solids of the same bodies (bench/ccx_dam_modes.py: quadratic C3D20 bricks at three meshes, fixed base,
// free faces, Richardson-extrapolated; the finest mesh within 0.03 % of the extrapolation).
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "engine/scenario/presets.hpp"
#include "engine/scenario/scenario.hpp"
#include "engine/sim/build_frame.hpp"
#include "engine/structure/frame_system.hpp"
#include "verify/validate.hpp"

namespace dmi {
namespace {

// Timoshenko beam theory against elasticity for a section 0.4 to 0.6 of the height deep: a few per cent on the lowest
// modes (the section warps and the taper's axis is not straight in the solid), so 5 %.
constexpr double kPeriodTolerance = 0.05;

struct SolidModes {
  const char *tag, *example;
  double bending1_hz, bending2_hz, axial1_hz;  // CalculiX, extrapolated
};

// The frame's in-plane modes, each labelled bending (horizontal motion dominates) or axial.
struct PlaneMode {
  double period = 0;
  bool axial = false;
};
std::vector<PlaneMode> frame_modes(const FrameModel& model, int count) {
  const FrameSystem sys(model);
  const AssembledSystem::Modes m = sys.modes();
  std::vector<PlaneMode> modes;
  for (int k = 0; k < count; ++k) {
    double ux = 0, uy = 0;
    for (Eigen::Index node = 0; 3 * node < m.shapes.rows(); ++node) {  // DOFs ux, uy, rz per node
      ux += m.shapes(3 * node, k) * m.shapes(3 * node, k);
      uy += m.shapes(3 * node + 1, k) * m.shapes(3 * node + 1, k);
    }
    modes.push_back({2 * std::numbers::pi / std::sqrt(m.omega2(k)), uy > ux});
  }
  return modes;
}

std::vector<CaseResult> dam_periods() {
  CaseTimer timer;
  const SolidModes refs[] = {{"trial", "trial_dam_6m_boulder.json", 47.655, 149.496, 157.574},
                             {"demo", "concrete_dam_boulder_buffer.json", 51.888, 202.640, 226.060}};
  std::vector<CaseResult> r;
  for (const SolidModes& ref : refs) {
    const std::string file = std::string("examples/") + ref.example;
    const nlohmann::json low = expand_presets(nlohmann::json::parse(embedded_examples().at(ref.example)), file, "without_buffer");
    const std::vector<PlaneMode> modes = frame_modes(build_frame_model(parse_scenario(low, file)), 4);
    int bending = 0, axial = 0;
    const std::string tag = std::string(ref.tag) + ": ";
    for (const PlaneMode& m : modes) {
      if (m.axial && ++axial == 1)
        r.push_back(metric("dam_periods", tag + "axial mode 1 period", "s", m.period, 1 / ref.axial1_hz, kPeriodTolerance));
      if (!m.axial && ++bending <= 2)
        r.push_back(metric("dam_periods", tag + "in-plane bending mode " + std::to_string(bending) + " period", "s", m.period,
                           1 / (bending == 1 ? ref.bending1_hz : ref.bending2_hz), kPeriodTolerance));
    }
    if (bending < 2 || axial < 1) r.push_back(bound_metric("dam_periods", tag + "modes found among the lowest four", "-", bending + axial, 2.5, true));
  }
  return stamp(r, timer.seconds());
}

}  // namespace

std::vector<ValidationCase> dam_validation_cases() {
  return {{"dam_periods", "concrete dam members model: in-plane natural periods vs a CalculiX 3D solid of the trial and demo dams",
           dam_periods}};
}

}  // namespace dmi
