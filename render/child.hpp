// Child processes of the drawing commands (the second picture process, weasyprint) that end with this process: a
// child is sent SIGTERM when this process dies (PR_SET_PDEATHSIG), so no helper outlives an interrupted run.
#pragma once
#include <string>
#include <vector>

#include <sys/types.h>

namespace dmi::render {

// Starts args[0] with args; stdin from in_fd (-1: /dev/null; the child's copy only), stdout and stderr to out_path
// (/dev/null when empty). Returns its process id, or -1 when it could not be started.
pid_t start_child(const std::vector<std::string>& args, int in_fd, const std::string& out_path);
// Waits for the child: its exit status, or -1 when a signal ended it.
int wait_child(pid_t pid);
// Ends the child (SIGTERM) and waits for it.
void stop_child(pid_t pid);

}  // namespace dmi::render
