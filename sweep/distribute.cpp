#include "sweep/distribute.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>

#ifdef DMI_HAVE_MPI
#define OMPI_SKIP_MPICXX 1  // the C API only (no C++ bindings to link)
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>
#endif

namespace dmi::sweep {
using json = nlohmann::json;

namespace {

void log_row(const SweepRow& row, int rank, std::size_t n, bool quiet) {
  if (quiet) return;
  std::printf("[rank %d] %s/%zu %-8s %7.1f s  %s%s\n", rank, row.case_name.c_str(), n, row.status.c_str(), row.wall_seconds,
              row.max_utilisation ? ("max utilisation " + std::to_string(*row.max_utilisation).substr(0, 5)).c_str() : "",
              row.error ? (" " + *row.error).c_str() : "");
  std::fflush(stdout);
}

#ifdef DMI_HAVE_MPI
constexpr int kTagRequest = 1, kTagIndex = 2, kTagRows = 3;
#endif

}  // namespace

Ranks start_ranks(int* argc, char*** argv) {
  Ranks r;
#ifdef DMI_HAVE_MPI
  if (std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMI_SIZE") || std::getenv("PMIX_RANK")) {
    int provided = 0;
    MPI_Init_thread(argc, argv, MPI_THREAD_SERIALIZED, &provided);
    if (provided < MPI_THREAD_SERIALIZED) {
      std::fprintf(stderr, "damimpact: error: the MPI library gives thread level %d, the sweep needs MPI_THREAD_SERIALIZED\n", provided);
      MPI_Abort(MPI_COMM_WORLD, 2);
    }
    MPI_Comm_rank(MPI_COMM_WORLD, &r.rank);
    MPI_Comm_size(MPI_COMM_WORLD, &r.size);
    r.mpi = true;
  }
#else
  (void)argc, (void)argv;
#endif
  return r;
}

void stop_ranks(const Ranks& r) {
#ifdef DMI_HAVE_MPI
  if (r.mpi) MPI_Finalize();
#else
  (void)r;
#endif
}

void abort_ranks(const Ranks& r, int code) {
#ifdef DMI_HAVE_MPI
  if (r.mpi && r.size > 1) MPI_Abort(MPI_COMM_WORLD, code);
#else
  (void)r;
#endif
  std::exit(code);
}

std::vector<SweepRow> run_cases(const SweepSpec& spec, const SweepOptions& o, const Ranks& r) {
  const std::size_t n = spec.cases.size();
  std::vector<SweepRow> rows;
  if (r.size == 1) {
    for (std::size_t k = 0; k < n; ++k) {
      rows.push_back(run_case(spec, k, o));
      log_row(rows.back(), 0, n, o.quiet);
    }
    return rows;
  }
#ifdef DMI_HAVE_MPI
  if (r.rank == 0) {
    std::atomic<long> next{0};
    // Dispatcher: answers each worker's request with the next case index, -1 when none are left. It polls (Iprobe +
    // 20 ms sleep) instead of blocking in MPI_Recv, which would spin a core that the cases need.
    std::thread dispatcher([&] {
      int finished = 0;
      while (finished < r.size - 1) {
        int flag = 0;
        MPI_Status st;
        MPI_Iprobe(MPI_ANY_SOURCE, kTagRequest, MPI_COMM_WORLD, &flag, &st);
        if (!flag) {
          std::this_thread::sleep_for(std::chrono::milliseconds(20));
          continue;
        }
        int dummy = 0;
        MPI_Recv(&dummy, 1, MPI_INT, st.MPI_SOURCE, kTagRequest, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        long k = next.fetch_add(1);
        if (k >= static_cast<long>(n)) k = -1, ++finished;
        MPI_Send(&k, 1, MPI_LONG, st.MPI_SOURCE, kTagIndex, MPI_COMM_WORLD);
      }
    });
    for (long k; (k = next.fetch_add(1)) < static_cast<long>(n);) {
      rows.push_back(run_case(spec, static_cast<std::size_t>(k), o));
      log_row(rows.back(), 0, n, o.quiet);
    }
    dispatcher.join();
    for (int w = 1; w < r.size; ++w) {  // every worker's rows, one JSON text each
      MPI_Status st;
      MPI_Probe(w, kTagRows, MPI_COMM_WORLD, &st);
      int len = 0;
      MPI_Get_count(&st, MPI_CHAR, &len);
      std::string text(static_cast<std::size_t>(len), '\0');
      MPI_Recv(text.data(), len, MPI_CHAR, w, kTagRows, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      for (const json& row : json::parse(text)) rows.push_back(row_from_json(row));
    }
    std::sort(rows.begin(), rows.end(), [](const SweepRow& a, const SweepRow& b) { return a.index < b.index; });
  } else {
    json mine = json::array();
    while (true) {
      int dummy = 0;
      long k = -1;
      MPI_Send(&dummy, 1, MPI_INT, 0, kTagRequest, MPI_COMM_WORLD);
      MPI_Recv(&k, 1, MPI_LONG, 0, kTagIndex, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      if (k < 0) break;
      const SweepRow row = run_case(spec, static_cast<std::size_t>(k), o);
      mine.push_back(to_json(row));
      log_row(row, r.rank, n, o.quiet);
    }
    const std::string text = mine.dump();
    MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, 0, kTagRows, MPI_COMM_WORLD);
  }
#endif
  return rows;
}

}  // namespace dmi::sweep
