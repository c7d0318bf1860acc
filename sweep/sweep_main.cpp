#include "sweep/sweep_main.hpp"

#include <omp.h>

#include <chrono>
#include <cstdio>
#include <filesystem>

#include "engine/common/error.hpp"
#include "sweep/distribute.hpp"
#include "sweep/summary.hpp"

namespace dmi::sweep {

int sweep_main(const std::string& file, const SweepOptions& opts) {
  const Ranks ranks = start_ranks(nullptr, nullptr);
  SweepOptions o = opts;
  SweepSpec spec;
  try {
    spec = load_sweep(file);
    std::filesystem::create_directories(o.out_dir);
  } catch (const std::exception& e) {  // every rank reads the same file: rank 0 says it once
    if (ranks.rank == 0) std::fprintf(stderr, "damimpact: error: %s\n", e.what());
    stop_ranks(ranks);
    return 2;
  }
  if (o.threads > 0) omp_set_num_threads(o.threads);
  if (ranks.rank == 0 && !o.quiet)
    std::printf("sweep %s: %zu cases, %zu parameters, %d rank(s) x %d thread(s) -> %s\n", spec.name.c_str(), spec.cases.size(),
                spec.parameters.size(), ranks.size, omp_get_max_threads(), o.out_dir.c_str());
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<SweepRow> rows;
  try {
    rows = run_cases(spec, o, ranks);
  } catch (const std::exception& e) {  // an interrupt or an I/O failure outside a case: stop every rank
    std::fprintf(stderr, "damimpact: sweep stopped on rank %d: %s\n", ranks.rank, e.what());
    abort_ranks(ranks, 2);
  }
  int rc = 0;
  if (ranks.rank == 0) {
    SweepRun run;
    run.ranks = ranks.size;
    run.threads_per_rank = omp_get_max_threads();
    run.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const SweepSummary s = summary_document(spec, std::move(rows), run, o.software_version);
    write_summary(s, o.out_dir, o.pdf, o.quiet);
    const int cases = static_cast<int>(s.cases.size());
    if (!o.quiet)
      std::printf("%d of %d cases pass; %d could not run; %d reused; %.1f s (%.1f cases per hour)\n", s.passed, cases, s.failed_runs, s.reused,
                  run.wall_seconds, s.cases_per_hour);
    rc = s.passed == cases ? 0 : 1;
  }
  stop_ranks(ranks);
  return rc;
}

}  // namespace dmi::sweep
