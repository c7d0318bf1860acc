// `damimpact bench`: performance figures that are printed, never asserted (docs/performance.md).
// Kernel throughput: a freely falling elastic block of N particles stepped in memory; per-step time is the
// median over repeats of (time of S steps) / S after warm-up steps, so set-up and first-touch costs cancel.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace dmi {

struct KernelBench {
  std::string shape, transfer;
  int threads = 1;
  long particles = 0, active_nodes = 0;
  double seconds_per_step = 0;   // median
  double updates_per_second = 0; // particles / seconds_per_step
  double spread = 0;             // (max - min) / median of the repeats
  double bytes_per_particle = 0; // particle arrays (all fields, per particle)
};

struct BenchOptions {
  long particles = 1000000;
  int steps = 10, warmup = 3, repeats = 3;
  std::vector<int> threads = {1, 2};
  std::vector<std::string> shapes = {"linear", "gimp", "bspline2"}, transfers = {"flip", "apic"};
  int dimension = 2;  // the kernel block: a square (2 x 2 particles per cell) or a cube (2 x 2 x 2)
};

// The kernel benchmark's scene: a square linear-elastic block of about n particles (2 x 2 per cell, h = 0.05 m),
// falling freely with a small drift, on a grid 1 m wider on every side. Also used by bench/kernels.cpp.
struct Scenario;
Scenario block_scenario(long n, const std::string& shape, const std::string& transfer, int dim = 2);

std::vector<KernelBench> kernel_bench(const BenchOptions& o, bool progress);
nlohmann::json to_json(const KernelBench& b);

// Lin & Yang verification 1 run time vs error (a Pareto front), Lin & Yang verification 2 cost vs depth, scene costs that should vanish
// (bench_cases.cpp), and the block with an idle frame or a 10x grid (bench.cpp).
nlohmann::json bench_a5(bool progress);
nlohmann::json bench_a6(bool progress);
nlohmann::json bench_bar(bool progress);
nlohmann::json bench_disks(bool progress);
nlohmann::json bench_skip(bool progress);
// The main job's run time against its error: the concrete dam struck by a boulder, bare and with a tyre buffer, at
// cells 0.08 m down to 0.01 m by halving (to 0.02 m with quick); errors against the Richardson value of the three
// finest cells.
nlohmann::json bench_dam(bool progress, bool quick);
nlohmann::json skip_block_bench(bool progress);
// Small scenes against the kernel: the demo's variants on one thread, wall time per particle-step by phase, and the
// kernel's (1 M particles; 100 k with quick) from the same run.
nlohmann::json bench_small(bool progress, bool quick);

// `damimpact bench [CASE...] [--json] [--quick] [--particles N] [--shape S]... [--transfer T]... [--threads N]...`;
// cases: kernel, a5, a6, skip (default all). Empty lists keep the defaults of BenchOptions. Returns the exit code.
int bench_main(const std::vector<std::string>& cases, bool json, bool quick, BenchOptions o);

}  // namespace dmi
