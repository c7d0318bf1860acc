#include "engine/sim/run.hpp"

#include "engine/scenario/design_basis_json.hpp"
#include "engine/sim/solid_check.hpp"

#include <omp.h>

#include <cctype>
#include <algorithm>
#include <chrono>
#include <numbers>
#include <csignal>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <sstream>
#include <exception>
#include <mutex>
#include <optional>

#include "engine/common/error.hpp"
#include "engine/io/results_writer.hpp"
#include "engine/io/vtu.hpp"
#include "engine/mpm/solver.hpp"
#include "engine/sim/build_frame.hpp"
#include "engine/structure/assembled_system.hpp"
#include "engine/sim/build_scene.hpp"
#include "engine/sim/checkpoint.hpp"
#include "engine/sim/recorder.hpp"
#include "engine/sim/run_estimate.hpp"

namespace dmi {
namespace {

// SIGINT / SIGTERM during a run: the handler only records the signal; the step loop stops after the step in hand,
// writes what it has into results.h5.partial (complete = 0) and throws Interrupted. Previous handlers come back after.
volatile std::sig_atomic_t g_signal = 0;
extern "C" void on_signal(int sig) { g_signal = sig; }

constexpr const char* kCheckpointName = "checkpoint.dmi";

// Stops the run between steps (a signal, or --stop-after): first the checkpoint (the state exactly as the next step
// would read it), then the histories so far into results.h5.partial (complete = 0), then Interrupted. An older
// complete results.h5 in the folder is never replaced.
template <int D>
[[noreturn]] void stop_run(int sig, const Solver<D>& solver, Recorder<D>& rec, RunInfo& info, ResultsWriter* writer,
                           const std::string& results_path, double wall, const std::function<void()>& checkpoint,
                           const std::string& ckpt) {
  const std::string why = sig == SIGINT ? "SIGINT" : sig == SIGTERM ? "SIGTERM" : "--stop-after " + std::to_string(solver.steps());
  std::string where = "nothing written (no output folder)";
  if (writer) {
    checkpoint();
    if (rec.time().empty() || rec.time().back() < solver.time()) rec.sample(solver, 0.0);
    info.stats.status = sig == 0 ? "stopped (" + why + ")" : "interrupted (" + why + ")";
    info.stats.steps = static_cast<double>(solver.steps());
    info.stats.wall_seconds = wall;
    writer->abandon(rec.time(), rec.series(), info);
    where = "partial results in " + results_path + ".partial (complete = 0), checkpoint " + ckpt +
            "; continue with the same command and --restart";
  }
  throw Interrupted(sig, std::string(sig == 0 ? "run stopped by " : "run interrupted by ") + why + " at step " +
                             std::to_string(solver.steps()) + ", t = " + std::to_string(solver.time()) + " s: " + where);
}

// Disk full: refuse before the long run when the folder cannot hold the snapshots (HDF5 + .vtu copies) and a
// checkpoint, estimated from the particle count. Bytes per particle and snapshot: position, displacement, velocity
// (3 D doubles), stress (6), von Mises, volume (2), body and material (2 x 4 bytes); the .vtu copy about the same.
void check_disk_space(const Scenario& s, std::size_t particles, const std::string& dir) {
  const double snaps = s.output.snapshot_interval > 0 ? std::floor(s.analysis.end_time / s.output.snapshot_interval) + 2 : 2;
  const double d = s.analysis.dimension, per = (3 * d + 8) * 8 + 8;
  const double ckpt = particles * (8 * d * d + 6 * d + 12) * 8.0;
  const double need = snaps * particles * per * (s.output.vtk ? 2 : 1) + ckpt + (1 << 20);
  std::error_code ec;
  const auto sp = std::filesystem::space(dir, ec);
  if (ec) return;  // unknown: the writes themselves report a full disk
  if (static_cast<double>(sp.available) < need) {
    char msg[256];
    std::snprintf(msg, sizeof msg, "needs about %.0f MB (%.0f snapshots of %zu particles%s and a checkpoint), %.0f MB free",
                  need / 1048576, snaps, particles, s.output.vtk ? ", HDF5 and .vtu" : "", double(sp.available) / 1048576);
    throw InputError(dir + ": not enough disk space for the run's output: " + msg +
                     " (free space, or raise /output/snapshot_interval)");
  }
}

// Largest CFL factor at which every run of `validate --stress` cfl_sweep stayed stable (free-free bar and colliding
// disks, CFL 0.3-1.0; docs/reliability.md): uGIMP FLIP 0.5, uGIMP APIC 0.7, B-spline FLIP 0.8, B-spline APIC 0.9.
// Linear shapes showed no stable factor on the bar (cell-crossing noise); 0.5, the default, is kept for them.
double stable_cfl_limit(ShapeKind shape, TransferKind transfer) {
  const bool apic = transfer == TransferKind::apic;
  switch (shape) {
    case ShapeKind::gimp: return apic ? 0.7 : 0.5;
    case ShapeKind::bspline2: return apic ? 0.9 : 0.8;
    default: return 0.5;
  }
}

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
  info.stats.cell_size = s.grid.cell_size;
  info.stats.end_time = s.analysis.end_time;
  info.stats.cfl = s.analysis.cfl;
  info.stats.shape_function = name_of(s.mpm.shape);
  info.stats.transfer = s.mpm.transfer == TransferKind::apic ? "apic" : "flip";
  info.stats.flip_blend = s.mpm.flip_blend;
  info.stats.stress_update = s.mpm.update == StressUpdate::usl ? "usl" : "musl";
  info.stats.plane = s.analysis.dimension == 3 ? "none" : s.analysis.plane == Plane::strain ? "strain" : "stress";
  info.stats.contact = s.contact.method == ContactMethod::multi_field ? "multi_field" : "single_field";
  info.design_basis = s.design_basis;
  return info;
}

// A run that cannot finish is refused before anything is written: its step count and its wall time on one core
// (engine/sim/run_estimate.hpp) against /analysis/max_steps and /analysis/max_wall_hours. Both are first guesses,
// not bounds.
// Particles at the end of the run: those built, and those an inflow will create.
template <int D> double final_particles(const Scene<D>& sc) {
  double n = static_cast<double>(sc.particles.size());
  for (const Inflow<D>& in : sc.inflows) n += in.hydrograph.particle_estimate(in.spacing);
  return n;
}

void save_peak_snapshot(StateWriter& w, const std::optional<Snapshot>& s, double force) {
  w.put(force), w.put(static_cast<std::uint8_t>(s.has_value()));
  if (!s) return;
  w.put(s->time), w.put(s->step), w.put(s->dim), w.put(static_cast<std::uint64_t>(s->count));
  w.put(s->position), w.put(s->displacement), w.put(s->velocity), w.put(s->stress), w.put(s->von_mises), w.put(s->volume);
  w.put(s->body), w.put(s->material);
}

void load_peak_snapshot(StateReader& r, std::optional<Snapshot>& s, double& force) {
  std::uint8_t has = 0;
  r.get(force), r.get(has);
  s.reset();
  if (!has) return;
  Snapshot& p = s.emplace();
  std::uint64_t count = 0;
  r.get(p.time), r.get(p.step), r.get(p.dim), r.get(count);
  p.count = static_cast<std::size_t>(count);
  r.get(p.position), r.get(p.displacement), r.get(p.velocity), r.get(p.stress), r.get(p.von_mises), r.get(p.volume);
  r.get(p.body), r.get(p.material);
}

template <int D> RunEstimate step_budget(const Solver<D>& solver, const Scenario& s) {
  const double dt0 = solver.stable_time_step(s.analysis.end_time);
  const double np = final_particles(solver.scene());
  const RunEstimate guess = estimate_run(solver, s, dt0, np);
  const double est = guess.steps, wall = guess.wall_s;
  std::ostringstream end, os;
  end << s.analysis.end_time;
  os.precision(3);
  if (!(dt0 > 0) || !std::isfinite(dt0))
    os << "a run with a first step above 0 s (it is " << dt0 << " s: a speed or wave speed far out of range)";
  else if (!(est <= s.analysis.max_steps))
    os << "a run of at most /analysis/max_steps = " << s.analysis.max_steps << " steps: at its first step (dt = " << dt0
       << " s) it needs about " << est << " steps; shorten end_time or raise /analysis/max_steps";
  else if (!(wall <= 3600 * s.analysis.max_wall_hours))
    os << "a run of at most /analysis/max_wall_hours = " << s.analysis.max_wall_hours << " h: about " << est << " steps of " << np
       << " particles take about " << wall / 3600 << " h on one core by a first guess (docs/performance.md); shorten end_time, coarsen the "
       << "grid or raise /analysis/max_wall_hours";
  else
    return {est, wall};
  throw InputError(s.message_source(), "/analysis/end_time", end.str(), os.str());
}

// The members' three lowest natural periods (s) as frame_period_1..3 (fewer for a frame with fewer free DOFs; none
// above the dense eigen solve's size).
template <class F> void record_periods(const F& f, RunInfo& info) {
  if (f.ndof() > AssembledSystem::kModalDenseMax) return;
  std::vector<double> w;
  for (int n = std::min(3, f.ndof()); n > 0 && w.empty(); --n) {
    try {
      w = f.natural_frequencies(n);
    } catch (const std::invalid_argument&) {  // fewer free DOFs than asked for
    }
  }
  info.stats.frame_periods.clear();
  for (double wk : w) info.stats.frame_periods.push_back(2 * std::numbers::pi / wk);
}

// One run: the solver and its recorder, the step loop, results.h5 with its snapshots (periodic, and one at the member
// contact's peak), the checkpoint, and the RunInfo written at the end.
template <int D> class RunDriver {
 public:
  RunDriver(const Scenario& s, const RunOptions& o)
      : s_(s), o_(o), solver_(build_scene<D>(s)), rec_(solver_, s), info_(make_info(s, o)), files_(!o.out_dir.empty()),
        fingerprint_(scenario_fingerprint(s)), end_(s.analysis.end_time), eps_(1e-12 * s.analysis.end_time) {}

  RunOutput execute() {
    describe();
    const InterruptScope signals;  // SIGINT and SIGTERM stop the run cleanly from before its partial results file exists
    open_output();
    if (!o_.restart) start();
    Progress progress(o_.progress, end_, s_.name);
    first_step_ = solver_.steps();
    solver_.profile(o_.profile);
    last_ckpt_ = Clock::now();
    // One thread below kParallelScene particles (re-checked as an inflow adds them); results do not depend on it. The
    // calling thread's count is restored however the run ends (a sweep runs its next case on the same thread).
    requested_ = omp_get_max_threads();
    const RestoreThreads restore{requested_};
    choose_threads();
    while (solver_.time() < end_ - eps_) step(progress);
    write_peak();
    snapshot();
    progress.finish(solver_.time(), solver_.steps());
    record_end();
    return finish();
  }

 private:
  using Clock = std::chrono::steady_clock;
  struct RestoreThreads {
    int n;
    ~RestoreThreads() { omp_set_num_threads(n); }
  };

  // The scene's particles and periods, the CFL factor used and the first guess of the run's cost.
  void describe() {
    info_.stats.particles = static_cast<double>(solver_.scene().particles.size());
    if (const auto* f = solver_.scene().frame.get()) record_periods(*f, info_);
    // A CFL factor above the scheme's measured stability limit is reduced to it, with a message (docs/reliability.md).
    if (const double lim = stable_cfl_limit(s_.mpm.shape, s_.mpm.transfer); s_.analysis.cfl > lim && !s_.mpm.allow_unstable_cfl) {
      solver_.scene().options.cfl = lim;
      char msg[256];
      std::snprintf(msg, sizeof msg, "/analysis/cfl = %g is above the stable limit %g measured for %s %s; the run uses %g", s_.analysis.cfl,
                    lim, name_of(s_.mpm.shape), s_.mpm.transfer == TransferKind::apic ? "APIC" : "FLIP", lim);
      info_.stats.notes = msg;
      info_.stats.cfl_used = lim;
      if (o_.progress != ProgressMode::quiet) std::fprintf(stderr, "damimpact: note: %s\n", msg);
    }
    if (!o_.restart) {
      const RunEstimate e = step_budget(solver_, s_);
      info_.stats.steps_estimate = e.steps, info_.stats.wall_estimate_s = e.wall_s;
    }
  }

  // The output folder and results.h5: new, or resumed with the state of the checkpoint and the partial results up to it.
  void open_output() {
    namespace fs = std::filesystem;
    if (o_.restart && !files_) throw InputError("--restart needs the output folder of the run to continue (-o)");
    if (files_) {
      fs::create_directories(o_.out_dir);
      if (s_.output.vtk) fs::create_directories(fs::path(o_.out_dir) / "fields");
      results_path_ = (fs::path(o_.out_dir) / "results.h5").string();
      ckpt_ = (fs::path(o_.out_dir) / kCheckpointName).string();
      if (!o_.restart) check_disk_space(s_, static_cast<std::size_t>(final_particles(solver_.scene())), o_.out_dir);
    }
    if (o_.restart) {
      StateReader r(read_checkpoint(ckpt_, D, fingerprint_), ckpt_);
      solver_.load_state(r);
      rec_.load_state(r);
      loop_.load(r);
      load_peak_snapshot(r, peak_snap_, peak_snapped_);
      if (!r.at_end()) r.fail("unread bytes after the step-loop state");
      writer_ = std::make_unique<ResultsWriter>(results_path_, info_, ResultsWriter::Resume{loop_.snapshots});
    } else if (files_) {
      std::error_code ec;
      fs::remove(ckpt_, ec);  // a checkpoint of an earlier run in this folder no longer matches its partial results
      writer_ = std::make_unique<ResultsWriter>(results_path_, info_);
    }
  }

  // A new run's first sample and snapshot.
  void start() {
    rec_.sample(solver_, 0.0);
    snapshot();
    loop_.next_sample = s_.output.history_interval, loop_.next_snap = s_.output.snapshot_interval;
    loop_.dt_min = std::numeric_limits<double>::infinity(), loop_.dt_max = 0, loop_.courant_max = 0, loop_.j_min = solver_.min_jacobian();
  }

  // The first multiple of `interval` after t (one division, whatever dt / interval is).
  double next_after(double t, double interval) const { return interval * (std::floor((t + eps_) / interval) + 1); }

  // One step and what follows it: histories, snapshots, progress, profile and checkpoint.
  void step(Progress& progress) {
    if (solver_.steps() % 64 == 0) choose_threads();
    const bool stop = o_.stop_after_steps > 0 && solver_.steps() >= o_.stop_after_steps && solver_.steps() > first_step_;
    if (g_signal != 0 || stop)
      stop_run(g_signal, solver_, rec_, info_, writer_.get(), results_path_, wall_now(), [this] { checkpoint(); }, ckpt_);
    const auto tp0 = o_.profile ? Clock::now() : Clock::time_point{};
    const double dt = solver_.stable_time_step(end_ - solver_.time());
    loop_.courant_max = std::max(loop_.courant_max, solver_.courant());
    const auto tp1 = o_.profile ? Clock::now() : tp0;
    solver_.step(dt);
    const auto tp2 = o_.profile ? Clock::now() : tp0;
    rec_.accumulate(solver_, dt);
    track_peak();
    loop_.dt_min = std::min(loop_.dt_min, dt);
    loop_.dt_max = std::max(loop_.dt_max, dt);
    const bool last = solver_.time() >= end_ - eps_;
    if (last || s_.output.history_interval <= 0 || solver_.time() >= loop_.next_sample - eps_) {
      rec_.sample(solver_, dt);
      loop_.j_min = std::min(loop_.j_min, solver_.min_jacobian());
      if (s_.output.history_interval > 0) loop_.next_sample = next_after(solver_.time(), s_.output.history_interval);
    }
    if (!last && s_.output.snapshot_interval > 0 && solver_.time() >= loop_.next_snap - eps_) {
      snapshot();
      loop_.next_snap = next_after(solver_.time(), s_.output.snapshot_interval);
    }
    progress.update(solver_.time(), solver_.steps(), dt);
    if (o_.profile) {
      const auto tp3 = Clock::now();
      profile_time_step_ += std::chrono::duration<double>(tp1 - tp0).count();
      profile_recorder_ += std::chrono::duration<double>(tp3 - tp2).count();
    }
    if (files_ && !last && o_.checkpoint_every > 0 && std::chrono::duration<double>(Clock::now() - last_ckpt_).count() >= o_.checkpoint_every) {
      checkpoint();
      last_ckpt_ = Clock::now();
    }
  }

  void choose_threads() {
    const int t = static_cast<Index>(solver_.scene().particles.size()) >= kParallelScene ? requested_ : 1;
    if (t != omp_get_max_threads()) omp_set_num_threads(t);
    used_ = std::max(used_, t);
  }

  double wall_now() const { return loop_.wall_seconds + std::chrono::duration<double>(Clock::now() - t0_).count(); }

  void snapshot() {
    namespace fs = std::filesystem;
    if (!files_) return;
    const Snapshot snap = rec_.snapshot(solver_);
    writer_->write_snapshot(snap);
    ++loop_.snapshots;
    if (!s_.output.vtk) return;
    char name[64];
    std::snprintf(name, sizeof name, "particles_%04zu.vtu", loop_.vtk_files.size());
    write_vtu((fs::path(o_.out_dir) / "fields" / name).string(), snap);
    loop_.vtk_files.emplace_back(snap.time, name);
    if (const auto* f = solver_.scene().frame.get()) {
      std::snprintf(name, sizeof name, "members_%04zu.vtu", loop_.member_files.size());
      write_lines_vtu((fs::path(o_.out_dir) / "fields" / name).string(), Recorder<D>::member_snapshot(*f));
      loop_.member_files.emplace_back(snap.time, name);
    }
  }

  // The state at the largest member contact force: kept at each new peak and written once the force has fallen below
  // 90 % of it, or at the end, so that the pictures of a short pulse have a snapshot at its peak whatever the snapshot
  // interval (the reader orders snapshots by time); a checkpoint carries it.
  void track_peak() {
    const auto* mc = solver_.member_contact();
    if (!files_ || !mc || s_.output.snapshot_interval <= 0) return;
    const double f = mc->force().norm();
    if (f > peak_snapped_)
      peak_snap_ = rec_.snapshot(solver_), peak_snapped_ = f;
    else if (peak_snap_ && f < 0.9 * peak_snapped_)
      write_peak();
  }

  void write_peak() {
    if (files_ && peak_snap_) writer_->write_snapshot(*peak_snap_), ++loop_.snapshots;
    peak_snap_.reset();
  }

  // Between steps: everything the next step reads.
  void checkpoint() {
    StateWriter w;
    solver_.save_state(w);
    rec_.save_state(w);
    LoopState l = loop_;
    l.wall_seconds = wall_now();
    l.save(w);
    save_peak_snapshot(w, peak_snap_, peak_snapped_);
    write_checkpoint(ckpt_, D, fingerprint_, w.bytes());
  }

  // The run's figures: its cost, the profile, numerical health, the structure's documents and the solid check.
  void record_end() {
    info_.stats.steps = static_cast<double>(solver_.steps());
    info_.stats.wall_seconds = wall_now();
    info_.stats.particles = static_cast<double>(solver_.scene().particles.size());  // at the end (an inflow adds them)
    if (o_.profile) record_profile();
    info_.stats.dt_min = loop_.dt_min;
    info_.stats.dt_max = loop_.dt_max;
    info_.stats.courant_max = loop_.courant_max;  // numerical health (docs/results.md)
    info_.stats.jacobian_min = std::isfinite(loop_.j_min) ? loop_.j_min : 1.0;
    info_.stats.threads = requested_;
    info_.stats.threads_used = used_;  // the most the step loop used (kParallelScene)
    record_structure();
    record_solver_stats();
    if (s_.solid_check.present) {
      const auto t1 = Clock::now();
      auto docs = run_solid_check(s_, info_.peak_contact ? &*info_.peak_contact : nullptr);
      info_.solid_check = std::move(docs.check), info_.solid_field = std::move(docs.field);
      info_.stats.solid_check_seconds = std::chrono::duration<double>(Clock::now() - t1).count();
    }
    info_.stats.status = "complete";
  }

  void record_profile() {
    auto key = [](std::string n) {
      for (char& c : n) c = c == ' ' ? '_' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      return n;
    };
    for (int p = 0; p < Solver<D>::kPhases; ++p) info_.stats.profile_seconds[key(Solver<D>::phase_name(p))] = solver_.phase_seconds()[p];
    info_.stats.profile_seconds["time_step"] = profile_time_step_;
    info_.stats.profile_seconds["recorder"] = profile_recorder_;
    const long steps = solver_.steps() - first_step_;
    info_.stats.rigid_passes_per_step = steps > 0 ? double(solver_.rigid_passes()) / double(steps) : 0.0;
  }

  void record_structure() {
    const auto* frame = solver_.scene().frame.get();
    if (!frame) return;
    info_.structure = structure_record(s_, *frame);
    info_.peak_contact = rec_.peak_contact(*frame);
    info_.face_profile = rec_.face_profile();
  }

  void record_solver_stats() {
    const auto& bodies = solver_.scene().bodies;
    if (std::any_of(bodies.begin(), bodies.end(), [](const Body& b) { return b.rigid_when_free; })) {
      info_.stats.free_rigid_switches = static_cast<double>(solver_.free_switches());
      info_.stats.free_rigid_steps = static_cast<double>(solver_.free_rigid_steps());
    }
    if (const auto* iv = solver_.viscosity()) {
      info_.stats.viscous_steps = static_cast<double>(iv->stats().steps);
      info_.stats.viscous_stages = static_cast<double>(iv->stats().stages);
    }
    if (const auto* mc = solver_.member_contact()) {
      const MemberContactStats& st = mc->stats();
      info_.stats.member_contact_candidates = static_cast<double>(st.candidates);
      info_.stats.member_contact_loaded = static_cast<double>(st.loaded);
      info_.stats.projection_iterations_mean = st.candidates > 0 ? double(st.projection_iterations) / st.candidates : 0.0;
      info_.stats.projection_iterations_max = st.max_projection_iterations;
    }
  }

  // The results in memory and, with an output folder, results.h5 completed and the checkpoint removed.
  RunOutput finish() {
    namespace fs = std::filesystem;
    RunOutput out;
    out.results.info = info_;
    out.results.time = rec_.time();
    out.results.series = rec_.series();
    out.results.complete = true;
    if (!files_) return out;
    if (s_.output.vtk) write_pvd((fs::path(o_.out_dir) / "fields" / "particles.pvd").string(), loop_.vtk_files);
    if (s_.output.vtk && !loop_.member_files.empty()) write_pvd((fs::path(o_.out_dir) / "fields" / "members.pvd").string(), loop_.member_files);
    writer_->finish(out.results.time, out.results.series, info_);
    out.results_path = results_path_;
    std::error_code ec;
    fs::remove(ckpt_, ec);  // the run is complete: nothing to restart
    return out;
  }

  const Scenario& s_;
  const RunOptions& o_;
  const Clock::time_point t0_ = Clock::now();
  Solver<D> solver_;
  Recorder<D> rec_;
  RunInfo info_;
  std::unique_ptr<ResultsWriter> writer_;
  const bool files_;
  std::string results_path_, ckpt_;
  const std::uint64_t fingerprint_;
  LoopState loop_;
  std::optional<Snapshot> peak_snap_;  // the state at the largest member contact force so far, not yet written
  double peak_snapped_ = 0;            // its force (N)
  const double end_, eps_;
  long first_step_ = 0;
  double profile_time_step_ = 0, profile_recorder_ = 0;  // o.profile: stable_time_step; recorder, snapshots, progress
  Clock::time_point last_ckpt_;
  int requested_ = 1, used_ = 0;
};

template <int D> RunOutput run(const Scenario& s, const RunOptions& o) { return RunDriver<D>(s, o).execute(); }

// A scenario with only a solid_check (no bodies): the solid-FE load cases, no time stepping.
RunOutput run_solid_only(const Scenario& s, const RunOptions& o) {
  namespace fs = std::filesystem;
  const auto t0 = std::chrono::steady_clock::now();
  RunInfo info = make_info(s, o);
  RunOutput out;
  auto docs = run_solid_check(s, nullptr);
  info.solid_check = std::move(docs.check), info.solid_field = std::move(docs.field);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  info.stats.steps = 0;
  info.stats.wall_seconds = wall;
  info.stats.solid_check_seconds = wall;
  info.stats.status = "complete";
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

// Runs side by side (the variants of one scenario, the levels of a grid study) share the handlers: the first scope
// installs them, the last restores the previous ones, and a signal stops every run. A scope held around all of them
// keeps a signal from being forgotten between two runs (a run starting after it stops at once); when the outermost
// scope ends normally with a signal that no run acted on, the signal is raised again under the previous handlers.
namespace {
std::mutex g_scope_mu;
int g_scope_users = 0;
void (*g_old_int)(int) = nullptr;
void (*g_old_term)(int) = nullptr;
}  // namespace

InterruptScope::InterruptScope() {
  const std::lock_guard<std::mutex> lock(g_scope_mu);
  if (g_scope_users++ == 0) g_signal = 0, g_old_int = std::signal(SIGINT, on_signal), g_old_term = std::signal(SIGTERM, on_signal);
}

InterruptScope::~InterruptScope() {
  int pending = 0;
  {
    const std::lock_guard<std::mutex> lock(g_scope_mu);
    if (--g_scope_users != 0) return;
    std::signal(SIGINT, g_old_int), std::signal(SIGTERM, g_old_term);
    if (std::uncaught_exceptions() == 0) pending = g_signal;  // unwinding: the run that stopped reports it
    g_signal = 0;
  }
  if (pending != 0) std::raise(pending);
}

RunEstimate preflight(const Scenario& s) {
  if (s.bodies.empty()) return {};
  if (s.analysis.dimension == 2) return step_budget(Solver<2>(build_scene<2>(s)), s);
  return step_budget(Solver<3>(build_scene<3>(s)), s);
}

RunOutput run_scenario(const Scenario& s, const RunOptions& o) {
  if (o.threads > 0) omp_set_num_threads(o.threads);
  if (s.bodies.empty()) return run_solid_only(s, o);
  return s.analysis.dimension == 2 ? run<2>(s, o) : run<3>(s, o);
}

}  // namespace dmi
