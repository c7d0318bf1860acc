// Loops that enter OpenMP only when they are long enough to pay for it. `#pragma omp parallel for if (false)` still
// calls into libgomp (a team of one, and a futex wake per region): 0.33 us per region measured here with the passive
// wait policy. A small scene crosses ~20 regions per step, ~7 us of a ~30 us step (Lin & Yang verification 1, docs/performance.md),
// so below kParallelMin iterations the loop runs inline instead. Results do not depend on which way a loop ran: the
// bodies write disjoint entries, parallel_reduce combines fixed chunks in a fixed order, and parallel_or is exact
// in any order.
#pragma once
#include <algorithm>
#include <vector>

#include <omp.h>

#include "engine/common/types.hpp"

namespace dmi {

template <class F> inline void parallel_for(Index begin, Index end, F&& f) {
  if (end - begin <= kParallelMin) {
    for (Index i = begin; i < end; ++i) f(i);
    return;
  }
#pragma omp parallel for schedule(static)
  for (Index i = begin; i < end; ++i) f(i);
}

// Indices handed out dynamically in runs of consecutive ones, about 8 runs per thread (work items of very different
// particle counts balance; consecutive single tiles of a colour are neighbours 12 cells apart, and single tiles handed
// to alternating threads shared the cache lines of the nodal mass between them at every tile edge).
template <class F> inline void parallel_for_dynamic(Index n, bool parallel, F&& f) {
  if (!parallel) {
    for (Index i = 0; i < n; ++i) f(i);
    return;
  }
  const Index run = std::max<Index>(1, n / (8 * omp_get_max_threads()));
#pragma omp parallel for schedule(dynamic, run)
  for (Index i = 0; i < n; ++i) f(i);
}

// combine(...combine(combine(init, term(begin)), term(begin + 1))...) over [begin, end) in fixed chunks of 4096,
// each reduced from init, the partials combined in chunk order: bit-identical for any thread count, also for sums
// (not associative in floating point). One chunk runs inline; more run under OpenMP.
template <class T, class F, class C> inline T parallel_reduce(Index begin, Index end, T init, F&& term, C&& combine) {
  constexpr Index chunk = 4096;
  const Index n = end - begin, nc = (n + chunk - 1) / chunk;
  const auto reduce_chunk = [&](Index c) {
    T r = init;
    for (Index i = begin + c * chunk; i < std::min(end, begin + (c + 1) * chunk); ++i) r = combine(r, term(i));
    return r;
  };
  if (n <= kParallelMin) {
    T r = init;
    for (Index c = 0; c < nc; ++c) r = combine(r, reduce_chunk(c));
    return r;
  }
  std::vector<T> part(static_cast<std::size_t>(nc), init);
#pragma omp parallel for schedule(static)
  for (Index c = 0; c < nc; ++c) part[c] = reduce_chunk(c);
  T r = init;
  for (const T& x : part) r = combine(r, x);
  return r;
}

// Bitwise or of term(i) over [0, n): parallel when `parallel`.
template <class F> inline int parallel_or(Index n, bool parallel, F&& term) {
  int r = 0;
  if (!parallel) {
    for (Index i = 0; i < n; ++i) r |= term(i);
    return r;
  }
#pragma omp parallel for schedule(static) reduction(| : r)
  for (Index i = 0; i < n; ++i) r |= term(i);
  return r;
}

}  // namespace dmi
