// The sweep's summary (docs/sweep.md): summary.json, summary.csv, charts of the governing utilisation and the base
// reactions against each parameter (with vs without buffer), the design envelope, and summary.html/.pdf.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sweep/case_runner.hpp"

namespace dmi::sweep {

struct SweepRun {
  int ranks = 1, threads_per_rank = 1;
  double wall_seconds = 0;
};

// summary.json's document (format damimpact-sweep, version 1).
SweepSummary summary_document(const SweepSpec& spec, std::vector<SweepRow> rows, const SweepRun& run, const std::string& software_version);
// summary.csv: one line per case, parameters first.
std::string summary_csv(const SweepSummary& summary);
// Writes summary.json, summary.csv, images/*.png, summary.html and (with pdf) summary.pdf into out_dir.
void write_summary(const SweepSummary& summary, const std::string& out_dir, bool pdf, bool quiet);

}  // namespace dmi::sweep
