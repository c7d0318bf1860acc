// One case of a sweep: its scenario, every variant simulated, the design checks, optionally its report, and the
// summary row built from design.json (docs/sweep.md, "summary").
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "sweep/spec.hpp"
#include "sweep/summary_record.hpp"

namespace dmi::sweep {

struct SweepOptions {
  std::string out_dir;
  std::string limits_file;   // design limits (docs/design-checks.md), "" = defaults
  int threads = 0;           // OpenMP threads per case (per rank)
  bool case_reports = true;  // HTML report per case (pictures rendered off-screen)
  bool pdf = true;           // PDFs (case reports and the summary report)
  bool quiet = false;
  std::string software_version;
};

// Runs case k into OUT/cases/<id>/ and returns its summary row. A case whose complete results exist for the same
// scenario is not simulated again (status "reused"); a case that fails (bad input, failed run) gets status "failed"
// and its error, and never throws (except Interrupted, which stops the sweep).
SweepRow run_case(const SweepSpec& spec, std::size_t k, const SweepOptions& o);

}  // namespace dmi::sweep
