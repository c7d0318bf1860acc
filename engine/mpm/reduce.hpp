// Deterministic parallel sum: fixed chunks summed in parallel, partials added in chunk order,
// so the result is bit-identical for any thread count.
#pragma once
#include <vector>

#include "engine/common/parallel.hpp"
#include "engine/common/types.hpp"

namespace dmi {

template <class F> double deterministic_sum(Index n, F&& term) {
  constexpr Index chunk = 4096;
  const Index nc = (n + chunk - 1) / chunk;
  std::vector<double> part(static_cast<std::size_t>(nc), 0.0);
  const auto chunk_sum = [&](Index c) {
    double s = 0;
    const Index end = std::min(n, (c + 1) * chunk);
    for (Index i = c * chunk; i < end; ++i) s += term(i);
    part[c] = s;
  };
  if (n <= kParallelMin) {  // one chunk, inline (parallel.hpp: no OpenMP region for small loops)
    for (Index c = 0; c < nc; ++c) chunk_sum(c);
  } else {
#pragma omp parallel for schedule(static)
    for (Index c = 0; c < nc; ++c) chunk_sum(c);
  }
  double s = 0;
  for (double x : part) s += x;
  return s;
}

}  // namespace dmi
