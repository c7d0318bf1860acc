// libFuzzer target: scenario text -> dmi::parse_scenario and dmi::parse_scenario_variants (presets expanded,
// every variant parsed and validated). The documented rejection is dmi::InputError (engine/scenario/scenario.hpp;
// the CLI prints it as one line, exit 2): caught here and checked to be one non-empty line naming the file.
// Anything else is a finding: a crash, an ASan/UBSan report, another exception (the CLI's catch-all would turn it
// into an error without file, JSON path and expectation), a hang or a huge allocation. Seeds: examples/*.json,
// tests/data/bad/*.json (scripts/fuzz), regressions in fuzz/regressions/fuzz_scenario/.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "engine/common/error.hpp"
#include "engine/scenario/scenario.hpp"

namespace {

constexpr const char* kFile = "fuzz.json";

// The CLI's contract (README "Exit codes"): one line naming the file.
void check_message(const dmi::InputError& e) {
  const std::string m = e.what();
  if (m.empty() || m.find('\n') != std::string::npos || m.find(kFile) == std::string::npos) {
    std::fprintf(stderr, "fuzz_scenario: InputError message is not one line naming the file:\n%s\n", m.c_str());
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)dmi::parse_scenario(text, kFile);
  } catch (const dmi::InputError& e) {
    check_message(e);
  }
  try {
    (void)dmi::parse_scenario_variants(text, kFile);
  } catch (const dmi::InputError& e) {
    check_message(e);
  }
  return 0;
}
