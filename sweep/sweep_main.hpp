// `damimpact sweep STUDY.json -o OUT/` (docs/sweep.md).
#pragma once
#include "sweep/case_runner.hpp"

namespace dmi::sweep {

// Runs every case (over MPI ranks under mpirun), then rank 0 writes the summary. Returns 0 when every case ran and
// passed its design checks, 1 when a case fails a check or could not run; a bad sweep file gives 2 (one message).
int sweep_main(const std::string& file, const SweepOptions& o);

}  // namespace dmi::sweep
