// The memory a run may plan to use: the machine's physical memory, or DMI_MEMORY_LIMIT (bytes, e.g. 8e9) when set,
// for a shared machine or a job slot. Runs whose estimate exceeds it are refused before they allocate
// (engine/scenario/parse.cpp), instead of ending in std::bad_alloc or the kernel's OOM killer.
#pragma once
#include <unistd.h>

#include <cstdlib>

namespace dmi {

struct MemoryLimit {
  double bytes;
  const char* source;  // for messages
};

inline MemoryLimit memory_limit() {
  if (const char* e = std::getenv("DMI_MEMORY_LIMIT")) {
    char* end = nullptr;
    const double v = std::strtod(e, &end);
    if (end != e && v > 0) return {v, "DMI_MEMORY_LIMIT"};
  }
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  return {pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 1e18, "this machine's physical memory"};
}

}  // namespace dmi
