// Fluids' volume relaxation (engine/mpm/fluid_volume.hpp): the nodes' space in front of walls against closed forms,
// and the relaxation's rate.
#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "engine/mpm/fluid_volume.hpp"
#include "engine/mpm/solver.hpp"
#include "engine/scenario/scenario.hpp"
#include "engine/sim/build_scene.hpp"

namespace dmi {
namespace {

using json = nlohmann::json;

json water_scene(const std::string& shape, double relax) {
  return {{"schema_version", 1},
          {"name", "volumes"},
          {"analysis", {{"dimension", 2}, {"end_time", 1.0}, {"gravity", {0, 0}}}},
          {"mpm", {{"shape_function", shape}}},
          {"grid", {{"origin", {0, 0}}, {"size", {1.0, 1.0}}, {"cell_size", 0.1}}},
          {"materials", {{{"name", "water"}, {"model", "newtonian"}, {"density", 1000}, {"bulk_modulus", 1e5}, {"viscosity", 1e-3},
                          {"volume_relaxation", relax}}}},
          {"bodies", {{{"name", "w"}, {"material", "water"}, {"shape", {{"type", "box"}, {"min", {0.3, 0.2}}, {"max", {0.8, 0.8}}}}}}},
          {"walls", {{{"name", "left"}, {"type", "plane"}, {"point", {0.3, 0}}, {"normal", {1, 0}}, {"condition", "slip"}}}}};
}

// V_i = h^2 times the integral of the nodal shape function (per axis, r = (x - x_i)/h) over x >= the wall on the grid
// line x = 0.3: quadratic B-spline 1/48, 1/2, 47/48, 1 for the nodes at x = 0.2, 0.3, 0.4, 0.5 and 0 further behind;
// the hat (linear and uGIMP) 0, 1/2, 1. The quadrature is the midpoint rule on 8 points per cell, whose points' cells
// meet at the integrand's breaks: exact where f' is the same at both ends of the range (the node on the plane; the
// hat), else off by exactly -(f'(b) - f'(a)) dq^2 / 24 on a piecewise quadratic: for the node behind, r in [1, 1.5],
// -(0 - (-1/2)) (1/8)^2 / 24 = -3.3e-4, and the opposite for the node in front.
TEST(FluidVolumes, NodeVolumesIntegrateTheShapeFunctionInFrontOfAWall) {
  const double h = 0.1, h2 = h * h, mid = 0.5 * (1.0 / 64) / 24;
  for (const std::string shape : {"bspline2", "gimp", "linear"}) {
    const Scene<2> sc = build_scene<2>(parse_scenario(water_scene(shape, 100), "v.json"));
    const std::vector<double> V = FluidVolumes<2>::node_volumes(sc);
    const Grid<2>& g = *sc.grid;
    auto at = [&](int i) { return V[static_cast<std::size_t>(g.node_id(IVec<2>(i, 5)))] / h2; };
    if (shape == "bspline2") {
      EXPECT_NEAR(at(1), 0.0, 1e-15);
      EXPECT_NEAR(at(2), 1.0 / 48 - mid, 1e-12) << shape;
      EXPECT_NEAR(at(3), 0.5, 1e-12) << shape;
      EXPECT_NEAR(at(4), 47.0 / 48 + mid, 1e-12) << shape;
      EXPECT_NEAR(at(5), 1.0, 1e-12) << shape;
    } else {
      EXPECT_NEAR(at(2), 0.0, 1e-15) << shape;
      EXPECT_NEAR(at(3), 0.5, 1e-12) << shape;
      EXPECT_NEAR(at(4), 1.0, 1e-12) << shape;
    }
  }
}

// Water at rest without gravity whose volumes overfill its space twice (J = 2 set on particles seeded at J = 1): no
// pressure (tension cut-off) and no motion, so J relaxes only by the rule, ln J_n = ln 2 (1 - kappa)^n with kappa =
// dt c0 / (n_relax h), inside the body where the grid reads the space exactly (quadratic B-splines, 2 x 2 particles per
// cell: sum_q N_iq V0_q = h^2). The strain energy it adds is counted as negative dissipation (the balance closes).
TEST(FluidVolumes, OverfilledVolumesRelaxAtTheStatedRate) {
  json j = water_scene("bspline2", 20);
  j["walls"] = json::array();
  j["bodies"][0]["shape"] = {{"type", "box"}, {"min", {0.1, 0.1}}, {"max", {0.9, 0.9}}};
  Solver<2> s(build_scene<2>(parse_scenario(j, "v.json")));
  auto& P = s.scene().particles;
  for (std::size_t i = 0; i < P.size(); ++i) P.F[i] = std::sqrt(2.0) * Mat<2>::Identity(), P.vol[i] = 2 * P.vol0[i];
  const double e0 = 0;  // nothing moves and nothing is stored at J >= 1
  const double dt = 1e-4, c0 = std::sqrt(1e5 / 1000), kappa = dt * c0 / (20 * 0.1);
  const int n = 40;
  for (int k = 0; k < n; ++k) s.step(dt);
  int inside = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const Vec<2>& x = P.x[i];
    // three cells clear of the body's edges: a stencil reaches 1.5 cells, its nodes' sums 1.5 more
    if (x.x() < 0.4 || x.x() > 0.6 || x.y() < 0.4 || x.y() > 0.6) continue;
    ++inside;
    EXPECT_NEAR(std::log(P.F[i].determinant()), std::log(2.0) * std::pow(1 - kappa, n), 1e-9) << i;
  }
  EXPECT_GT(inside, 0);
  EXPECT_NEAR(s.diagnostics().balance(e0), 0.0, 1e-9);
}

// Off by default: J follows the velocity gradient alone.
TEST(FluidVolumes, OffUnlessAskedFor) {
  json j = water_scene("bspline2", 0);
  EXPECT_FALSE(FluidVolumes<2>::needed(build_scene<2>(parse_scenario(j, "v.json"))));
  j["materials"][0].erase("volume_relaxation");
  EXPECT_FALSE(FluidVolumes<2>::needed(build_scene<2>(parse_scenario(j, "v.json"))));
  j["materials"][0]["volume_relaxation"] = 100;
  EXPECT_TRUE(FluidVolumes<2>::needed(build_scene<2>(parse_scenario(j, "v.json"))));
}

}  // namespace
}  // namespace dmi
