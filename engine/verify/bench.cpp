#include "engine/verify/bench.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "engine/common/error.hpp"
#include "engine/mpm/solver.hpp"
#include "engine/scenario/scenario.hpp"
#include "engine/sim/build_scene.hpp"

namespace dmi {

using nlohmann::json;

namespace {

// A square elastic block of about n particles (2 x 2 per cell), falling freely with a small drift: every
// particle goes through P2G, the grid update, G2P and the stress update each step, with no walls or contact.
Scenario block_scenario(long n, const std::string& shape, const std::string& transfer) {
  const double h = 0.05;
  const double side = std::sqrt(static_cast<double>(n) / 4.0) * h;  // 4 particles per cell
  json j{{"schema_version", 1},
         {"name", "kernel benchmark"},
         {"analysis", {{"dimension", 2}, {"plane", "strain"}, {"end_time", 1.0}, {"dt_max", 1e-3}, {"gravity", {0, -9.81}}}},
         {"mpm", {{"shape_function", shape}, {"transfer", transfer}}},
         {"grid", {{"origin", {-1.0, -1.0}}, {"size", {side + 2.0, side + 2.0}}, {"cell_size", h}}},
         {"materials", {{{"name", "soft"}, {"model", "linear_elastic"}, {"density", 1000}, {"youngs_modulus", 1e5}, {"poisson_ratio", 0.3}}}},
         {"bodies", {{{"name", "block"}, {"material", "soft"}, {"particles_per_cell", 2}, {"shape", {{"type", "box"}, {"min", {0, 0}}, {"max", {side, side}}}},
                      {"velocity", {0.1, 0.2}}}}},
         {"output", {{"vtk", false}}}};
  return parse_scenario(j, "<kernel benchmark>");
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

json to_json(const KernelBench& b) {
  return json{{"shape", b.shape}, {"transfer", b.transfer}, {"threads", b.threads}, {"particles", b.particles}, {"active_nodes", b.active_nodes},
              {"seconds_per_step", b.seconds_per_step}, {"updates_per_second", b.updates_per_second}, {"spread", b.spread},
              {"bytes_per_particle", b.bytes_per_particle}};
}

std::vector<KernelBench> kernel_bench(const BenchOptions& o, bool progress) {
  using clock = std::chrono::steady_clock;
  std::vector<KernelBench> out;
  const int max_threads = omp_get_max_threads();
  for (const auto& shape : o.shapes)
    for (const auto& transfer : o.transfers) {
      if (shape == "linear" && transfer == "apic") continue;  // APIC needs D_p > 0 (GIMP, B-splines)
      for (int t : o.threads) {
        if (t > max_threads && t > 1) continue;
        omp_set_num_threads(t);
        Solver<2> solver(build_scene<2>(block_scenario(o.particles, shape, transfer)));
        const double dt = solver.stable_time_step(1e-3);
        for (int k = 0; k < o.warmup; ++k) solver.step(dt);
        std::vector<double> per_step;
        for (int r = 0; r < o.repeats; ++r) {
          const auto t0 = clock::now();
          for (int k = 0; k < o.steps; ++k) solver.step(dt);
          per_step.push_back(std::chrono::duration<double>(clock::now() - t0).count() / o.steps);
        }
        KernelBench b;
        b.shape = shape, b.transfer = transfer, b.threads = t;
        b.particles = static_cast<long>(solver.scene().particles.size());
        b.active_nodes = static_cast<long>(solver.scene().grid->active().size());
        b.seconds_per_step = median(per_step);
        b.updates_per_second = b.particles / b.seconds_per_step;
        b.spread = (*std::max_element(per_step.begin(), per_step.end()) - *std::min_element(per_step.begin(), per_step.end())) / b.seconds_per_step;
        // Particle arrays: x, x0, v, half_size (4 vectors), F, L, C, stress (4 matrices), stress_zz, mass, vol0, vol, body,
        // id, slot; plus the material's own arrays (none for undamped linear elasticity).
        b.bytes_per_particle = 4 * sizeof(Vec<2>) + 4 * sizeof(Mat<2>) + 4 * sizeof(double) + sizeof(int) + 2 * sizeof(Index);
        out.push_back(b);
        if (progress)
          std::fprintf(stderr, "kernel %-8s %-4s %d thread(s): %.3f s/step, %.2f M updates/s (spread %.0f %%)\n", shape.c_str(), transfer.c_str(), t,
                       b.seconds_per_step, b.updates_per_second / 1e6, 100 * b.spread);
      }
    }
  omp_set_num_threads(max_threads);
  return out;
}

int bench_main(const std::vector<std::string>& cases, bool as_json, bool quick, BenchOptions o) {
  const std::vector<std::string> all = {"kernel"};
  for (const auto& c : cases)
    if (std::find(all.begin(), all.end(), c) == all.end()) throw InputError("bench: unknown case '" + c + "' (known: kernel)");
  const BenchOptions d;
  if (o.shapes.empty()) o.shapes = d.shapes;
  if (o.transfers.empty()) o.transfers = d.transfers;
  if (o.threads.empty()) o.threads = d.threads;
  if (o.particles <= 0) o.particles = quick ? 100000 : d.particles;
  if (quick) o.steps = 5, o.repeats = 3, o.warmup = 2;
  json out = json::object();
  const auto results = kernel_bench(o, !as_json);
  json rows = json::array();
  for (const auto& b : results) rows.push_back(to_json(b));
  out["kernel"] = rows;
  if (as_json) {
    std::cout << out.dump(1) << "\n";
    return 0;
  }
  std::printf("\nMPM kernel throughput (2D, linear elastic, %ld particles, median of %d x %d steps)\n", o.particles, o.repeats, o.steps);
  if (!results.empty()) std::printf("particle arrays: %.0f bytes per particle\n", results.front().bytes_per_particle);
  std::printf("%-9s %-9s %7s %12s %14s %10s %8s\n", "shape", "transfer", "threads", "s/step", "M updates/s", "speed-up", "spread");
  for (const auto& b : results) {
    double one = 0;
    for (const auto& c : results)
      if (c.shape == b.shape && c.transfer == b.transfer && c.threads == 1) one = c.seconds_per_step;
    std::printf("%-9s %-9s %7d %12.4f %14.2f %10.2f %7.0f%%\n", b.shape.c_str(), b.transfer.c_str(), b.threads, b.seconds_per_step,
                b.updates_per_second / 1e6, one > 0 ? one / b.seconds_per_step : 0.0, 100 * b.spread);
  }
  return 0;
}

}  // namespace dmi
