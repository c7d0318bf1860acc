#include "verify/bench.hpp"

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
double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

json block_json(long n, const std::string& shape, const std::string& transfer, int dim = 2) {
  const double h = 0.05;
  if (dim == 3) {  // a cube, 2 x 2 x 2 particles per cell
    const double side = std::cbrt(static_cast<double>(n) / 8.0) * h;
    return json{{"schema_version", 1},
                {"name", "kernel benchmark (3D)"},
                {"analysis", {{"dimension", 3}, {"end_time", 1.0}, {"dt_max", 1e-3}, {"gravity", {0, -9.81, 0}}}},
                {"mpm", {{"shape_function", shape}, {"transfer", transfer}}},
                {"grid", {{"origin", {-0.5, -0.5, -0.5}}, {"size", {side + 1.0, side + 1.0, side + 1.0}}, {"cell_size", h}}},
                {"materials", {{{"name", "soft"}, {"model", "linear_elastic"}, {"density", 1000}, {"youngs_modulus", 1e5}, {"poisson_ratio", 0.3}}}},
                {"bodies", {{{"name", "block"}, {"material", "soft"}, {"particles_per_cell", 2},
                             {"shape", {{"type", "box"}, {"min", {0, 0, 0}}, {"max", {side, side, side}}}}, {"velocity", {0.1, 0.2, 0.05}}}}},
                {"output", {{"vtk", false}}}};
  }
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
  return j;
}


// Median per-step wall time of a scene (s): warm-up steps, then 3 repeats of `steps` steps.
double step_time(const Scenario& s, int steps) {
  using clock = std::chrono::steady_clock;
  Solver<2> solver(build_scene<2>(s));
  const double dt = solver.stable_time_step(1e-3);
  for (int k = 0; k < 3; ++k) solver.step(dt);
  std::vector<double> v;
  for (int r = 0; r < 3; ++r) {
    const auto t0 = clock::now();
    for (int k = 0; k < steps; ++k) solver.step(dt);
    v.push_back(std::chrono::duration<double>(clock::now() - t0).count() / steps);
  }
  return median(v);
}


}  // namespace

Scenario block_scenario(long n, const std::string& shape, const std::string& transfer, int dim) {
  return parse_scenario(block_json(n, shape, transfer, dim), "<kernel benchmark>");
}

json to_json(const KernelBench& b) {
  return json{{"shape", b.shape}, {"transfer", b.transfer}, {"threads", b.threads}, {"particles", b.particles}, {"active_nodes", b.active_nodes},
              {"seconds_per_step", b.seconds_per_step}, {"updates_per_second", b.updates_per_second}, {"spread", b.spread},
              {"bytes_per_particle", b.bytes_per_particle}};
}

// The block with a small frame out of the particles' reach (member contact culls it), or on a grid 10 times wider
// and taller (the active grid: empty space must not cost steps).
json skip_block_bench(bool progress) {
  const long n = 100000;
  const json base = block_json(n, "bspline2", "flip");
  const double side = std::sqrt(n / 4.0) * 0.05;
  json framed = base;
  framed["materials"].push_back({{"name", "steel"}, {"model", "linear_elastic"}, {"density", 7850}, {"youngs_modulus", 2e11}, {"poisson_ratio", 0.3}});
  framed["structure"] = {{"self_weight", false}, {"integrator", "newmark"},
                         {"nodes", {{{"name", "A"}, {"position", {side + 0.8, -0.8}}}, {{"name", "B"}, {"position", {side + 0.8, 0.2}}}}},
                         {"members", {{{"name", "post"}, {"start", "A"}, {"end", "B"}, {"material", "steel"}, {"elements", 4},
                                       {"section", {{"type", "rectangle"}, {"width", 0.1}, {"depth", 0.1}}}}}},
                         {"supports", {{{"node", "A"}, {"type", "fixed"}}}}};
  json wide = base;
  wide["grid"]["size"] = {10 * (side + 2.0), 10 * (side + 2.0)};
  const double t0 = step_time(parse_scenario(base, "<bench>"), 10);
  const double tf = step_time(parse_scenario(framed, "<bench>"), 10);
  const double tw = step_time(parse_scenario(wide, "<bench>"), 10);
  if (progress) std::fprintf(stderr, "skip: block %.4f s/step, with an idle frame %.4f, on a 10x wider grid %.4f\n", t0, tf, tw);
  return json{{"particles", n}, {"block_s_per_step", t0}, {"idle_frame_s_per_step", tf}, {"idle_frame_ratio", tf / t0},
              {"grid_10x_s_per_step", tw}, {"grid_10x_ratio", tw / t0}};
}

namespace {

template <int D> std::vector<KernelBench> kernel_bench_d(const BenchOptions& o, bool progress) {
  using clock = std::chrono::steady_clock;
  std::vector<KernelBench> out;
  const int max_threads = omp_get_max_threads();
  for (const auto& shape : o.shapes)
    for (const auto& transfer : o.transfers) {
      if (shape == "linear" && transfer == "apic") continue;  // APIC needs D_p > 0 (GIMP, B-splines)
      for (int t : o.threads) {
        if (t > max_threads && t > 1) continue;
        omp_set_num_threads(t);
        Solver<D> solver(build_scene<D>(block_scenario(o.particles, shape, transfer, D)));
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
        b.bytes_per_particle = Particles<D>::kBytesPerParticle;
        out.push_back(b);
        if (progress)
          std::fprintf(stderr, "kernel %dD %-8s %-4s %d thread(s): %.3f s/step, %.2f M updates/s (spread %.0f %%)\n", D, shape.c_str(), transfer.c_str(), t,
                       b.seconds_per_step, b.updates_per_second / 1e6, 100 * b.spread);
      }
    }
  omp_set_num_threads(max_threads);
  return out;
}

}  // namespace

std::vector<KernelBench> kernel_bench(const BenchOptions& o, bool progress) {
  return o.dimension == 3 ? kernel_bench_d<3>(o, progress) : kernel_bench_d<2>(o, progress);
}

namespace {

// The main job: run time against error.
void print_dam(const json& out) {
  if (!out.contains("dam")) return;
  const json& d = out["dam"];
  std::printf("\nThe main job: run time against error (%s)\n", d["reference"].get<std::string>().c_str());
  std::printf("%-12s %8s %9s %14s %14s %16s\n", "dam", "cell m", "wall s", "shear error", "moment error", "contact error");
  auto pct = [](const json& e) { return e.is_number() ? std::to_string(100 * e.get<double>()).substr(0, 5) + " %" : std::string("n/a"); };
  for (const auto& p : d["points"])
    std::printf("%-12s %8.4f %9.2f %14s %14s %16s%s\n", p["group"].get<std::string>().c_str(), p["cell_size"].get<double>(),
                p["wall_seconds"].get<double>(), pct(p["base_shear_error"]).c_str(), pct(p["base_moment_error"]).c_str(),
                pct(p["contact_force_error"]).c_str(), p["front"].get<bool>() ? "  (front)" : "");
  for (const char* g : {"bare", "with buffer"})
    for (const char* k : {"base_shear", "base_moment", "contact_force"})
      std::printf("  %s, %s: %s\n", g, k, d[g][k]["statement"].get<std::string>().c_str());
}

void print_small(const json& out) {
  if (!out.contains("small")) return;
  const json& sm = out["small"];
  std::printf("\nSmall scenes against the kernel (1 thread; kernel: %ld particles, %.1f ns per particle-step)\n",
              sm["kernel_particles"].get<long>(), sm["kernel_ns_per_particle_step"].get<double>());
  for (const auto& v : sm["variants"]) {
    std::printf("%s at h %g m: %.0f particles, %.0f steps, loop %.2f s, %.1f ns per particle-step = %.2f x kernel\n",
                v["variant"].get<std::string>().c_str(), v["cell_size"].get<double>(), v["particles"].get<double>(), v["steps"].get<double>(), v["loop_seconds"].get<double>(), v["ns_per_particle_step"].get<double>(),
                v["ratio_to_kernel"].get<double>());
    for (const auto& [k, ns] : v["phases_ns"].items()) std::printf("  %-24s %8.1f ns\n", k.c_str(), ns.get<double>());
    std::printf("  rigid constraint passes per step: %.1f\n", v["rigid_passes_per_step"].get<double>());
  }
}

void print_kernel(const std::vector<KernelBench>& results, const BenchOptions& o) {
  if (results.empty()) return;
  std::printf("\nMPM kernel throughput (%dD, linear elastic, %ld particles, median of %d x %d steps)\n", o.dimension, o.particles, o.repeats, o.steps);
  std::printf("particle arrays: %.0f bytes per particle\n", results.front().bytes_per_particle);
  std::printf("%-9s %-9s %7s %12s %14s %10s %8s\n", "shape", "transfer", "threads", "s/step", "M updates/s", "speed-up", "spread");
  for (const auto& b : results) {
    double one = 0;
    for (const auto& c : results)
      if (c.shape == b.shape && c.transfer == b.transfer && c.threads == 1) one = c.seconds_per_step;
    std::printf("%-9s %-9s %7d %12.4f %14.2f %10.2f %7.0f%%\n", b.shape.c_str(), b.transfer.c_str(), b.threads, b.seconds_per_step,
                b.updates_per_second / 1e6, one > 0 ? one / b.seconds_per_step : 0.0, 100 * b.spread);
  }
}

void print_a5(const json& out) {
  if (!out.contains("a5")) return;
  const json& a = out["a5"];
  std::printf("\nLin & Yang verification 1: error (NRMS vs %s) against wall time; * = Pareto front\n", a["reference"].get<std::string>().c_str());
  std::printf("%-15s %8s %-17s %10s %10s\n", "frame", "elements", "time step", "error", "wall s");
  for (const auto& p : a["points"])
    std::printf("%-15s %8d %-17s %10.4f %10.3f %s%s\n", p["integrator"].get<std::string>().c_str(), p["elements"].get<int>(),
                p["time_step"].get<std::string>().c_str(), p["error"].get<double>(), p["wall_seconds"].get<double>(), p["front"].get<bool>() ? "*" : "",
                p["paper_setup"].get<bool>() ? "  (paper set-up)" : "");
  std::printf("paper set-up %.3f s, fastest as accurate (%s, %d elements, %s) %.3f s (medians of 3): speed-up %.1fx\n",
              a["paper_wall_median_s"].get<double>(), a["fastest_as_accurate"]["integrator"].get<std::string>().c_str(),
              a["fastest_as_accurate"]["elements"].get<int>(), a["fastest_as_accurate"]["time_step"].get<std::string>().c_str(),
              a["fastest_wall_median_s"].get<double>(), a["speed_up"].get<double>());
}

void print_a6(const json& out) {
  if (!out.contains("a6")) return;
  std::printf("\nLin & Yang verification 2, beam-column members: wall time vs depth (median of 3)\n%8s %10s %8s %12s\n", "h/L", "wall s", "steps", "proj. iter.");
  for (const auto& r : out["a6"]["rows"])
    std::printf("%8.3f %10.3f %8ld %12.0f\n", r["h_over_L"].get<double>(), r["wall_seconds"].get<double>(), r["steps"].get<long>(),
                r["projection_iterations_max"].get<double>());
  std::printf("ratio h/L 0.025 : 0.2 = %.2f\n", out["a6"]["ratio_slender_to_thick"].get<double>());
  std::printf("\nLin & Yang verification 2 at h/L 0.025: error against wall time (reference: %s), Pareto front\n%-9s %4s %8s %-16s %10s %10s\n",
              out["a6"]["reference"].get<std::string>().c_str(), "frame", "el.", "cell m", "time step", "NRMS err", "wall s");
  std::vector<const json*> front;
  for (const auto& p : out["a6"]["points"])
    if (p["front"].get<bool>()) front.push_back(&p);
  std::sort(front.begin(), front.end(), [](const json* a, const json* b) { return (*a)["wall_seconds"] < (*b)["wall_seconds"]; });
  for (const json* p : front)
    std::printf("%-9s %4d %8.4f %-16s %10.4f %10.3f\n", (*p)["integrator"].get<std::string>().c_str(), (*p)["elements"].get<int>(),
                (*p)["cell_size"].get<double>(), (*p)["time_step"].get<std::string>().c_str(), (*p)["error"].get<double>(),
                (*p)["wall_seconds"].get<double>());
}

// The bar and the colliding disks: the Pareto front of error against wall time.
void print_fronts(const json& out) {
  for (const char* c : {"bar", "disks"}) {
    if (!out.contains(c)) continue;
    std::printf("\n%s: error (%s) against wall time, Pareto front only (all points: --json)\n", c, out[c]["reference"].get<std::string>().c_str());
    std::vector<const json*> front;
    for (const auto& p : out[c]["points"])
      if (p["front"].get<bool>()) front.push_back(&p);
    std::sort(front.begin(), front.end(), [](const json* a, const json* b) { return (*a)["wall_seconds"] < (*b)["wall_seconds"]; });
    for (const json* p : front)
      std::printf("%-22s h %-7g %s error %.3e  wall %.3f s\n", (*p)["group"].get<std::string>().c_str(), (*p)["cell_size"].get<double>(),
                  p->contains("cfl") ? ("cfl " + std::to_string((*p)["cfl"].get<double>()).substr(0, 3)).c_str() : "", (*p)["error"].get<double>(),
                  (*p)["wall_seconds"].get<double>());
  }
}

void print_skip(const json& out) {
  if (!out.contains("skip")) return;
  const json& s = out["skip"];
  std::printf("\nSkip what a scene does not need (medians of 3)\n");
  std::printf("frame on the dam: Newmark %ld steps %.2f s, explicit %ld steps %.2f s (x%.1f); peak base shear differs by %.2f %%\n",
              s["implicit_frame"]["newmark_steps"].get<long>(), s["implicit_frame"]["newmark_wall_s"].get<double>(),
              s["implicit_frame"]["explicit_steps"].get<long>(), s["implicit_frame"]["explicit_wall_s"].get<double>(),
              s["implicit_frame"]["wall_ratio_explicit_to_newmark"].get<double>(), 100 * s["implicit_frame"]["peak_difference"].get<double>());
  std::printf("files: no snapshots %.2f s, 15 snapshots + .vtu %.2f s (ratio %.3f)\n", s["output_cost"]["no_snapshots_wall_s"].get<double>(),
              s["output_cost"]["snapshots_every_10ms_wall_s"].get<double>(), s["output_cost"]["ratio"].get<double>());
  std::printf("100 k-particle block: idle frame out of reach x%.3f per step, grid 10x wider and taller x%.3f per step\n",
              s["block"]["idle_frame_ratio"].get<double>(), s["block"]["grid_10x_ratio"].get<double>());
}

}  // namespace

int bench_main(const std::vector<std::string>& cases, bool as_json, bool quick, BenchOptions o) {
  const std::vector<std::string> all = {"kernel", "a5", "a6", "bar", "disks", "skip", "dam", "small"};
  for (const auto& c : cases)
    if (std::find(all.begin(), all.end(), c) == all.end()) throw InputError("bench: unknown case '" + c + "' (known: kernel, a5, a6, bar, disks, skip, dam, small)");
  auto wanted = [&](const char* c) { return cases.empty() || std::find(cases.begin(), cases.end(), c) != cases.end(); };
  const BenchOptions d;
  if (o.shapes.empty()) o.shapes = d.shapes;
  if (o.transfers.empty()) o.transfers = d.transfers;
  if (o.threads.empty()) o.threads = d.threads;
  if (o.particles <= 0) o.particles = quick ? 100000 : d.particles;
  if (quick) o.steps = 5, o.repeats = 3, o.warmup = 2;
  json out = json::object();
  out["threads_available"] = omp_get_max_threads();
  std::vector<KernelBench> results;
  if (wanted("kernel")) {
    results = kernel_bench(o, !as_json);
    json rows = json::array();
    for (const auto& b : results) rows.push_back(to_json(b));
    out["kernel"] = rows;
  }
  if (wanted("a5")) out["a5"] = bench_a5(!as_json);
  if (wanted("a6")) out["a6"] = bench_a6(!as_json);
  if (wanted("bar")) out["bar"] = bench_bar(!as_json);
  if (wanted("disks")) out["disks"] = bench_disks(!as_json);
  if (wanted("skip")) {
    out["skip"] = bench_skip(!as_json);
    out["skip"]["block"] = skip_block_bench(!as_json);
  }
  if (wanted("dam")) out["dam"] = bench_dam(!as_json, quick);
  if (wanted("small")) out["small"] = bench_small(!as_json, quick);
  if (as_json) {
    std::cout << out.dump(1) << "\n";
    return 0;
  }
  print_dam(out);
  print_small(out);
  print_kernel(results, o);
  print_a5(out);
  print_a6(out);
  print_fronts(out);
  print_skip(out);
  return 0;
}

}  // namespace dmi
