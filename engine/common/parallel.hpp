// Loops that enter OpenMP only when they are long enough to pay for it. `#pragma omp parallel for if (false)` still
// calls into libgomp (a team of one, and a futex wake per region): 0.33 us per region measured here with the passive
// wait policy. A small scene crosses ~20 regions per step, ~7 us of a ~30 us step (paper A.5, docs/performance.md),
// so below kParallelMin iterations the loop runs inline instead. Results do not depend on which way a loop ran: the
// bodies write disjoint entries, and min / max / or reductions are exact in any order.
#pragma once
#include <algorithm>

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

// Indices handed out dynamically in runs of consecutive ones, about 8 runs per thread (tiles of very different
// particle counts balance; consecutive tiles of a colour are neighbours 8 cells apart, and single tiles handed to
// alternating threads shared the cache lines of the nodal mass between them at every tile edge).
template <class F> inline void parallel_for_dynamic(Index n, bool parallel, F&& f) {
  if (!parallel) {
    for (Index i = 0; i < n; ++i) f(i);
    return;
  }
  const Index run = std::max<Index>(1, n / (8 * omp_get_max_threads()));
#pragma omp parallel for schedule(dynamic, run)
  for (Index i = 0; i < n; ++i) f(i);
}

template <class T, class F> inline T parallel_max(Index begin, Index end, T init, F&& term) {
  T m = init;
  if (end - begin <= kParallelMin) {
    for (Index i = begin; i < end; ++i) m = std::max(m, term(i));
    return m;
  }
#pragma omp parallel for schedule(static) reduction(max : m)
  for (Index i = begin; i < end; ++i) m = std::max(m, term(i));
  return m;
}

template <class T, class F> inline T parallel_min(Index begin, Index end, T init, F&& term) {
  T m = init;
  if (end - begin <= kParallelMin) {
    for (Index i = begin; i < end; ++i) m = std::min(m, term(i));
    return m;
  }
#pragma omp parallel for schedule(static) reduction(min : m)
  for (Index i = begin; i < end; ++i) m = std::min(m, term(i));
  return m;
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
