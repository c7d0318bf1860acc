// Cases over MPI ranks (docs/sweep.md "Distribution"): dynamic self-scheduling, rank 0 serving the next case index
// from a dispatcher thread (MPI_THREAD_SERIALIZED: while it runs, rank 0's working thread makes no MPI calls) and
// working on cases itself; rows return to rank 0 at the end. Without mpirun (or a build without MPI) the same
// call runs every case in this process.
#pragma once
#include <vector>

#include <nlohmann/json.hpp>

#include "sweep/case_runner.hpp"

namespace dmi::sweep {

struct Ranks {
  int rank = 0, size = 1;
  bool mpi = false;  // MPI initialised by us (finalise at the end)
};

// MPI_Init_thread when launched by mpirun (OMPI_COMM_WORLD_SIZE / PMI_SIZE set) and built with MPI; else one rank.
Ranks start_ranks(int* argc, char*** argv);
void stop_ranks(const Ranks& r);
// Aborts every rank (a fatal error on one).
[[noreturn]] void abort_ranks(const Ranks& r, int code);

// Every case run once over the ranks; the rows in case order on rank 0, empty elsewhere.
std::vector<SweepRow> run_cases(const SweepSpec& spec, const SweepOptions& o, const Ranks& r);

}  // namespace dmi::sweep
