// Progress of a long run on stderr: a self-updating line on a terminal, plain lines otherwise.
#pragma once
#include <chrono>
#include <string>

namespace dmi {

enum class ProgressMode { automatic, terminal, lines, quiet };

class Progress {
 public:
  Progress(ProgressMode mode, double end_time, std::string label);
  void update(double t, long step, double dt);  // cheap; prints at most ~4 times a second (terminal) or every 10 % (lines)
  void finish(double t, long step);

 private:
  std::string line(double t, long step, double dt) const;
  ProgressMode mode_;
  double end_time_;
  std::string label_;
  std::chrono::steady_clock::time_point start_, last_;
  int next_decile_ = 1;
};

}  // namespace dmi
