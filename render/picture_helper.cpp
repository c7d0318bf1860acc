#include "render/picture_helper.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <vector>

#include <sched.h>
#include <unistd.h>

#include "render/child.hpp"

namespace dmi::render {

namespace fs = std::filesystem;

namespace {
std::string& program() {
  static std::string p;
  return p;
}
}  // namespace

void set_picture_program(const std::string& path) { program() = path; }

int usable_cpus() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) != 0) return 1;
  return std::max(1, CPU_COUNT(&set));
}

PictureHelper::PictureHelper(const std::string& out_dir, const std::string& quantity, int processes) {
  const std::string exe = program();
  if (processes < 2 || exe.empty() || usable_cpus() < 2) return;
  std::error_code ec;
  std::string tmpl = (fs::temp_directory_path(ec) / "dmi_pictures_XXXXXX").string();
  if (ec || !::mkdtemp(tmpl.data())) return;
  claims_ = tmpl;
  // Quiet (stdout and stderr to /dev/null): should it fail, this process draws its pictures and meets the same error
  // itself, reported once.
  pid_ = start_child({exe, "render", "--quantity", quantity, "-q", "--helper-of", std::to_string(::getpid()), "--claims", claims_, "--", out_dir},
                     -1, "");
  if (pid_ <= 0) fs::remove_all(claims_, ec), claims_.clear();
}

bool PictureHelper::wait() {
  if (pid_ <= 0) return false;
  const int status = wait_child(pid_);
  pid_ = -1;
  return status == 0;
}

void PictureHelper::stop(const std::string& image_dir) {
  if (pid_ > 0) stop_child(pid_);
  pid_ = -1;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(image_dir, ec)) {
    const std::string n = e.path().filename().string();
    auto ends = [&](const std::string& s) { return n.size() > s.size() && n.compare(n.size() - s.size(), s.size(), s) == 0; };
    if (ends(".tmp") || ends(".tmp.svg")) fs::remove(e.path(), ec);
  }
}

PictureHelper::~PictureHelper() {
  if (pid_ > 0) stop_child(pid_);
  std::error_code ec;
  if (!claims_.empty()) fs::remove_all(claims_, ec);
}

}  // namespace dmi::render
