// A second process for the pictures: `damimpact-full render --helper-of PID --claims DIR -q -- OUT` draws the pictures
// it claims before this process does (render_runs): a picture's claim is an exclusive file in DIR, a folder made
// afresh for each invocation and removed with it. Each picture is drawn whole by one process from the runs alone, so
// the files are the same whichever process draws them; the manifest (images.json) is this process's. Started before
// the runs are read, so that the helper's start-up, reading and EGL set-up overlap this process's
// (docs/performance.md, "Pictures in two processes").
#pragma once
#include <string>

#include <sys/types.h>

namespace dmi::render {

class PictureHelper {
 public:
  // Starts the helper when `processes` >= 2, this process may run on two or more CPUs (its affinity mask) and a
  // picture program is set; otherwise there is none (active() is false).
  PictureHelper(const std::string& out_dir, const std::string& quantity, int processes);
  ~PictureHelper();  // stops a helper not waited for; removes the claims folder
  PictureHelper(const PictureHelper&) = delete;
  PictureHelper& operator=(const PictureHelper&) = delete;
  bool active() const { return pid_ > 0; }
  const std::string& claims() const { return claims_; }
  // Waits for the helper to end: true when it drew its pictures (exit 0); false otherwise.
  bool wait();
  // Ends it now if it runs (an error in this process) and removes what a picture cut short left in image_dir (*.tmp,
  // *.tmp.svg).
  void stop(const std::string& image_dir);

 private:
  pid_t pid_ = -1;
  std::string claims_;
};

// CPUs this process may run on (sched_getaffinity), at least 1.
int usable_cpus();

// The program the helper runs (`PROGRAM render --helper-of PID --claims DIR -- OUT`): the command-line tool sets its
// own file; unset, no helper starts.
void set_picture_program(const std::string& path);

}  // namespace dmi::render
