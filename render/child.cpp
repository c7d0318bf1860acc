#include "render/child.hpp"

#include <cerrno>
#include <csignal>

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace dmi::render {

pid_t start_child(const std::vector<std::string>& args, int in_fd, const std::string& out_path) {
  if (args.empty()) return -1;
  std::vector<char*> argv;  // built before fork: the child calls only async-signal-safe functions
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const char* out = out_path.empty() ? "/dev/null" : out_path.c_str();
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid != 0) return pid < 0 ? -1 : pid;
  if (::prctl(PR_SET_PDEATHSIG, SIGTERM) != 0 || ::getppid() != parent) ::_exit(127);  // the parent already gone
  // Close-on-exec: only the copies on 0, 1 and 2 reach the program.
  const int in = in_fd >= 0 ? in_fd : ::open("/dev/null", O_RDONLY | O_CLOEXEC);
  const int o = ::open(out, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (in < 0 || o < 0 || ::dup2(in, 0) < 0 || ::dup2(o, 1) < 0 || ::dup2(o, 2) < 0) ::_exit(127);
  ::execv(argv[0], argv.data());
  ::_exit(127);
}

int wait_child(pid_t pid) {
  int status = 0;
  pid_t r;
  do r = ::waitpid(pid, &status, 0);
  while (r < 0 && errno == EINTR);
  return r > 0 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

void stop_child(pid_t pid) {
  ::kill(pid, SIGTERM);
  wait_child(pid);
}

}  // namespace dmi::render
