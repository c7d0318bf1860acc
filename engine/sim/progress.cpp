#include "engine/sim/progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace dmi {

Progress::Progress(ProgressMode mode, double end_time, std::string label)
    : mode_(mode), end_time_(end_time), label_(std::move(label)), start_(std::chrono::steady_clock::now()), last_(start_) {
  if (mode_ == ProgressMode::automatic) mode_ = isatty(STDERR_FILENO) ? ProgressMode::terminal : ProgressMode::lines;
}

std::string Progress::line(double t, long step, double dt) const {
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double frac = end_time_ > 0 ? t / end_time_ : 1.0;
  const double eta = frac > 1e-9 ? wall * (1 - frac) / frac : 0.0;
  char buf[256];
  std::snprintf(buf, sizeof buf, "%s: t = %.4g / %.4g s (%3.0f%%), step %ld, dt = %.3g s, wall %.1f s, ETA %.1f s",
                label_.c_str(), t, end_time_, 100 * frac, step, dt, wall, eta);
  return buf;
}

void Progress::update(double t, long step, double dt) {
  if (mode_ == ProgressMode::quiet) return;
  if (mode_ == ProgressMode::terminal) {
    if ((step & 63) != 0) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < std::chrono::milliseconds(250)) return;
    last_ = now;
    std::fprintf(stderr, "\r%s\033[K", line(t, step, dt).c_str());
    return;
  }
  if (end_time_ > 0 && t >= next_decile_ * 0.1 * end_time_) {
    while (t >= next_decile_ * 0.1 * end_time_) ++next_decile_;
    std::fprintf(stderr, "%s\n", line(t, step, dt).c_str());
  }
}

void Progress::finish(double t, long step) {
  if (mode_ == ProgressMode::quiet) return;
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (mode_ == ProgressMode::terminal) std::fprintf(stderr, "\r\033[K");
  std::fprintf(stderr, "%s: done, t = %.4g s, %ld steps, wall %.2f s\n", label_.c_str(), t, step, wall);
}

}  // namespace dmi
