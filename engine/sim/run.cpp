#include "engine/sim/run.hpp"

#include "engine/sim/solid_check.hpp"

#include <omp.h>

#include <chrono>
#include <csignal>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "engine/common/error.hpp"
#include "engine/io/results_writer.hpp"
#include "engine/io/vtu.hpp"
#include "engine/mpm/solver.hpp"
#include "engine/sim/build_frame.hpp"
#include "engine/sim/build_scene.hpp"
#include "engine/sim/recorder.hpp"

namespace dmi {
namespace {

// SIGINT / SIGTERM during a run: the handler only records the signal; the step loop stops after the step in hand,
// writes what it has into results.h5.partial (complete = 0) and throws Interrupted. Previous handlers come back after.
volatile std::sig_atomic_t g_signal = 0;
extern "C" void on_signal(int sig) { g_signal = sig; }
struct SignalGuard {
  using Handler = void (*)(int);
  Handler old_int, old_term;
  SignalGuard() : old_int(std::signal(SIGINT, on_signal)), old_term(std::signal(SIGTERM, on_signal)) { g_signal = 0; }
  ~SignalGuard() {
    std::signal(SIGINT, old_int);
    std::signal(SIGTERM, old_term);
  }
};

const char* name_of(ShapeKind k) { return k == ShapeKind::linear ? "linear" : k == ShapeKind::gimp ? "gimp" : "bspline2"; }

RunInfo make_info(const Scenario& s, const RunOptions& o) {
  RunInfo info;
  info.scenario_name = s.name;
  info.scenario_file = s.source_file;
  info.scenario_json = s.source_text;
  info.scenario_expanded_json = s.expanded_text;
  info.variant = s.variant;
  info.software_version = o.software_version;
  info.dimension = s.analysis.dimension;
  for (const auto& b : s.bodies) info.body_names.push_back(b.name);
  for (const auto& m : s.materials) info.material_names.push_back(m.name);
  info.numbers["cell_size"] = s.grid.cell_size;
  info.numbers["end_time"] = s.analysis.end_time;
  info.numbers["cfl"] = s.analysis.cfl;
  info.strings["shape_function"] = name_of(s.mpm.shape);
  info.strings["transfer"] = s.mpm.transfer == TransferKind::apic ? "apic" : "flip";
  info.numbers["flip_blend"] = s.mpm.flip_blend;
  info.strings["stress_update"] = s.mpm.update == StressUpdate::usl ? "usl" : "musl";
  info.strings["plane"] = s.analysis.dimension == 3 ? "none" : s.analysis.plane == Plane::strain ? "strain" : "stress";
  info.strings["contact"] = s.contact.method == ContactMethod::multi_field ? "multi_field" : "single_field";
  if (!s.design_basis_text.empty()) info.documents["design_basis"] = s.design_basis_text;
  return info;
}

template <int D> RunOutput run(const Scenario& s, const RunOptions& o) {
  namespace fs = std::filesystem;
  const auto t0 = std::chrono::steady_clock::now();
  Solver<D> solver(build_scene<D>(s));
  Recorder<D> rec(solver, s);
  RunInfo info = make_info(s, o);
  info.numbers["particles"] = static_cast<double>(solver.scene().particles.size());

  std::unique_ptr<ResultsWriter> writer;
  std::vector<std::pair<double, std::string>> vtk_files, member_files;
  const bool files = !o.out_dir.empty();
  std::string results_path;
  if (files) {
    fs::create_directories(o.out_dir);
    if (s.output.vtk) fs::create_directories(fs::path(o.out_dir) / "fields");
    results_path = (fs::path(o.out_dir) / "results.h5").string();
    writer = std::make_unique<ResultsWriter>(results_path, info);
  }
  auto snapshot = [&]() {
    if (!files) return;
    const Snapshot snap = rec.snapshot(solver);
    writer->write_snapshot(snap);
    if (s.output.vtk) {
      char name[64];
      std::snprintf(name, sizeof name, "particles_%04zu.vtu", vtk_files.size());
      write_vtu((fs::path(o.out_dir) / "fields" / name).string(), snap);
      vtk_files.emplace_back(snap.time, name);
      if (const Frame* f = solver.scene().frame.get()) {
        std::snprintf(name, sizeof name, "members_%04zu.vtu", member_files.size());
        write_lines_vtu((fs::path(o.out_dir) / "fields" / name).string(), Recorder<D>::member_snapshot(*f));
        member_files.emplace_back(snap.time, name);
      }
    }
  };

  const double end = s.analysis.end_time;
  const double eps = 1e-12 * end;
  // The first multiple of `interval` after t (one division, whatever dt / interval is).
  auto next_after = [eps](double t, double interval) { return interval * (std::floor((t + eps) / interval) + 1); };
  rec.sample(solver, 0.0);
  snapshot();
  double next_sample = s.output.history_interval, next_snap = s.output.snapshot_interval;
  double dt_min = std::numeric_limits<double>::infinity(), dt_max = 0, courant_max = 0, j_min = solver.min_jacobian();
  Progress progress(o.progress, end, s.name);
  const SignalGuard signals;
  while (solver.time() < end - eps) {
    if (g_signal != 0) {  // stopped by the user: keep what is done, never as a complete result
      const int sig = g_signal;
      if (rec.time().empty() || rec.time().back() < solver.time()) rec.sample(solver, 0.0);
      info.strings["status"] = sig == SIGINT ? "interrupted (SIGINT)" : "interrupted (SIGTERM)";
      info.numbers["steps"] = static_cast<double>(solver.steps());
      info.numbers["wall_seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::string where = "nothing written (no output folder)";
      if (files) {
        writer->abandon(rec.time(), rec.series(), info);
        where = "partial results in " + results_path + ".partial (complete = 0)";
      }
      throw Interrupted(sig, "run interrupted by " + std::string(sig == SIGINT ? "SIGINT" : "SIGTERM") + " at step " +
                                 std::to_string(solver.steps()) + ", t = " + std::to_string(solver.time()) + " s: " + where);
    }
    const double dt = solver.stable_time_step(end - solver.time());
    courant_max = std::max(courant_max, solver.courant());
    solver.step(dt);
    rec.accumulate(solver, dt);
    dt_min = std::min(dt_min, dt);
    dt_max = std::max(dt_max, dt);
    const bool last = solver.time() >= end - eps;
    if (last || s.output.history_interval <= 0 || solver.time() >= next_sample - eps) {
      rec.sample(solver, dt);
      j_min = std::min(j_min, solver.min_jacobian());
      if (s.output.history_interval > 0) next_sample = next_after(solver.time(), s.output.history_interval);
    }
    if (!last && s.output.snapshot_interval > 0 && solver.time() >= next_snap - eps) {
      snapshot();
      next_snap = next_after(solver.time(), s.output.snapshot_interval);
    }
    progress.update(solver.time(), solver.steps(), dt);
  }
  snapshot();
  progress.finish(solver.time(), solver.steps());

  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  info.numbers["steps"] = static_cast<double>(solver.steps());
  info.numbers["wall_seconds"] = wall;
  info.numbers["dt_min"] = dt_min;
  info.numbers["dt_max"] = dt_max;
  info.numbers["courant_max"] = courant_max;   // numerical health (docs/results.md)
  info.numbers["jacobian_min"] = std::isfinite(j_min) ? j_min : 1.0;
  info.numbers["threads"] = omp_get_max_threads();
  if (solver.scene().frame) {
    info.documents["structure"] = structure_document(s, solver.scene().frame->model());
    const std::string doc = rec.peak_contact_document(*solver.scene().frame);
    if (!doc.empty()) info.documents["peak_contact"] = doc;
  }
  if (const auto* mc = solver.member_contact()) {
    const MemberContactStats& st = mc->stats();
    info.numbers["member_contact_candidates"] = static_cast<double>(st.candidates);
    info.numbers["member_contact_loaded"] = static_cast<double>(st.loaded);
    info.numbers["projection_iterations_mean"] = st.candidates > 0 ? double(st.projection_iterations) / st.candidates : 0.0;
    info.numbers["projection_iterations_max"] = st.max_projection_iterations;
  }
  if (s.solid_check.present) {
    const auto t1 = std::chrono::steady_clock::now();
    const auto it = info.documents.find("peak_contact");
    info.documents["solid_check"] = run_solid_check(s, it == info.documents.end() ? "" : it->second);
    info.numbers["solid_check_seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  }
  info.strings["status"] = "complete";
  RunOutput out;
  out.results.info = info;
  out.results.time = rec.time();
  out.results.series = rec.series();
  out.results.complete = true;
  if (files) {
    if (s.output.vtk) write_pvd((fs::path(o.out_dir) / "fields" / "particles.pvd").string(), vtk_files);
    if (s.output.vtk && !member_files.empty()) write_pvd((fs::path(o.out_dir) / "fields" / "members.pvd").string(), member_files);
    writer->finish(out.results.time, out.results.series, info);
    out.results_path = results_path;
  }
  return out;
}

// A scenario with only a solid_check (no bodies): the solid-FE load cases, no time stepping.
RunOutput run_solid_only(const Scenario& s, const RunOptions& o) {
  namespace fs = std::filesystem;
  const auto t0 = std::chrono::steady_clock::now();
  RunInfo info = make_info(s, o);
  RunOutput out;
  info.documents["solid_check"] = run_solid_check(s, "");
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  info.numbers["steps"] = 0;
  info.numbers["wall_seconds"] = wall;
  info.numbers["solid_check_seconds"] = wall;
  info.strings["status"] = "complete";
  out.results.info = info;
  out.results.complete = true;
  if (!o.out_dir.empty()) {
    fs::create_directories(o.out_dir);
    out.results_path = (fs::path(o.out_dir) / "results.h5").string();
    ResultsWriter writer(out.results_path, info);
    writer.finish({}, {}, info);
  }
  return out;
}

}  // namespace

RunOutput run_scenario(const Scenario& s, const RunOptions& o) {
  if (o.threads > 0) omp_set_num_threads(o.threads);
  if (s.bodies.empty()) return run_solid_only(s, o);
  return s.analysis.dimension == 2 ? run<2>(s, o) : run<3>(s, o);
}

}  // namespace dmi
