// libFuzzer target: bytes -> a temporary file -> dmi::read_results(path, true), then, for a file it accepts, the
// design layer's reading of it (dmi::design::design_run with the default limits: /documents/structure,
// /documents/peak_contact, /documents/solid_check, /documents/design_basis and the histories they name), which is
// what `damimpact check` does after read_results. Documented rejections: std::runtime_error naming the file from
// read_results (engine/io/results_writer.hpp: it converts every other failure itself) and std::exception from
// design_run (design/check_main.cpp turns both into InputError, exit 2). Anything else is a finding: a crash, an
// ASan/UBSan report, another exception, a hang or a huge allocation. HDF5's own error printing is silenced by
// read_results (H5Eset_auto2). Seeds: results.h5 files of short runs (scripts/fuzz), fuzz/regressions/fuzz_results/.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "design/design.hpp"
#include "engine/io/results_writer.hpp"

namespace {

const std::string& temp_path() {
  static const std::string p = [] {
    const char* dir = std::getenv("DMI_FUZZ_TMP");  // scripts/fuzz points it at /dev/shm when there is one
    const std::filesystem::path d = dir && *dir ? std::filesystem::path(dir) : std::filesystem::temp_directory_path();
    return (d / ("dmi-fuzz-results-" + std::to_string(::getpid()) + ".h5")).string();
  }();
  static const struct Cleanup {
    ~Cleanup() { std::remove(p.c_str()); }
  } cleanup;
  return p;
}

void check_message(const std::exception& e) {
  const std::string m = e.what();
  if (m.find(temp_path()) == std::string::npos) {
    std::fprintf(stderr, "fuzz_results: error message does not name the file:\n%s\n", m.c_str());
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = temp_path();
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!out) {
      std::fprintf(stderr, "fuzz_results: cannot write %s\n", path.c_str());
      std::abort();
    }
  }
  dmi::Results r;
  try {
    r = dmi::read_results(path, true);
  } catch (const std::runtime_error& e) {
    check_message(e);
    return 0;
  }
  try {
    (void)dmi::design::design_run(r, dmi::design::Limits{}, path);
  } catch (const std::runtime_error& e) {  // design/ names the file itself (check_main passes it on as it is)
    check_message(e);
  } catch (const std::exception&) {  // check_main prefixes the file name
  }
  return 0;
}
